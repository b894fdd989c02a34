#include "surface/true_points.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <optional>
#include <vector>

#include "mesh/move_vertices.hpp"

namespace molsurf {

namespace {

struct Ball {
  Vec3 c;
  double r;
};

// The point of sphere a nearest p.
std::optional<Vec3> on_sphere(const Ball& a, const Vec3& p) {
  const Vec3 d = p - a.c;
  const double n = norm(d);
  if (!(n > 0)) return std::nullopt;
  return a.c + d * (a.r / n);
}

// The point of the circle where spheres a and b meet nearest p.
std::optional<Vec3> on_circle(const Ball& a, const Ball& b, const Vec3& p) {
  const Vec3 ab = b.c - a.c;
  const double d = norm(ab);
  if (!(d > 0)) return std::nullopt;
  const Vec3 n = ab / d;
  const double h = (d * d + a.r * a.r - b.r * b.r) / (2 * d), rho2 = a.r * a.r - h * h;
  if (!(rho2 > 0)) return std::nullopt;
  const Vec3 m = a.c + n * h, w = (p - m) - n * dot(p - m, n);
  const double wn = norm(w);
  if (!(wn > 0)) return std::nullopt;
  return m + w * (std::sqrt(rho2) / wn);
}

// The common point of spheres a, b and c nearest p.
std::optional<Vec3> at_triple_point(const Ball& a, const Ball& b, const Ball& c, const Vec3& p) {
  const Vec3 dj = b.c - a.c, dk = c.c - a.c;
  const double jj = dot(dj, dj), kk = dot(dk, dk), jk = dot(dj, dk);
  const double ej = jj + (a.r - b.r) * (a.r + b.r), ek = kk + (a.r - c.r) * (a.r + c.r);
  const Vec3 w = cross(dj, dk);
  const double g = dot(w, w);
  if (!(g > 0)) return std::nullopt;
  const Vec3 y0 = ((ej * kk - ek * jk) * dj + (ek * jj - ej * jk) * dk) / (2 * g);
  const double h = a.r * a.r - dot(y0, y0);
  if (!(h > 0)) return std::nullopt;
  const Vec3 off = w * (std::sqrt(h) / std::sqrt(g));
  const Vec3 p1 = a.c + y0 + off, p2 = a.c + y0 - off;
  return dot(p1 - p, p1 - p) <= dot(p2 - p, p2 - p) ? p1 : p2;
}

}  // namespace

TruePointStats move_to_true_points(Mesh& mesh, std::span<const Atom> atoms, const SphereOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (mesh.faces.empty()) return {};
  std::vector<std::vector<std::int32_t>> tags(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (const Index v : mesh.faces[f]) tags[v].push_back(mesh.tag(f));
  auto ball = [&](std::int32_t atom) { return Ball{atoms[atom].centre, sphere_radius(atoms[atom], options)}; };
  std::vector<Vec3> target(mesh.vertices.size());
  std::vector<std::uint8_t> has_target(mesh.vertices.size(), 0);
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    std::vector<std::int32_t>& t = tags[v];
    if (t.empty()) continue;
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    if (t.front() < 0 || static_cast<std::size_t>(t.back()) >= atoms.size()) continue;
    const Vec3 p = mesh.vertices[v];
    std::optional<Vec3> point;
    if (t.size() == 1) point = on_sphere(ball(t[0]), p);
    if (t.size() == 2) point = on_circle(ball(t[0]), ball(t[1]), p);
    if (t.size() == 3) point = at_triple_point(ball(t[0]), ball(t[1]), ball(t[2]), p);
    if (point) {
      target[v] = *point;
      has_target[v] = 1;
    }
  }
  TruePointStats stats = move_vertices_toward(mesh, target, has_target, 0);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace molsurf
