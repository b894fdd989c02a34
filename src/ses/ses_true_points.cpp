#include "ses/ses_true_points.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <vector>

#include "mesh/move_vertices.hpp"
#include "ses/nearest_probe.hpp"

namespace molsurf::ses_detail {

TruePointStats move_to_ses_points(Mesh& mesh, std::span<const Atom> atoms, double probe,
                                  const SphereArrangement& arrangement, double max_move,
                                  std::span<const std::uint8_t> frozen) {
  const auto start = std::chrono::steady_clock::now();
  if (mesh.faces.empty() || atoms.empty() || !(probe > 0)) return {};
  const ses::NearestProbe nearest(atoms, probe, arrangement);
  const std::size_t n = mesh.vertices.size();
  std::vector<Vec3> target(n);
  std::vector<std::uint8_t> has_target(n, 0);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::int64_t k = 0; k < static_cast<std::int64_t>(n); ++k) {
    const auto v = static_cast<std::size_t>(k);
    if (!frozen.empty() && frozen[v]) continue;
    const ses::ProbePosition q = nearest.nearest(mesh.vertices[v]);
    // Contact vertices stay where the rolled surface drew them, at the radius where their
    // facets' area and volume errors balance (contact_scale.hpp); on the atom's sphere one
    // atom's SES was 1.2 % short in area and 2.2 % in volume. None within reach, or the
    // vertex at the probe's centre: no direction to move along.
    if (q.type == PatchType::contact || !(q.distance < 2 * probe) || !(q.distance > 0)) continue;
    // Farther than that from the true surface, the drawn surface departs from it on
    // purpose: a crease the probe balls carved, or a tunnel pinched at a hole the probe only
    // just passes, where the move would bridge it (+1.3 % volume on such a ring of five).
    if (std::abs(q.distance - probe) > max_move) continue;
    target[v] = q.point + (mesh.vertices[v] - q.point) * (probe / q.distance);
    has_target[v] = 1;
  }
  // The cleanup's aim (CleanupOptions::min_angle_deg): no move makes a face worse than it.
  TruePointStats stats = move_vertices_toward(mesh, target, has_target, 5);
  // Counted over the vertices it moves: the contact vertices were never asked to.
  std::size_t unasked = 0;
  for (std::size_t v = 0; v < n; ++v) unasked += !has_target[v];
  stats.vertices -= std::min(stats.vertices, unasked);
  stats.not_moved -= std::min(stats.not_moved, unasked);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

double ses_max_true_point_move(double density) { return 0.1 * std::sqrt(2 / (std::sqrt(3.0) * density)); }

}  // namespace molsurf::ses_detail
