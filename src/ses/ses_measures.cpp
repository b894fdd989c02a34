#include "molsurf/ses_measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "ses/nearest_probe.hpp"

namespace molsurf {

namespace {

constexpr int kMaxAtoms = 8;      // atoms one reentrant patch may touch (more: the rest share the last slot)
constexpr int kRefinements = 4;   // halvings of a cell where the SES's edge crosses it

// What one patch adds: area, the divergence integral, and area per touched atom (its slots).
struct PatchSum {
  double area = 0, divergence = 0;
  std::array<double, kMaxAtoms> atom_area{};
};

// A point of a patch: where it is, the area its parameters stand for, its outward normal,
// and which of the patch's atoms it goes to.
struct PatchPoint {
  Vec3 x;
  double jacobian = 0;
  Vec3 normal;
  int slot = 0;
};

// Gauss-Legendre 2x2 on [s0,s1] x [t0,t1]; a cell whose points or corners disagree on being on
// the SES is halved both ways, kRefinements times at most.
template <class Point, class OnSes>
void integrate(double s0, double s1, double t0, double t1, int depth, const Point& point, const OnSes& on_ses,
               const Vec3& origin, PatchSum& sum) {
  constexpr double g = 0.5773502691896257;  // 1 / sqrt(3)
  std::array<PatchPoint, 4> points;
  std::array<bool, 4> on{};
  int count = 0;
  for (int k = 0; k < 4; ++k) {
    const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * (k & 1 ? g : -g);
    const double t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * (k & 2 ? g : -g);
    points[k] = point(s, t);
    on[k] = on_ses(points[k].x);
    count += on[k];
  }
  // The corners too: an edge of the SES can cut a cell's corner off between its Gauss points.
  bool mixed = count != 0 && count != 4;
  for (int k = 0; k < 4 && !mixed && depth < kRefinements; ++k)
    mixed = on_ses(point(k & 1 ? s1 : s0, k & 2 ? t1 : t0).x) != (count == 4);
  if (mixed && depth < kRefinements) {
    const double sm = 0.5 * (s0 + s1), tm = 0.5 * (t0 + t1);
    integrate(s0, sm, t0, tm, depth + 1, point, on_ses, origin, sum);
    integrate(sm, s1, t0, tm, depth + 1, point, on_ses, origin, sum);
    integrate(s0, sm, tm, t1, depth + 1, point, on_ses, origin, sum);
    integrate(sm, s1, tm, t1, depth + 1, point, on_ses, origin, sum);
    return;
  }
  const double weight = 0.25 * (s1 - s0) * (t1 - t0);
  for (int k = 0; k < 4; ++k) {
    if (!on[k]) continue;
    const double a = weight * points[k].jacobian;
    sum.area += a;
    sum.divergence += a * dot(points[k].x - origin, points[k].normal);
    sum.atom_area[static_cast<std::size_t>(points[k].slot)] += a;
  }
}

// Of `atoms`, the slot of the one whose van der Waals sphere is nearest x.
int nearest_slot(const Vec3& x, std::span<const std::uint32_t> atoms, std::span<const Atom> all) {
  int best = 0;
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < atoms.size(); ++k)
    if (const double g = norm(x - all[atoms[k]].centre) - all[atoms[k]].radius; g < gap) {
      gap = g;
      best = static_cast<int>(std::min<std::size_t>(k, kMaxAtoms - 1));
    }
  return best;
}

Vec3 unit(const Vec3& v) { return v / norm(v); }

// Any unit vector perpendicular to the unit vector n.
Vec3 perpendicular(const Vec3& n) {
  const Vec3 a = std::fabs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return unit(a - n * dot(a, n));
}

struct Patches {
  std::span<const Atom> atoms;
  double probe;
  double cell;
  Vec3 origin;
  const SphereArrangement& arrangement;
  const ses::NearestProbe& nearest;

  // A point of the patch is on the SES when no probe position is nearer than its own (one
  // probe radius away; the margin is rounding's).
  bool on_ses(const ses::ProbeRegion& region, const Vec3& x) const {
    return !nearest.nearer_than(region, x, probe * (1 - 1e-9));
  }

