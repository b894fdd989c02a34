#pragma once
// Join (the one-pass union's last step): the pieces of all atoms become one mesh. Points are
// merged by definition (the same input elements name the same point), then points equal by
// exact value but defined differently (degenerate contacts) are merged too; only then are
// they rounded to doubles, and what rounding breaks is repaired by the union engine's
// exact repair (src/boolean/repair_rounding.hpp).
#include <cstdint>
#include <vector>

#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/atom_pieces.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::surface_detail::one_pass {

// Where a vertex of the joined mesh comes from: the definition of the point it was first
// named by, and where that point first appeared (the atom, and the point's position among
// that atom's points). The whole union decides a vertex's coordinates by the first
// appearance among the points equal to it, so pieces of the union joined apart can be
// glued as the whole join would have joined them.
struct VertexOrigin {
  PointDefinition definition;
  std::uint32_t atom = 0, position = 0;
};

// Atoms in index order: the mesh is the same for any thread count. `pieces` is freed as
// soon as its faces are joined (the peak memory). Adds the trim's counts, merged_points and
// open_edges (directed edges without their reverse: 0 for a closed surface) to `stats`.
// With `origins` (may be null), each vertex's origin.
void join_pieces(std::vector<AtomPieces> pieces, const AtomPolyhedra& polyhedra, int threads, Mesh& mesh,
                 OnePassStats& stats, std::vector<VertexOrigin>* origins = nullptr);

}  // namespace molsurf::surface_detail::one_pass
