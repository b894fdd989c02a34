#pragma once
// How far the seams' cleanup may carry a face of a seam band from the band as its piece
// left it, and the measure of it. A piece keeps in its border the written faces that come
// within band_reach of one of its own band's vertices; after the seams' cleanup every
// seam face is measured (BandVertices::drift) and must lie within that reach of its own
// block's band vertices, or the run stops with a plain error. So any written face of the
// same block that a cleaned seam face could cross or touch is in the border, and the
// border need not hold every written face near a band atom's sphere: on 2btv in 8 blocks
// that rule kept 404 000 faces, this one keeps a ring or two beyond the band.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point_grid.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::blocks {

// Half an angstrom and two and a half times the edge length the density asks for
// (1.1 / sqrt(density) A). A collapse to a midpoint moves a vertex by half an edge, a move
// toward its neighbours' centre by less than an edge, and a face's points lie within
// 1/sqrt(3) of its longest edge of one of its corners. Measured, no seam face lay farther
// than 1.3 edge lengths from its band (1crn, 2hhb and 2btv at densities 0.3 to 4, probes
// 0 and 1.4, in 4 to 8 blocks).
double band_reach(const SphereOptions& spheres);

// A band's vertices as its pieces left them, each with the block whose band face holds it
// (a seam vertex once per block).
class BandVertices {
 public:
  // `block_of_face`: per face of `band`, its block.
  BandVertices(const Mesh& band, std::span<const std::uint32_t> block_of_face, double reach);
  // How far face f of `mesh` may lie from the vertices of block `block`'s band: the
  // farthest of its corners from the nearest such vertex, plus the reach of its points from
  // its corners (1/sqrt(3) of its longest edge). Infinite when a corner has no vertex of
  // that block within the reach.
  double drift(const Mesh& mesh, std::size_t f, std::uint32_t block) const;

 private:
  std::vector<std::uint32_t> block_;  // before points_: points_of fills it
  std::vector<Vec3> points_;
  double reach_;
  geometry::PointGrid grid_;
};

}  // namespace molsurf::blocks
