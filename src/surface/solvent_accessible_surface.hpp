#pragma once
// The union stage of the surface job (compute_surface runs it): the atoms' spheres joined
// into the solvent-accessible surface, with the counts and times of the method used.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/cancel.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

struct SphereUnionOptions {
  SphereOptions spheres;
  SurfaceMethod method = SurfaceMethod::one_pass;
  int threads = 0;  // 0: all cores
  // Called from one thread as the work advances: (atoms trimmed, atoms) for the one-pass
  // method, (merges done, merges in all) after each level for the pairwise one; may be empty.
  std::function<void(std::size_t, std::size_t)> progress;
  // Called once by the one-pass method before its pass, when the spheres have more than
  // `estimate_size_above` faces, with the union's size estimated from a sample of atoms
  // trimmed on their own (a fraction of a percent of the pass); it may throw to stop the
  // job before the memory is spent. May be empty.
  std::function<void(const SurfaceSizeEstimate&)> check_size;
  std::uint64_t estimate_size_above = 0;
  // Set from another thread to stop the union (cancel.hpp): read per atom in the one-pass
  // trim and per merge in the pairwise union. May be null.
  const CancelFlag* cancel = nullptr;
};

struct SphereUnionTimings {  // seconds
  double union_levels = 0;  // the whole union, either method
  double subtrees = 0;      // of union_levels: the subtrees below SphereUnion::subtree_height
};

// One level of the merge tree: where the time goes (step times are summed over the
// level's merges, so they are CPU seconds when merges run in parallel).
struct SurfaceLevel {
  std::size_t merges = 0;
  std::size_t faces_in = 0, active_faces = 0, faces_out = 0;
  std::size_t split_faces = 0, ray_casts = 0, whole_reruns = 0;
  BooleanTimings steps;
  // Wall time of the level; for the levels merged inside subtrees (below
  // SphereUnion::subtree_height), the summed durations of their merges instead.
  double seconds = 0;

  // The merge's counts and step times added in (one more merge); levels add up likewise.
  SurfaceLevel& operator+=(const BooleanStats& merge);
  SurfaceLevel& operator+=(const SurfaceLevel& other);
};

// The one-pass method's counts: where the faces of all polyhedra went.
struct OnePassStats {
  // contained_atoms: atoms inside another atom's ball (copies, concentric smaller ones),
  // left out of the union.
  std::size_t atoms = 0, contained_atoms = 0, neighbour_pairs = 0;
  std::size_t faces_in = 0;       // all polyhedra's faces
  std::size_t faces_inside = 0;   // dropped whole (inside a neighbour)
  std::size_t faces_whole = 0;    // kept whole (reached by no neighbour)
  std::size_t faces_cut = 0;      // re-triangulated
  std::size_t crossings = 0;      // three-plane points (two traces crossing inside a face)
  std::size_t merged_points = 0;  // equal points with different definitions, merged by value
  std::size_t open_edges = 0;     // directed edges without a reverse after the join (0: closed)
  double seconds_trim = 0, seconds_join = 0;
};

// The union stage's own result (internal): the surface job's is ComputedSurface
// (compute_surface.hpp), which takes this mesh through cleanup, check and measures.
struct SphereUnion {
  Mesh mesh;  // face tags: index of the atom whose sphere the face comes from
  SurfaceMethod method = SurfaceMethod::one_pass;  // the method that made `mesh`
  OnePassStats one_pass;
  std::size_t merges = 0, levels = 0;
  std::vector<SurfaceLevel> level_stats;  // bottom (sphere pairs) first
  // Levels below this height were merged subtree by subtree (each depth first, one per
  // thread); the ones above level by level.
  std::size_t subtree_height = 0;
  SphereUnionTimings seconds;
};

// The solvent-accessible surface: the union of all atoms' spheres, by the method asked
// for: in one pass (src/surface/one_pass/), or by the hierarchical pairwise mesh union along
// a k-d tree of the atoms (src/surface/pairwise_union.hpp). Either result does not depend
// on the number of threads. A one-pass result that is not closed (never seen; it would be
// a bug) is returned as it is, with one_pass.open_edges above 0: the fallback to the
// pairwise method is compute_surface's decision (compute_surface.hpp).
SphereUnion solvent_accessible_surface(std::span<const Atom> atoms, const SphereUnionOptions& options);

}  // namespace molsurf
