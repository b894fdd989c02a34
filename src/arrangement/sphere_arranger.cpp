// Steps 1 and 2 of the arrangement on one sphere: which balls cut sphere i (and which
// bury it), and how each pair of their caps meets: crossing (two vertices), one circle
// inside the other cap (covered), or apart. Every decision exact: a floating-point
// filter, then rational arithmetic.
#include "arrangement/sphere_arranger.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace molsurf::arrangement {

SphereResult SphereArranger::arrange(std::uint32_t i) const {
  SphereResult out;
  if (!find_caps(i, out)) return out;
  // Scratch arrays reused sphere after sphere by each thread.
  thread_local std::vector<Endpoint> raw, ends;
  thread_local std::vector<std::uint32_t> offset;
  raw.clear();
  cross_circles(i, raw, out);
  if (out.covered) {
    out.caps = {};
    return out;
  }
  // The ends grouped by circle, in the order they were found (a crossing's two ends
  // stay next to each other).
  offset.assign(out.caps.size() + 1, 0);
  for (const Endpoint& e : raw) ++offset[e.circle + 1];
  for (std::size_t j = 0; j < out.caps.size(); ++j) offset[j + 1] += offset[j];
  ends.resize(raw.size());
  for (const Endpoint& e : raw) ends[offset[e.circle]++] = e;
  for (std::size_t j = out.caps.size(); j > 0; --j) offset[j] = offset[j - 1];
  offset[0] = 0;
  for (std::uint32_t j = 0; j < out.caps.size(); ++j)
    if (!out.caps[j].covered)
      exposed_arcs(i, j, std::span<const Endpoint>(ends.data() + offset[j], offset[j + 1] - offset[j]), out);
  measure(i, out);
  for (LocalArc& arc : out.arcs) arc.other = out.caps[arc.cap].other;
  out.caps = {};  // the joined arrangement needs only the arcs and patches
  return out;
}

// Step 1. False when sphere i is buried (inside another ball, or a later copy).
bool SphereArranger::find_caps(std::uint32_t i, SphereResult& out) const {
  const Vec3& ci = c_[i];
  const double ri = r_[i];
  if (ri == 0 || neighbours_.hidden[i]) {
    out.buried = true;
    return false;
  }
  bool buried = false;
  for (std::uint32_t n = neighbours_.offset[i]; n < neighbours_.offset[i + 1] && !buried; ++n) [&] {
    const std::uint32_t j = neighbours_.list[n];
    const Vec3& cj = c_[j];
    const double rj = r_[j];
    if (rj == 0) return;
    if (cj == ci && rj == ri) {  // identical spheres: the lowest index counts
      if (j < i) buried = out.duplicate = true;
      return;
    }
    // Apart, or touching from outside: no cap. Floating point decides when the squared
    // distance is clearly apart from the bound (its rounding is some 1e-16 of it).
    const Vec3 dd = cj - ci;
    const double d2 = dot(dd, dd), reach = (ri + rj) * (ri + rj);
    if (d2 > reach * (1 + 1e-12)) return;
    if (d2 >= reach * (1 - 1e-12) && exact_sign([&]<class T>() -> T {
          const auto d = arrangement::difference<T>(cj, ci);
          return (T(ri) + T(rj)) * (T(ri) + T(rj)) - dot(d, d);
        }, out.decisions) <= 0)
      return;
    // Nested (closed balls): ball i inside ball j buries sphere i; ball j inside ball i
    // cuts nothing (a touching point at most).
    auto nested = [&](double big, double small) { return arrangement::ball_in_ball(ci, small, cj, big, out.decisions); };
    if (nested(rj, ri)) {
      buried = true;
      return;
    }
    if (nested(ri, rj)) return;
    Cap cap;
    cap.other = j;
    cap.d = cj - ci;
    const double dn = norm(cap.d);
    const double a = (dot(cap.d, cap.d) + (ri - rj) * (ri + rj)) / (2 * dn);  // plane's distance from c_i
    const double c0 = std::clamp(a / ri, -1.0, 1.0);
    cap.frame = arrangement::circle_frame(cap.d / dn, c0, std::sqrt(std::max(0.0, (1 - c0) * (1 + c0))));
    out.caps.push_back(cap);
  }();
  if (buried) {
    out.buried = true;
    out.caps = {};
    return false;
  }
  // The neighbours are sorted: the caps are in the order of their spheres.
  out.circles = out.caps.size();
  return true;
}

