#pragma once
// Reference values for the solvent-excluded surface, written apart from its construction
// (src/ses/): nothing here uses the SAS mesh, the arrangement or the Boolean engine.
//   - two atoms: area and volume of the solid of revolution, from its meridian profile
//     (contact arcs, the probe's arc, clipped at the axis for a spindle torus);
//   - any atoms: a point is inside the SES solid iff its distance to the probe-accessible
//     region (the points outside every ball r_vdW + probe) is at least the probe radius.
//     The distance is the smallest over the accessible boundary's candidates: radial
//     projections onto each sphere, closest points on each pair's circle, and the points
//     where three spheres meet, each kept only when no other ball holds it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::ses_reference {

// Placements the SES tests and its accuracy bench share.
inline Atom atom_at(Vec3 centre, double radius) {
  Atom a;
  a.centre = centre;
  a.radius = radius;
  a.element = "C";
  return a;
}

// n atoms evenly on a circle in the z = 0 plane.
inline std::vector<Atom> ring(int n, double radius, double atom_radius) {
  std::vector<Atom> atoms;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    atoms.push_back(atom_at({radius * std::cos(a), radius * std::sin(a), 0}, atom_radius));
  }
  return atoms;
}

// n atoms spread evenly on a sphere (a golden-angle spiral): a cage with a void inside.
inline std::vector<Atom> cage(int n, double radius, double atom_radius) {
  std::vector<Atom> atoms;
  for (int k = 0; k < n; ++k) {
    const double z = 1 - (2.0 * k + 1) / n, r = std::sqrt(1 - z * z), a = k * std::numbers::pi * (3 - std::sqrt(5.0));
    atoms.push_back(atom_at({radius * r * std::cos(a), radius * r * std::sin(a), radius * z}, atom_radius));
  }
  return atoms;
}

struct AreaVolume {
  double area = 0, volume = 0;
};

// Two atoms of radii r1, r2 at distance d, probe p, with the SAS spheres overlapping.
inline AreaVolume two_atoms(double r1, double r2, double d, double p) {
  const double pi = std::numbers::pi;
  const double R1 = r1 + p, R2 = r2 + p;
  const double t = (d * d + R1 * R1 - R2 * R2) / (2 * d), rho = std::sqrt(R1 * R1 - t * t);
  const double c1 = t / R1, c2 = (d - t) / R2;
  AreaVolume out;
  out.area = 2 * pi * r1 * r1 * (1 + c1) + 2 * pi * r2 * r2 * (1 + c2);
  // The probe's arc in the meridian half-plane (axial x, radial y), from its contact with
  // atom 1 to its contact with atom 2 on the side facing the axis.
  double f1 = std::atan2(-rho, -t);
  const double f2 = std::atan2(-rho, d - t);
  if (f1 > f2) f1 -= 2 * pi;
  const int n = 200000;
  std::vector<std::array<double, 2>> profile;
  const double th1 = std::acos(c1), th2 = std::acos(c2);
  for (int k = 0; k <= n; ++k) {
    const double a = pi + (th1 - pi) * k / n;
    profile.push_back({r1 * std::cos(a), r1 * std::sin(a)});
  }
  for (int k = 0; k <= n; ++k) {
    const double f = f1 + (f2 - f1) * k / n;
    const double y = rho + p * std::sin(f);
    profile.push_back({t + p * std::cos(f), std::max(0.0, y)});  // the axis clips a spindle
    const double fm = f1 + (f2 - f1) * (k + 0.5) / n;
    if (k < n) out.area += 2 * pi * p * std::max(0.0, rho + p * std::sin(fm)) * (f2 - f1) / n;
  }
  for (int k = 0; k <= n; ++k) {
    const double a = (pi - th2) * (1.0 - static_cast<double>(k) / n);
    profile.push_back({d + r2 * std::cos(a), r2 * std::sin(a)});
  }
  for (std::size_t k = 1; k < profile.size(); ++k) {
    const auto [x0, y0] = profile[k - 1];
    const auto [x1, y1] = profile[k];
    out.volume += pi * (y0 * y0 + y0 * y1 + y1 * y1) / 3 * (x1 - x0);
  }
  return out;
}

class ExcludedSolid {
 public:
  ExcludedSolid(std::span<const Atom> atoms, double probe) : probe_(probe) {
    for (const Atom& a : atoms) {
      centre_.push_back(a.centre);
      radius_.push_back(a.radius + probe);
    }
  }

