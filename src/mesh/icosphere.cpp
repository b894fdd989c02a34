#include "mesh/icosphere.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace molsurf {

namespace {

struct Icosahedron {
  std::array<Vec3, 12> vertices;  // unit length
  std::vector<Triangle> faces;    // 20, counter-clockwise seen from outside
};

Icosahedron make_icosahedron() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  const std::array<Vec3, 12> raw = {{{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                                     {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                                     {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}}};
  Icosahedron ico;
  for (std::size_t i = 0; i < 12; ++i) ico.vertices[i] = normalized(raw[i]);
  // Faces are the triples of mutually adjacent vertices: edges have length 2 in the raw
  // coordinates, every other vertex pair is at least 2*phi apart.
  auto adjacent = [&](std::size_t i, std::size_t j) { return dot(raw[i] - raw[j], raw[i] - raw[j]) < 5; };
  for (Index i = 0; i < 12; ++i)
    for (Index j = i + 1; j < 12; ++j)
      for (Index k = j + 1; k < 12; ++k) {
        if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k)) continue;
        const Vec3 n = cross(raw[j] - raw[i], raw[k] - raw[i]);
        if (dot(n, raw[i] + raw[j] + raw[k]) > 0)
          ico.faces.push_back({i, j, k});
        else
          ico.faces.push_back({i, k, j});
      }
  return ico;
}

// Class I geodesic subdivision of the unit icosahedron. Points on an icosahedron edge are
// computed from the edge's canonical (lower, higher) corner order, so both faces that
// share the edge use the same vertex.
Mesh unit_icosphere(int n) {
  const Icosahedron ico = make_icosahedron();
  Mesh mesh;
  mesh.vertices.reserve(10 * n * n + 2);
  mesh.faces.reserve(20 * n * n);
  for (const Vec3& v : ico.vertices) mesh.vertices.push_back(v);

  std::map<std::pair<Index, Index>, std::vector<Index>> edge_points;  // inner points, from lower corner
  auto edge_point = [&](Index from, Index to, int step) -> Index {  // step in [1, n-1] from `from`
    const Index lo = std::min(from, to), hi = std::max(from, to);
    const int k = from == lo ? step : n - step;
    auto [it, inserted] = edge_points.try_emplace({lo, hi});
    if (inserted) {
      for (int s = 1; s < n; ++s) {
        it->second.push_back(static_cast<Index>(mesh.vertices.size()));
        mesh.vertices.push_back(normalized(ico.vertices[lo] * double(n - s) + ico.vertices[hi] * double(s)));
      }
    }
    return it->second[k - 1];
  };

  std::vector<Index> grid((n + 1) * (n + 1));
  auto at = [&](int i, int j) -> Index& { return grid[i * (n + 1) + j]; };
  for (const Triangle& face : ico.faces) {
    const Index a = face[0], b = face[1], c = face[2];
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        if (i == 0 && j == 0) at(i, j) = a;
        else if (i == n) at(i, j) = b;
        else if (j == n) at(i, j) = c;
        else if (j == 0) at(i, j) = edge_point(a, b, i);
        else if (i == 0) at(i, j) = edge_point(a, c, j);
        else if (i + j == n) at(i, j) = edge_point(b, c, j);
        else {
          at(i, j) = static_cast<Index>(mesh.vertices.size());
          mesh.vertices.push_back(normalized(ico.vertices[a] * double(n - i - j) +
                                             ico.vertices[b] * double(i) + ico.vertices[c] * double(j)));
        }
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        mesh.faces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j < n - 1) mesh.faces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return mesh;
}

}  // namespace


Mesh make_icosphere(const Vec3& centre, double radius, const IcosphereOptions& options) {
  if (options.frequency < 1) throw std::invalid_argument("icosphere frequency must be at least 1");
  if (!(radius > 0)) throw std::invalid_argument("icosphere radius must be positive");
  Mesh mesh = unit_icosphere(options.frequency);
  const double scale = icosphere_scale(centre, radius, surface_area(mesh), options.area_corrected);
  for (Vec3& v : mesh.vertices) v = centre + v * scale;
  mesh.face_tags.assign(mesh.faces.size(), options.tag);
  if (options.tag == kNoTag) mesh.face_tags.clear();
  return mesh;
}

Mesh make_unit_icosphere(int frequency) {
  if (frequency < 1) throw std::invalid_argument("icosphere frequency must be at least 1");
  return unit_icosphere(frequency);
}

double icosphere_scale(const Vec3& centre, double radius, double unit_area, bool area_corrected) {
  if (area_corrected) return radius * std::sqrt(4 * std::numbers::pi / unit_area);
  const double reach = std::max({std::fabs(centre.x), std::fabs(centre.y), std::fabs(centre.z)});
  return radius - (std::ldexp(radius, -30) + std::ldexp(reach, -48));
}

int frequency_for_density(double radius, double density) {
  const double target = density * 4 * std::numbers::pi * radius * radius;
  // Vertex count 10 n^2 + 2 grows monotonically: take the n whose count is nearest.
  const int guess = std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(0.0, target - 2) / 10))));
  int best = guess;
  for (int n = std::max(1, guess - 1); n <= guess + 1; ++n)
    if (std::abs(10.0 * n * n + 2 - target) < std::abs(10.0 * best * best + 2 - target)) best = n;
  return best;
}

}  // namespace molsurf