  // The probe rolling along the arc: centres q(phi) on the circle, the meridian arc from the
  // contact with atom i to the contact with atom j.
  PatchSum toroidal(const ArrangementArc& arc) const {
    PatchSum sum;
    const std::uint32_t i = arc.sphere, j = arc.other;
    const Vec3 ci = atoms[i].centre, cj = atoms[j].centre;
    const double Ri = atoms[i].radius + probe, Rj = atoms[j].radius + probe;
    const double d = norm(cj - ci);
    const Vec3 n = (cj - ci) / d;
    const double t = (d * d + Ri * Ri - Rj * Rj) / (2 * d);
    const double rho = std::sqrt(std::max(0.0, Ri * Ri - t * t));
    const Vec3 o = ci + n * t;
    if (!(rho > 0) || !(arc.angle > 0)) return sum;
    const Vec3 start = arc.from >= 0 ? arrangement.vertices[static_cast<std::size_t>(arc.from)].point : o + perpendicular(n) * rho;
    Vec3 w0 = start - o;
    w0 = unit(w0 - n * dot(w0, n));
    // The arc runs with sphere i's exposed part (away from j) on its left, seen from outside.
    const Vec3 outward = (start - ci) / Ri;
    const double sense = dot(cross(outward, cross(n, w0)), n) > 0 ? -1.0 : 1.0;
    const Vec3 w1 = cross(n, w0) * sense;
    // Where four or more spheres meet at one point, the arrangement can list an arc between two
    // of its vertices on only one of its spheres, through other balls: no probe rolls there.
    const Vec3 middle = o + (w0 * std::cos(arc.angle / 2) + w1 * std::sin(arc.angle / 2)) * rho;
    if (nearest.buried(middle, i, j)) return sum;
    const std::array<std::uint32_t, 2> pair{i, j};
    const auto point = [&](double phi, double theta) {
      const Vec3 q = o + (w0 * std::cos(phi) + w1 * std::sin(phi)) * rho;
      const Vec3 ei = (ci - q) / Ri, ej = (cj - q) / Rj;
      const Vec3 f = unit(ej - ei * dot(ei, ej));
      const Vec3 e = ei * std::cos(theta) + f * std::sin(theta);
      const Vec3 x = q + e * probe;
      const Vec3 r = (x - o) - n * dot(x - o, n);
      return PatchPoint{x, probe * norm(r), e * -1.0, nearest_slot(x, pair, atoms)};
    };
    // The meridian arc's angle is the same all along the circle.
    const Vec3 q0 = o + w0 * rho;
    const double beta = std::acos(std::clamp(dot((ci - q0) / Ri, (cj - q0) / Rj), -1.0, 1.0));
    const int n_phi = std::max(1, static_cast<int>(std::ceil(arc.angle * (rho + probe) / cell)));
    const int n_theta = std::max(1, static_cast<int>(std::ceil(beta * probe / cell)));
    // The candidates by stretches of the arc about a probe radius long, so that each point is
    // tested against what lies near its stretch only.
    const int stretches = std::max(1, static_cast<int>(std::ceil(arc.angle * rho / probe)));
    for (int k = 0; k < stretches; ++k) {
      const int a0 = n_phi * k / stretches, a1 = n_phi * (k + 1) / stretches;
      if (a0 == a1) continue;
      const double phi0 = arc.angle * a0 / n_phi, phi1 = arc.angle * a1 / n_phi, mid = 0.5 * (phi0 + phi1);
      const Vec3 q = o + (w0 * std::cos(mid) + w1 * std::sin(mid)) * rho;
      const ses::ProbeRegion region = nearest.region(q, probe + rho * 0.5 * (phi1 - phi0));
      const auto on = [&](const Vec3& x) { return on_ses(region, x); };
      for (int a = a0; a < a1; ++a)
        for (int b = 0; b < n_theta; ++b)
          integrate(arc.angle * a / n_phi, arc.angle * (a + 1) / n_phi, beta * b / n_theta, beta * (b + 1) / n_theta,
                    0, point, on, origin, sum);
    }
    return sum;
  }

