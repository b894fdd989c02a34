#include "mesh/component_volume.hpp"

#include <cmath>
#include <limits>

#include "geometry/exact_integers.hpp"

namespace molsurf {

ComponentVolumes component_volumes(const Mesh& mesh, const Components& components) {
  ComponentVolumes out;
  out.volume.assign(components.count, 0.0);
  out.sign.assign(components.count, 0);
  std::vector<std::uint32_t> first_face(components.count, ~0u);
  std::vector<double> magnitude(components.count, 0.0);
  std::vector<std::size_t> faces(components.count, 0);
  auto l1 = [](const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); };
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
    const std::uint32_t c = components.face_component[f];
    if (first_face[c] == ~0u) first_face[c] = f;
    const Vec3 r = mesh.vertices[mesh.faces[first_face[c]][0]];
    const Triangle& t = mesh.faces[f];
    const Vec3 a = mesh.vertices[t[0]] - r, b = mesh.vertices[t[1]] - r, d = mesh.vertices[t[2]] - r;
    out.volume[c] += dot(a, cross(b, d));
    magnitude[c] += l1(a) * l1(b) * l1(d);
    ++faces[c];
  }
  constexpr double eps = std::numeric_limits<double>::epsilon();
  std::vector<std::vector<std::uint32_t>> uncertain;
  for (std::size_t c = 0; c < components.count; ++c) {
    // Rounding of the differences, the products and the sum: a generous bound.
    const double bound = (static_cast<double>(faces[c]) + 64) * eps * magnitude[c];
    out.sign[c] = out.volume[c] > bound ? 1 : (out.volume[c] < -bound ? -1 : 2);
    out.volume[c] /= 6;
  }
  for (std::size_t c = 0; c < components.count; ++c) {
    if (out.sign[c] != 2) continue;
    std::vector<double> values;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
      if (components.face_component[f] == c)
        for (Index v : mesh.faces[f]) values.insert(values.end(), {mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z});
    const int exponent = geometry::common_exponent(values);
    const geometry::IntVec r = geometry::scaled(mesh.vertices[mesh.faces[first_face[c]][0]], exponent);
    mpz_class exact = 0;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
      if (components.face_component[f] != c) continue;
      const Triangle& t = mesh.faces[f];
      exact += geometry::det3(geometry::scaled(mesh.vertices[t[1]], exponent) - r,
                              geometry::scaled(mesh.vertices[t[2]], exponent) - r,
                              geometry::scaled(mesh.vertices[t[0]], exponent) - r);
    }
    out.sign[c] = sgn(exact);
    // Keep the reported volume's sign consistent with the exact one.
    if ((out.volume[c] > 0) != (out.sign[c] > 0) || out.sign[c] == 0)
      out.volume[c] = out.sign[c] * std::fabs(out.volume[c]);
  }
  return out;
}

}  // namespace molsurf
