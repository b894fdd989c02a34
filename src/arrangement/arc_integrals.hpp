#pragma once
// Closed forms along an arc of a circle on the unit sphere, the circle {x : n . x = c0}
// parametrised as x(t) = c0 n + s0 (cos t u + sin t v) with u x v = n (t grows
// counter-clockwise seen from outside above n). Scale by r^2 for a sphere of radius r.
//
// The area of a region R of the sphere follows from its boundary by Stokes' theorem with
// the 1-form alpha_p = (1 - cos theta) d phi of polar angles about a pole p, whose exterior
// derivative is the area form and whose only singular point is -p:
//   area(R) = sum over the boundary's arcs of the integral of alpha_p + 4 pi [-p in R].
// Along a point x moving on the sphere, alpha_p = p . (x x dx) / (1 + p . x); on a circle
// that integrand is (p.n + c0) / (1 + c0 p.n + beta cos psi) - c0, with psi = t - t_p and
// beta = s0 |p - (p.n) n|, whose antiderivative is elementary (the denominator's
// discriminant is (c0 + p.n)^2, zero only when the circle passes through -p).
#include <cmath>
#include <numbers>

#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

struct CircleFrame {
  Vec3 n, u, v;
  double c0 = 0, s0 = 1;

  Vec3 point(double t) const { return c0 * n + s0 * (std::cos(t) * u + std::sin(t) * v); }
  double angle_of(const Vec3& x) const { return std::atan2(dot(x, v), dot(x, u)); }
};

// An orthonormal frame about unit axis n.
inline CircleFrame circle_frame(const Vec3& n, double c0, double s0) {
  CircleFrame f;
  f.n = n;
  f.c0 = c0;
  f.s0 = s0;
  const Vec3 axis = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? Vec3{1, 0, 0}
                    : std::fabs(n.y) <= std::fabs(n.z)                                  ? Vec3{0, 1, 0}
                                                                                         : Vec3{0, 0, 1};
  f.u = normalized(cross(n, axis));
  f.v = cross(n, f.u);
  return f;
}

// The integral of alpha_p along the arc from t0 to t0 + dt (dt of either sign).
inline double pole_form_integral(const CircleFrame& f, const Vec3& p, double t0, double dt) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const double pn = dot(p, f.n), pu = dot(p, f.u), pv = dot(p, f.v);
  const double gamma = std::hypot(pu, pv), tp = std::atan2(pv, pu);
  const double e = 1 + f.c0 * pn, beta = f.s0 * gamma, sum = f.c0 + pn;
  const double k = std::fabs(sum) / (e + beta);
  // 2 atan(k tan(psi / 2)), continued over every turn: increasing, and 2 pi more per turn.
  auto h = [k](double psi) {
    const double turns = std::nearbyint(psi / kTwoPi), rest = psi - turns * kTwoPi;
    return 2 * std::atan2(k * std::sin(rest / 2), std::cos(rest / 2)) + turns * kTwoPi;
  };
  const double psi0 = t0 - tp;
  return -f.c0 * dt + (sum > 0 ? 1.0 : -1.0) * (h(psi0 + dt) - h(psi0));
}

// Half the integral of x x dx along the arc: summed over a region's boundary, the
// integral of the outward normal over the region (its vector area).
inline Vec3 half_moment(const CircleFrame& f, double t0, double dt) {
  const double t1 = t0 + dt;
  const double cs = f.c0 * f.s0;
  return 0.5 * (cs * ((std::cos(t1) - std::cos(t0)) * f.v - (std::sin(t1) - std::sin(t0)) * f.u) +
                f.s0 * f.s0 * dt * f.n);
}

}  // namespace molsurf::arrangement
