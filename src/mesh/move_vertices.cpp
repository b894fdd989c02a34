#include "mesh/move_vertices.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/mesh_editor.hpp"

namespace molsurf {

namespace {

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  auto at = [](const Vec3& p, const Vec3& q, const Vec3& r) {
    const Vec3 u = q - p, v = r - p;
    return std::atan2(norm(cross(u, v)), dot(u, v));
  };
  return std::min({at(a, b, c), at(b, c, a), at(c, a, b)});
}

}  // namespace

TruePointStats move_vertices_toward(Mesh& mesh, std::span<const Vec3> target, std::span<const std::uint8_t> has_target,
                                    double min_angle_deg) {
  TruePointStats stats;
  if (mesh.faces.empty()) return stats;
  double total = 0;
  for (const Triangle& t : mesh.faces)
    total += norm(mesh.vertices[t[1]] - mesh.vertices[t[0]]) + norm(mesh.vertices[t[2]] - mesh.vertices[t[1]]);
  const double mean_edge = total / (2 * static_cast<double>(mesh.faces.size()));
  EditableMesh editable(mesh);
  editable.index_all(std::max(mean_edge, 1e-9) * 2);
  MeshEditor editor(editable);
  constexpr double kMaxTurnCos = 0.5;  // no face turns more than 60 degrees (the cleanup's rule)
  const double min_angle = min_angle_deg * std::numbers::pi / 180;
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    if (editor.faces_of(v).empty()) continue;
    ++stats.vertices;
    if (!has_target[v]) {
      ++stats.not_moved;
      continue;
    }
    const Vec3 p = mesh.vertices[v];
    auto corner = [&](const Vec3& q, Index w) -> const Vec3& { return w == v ? q : mesh.vertices[w]; };
    auto try_move = [&](const Vec3& q) {
      if (q == mesh.vertices[v]) return true;
      const MeshEdit e = editor.move(v, q);
      double before = std::numbers::pi, after = std::numbers::pi;
      for (std::size_t k = 0; k < e.faces.size(); ++k) {
        const Triangle& t = e.after[k];
        if (!MeshEditor::keeps_facing(corner(q, t[0]), corner(q, t[1]), corner(q, t[2]), e.reference[k], kMaxTurnCos))
          return false;
        if (min_angle > 0) {
          before = std::min(before, smallest_angle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
          after = std::min(after, smallest_angle(corner(q, t[0]), corner(q, t[1]), corner(q, t[2])));
        }
      }
      if (after < std::min(before, min_angle)) return false;
      if (!editor.crosses_nothing(e)) return false;
      editor.commit(e);
      return true;
    };
    if (try_move(target[v])) {
      ++stats.on_true_point;
      continue;
    }
    const bool half = try_move(p + (target[v] - p) * 0.5);
    ++(half ? stats.partly : stats.not_moved);
    stats.max_distance_left = std::max(stats.max_distance_left, norm(target[v] - mesh.vertices[v]));
  }
  return stats;
}

}  // namespace molsurf