  // Distance from x to the accessible region, capped at the probe radius.
  double depth(const Vec3& x) const {
    std::vector<std::size_t> near;
    bool inside = false;
    for (std::size_t i = 0; i < centre_.size(); ++i) {
      const double r = norm(x - centre_[i]);
      if (r < radius_[i]) inside = true;
      if (std::abs(r - radius_[i]) <= probe_) near.push_back(i);
    }
    if (!inside) return 0;
    double best = probe_;
    auto consider = [&](const Vec3& q, std::array<std::size_t, 3> on) {
      const double d = norm(x - q);
      if (d < best && exposed(q, on)) best = d;
    };
    for (std::size_t i : near) {
      const Vec3 v = x - centre_[i];
      const double r = norm(v);
      if (r > 0) consider(centre_[i] + v * (radius_[i] / r), {i, i, i});
    }
    for (std::size_t a = 0; a < near.size(); ++a)
      for (std::size_t b = a + 1; b < near.size(); ++b) {
        const std::size_t i = near[a], j = near[b];
        const Vec3 axis = centre_[j] - centre_[i];
        const double d = norm(axis);
        if (!(d > 0) || d >= radius_[i] + radius_[j] || d <= std::abs(radius_[i] - radius_[j])) continue;
        const Vec3 n = axis / d;
        const double t = (d * d + radius_[i] * radius_[i] - radius_[j] * radius_[j]) / (2 * d);
        const double rho = std::sqrt(std::max(0.0, radius_[i] * radius_[i] - t * t));
        const Vec3 o = centre_[i] + n * t;
        Vec3 w = (x - o) - n * dot(x - o, n);
        const double wn = norm(w);
        if (wn > 0) consider(o + w * (rho / wn), {i, j, j});
        for (std::size_t c = b + 1; c < near.size(); ++c)
          for (const Vec3& q : triple_points(i, j, near[c])) consider(q, {i, j, near[c]});
      }
    return best;
  }

  bool inside(const Vec3& x) const { return depth(x) >= probe_; }

  // The solid's volume by counting a grid of points (spacing h, offset by half a cell).
  double grid_volume(double h) const {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < centre_.size(); ++i) {
      lo = {std::min(lo.x, centre_[i].x - radius_[i]), std::min(lo.y, centre_[i].y - radius_[i]),
            std::min(lo.z, centre_[i].z - radius_[i])};
      hi = {std::max(hi.x, centre_[i].x + radius_[i]), std::max(hi.y, centre_[i].y + radius_[i]),
            std::max(hi.z, centre_[i].z + radius_[i])};
    }
    std::size_t count = 0;
    for (double z = lo.z + h / 2; z < hi.z; z += h)
      for (double y = lo.y + h / 2; y < hi.y; y += h)
        for (double x = lo.x + h / 2; x < hi.x; x += h) count += inside({x, y, z});
    return static_cast<double>(count) * h * h * h;
  }

 private:
  bool exposed(const Vec3& q, std::array<std::size_t, 3> on) const {
    for (std::size_t k = 0; k < centre_.size(); ++k) {
      if (k == on[0] || k == on[1] || k == on[2]) continue;
      if (norm(q - centre_[k]) < radius_[k] * (1 - 1e-12)) return false;
    }
    return true;
  }

  std::vector<Vec3> triple_points(std::size_t i, std::size_t j, std::size_t k) const {
    // |q - a|^2 = R^2 for the three spheres: two planes (differences) and sphere i.
    const Vec3 a = centre_[i], b = centre_[j], c = centre_[k];
    const Vec3 n1 = (b - a) * 2, n2 = (c - a) * 2;
    const double e1 = dot(b, b) - dot(a, a) - radius_[j] * radius_[j] + radius_[i] * radius_[i];
    const double e2 = dot(c, c) - dot(a, a) - radius_[k] * radius_[k] + radius_[i] * radius_[i];
    const Vec3 dir = cross(n1, n2);
    const double dd = dot(dir, dir);
    if (!(dd > 0)) return {};
    // A point on both planes: p0 = (e1 (n2 x dir) + e2 (dir x n1)) / |dir|^2.
    const Vec3 p0 = (cross(n2, dir) * e1 + cross(dir, n1) * e2) / dd;
    const Vec3 u = dir / std::sqrt(dd);
    const Vec3 w = p0 - a;
    const double bq = dot(w, u), cq = dot(w, w) - radius_[i] * radius_[i];
    const double disc = bq * bq - cq;
    if (disc < 0) return {};
    const double s = std::sqrt(disc);
    return {p0 + u * (-bq - s), p0 + u * (-bq + s)};
  }

  double probe_;
  std::vector<Vec3> centre_;
  std::vector<double> radius_;
};

}  // namespace molsurf::ses_reference
