#pragma once
// A piece's seam: its directed edges without a reverse in the piece, which the neighbouring
// pieces hold reversed, and the points on them. Pieces are glued at these points as the
// whole union's join would have joined them: points with one definition are one point,
// points equal by exact value are one point too (degenerate contacts, where the two sides
// may name the point differently), and the merged vertex takes the coordinates of the
// point that appears first in atom order, as in the whole union.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "molsurf/mesh.hpp"
#include "surface/one_pass/join.hpp"
#include "surface/one_pass/point_definition.hpp"

namespace molsurf::blocks {

// A vertex on a piece's seam: where it is, its definition (atom indices of the whole
// structure) and where it first appears (atom, and its place among that atom's points).
struct SeamPoint {
  Vec3 position;
  surface_detail::PointDefinition definition;
  std::uint32_t atom = 0, position_in_atom = 0;
};

// The directed edges (u, v) of `mesh`'s faces whose reverse no face holds, sorted.
std::vector<std::array<Index, 2>> seam_edges(const Mesh& mesh);

// Per vertex: 1 when it lies on a seam edge.
std::vector<std::uint8_t> seam_vertices(const Mesh& mesh);

// The seam points of a piece just joined: `origins` per vertex (atoms numbered as the
// piece's atoms), `global_index` per piece atom its index in the whole structure.
std::vector<SeamPoint> seam_points(const Mesh& mesh, std::span<const surface_detail::one_pass::VertexOrigin> origins,
                                   std::span<const std::uint32_t> global_index);

// Whether two definitions (atom indices of the whole structure) name the same exact point.
using SamePoint = std::function<bool(const surface_detail::PointDefinition&, const surface_detail::PointDefinition&)>;

// The pieces as one mesh: faces in piece order (tags kept), vertices in piece order, the
// seam vertices of all pieces merged as above (`seams[k]`: piece k's seam points, found by
// position; its seam vertices must still be where they were when it was joined). A piece
// may be a part of its block's piece that holds the whole seam (a seam band).
// `same_point` is asked only about points with different definitions whose coordinates lie
// within a few units in the last place.
// With `on_seam` (may be null): per vertex of the glued mesh, 1 where pieces were glued.
Mesh glue_pieces(std::span<const Mesh> pieces, std::span<const std::vector<SeamPoint>> seams,
                 const SamePoint& same_point, std::vector<std::uint8_t>* on_seam = nullptr);

// Pieces whose seam vertices are shared to the bit (the SES's: ses_piece.hpp) as one mesh:
// faces in piece order (tags kept), vertices in piece order, the vertices on each piece's
// seam merged with the other pieces' seam vertices at the same coordinates. With `on_seam`
// (may be null): per vertex of the glued mesh, 1 where pieces were glued. Whether the glue
// closed every seam is the caller's to check (seam_edges of the result).
Mesh glue_by_position(std::span<const Mesh> pieces, std::vector<std::uint8_t>* on_seam = nullptr);

// Per vertex: 1 unless within `rings` edges of a vertex `near` marks (the vertices a seam's
// cleanup must leave where they are).
std::vector<std::uint8_t> frozen_beyond(const Mesh& mesh, std::span<const std::uint8_t> near, int rings);

}  // namespace molsurf::blocks
