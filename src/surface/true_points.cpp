#include "surface/true_points.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "mesh/mesh_editor.hpp"

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
  TruePointStats stats;
  if (mesh.faces.empty()) return stats;
  double total = 0;
  for (const Triangle& t : mesh.faces)
    total += norm(mesh.vertices[t[1]] - mesh.vertices[t[0]]) + norm(mesh.vertices[t[2]] - mesh.vertices[t[1]]);
  const double mean_edge = total / (2 * mesh.faces.size());
  EditableMesh editable(mesh);
  editable.index_all(std::max(mean_edge, 1e-9) * 2);
  MeshEditor editor(editable);
  constexpr double kMaxTurnCos = 0.5;  // no face turns more than 60 degrees (the cleanup's rule)
  auto ball = [&](std::int32_t atom) { return Ball{atoms[atom].centre, sphere_radius(atoms[atom], options)}; };
  std::vector<std::int32_t> tags;
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    const std::span<const std::uint32_t> around = editor.faces_of(v);
    if (around.empty()) continue;
    ++stats.vertices;
    tags.clear();
    for (const std::uint32_t f : around) tags.push_back(mesh.tag(f));
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    const Vec3 p = mesh.vertices[v];
    std::optional<Vec3> target;
    if (tags.front() >= 0 && static_cast<std::size_t>(tags.back()) < atoms.size()) {
      if (tags.size() == 1) target = on_sphere(ball(tags[0]), p);
      if (tags.size() == 2) target = on_circle(ball(tags[0]), ball(tags[1]), p);
      if (tags.size() == 3) target = at_triple_point(ball(tags[0]), ball(tags[1]), ball(tags[2]), p);
    }
    if (!target) {
      ++stats.not_moved;
      continue;
    }
    // The move, whole or halfway, kept when its faces face as before and cross nothing.
    auto try_move = [&](const Vec3& q) {
      if (q == mesh.vertices[v]) return true;
      const MeshEdit e = editor.move(v, q);
      for (std::size_t k = 0; k < e.faces.size(); ++k) {
        const Triangle& t = e.after[k];
        const Vec3& a = t[0] == v ? q : mesh.vertices[t[0]];
        const Vec3& b = t[1] == v ? q : mesh.vertices[t[1]];
        const Vec3& c = t[2] == v ? q : mesh.vertices[t[2]];
        if (!MeshEditor::keeps_facing(a, b, c, e.reference[k], kMaxTurnCos)) return false;
      }
      if (!editor.crosses_nothing(e)) return false;
      editor.commit(e);
      return true;
    };
    if (try_move(*target)) {
      ++stats.on_true_point;
      continue;
    }
    const bool half = try_move(p + (*target - p) * 0.5);
    ++(half ? stats.partly : stats.not_moved);
    stats.max_distance_left = std::max(stats.max_distance_left, norm(*target - mesh.vertices[v]));
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace molsurf