// Step 2: every pair of caps; the ends of the arcs each cap covers on the other's circle.
void SphereArranger::cross_circles(std::uint32_t i, std::vector<Endpoint>& ends, SphereResult& out) const {
  std::vector<Cap>& caps = out.caps;
  const Vec3& ci = c_[i];
  const double ri = r_[i];
  thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> crossings;
  crossings.clear();
  for (std::uint32_t x = 0; x < caps.size(); ++x)
    for (std::uint32_t y = x + 1; y < caps.size(); ++y) {
      const std::uint32_t j = caps[x].other, k = caps[y].other;
      const Vec3 &cj = c_[j], &ck = c_[k];
      const double rj = r_[j], rk = r_[k];
      // Balls j and k apart: their caps are too (a sure floating-point decision).
      const Vec3 djk = ck - cj;
      if (dot(djk, djk) > (rj + rk) * (rj + rk) * (1 + 1e-9)) continue;
      // Most pairs are decided by the caps' angular radii and the angle between their
      // axes (cosines, all of magnitude 1 or less, with errors near 1e-16 that grow as
      // 1/sin on tiny circles): crossing when |a_x - a_y| < angle < a_x + a_y (or the
      // complement's), nested below that, apart or complementary above.
      {
        const CircleFrame &fx = caps[x].frame, &fy = caps[y].frame;
        const double cosine = dot(fx.n, fy.n), cc = fx.c0 * fy.c0, ss = fx.s0 * fy.s0;
        const double margin = 1e-9 * (1 + 1e-5 / (ss + 1e-300));
        if (cosine > cc - ss + margin && cosine < cc + ss - margin) {
          crossings.emplace_back(x, y);
          continue;
        }
        if (cosine < cc - ss - margin) {
          if (fx.c0 + fy.c0 > margin) continue;  // caps apart
          if (fx.c0 + fy.c0 < -margin) {         // complements apart: the two caps cover the sphere
            out.covered = true;
            return;
          }
        } else if (cosine > cc + ss + margin) {  // nested: the smaller circle inside the larger cap
          if (fx.c0 > fy.c0 + margin) {
            caps[x].covered = true;
            continue;
          }
          if (fy.c0 > fx.c0 + margin) {
            caps[y].covered = true;
            continue;
          }
        }
      }
      const auto pa = arrangement::circle_pair<Approx>(ci, ri, cj, rj, ck, rk);
      auto certain = [](const Approx& a) { return std::isfinite(a.m) && std::fabs(a.v) > 1e-11 * a.m; };
      int g_sign = certain(pa.g) ? (pa.g.v > 0 ? 1 : -1) : 0;
      int q_sign = certain(pa.q) ? (pa.q.v > 0 ? 1 : -1) : 0;
      if (g_sign == 0 || (g_sign > 0 && q_sign == 0)) {
        ++out.decisions.exact;
        const auto pe = arrangement::circle_pair<mpq_class>(ci, ri, cj, rj, ck, rk);
        g_sign = sgn(pe.g);
        q_sign = sgn(pe.q);
      }
      if (g_sign > 0 && q_sign > 0) {
        crossings.emplace_back(x, y);
        continue;
      }
      // Not crossing: a circle inside the other cap is covered (the lower index owns a
      // circle that two caps share; complementary caps cover each other's circle).
      bool same_circle = false;
      auto inside = [&](std::uint32_t p, std::uint32_t q) {  // circle p against cap q
        const Vec3 &cp = c_[caps[p].other], &cq = c_[caps[q].other];
        const double rp = r_[caps[p].other], rq = r_[caps[q].other];
        const int centre = exact_sign([&]<class T>() -> T {
          const auto dp = arrangement::difference<T>(cp, ci), dq = arrangement::difference<T>(cq, ci);
          const T ep = arrangement::sphere_term(dp, ri, rp), eq = arrangement::sphere_term(dq, ri, rq);
          return ep * dot(dq, dp) - eq * dot(dp, dp);
        }, out.decisions);
        if (centre != 0) return centre > 0;
        const int same = exact_sign([&]<class T>() -> T {
          return dot(arrangement::difference<T>(cp, ci), arrangement::difference<T>(cq, ci));
        }, out.decisions);
        same_circle = true;
        return same < 0 || caps[q].other < caps[p].other;
      };
      const bool x_in_y = inside(x, y), y_in_x = inside(y, x);
      // One circle cut by two spheres (its two names are aliases, for the shells).
      if (same_circle) out.aliases.emplace_back(circle_key(i, j), circle_key(i, k));
      if (x_in_y && y_in_x) {  // each circle in the other cap: together they cover the sphere
        out.covered = true;
        return;
      }
      caps[x].covered |= x_in_y;
      caps[y].covered |= y_in_x;
    }
  // A cap whose circle lies in another cap lies in that cap (else the two would cover the
  // sphere): it adds nothing. The crossings' points, between the caps that remain.
  for (const auto& [x, y] : crossings)
    if (!caps[x].covered && !caps[y].covered) add_crossing(i, x, y, ends, out);
}

void SphereArranger::add_crossing(std::uint32_t i, std::uint32_t x, std::uint32_t y,
                                  std::vector<Endpoint>& ends, SphereResult& out) const {
  const Cap &cx = out.caps[x], &cy = out.caps[y];
  const double ri = r_[i];
  const double rj = r_[cx.other], rk = r_[cy.other];
  // The two points in floating point: y0 + s sqrt(h) w / |w|.
  const Vec3 &dj = cx.d, &dk = cy.d;
  const double jj = dot(dj, dj), kk = dot(dk, dk), jk = dot(dj, dk);
  const double ej = jj + (ri - rj) * (ri + rj), ek = kk + (ri - rk) * (ri + rk);
  const Vec3 w = cross(dj, dk);
  const double g = dot(w, w);
  const Vec3 y0 = ((ej * kk - ek * jk) * dj + (ek * jj - ej * jk) * dk) / (2 * g);
  const double h = std::max(0.0, ri * ri - dot(y0, y0));
  const double root = std::sqrt(h);
  const Vec3 wn = w / std::sqrt(g);
  // Rounding: the positions' error grows as 1/sqrt(h) near tangency and the angles' as
  // 1/rho on small circles; a thousand times a generous estimate.
  const double position_error = 1e-13 * ri * (1 + ri / std::max(root, 1e-300));
  for (int s : {-1, 1}) {
    const Vec3 p = y0 + (s * root) * wn;
    // On circle x, s = -1 enters cap y counter-clockwise; on circle y (w reversed) it leaves cap x.
    ends.push_back({x, pseudo_angle(dot(p, cx.frame.u), dot(p, cx.frame.v)),
                    1e-10 + position_error / (ri * cx.frame.s0), y, s, p});
    ends.push_back({y, pseudo_angle(dot(p, cy.frame.u), dot(p, cy.frame.v)),
                    1e-10 + position_error / (ri * cy.frame.s0), x, -s, p});
  }
}

}  // namespace molsurf::arrangement