  // The probe resting at q on `touching` atoms: the spherical polygon their directions span,
  // as a fan of spherical triangles from the first corner.
  PatchSum reentrant(const Vec3& q, std::span<const std::uint32_t> touching) const {
    PatchSum sum;
    std::vector<Vec3> corners;
    for (std::uint32_t a : touching) corners.push_back(unit(atoms[a].centre - q));
    if (corners.size() > 3) corners = convex_cone(corners);
    const ses::ProbeRegion region = nearest.region(q, probe);
    const auto on = [&](const Vec3& x) { return on_ses(region, x); };
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      const Vec3 a = corners[0], b = corners[k], c = corners[k + 1];
      const auto point = [&](double s, double t) {
        const Vec3 p = a * (1 - s) + b * (s * (1 - t)) + c * (s * t);
        const double length = norm(p);
        const Vec3 e = p / length;
        const Vec3 x = q + e * probe;
        const double jacobian = probe * probe * std::fabs(dot(cross(b - a, c - a), p)) * s / (length * length * length);
        return PatchPoint{x, jacobian, e * -1.0, nearest_slot(x, touching, atoms)};
      };
      const double edge = std::max({angle(a, b), angle(b, c), angle(c, a)});
      const int cells = std::max(1, static_cast<int>(std::ceil(edge * probe / cell)));
      for (int u = 0; u < cells; ++u)
        for (int v = 0; v < cells; ++v)
          integrate(double(u) / cells, double(u + 1) / cells, double(v) / cells, double(v + 1) / cells, 0, point, on,
                    origin, sum);
    }
    return sum;
  }

  static double angle(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

  // The corners of the cone the unit vectors span (four or more atoms through one probe
  // position), in order around it: the 2-D convex hull of their projections onto the plane
  // across their mean.
  static std::vector<Vec3> convex_cone(const std::vector<Vec3>& directions) {
    Vec3 mean{0, 0, 0};
    for (const Vec3& e : directions) mean = mean + e;
    const Vec3 axis = unit(mean);
    const Vec3 u = perpendicular(axis), v = cross(axis, u);
    struct Projected {
      double x, y;
      Vec3 e;
    };
    std::vector<Projected> points;
    for (const Vec3& e : directions) {
      const double h = dot(e, axis);
      points.push_back({dot(e, u) / h, dot(e, v) / h, e});  // central projection onto the plane
    }
    std::sort(points.begin(), points.end(), [](const Projected& a, const Projected& b) {
      return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    const auto turn = [](const Projected& o, const Projected& a, const Projected& b) {
      return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<Projected> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t m = 0; m < points.size(); ++m) {
      while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[m]) <= 0) --k;
      hull[k++] = points[m];
    }
    for (std::size_t m = points.size() - 1, lower = k + 1; m-- > 0;) {
      while (k >= lower && turn(hull[k - 2], hull[k - 1], points[m]) <= 0) --k;
      hull[k++] = points[m];
    }
    hull.resize(k - 1);
    std::vector<Vec3> corners;
    for (const Projected& p : hull) corners.push_back(p.e);
    return corners;
  }
};

}  // namespace

