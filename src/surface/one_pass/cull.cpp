// Cull (paper §2.2.1) for the one-pass trim: a face inside a neighbour's inscribed ball is
// inside its polyhedron (the ball lies in the convex polyhedron) and is dropped before any
// trace is looked for; a face that meets no neighbour's circumscribed ball is outside all.
#include <algorithm>
#include <cmath>
#include <limits>

#include "surface/one_pass/atom_trimmer.hpp"

namespace molsurf::surface_detail::one_pass {

void AtomTrimmer::find_covering() {
  const PolyhedronTemplate& shape = polyhedra_.shape(atom_);
  const double scale = polyhedra_.scale(atom_), error = polyhedra_.vertex_error(atom_);
  for (std::uint32_t b = 0; b < 20; ++b) {
    const Vec3 centre = centre_ + shape.block_centre[b] * scale;
    // Every vertex of the block lies within `radius` of `centre` (rounding included).
    const double radius = shape.block_radius[b] * scale + 2 * error;
    std::array<double, kCovering> best_depth;
    best_depth.fill(-std::numeric_limits<double>::infinity());
    covering_[b].fill(~0u);
    for (std::uint32_t ni = 0; ni < nbr_count_; ++ni) {
      const Vec3 d = centre - nbr_[ni].centre;
      const double reach = nbr_[ni].inradius + radius, dist2 = dot(d, d);
      if (!(dist2 < reach * reach)) continue;  // its inscribed ball holds no vertex of the block
      const double depth = nbr_[ni].inradius - std::sqrt(dist2);
      if (!(depth > best_depth[kCovering - 1])) continue;
      int k = kCovering - 1;
      for (; k > 0 && depth > best_depth[k - 1]; --k) {
        best_depth[k] = best_depth[k - 1];
        covering_[b][k] = covering_[b][k - 1];
      }
      best_depth[k] = depth;
      covering_[b][k] = ni;
    }
    // The block's ball inside the first one's inscribed ball, with a margin far beyond the
    // rounding of the distance, so that every corner passes the cull's own test too.
    const double size = radius + std::max({std::fabs(centre.x), std::fabs(centre.y), std::fabs(centre.z)});
    buried_[b] = best_depth[0] > radius + 1e-12 * size;
  }
}

bool AtomTrimmer::culled(std::uint32_t f, std::uint32_t block) {
  const Triangle& tri = polyhedra_.shape(atom_).unit.faces[f];
  for (int k = 0; k < 3; ++k) f_[k] = vertices_[tri[k]];
  // A face whose corners are inside a neighbour's inscribed ball is inside it.
  auto deep_inside = [&](const Neighbour& n) {
    const double r2 = n.inradius * n.inradius;
    bool inside = true;  // all three tested: no branch per corner
    for (const Vec3& c : f_) {
      const Vec3 d = c - n.centre;
      inside &= dot(d, d) < r2;
    }
    return inside;
  };
  // The neighbours that hold the face's block most deeply usually hold the face.
  for (int k = 0; k < kCovering; ++k) {
    const std::uint32_t ni = covering_[block][k];
    if (ni != ~0u && deep_inside(nbr_[ni])) return true;
  }
  face_ = f;
  f_index_ = tri;
  f_box_ = box_of(f_[0], f_[1], f_[2]);
  work_.clear();
  // The neighbours that can reach the face, listed without a branch per neighbour (which
  // ones do is unpredictable); then, in order, one that buries it ends the search.
  std::uint32_t reaching = 0;
  for (std::uint32_t ni = 0; ni < nbr_count_; ++ni) {
    reaching_[reaching] = ni;
    reaching += f_box_.overlaps(nbr_[ni].box) & box_meets_ball(f_box_, nbr_[ni].centre, nbr_[ni].circumradius);
  }
  for (std::uint32_t k = 0; k < reaching; ++k) {
    if (deep_inside(nbr_[reaching_[k]])) return true;
    work_.near.push_back(reaching_[k]);
  }
  return false;
}

}  // namespace molsurf::surface_detail::one_pass
