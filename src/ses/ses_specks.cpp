#include "ses/ses_specks.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/topology.hpp"

namespace molsurf::ses_detail {

std::size_t remove_specks(Mesh& mesh, std::span<const Atom> atoms, double probe) {
  if (mesh.faces.empty() || atoms.empty()) return 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const Atom& a : atoms) smallest = std::min(smallest, a.radius);
  // Half the smaller ball's diameter: a cavity that just holds a probe ball, drawn with
  // facets inside its sphere, stays.
  const double ball = std::min(smallest, probe);
  const Components parts = connected_components(mesh);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<Vec3> lo(parts.count, Vec3{kInf, kInf, kInf}), hi(parts.count, Vec3{-kInf, -kInf, -kInf});
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::uint32_t c = parts.face_component[f];
    for (const Index v : mesh.faces[f]) {
      const Vec3& p = mesh.vertices[v];
      lo[c] = {std::min(lo[c].x, p.x), std::min(lo[c].y, p.y), std::min(lo[c].z, p.z)};
      hi[c] = {std::max(hi[c].x, p.x), std::max(hi[c].y, p.y), std::max(hi[c].z, p.z)};
    }
  }
  std::vector<std::uint8_t> speck(parts.count, 0);
  std::size_t count = 0;
  for (std::size_t c = 0; c < parts.count; ++c) {
    const Vec3 size = hi[c] - lo[c];
    speck[c] = std::max({size.x, size.y, size.z}) < ball;
    count += speck[c];
  }
  if (count == 0) return 0;
  std::vector<std::uint8_t> keep(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) keep[f] = !speck[parts.face_component[f]];
  keep_alive_faces(mesh, keep);
  drop_unused_vertices(mesh);
  return count;
}

}  // namespace molsurf::ses_detail