SesMeasures measure_ses(std::span<const Atom> atoms, double probe, const SphereArrangement& arrangement,
                        bool outer_only, double cell) {
  SesMeasures out;
  out.area_per_atom.assign(atoms.size(), 0.0);
  if (atoms.empty() || !(probe > 0)) return out;
  Vec3 origin{0, 0, 0};
  for (const Atom& a : atoms) origin = origin + a.centre / static_cast<double>(atoms.size());

  // Contact patches: the exposed r + probe patches scaled onto the atoms.
  double divergence = 0;
  const auto kept = [&](std::uint32_t patch) {
    return !outer_only || !arrangement.shells[arrangement.patches[patch].shell].cavity();
  };
  for (std::uint32_t p = 0; p < arrangement.patches.size(); ++p) {
    if (!kept(p)) continue;
    const ArrangementPatch& patch = arrangement.patches[p];
    const Atom& atom = atoms[patch.sphere];
    const double scale = atom.radius / (atom.radius + probe);
    const double area = patch.area * scale * scale;
    out.contact_area += area;
    out.area_per_atom[patch.sphere] += area;
    divergence += dot(atom.centre - origin, patch.vector_area * (scale * scale)) + atom.radius * area;
  }

  const ses::NearestProbe nearest(atoms, probe, arrangement);
  const Patches patches{atoms, probe, cell, origin, arrangement, nearest};

  // Each exposed arc is listed on both its spheres: one of them carries its torus.
  std::vector<std::size_t> arcs;
  // A vertex's probe lies on the shell of the arcs that reach it.
  std::vector<char> vertex_kept(arrangement.vertices.size(), 0);
  for (std::size_t k = 0; k < arrangement.arcs.size(); ++k) {
    const ArrangementArc& arc = arrangement.arcs[k];
    if (!kept(arc.patch)) continue;
    if (arc.sphere < arc.other) arcs.push_back(k);
    for (const std::int64_t v : {arc.from, arc.to})
      if (v >= 0) vertex_kept[static_cast<std::size_t>(v)] = 1;
  }
  // Vertices at one point (four or more atoms meet there; the arrangement joins them by arcs
  // of angle 0, or whose ends lie at one point up to rounding) are one probe position.
  std::vector<std::size_t> group(arrangement.vertices.size());
  std::iota(group.begin(), group.end(), std::size_t{0});
  const auto root = [&](std::size_t v) {
    while (group[v] != v) v = group[v] = group[group[v]];
    return v;
  };
  for (const ArrangementArc& arc : arrangement.arcs) {
    if (arc.from < 0 || arc.to < 0) continue;
    const auto a = static_cast<std::size_t>(arc.from), b = static_cast<std::size_t>(arc.to);
    const double scale = std::max(1.0, norm(arrangement.vertices[a].point - origin));
    if (arc.angle == 0 || norm(arrangement.vertices[a].point - arrangement.vertices[b].point) <= 1e-12 * scale)
      group[root(a)] = root(b);
  }
  std::map<std::size_t, std::vector<std::uint32_t>> touching_of;
  for (std::size_t v = 0; v < arrangement.vertices.size(); ++v)
    if (vertex_kept[v]) vertex_kept[root(v)] = 1;
  for (std::size_t v = 0; v < arrangement.vertices.size(); ++v) {
    std::vector<std::uint32_t>& touching = touching_of[root(v)];
    touching.insert(touching.end(), arrangement.vertices[v].spheres.begin(), arrangement.vertices[v].spheres.end());
  }
  std::vector<std::pair<Vec3, std::vector<std::uint32_t>>> probes;
  for (auto& [v, touching] : touching_of) {
    if (!vertex_kept[v]) continue;
    std::sort(touching.begin(), touching.end());
    touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
    probes.push_back({arrangement.vertices[v].point, std::move(touching)});
  }

  std::vector<PatchSum> torus_sums(arcs.size()), probe_sums(probes.size());
  const auto n_arcs = static_cast<std::int64_t>(arcs.size()), n_probes = static_cast<std::int64_t>(probes.size());
#pragma omp parallel
  {
#pragma omp for schedule(dynamic, 16) nowait
    for (std::int64_t k = 0; k < n_arcs; ++k)
      torus_sums[static_cast<std::size_t>(k)] = patches.toroidal(arrangement.arcs[arcs[static_cast<std::size_t>(k)]]);
#pragma omp for schedule(dynamic, 16)
    for (std::int64_t k = 0; k < n_probes; ++k) {
      const auto& [point, touching] = probes[static_cast<std::size_t>(k)];
      probe_sums[static_cast<std::size_t>(k)] = patches.reentrant(point, touching);
    }
  }
  for (std::size_t k = 0; k < arcs.size(); ++k) {
    const ArrangementArc& arc = arrangement.arcs[arcs[k]];
    out.toroidal_area += torus_sums[k].area;
    divergence += torus_sums[k].divergence;
    out.area_per_atom[arc.sphere] += torus_sums[k].atom_area[0];
    out.area_per_atom[arc.other] += torus_sums[k].atom_area[1];
  }
  for (std::size_t k = 0; k < probes.size(); ++k) {
    out.reentrant_area += probe_sums[k].area;
    divergence += probe_sums[k].divergence;
    const std::vector<std::uint32_t>& touching = probes[k].second;
    for (std::size_t s = 0; s < touching.size() && s < kMaxAtoms; ++s)
      out.area_per_atom[touching[s]] += probe_sums[k].atom_area[s];
  }
  out.area = out.contact_area + out.toroidal_area + out.reentrant_area;
  out.volume = divergence / 3;
  return out;
}

}  // namespace molsurf
