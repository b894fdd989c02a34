#include "arrangement/shell_moments.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace molsurf::arrangement {

void ShellMoments::add_patch(const Vec3& centre, double radius, double patch_area, const Vec3& patch_vector_area) {
  area += patch_area;
  volume += (radius * patch_area + dot(centre - origin, patch_vector_area)) / 3;
  vector_area += patch_vector_area;
  moment += (centre - origin) * patch_area + radius * patch_vector_area;
  // A patch's area and vector area come from integrals of order r^2 on the unit sphere,
  // each some 1e-15 r^2 off, summed over its arcs.
  volume_error += 1e-12 * radius * radius * (radius + norm(centre - origin));
  squared_radii += radius * radius;
}

void ShellMoments::add(const ShellMoments& other) {
  const Vec3 shift = other.origin - origin;
  area += other.area;
  volume += other.volume + dot(shift, other.vector_area) / 3;
  vector_area += other.vector_area;
  moment += other.moment + shift * other.area;
  volume_error += other.volume_error + 1e-12 * other.squared_radii * norm(shift);
  squared_radii += other.squared_radii;
}

FinishedShells finish_shells(std::span<const ShellMoments> moments, std::vector<std::vector<std::uint32_t>> spheres,
                             const std::function<Ball(std::uint32_t)>& ball_of) {
  std::vector<ArrangementShell> shells(moments.size());
  for (std::size_t s = 0; s < shells.size(); ++s) {
    const ShellMoments& m = moments[s];
    ArrangementShell& shell = shells[s];
    shell.area = m.area;
    shell.volume = m.volume;
    shell.centroid = m.area > 0 ? m.origin + m.moment / m.area : m.origin;
    shell.spheres = std::move(spheres[s]);
    std::sort(shell.spheres.begin(), shell.spheres.end());
    shell.spheres.erase(std::unique(shell.spheres.begin(), shell.spheres.end()), shell.spheres.end());
    if (std::fabs(shell.volume) > m.volume_error) continue;
    // A shell too small for its volume's sign (a void of 1e-13 A^3 where four spheres nearly
    // meet). An outer shell holds whole balls, so its area is at least that of its smallest
    // sphere (a surface around a ball is no smaller than the ball's sphere): a shell with
    // less is a cavity. Otherwise (not seen) its centroid decides: outside its balls, a void.
    double smallest = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (std::uint32_t i : shell.spheres) {
      const Ball b = ball_of(i);
      smallest = std::min(smallest, b.radius);
      const Vec3 d = shell.centroid - b.centre;
      inside |= dot(d, d) < b.radius * b.radius;
    }
    if (shell.area < 4 * std::numbers::pi * smallest * smallest) inside = false;
    shell.volume = inside ? std::fabs(shell.volume) : -std::fabs(shell.volume);
    if (shell.volume == 0) shell.volume = inside ? 0.0 : -0.0;
  }
  // The largest outer shell first, then by area.
  std::vector<std::size_t> order(shells.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if (shells[x].cavity() != shells[y].cavity()) return !shells[x].cavity();
    return shells[x].area > shells[y].area;
  });
  FinishedShells out;
  out.rank.resize(shells.size());
  out.shells.reserve(shells.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    out.rank[order[k]] = static_cast<std::uint32_t>(k);
    out.shells.push_back(std::move(shells[order[k]]));
  }
  return out;
}

}  // namespace molsurf::arrangement
