#pragma once
// The hierarchical pairwise union (the reference method, the paper's formulation): the
// atoms' spheres joined two at a time by the exact Boolean union (src/boolean/) along a
// merge tree. The tree is a k-d tree over the atom centres: each node's atoms are split by
// a plane across their longest extent, so two merged halves meet only in a slab around
// that plane, and a merge costs in proportion to that slab (the Boolean only works on
// faces in the overlap of the operands' boxes). Its bottom is merged as whole subtrees,
// one per thread, each depth first; its top one level at a time, a level's merges in
// parallel when there are enough of them. A merge frees its operands, and a sphere is
// built when its first merge runs. The result does not depend on the number of threads.
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::surface_detail {

// Fills `result`'s mesh and the merge tree's counts and times (merges, levels,
// level_stats, subtree_height, seconds.subtrees); `threads` above 0.
void pairwise_union(std::span<const Atom> atoms, const SphereUnionOptions& options, int threads, SphereUnion& result);

}  // namespace molsurf::surface_detail
