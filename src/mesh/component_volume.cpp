#include "mesh/component_volume.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>

#include "geometry/exact_integers.hpp"
#include "geometry/expansion.hpp"

namespace molsurf {

namespace {

// The sign of the sum of `faces`' signed tetrahedron volumes about vertex `origin`, exactly,
// in integers: every double is an integer times a power of two.
int exact_sign(const Mesh& mesh, std::span<const std::uint32_t> faces, Index origin) {
  int exponent = INT_MAX;
  for (std::uint32_t f : faces)
    for (Index v : mesh.faces[f]) {
      const Vec3& p = mesh.vertices[v];
      exponent = std::min(exponent, geometry::common_exponent(std::array{p.x, p.y, p.z}));
    }
  const geometry::IntVec r = geometry::scaled(mesh.vertices[origin], exponent);
  mpz_class exact = 0;
  for (std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    exact += geometry::det3(geometry::scaled(mesh.vertices[t[1]], exponent) - r,
                            geometry::scaled(mesh.vertices[t[2]], exponent) - r,
                            geometry::scaled(mesh.vertices[t[0]], exponent) - r);
  }
  return sgn(exact);
}

}  // namespace

// Each term (a determinant of three differences) is within 16 u of its magnitude bound
// l1(a) l1(b) l1(d) of the exact one (Shewchuk's orient3d bound is 7 u of the permanent, which
// that bound exceeds), u = 2^-53. The terms are summed with each addition's error kept
// (two_sum, Ogita, Rump & Oishi's Sum2): the result is within u |S| + gamma(n)^2 sum |t| of
// the terms' exact sum S, gamma(n) = n u / (1 - n u). So the sign is certain when |sum| (1 -
// 2u) exceeds (16 u + 2 gamma(n)^2) times the magnitudes' sum (taken 1 % larger for its own
// rounding): an error bound that grows with the faces only through gamma^2, where plain
// summation's grows with their number (the capsid's outer surface at density 4 had an
// uncertain sign with that one and went to integers).
ComponentVolumes component_volumes(const Mesh& mesh, const Components& components) {
  ComponentVolumes out;
  out.volume.assign(components.count, 0.0);
  out.sign.assign(components.count, 0);
  std::vector<std::uint32_t> first_face(components.count, ~0u);
  std::vector<double> compensation(components.count, 0.0), magnitude(components.count, 0.0);
  std::vector<std::uint32_t> faces(components.count, 0);
  auto l1 = [](const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); };
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
    const std::uint32_t c = components.face_component[f];
    if (first_face[c] == ~0u) first_face[c] = f;
    const Vec3 r = mesh.vertices[mesh.faces[first_face[c]][0]];
    const Triangle& t = mesh.faces[f];
    const Vec3 a = mesh.vertices[t[0]] - r, b = mesh.vertices[t[1]] - r, d = mesh.vertices[t[2]] - r;
    double error = 0;
    geometry::expansion_detail::two_sum(out.volume[c], dot(a, cross(b, d)), out.volume[c], error);
    compensation[c] += error;
    magnitude[c] += l1(a) * l1(b) * l1(d);
    ++faces[c];
  }
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  std::vector<std::uint32_t> uncertain;
  for (std::uint32_t c = 0; c < components.count; ++c) {
    const double sum = out.volume[c] + compensation[c];
    const double gamma = static_cast<double>(faces[c]) * u / (1 - static_cast<double>(faces[c]) * u);
    const double bound = (16 * u + 2 * gamma * gamma) * magnitude[c] * 1.01;
    const double certain = std::fabs(sum) * (1 - 2 * u);
    out.sign[c] = certain > bound ? (sum > 0 ? 1 : -1) : 2;
    if (out.sign[c] == 2) uncertain.push_back(c);
    out.volume[c] = sum / 6;
  }
  out.exact_signs = uncertain.size();
  if (uncertain.empty()) return out;

  // The uncertain components' faces, each component's in face order, in one pass.
  std::vector<std::uint32_t> row(components.count, ~0u);
  std::vector<std::size_t> start(uncertain.size() + 1, 0);
  for (std::size_t k = 0; k < uncertain.size(); ++k) {
    row[uncertain[k]] = static_cast<std::uint32_t>(k);
    start[k + 1] = start[k] + faces[uncertain[k]];
  }
  std::vector<std::uint32_t> listed(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
    if (const std::uint32_t k = row[components.face_component[f]]; k != ~0u) listed[next[k]++] = f;
  for (std::size_t k = 0; k < uncertain.size(); ++k) {
    const std::uint32_t c = uncertain[k];
    const std::span<const std::uint32_t> of_c(listed.data() + start[k], start[k + 1] - start[k]);
    out.sign[c] = exact_sign(mesh, of_c, mesh.faces[first_face[c]][0]);
    // Keep the reported volume's sign consistent with the exact one.
    if ((out.volume[c] > 0) != (out.sign[c] > 0) || out.sign[c] == 0)
      out.volume[c] = out.sign[c] * std::fabs(out.volume[c]);
  }
  return out;
}

}  // namespace molsurf
