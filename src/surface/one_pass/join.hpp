#pragma once
// Join (the one-pass union's last step): the pieces of all atoms become one mesh. Points are
// merged by definition (the same input elements name the same point), then points equal by
// exact value but defined differently (degenerate contacts) are merged too; only then are
// they rounded to doubles, and what rounding breaks is repaired by the union engine's
// exact repair (src/boolean/repair_rounding.hpp).
#include <vector>

#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/atom_pieces.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::surface_detail::one_pass {

// Atoms in index order: the mesh is the same for any thread count. `pieces` is freed as
// soon as its faces are joined (the peak memory). Adds the trim's counts, merged_points and
// open_edges (directed edges without their reverse: 0 for a closed surface) to `stats`.
void join_pieces(std::vector<AtomPieces> pieces, const AtomPolyhedra& polyhedra, int threads, Mesh& mesh,
                 OnePassStats& stats);

}  // namespace molsurf::surface_detail::one_pass
