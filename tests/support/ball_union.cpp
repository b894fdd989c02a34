#include "support/ball_union.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "common/parallel_exceptions.hpp"
#include "geometry/point_grid.hpp"

namespace molsurf {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct Arc {
  double from, to;  // radians, from < to, within [0, 2 pi]
};

}  // namespace

BallUnionMeasure measure_ball_union(std::span<const Vec3> centres, std::span<const double> radii, int slices) {
  if (centres.size() != radii.size()) throw std::invalid_argument("measure_ball_union: one radius per centre");
  BallUnionMeasure m;
  m.area_per_ball.assign(centres.size(), 0);
  if (centres.empty()) return m;
  const double largest = *std::max_element(radii.begin(), radii.end());
  const geometry::PointGrid grid(centres, 2 * largest);
  std::vector<double> volume_per_ball(centres.size(), 0);

  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(centres.size()); ++i)
    errors.run(i, [&] {
      const Vec3& c = centres[i];
      const double r = radii[i];
      std::vector<std::size_t> others;
      bool buried = false;
      grid.for_each_near(c, [&](std::size_t j) {
        if (buried || static_cast<std::int64_t>(j) == i) return;
        const double d = norm(centres[j] - c);
        if (d >= r + radii[j]) return;
        // Inside another ball (or an identical copy later in the list): nothing exposed.
        if (d + r < radii[j] || (d == 0 && r == radii[j] && static_cast<std::int64_t>(j) < i)) {
          buried = true;
          return;
        }
        if (d + radii[j] <= r) return;  // that ball is inside this one: it covers nothing of its sphere
        others.push_back(j);
      });
      if (buried) return;
      const double dz = 2 * r / slices;
      double area = 0, volume = 0;
      std::vector<Arc> covered;
      for (int s = 0; s < slices; ++s) {
        const double z = -r + (s + 0.5) * dz;  // slice centre, relative to c
        const double rho = std::sqrt(std::max(0.0, r * r - z * z));
        covered.clear();
        bool all = false;
        for (std::size_t j : others) {
          const Vec3 d{c.x - centres[j].x, c.y - centres[j].y, c.z + z - centres[j].z};
          const double k = radii[j] * radii[j] - dot(d, d) - rho * rho;
          const double big_r = 2 * rho * std::hypot(d.x, d.y);
          if (k >= big_r) {  // the whole circle is inside ball j
            all = true;
            break;
          }
          if (k <= -big_r) continue;
          // Covered where cos(phi - alpha) < k / big_r: an arc centred on alpha + pi.
          const double alpha = std::atan2(d.y, d.x), beta = std::acos(k / big_r);
          double from = alpha + beta, to = alpha + kTwoPi - beta;
          from = std::fmod(from, kTwoPi);
          if (from < 0) from += kTwoPi;
          to = from + (kTwoPi - 2 * beta);
          if (to <= kTwoPi) {
            covered.push_back({from, to});
          } else {
            covered.push_back({from, kTwoPi});
            covered.push_back({0, to - kTwoPi});
          }
        }
        if (all) continue;
        std::sort(covered.begin(), covered.end(), [](const Arc& a, const Arc& b) { return a.from < b.from; });
        // Exposed arcs are the gaps between merged covered arcs.
        double exposed = 0, cos_sum = 0, sin_sum = 0, cursor = 0;
        auto expose = [&](double a, double b) {
          if (b <= a) return;
          exposed += b - a;
          cos_sum += std::sin(b) - std::sin(a);  // integral of cos
          sin_sum += std::cos(a) - std::cos(b);  // integral of sin
        };
        for (const Arc& arc : covered) {
          expose(cursor, arc.from);
          cursor = std::max(cursor, arc.to);
        }
        expose(cursor, kTwoPi);
        area += r * dz * exposed;
        // x.n = c.n + r with n = (rho cos phi, rho sin phi, z) / r.
        const double c_dot_n = (c.x * rho * cos_sum + c.y * rho * sin_sum + c.z * z * exposed) / r;
        volume += (c_dot_n + r * exposed) * r * dz / 3;
      }
      m.area_per_ball[i] = area;
      volume_per_ball[i] = volume;
    });
  errors.rethrow();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    m.area += m.area_per_ball[i];
    m.volume += volume_per_ball[i];
  }
  return m;
}

}  // namespace molsurf
