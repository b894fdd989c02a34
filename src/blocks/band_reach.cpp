#include "blocks/band_reach.hpp"

#include <algorithm>
#include <cmath>

#include "blocks/streamed_piece.hpp"

namespace molsurf::blocks {

double band_reach(const SphereOptions& spheres) {
  return 0.5 + 2.5 * 1.1 / std::sqrt(std::max(spheres.density, 0.01));
}

namespace {

std::vector<Vec3> points_of(const Mesh& band, std::span<const std::uint32_t> block_of_face,
                            std::vector<std::uint32_t>& block) {
  std::vector<std::uint64_t> pairs;  // block << 32 | vertex, each once
  for (std::size_t f = 0; f < band.faces.size(); ++f)
    for (Index v : band.faces[f]) pairs.push_back((static_cast<std::uint64_t>(block_of_face[f]) << 32) | v);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<Vec3> points;
  points.reserve(pairs.size());
  block.reserve(pairs.size());
  for (std::uint64_t p : pairs) {
    points.push_back(band.vertices[static_cast<Index>(p & 0xffffffffu)]);
    block.push_back(static_cast<std::uint32_t>(p >> 32));
  }
  return points;
}

}  // namespace

BandVertices::BandVertices(const Mesh& band, std::span<const std::uint32_t> block_of_face, double reach)
    : points_(points_of(band, block_of_face, block_)), reach_(reach), grid_(points_, reach) {}

double BandVertices::drift(const Mesh& mesh, std::size_t f, std::uint32_t block) const {
  const Triangle& t = mesh.faces[f];
  double corners = 0, longest = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = mesh.vertices[t[k]];
    longest = std::max(longest, norm(mesh.vertices[t[(k + 1) % 3]] - p));
    double nearest = HUGE_VAL;
    grid_.for_each_near(p, [&](std::uint32_t i) {
      if (block_[i] == block) nearest = std::min(nearest, norm(points_[i] - p));
    });
    if (!(nearest <= reach_)) return HUGE_VAL;
    corners = std::max(corners, nearest);
  }
  // 0.578 > 1/sqrt(3): the covering radius of a triangle by its corners, with room for rounding.
  return corners + 0.578 * longest;
}

}  // namespace molsurf::blocks
