// The arrangement of the true spheres (include/molsurf/sphere_arrangement.hpp), sphere by
// sphere in parallel, then joined:
//  1. neighbours: which balls cut sphere i, which bury it (exact);
//  2. circles: each pair of caps either crosses (two vertices), or one circle lies inside
//     the other cap (covered), or they are apart (exact);
//  3. exposed arcs: on each circle, the arcs between the caps that cross it, outside every
//     cap. An end is decided by its angle when that is farther from every other cap's ends
//     than the angles' rounding, and otherwise by the exact test of the vertex against the
//     ball (whose answer all three spheres through the vertex share);
//  4. cycles: arcs joined at their vertices; patches: cycles grouped into the connected
//     exposed regions of the sphere (arc_integrals.hpp: each cycle's area on its exposed
//     side, and which cycles lie on which side of each other);
//  5. shells: patches that share a vertex or a whole circle, joined; area and volume per
//     sphere, patch and shell by Stokes' and the divergence theorem.
#include "molsurf/sphere_arrangement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "arrangement/arc_integrals.hpp"
#include "arrangement/contained_spheres.hpp"
#include "arrangement/sphere_predicates.hpp"
#include "common/parallel_exceptions.hpp"
#include "common/thread_count_scope.hpp"
#include "arrangement/power_neighbours.hpp"

namespace molsurf {

namespace {

using arrangement::Approx;
using arrangement::CircleFrame;
using arrangement::DecisionCounter;
using arrangement::exact_sign;

constexpr double kPi = std::numbers::pi, kTwoPi = 2 * std::numbers::pi;

// A vertex (three spheres and a side) or, with c == kWholeCircle, the whole circle of two.
struct Key {
  std::uint32_t a = 0, b = 0, c = 0;
  std::int32_t side = 0;
  friend auto operator<=>(const Key&, const Key&) = default;
};
constexpr std::uint32_t kWholeCircle = 0xffffffffu;

// The vertex on sphere i where circles j and k cross, on side s of w = D_j x D_k.
Key vertex_key(std::uint32_t i, std::uint32_t j, std::uint32_t k, int s) {
  std::uint32_t v[3] = {i, j, k};
  int parity = 1;
  for (int x = 0; x < 3; ++x)
    for (int y = x + 1; y < 3; ++y)
      if (v[y] < v[x]) parity = -parity;
  std::sort(v, v + 3);
  return {v[0], v[1], v[2], s * parity};
}

struct Cap {
  std::uint32_t other = 0;
  Vec3 d;           // c_other - c_i
  CircleFrame frame;
  bool covered = false;  // its circle lies in another cap (and so does the cap)
};

// The whole circle where spheres i and j meet.
Key circle_key(std::uint32_t i, std::uint32_t j) { return {std::min(i, j), std::max(i, j), kWholeCircle, 0}; }

struct Endpoint {
  std::uint32_t circle = 0;  // the cap whose circle it lies on
  double theta = 0;   // pseudo-angle on the circle
  double margin = 0;  // bound on theta's rounding
  std::uint32_t cap = 0;  // the cap whose boundary it is (index into caps)
  int s = 0;              // -1: entering that cap counter-clockwise, +1: leaving it
  Vec3 y;                 // relative to c_i
};

struct LocalArc {
  std::uint32_t cap = 0, other = 0;
  double theta = 0, delta = 0;  // runs from theta to theta - delta (clockwise)
  Key from, to;                 // unused for a whole circle
  Vec3 from_point;              // relative to c_i
  bool whole = false;
  std::uint32_t patch = 0;      // local
};

struct LocalPatch {
  double area = 0;
  Vec3 vector_area;
  std::vector<Key> keys;  // vertices and whole circles on its boundary
};

struct SphereResult {
  bool buried = false, duplicate = false, broken = false;
  bool covered = false;  // two caps cover the whole sphere
  std::size_t circles = 0, degenerate = 0;
  double area = 0;
  Vec3 vector_area;
  std::vector<LocalArc> arcs;
  std::vector<Cap> caps;  // released once the sphere is measured
  std::vector<LocalPatch> patches;
  std::vector<std::pair<Key, Key>> aliases;  // two keys of one point (four or more spheres through it)
  DecisionCounter decisions;
};

// Positions on a circle by a pseudo-angle in [0, 4) (the "diamond angle" of the point's
// coordinates in the circle's frame): increasing with the angle, with a derivative between
// 1/2 and 1 per radian, so an angle's error bound bounds it too; no transcendental call.
constexpr double kTurn = 4;
double pseudo_angle(double x, double y) {
  const double ax = std::fabs(x), ay = std::fabs(y), t = ay / (ax + ay);  // 0/0 only at the axis
  const double q = y >= 0 ? (x >= 0 ? t : 2 - t) : (x < 0 ? 2 + t : 4 - t);
  return q >= kTurn || q != q ? 0 : q;
}
double wrap(double a) {  // a in (-2 turns, 2 turns) into [0, 1 turn)
  a = a < 0 ? a + kTurn : a;
  a = a < 0 ? a + kTurn : a;
  a = a >= kTurn ? a - kTurn : a;
  return a >= kTurn ? a - kTurn : a;
}

class SphereArranger {
 public:
  SphereArranger(std::span<const Vec3> c, std::span<const double> r, const arrangement::PowerNeighbours& neighbours)
      : c_(c), r_(r), neighbours_(neighbours) {}

  SphereResult arrange(std::uint32_t i) const {
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

 private:
  // Step 1. False when sphere i is buried (inside another ball, or a later copy).
  bool find_caps(std::uint32_t i, SphereResult& out) const {
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
  void cross_circles(std::uint32_t i, std::vector<Endpoint>& ends, SphereResult& out) const {
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

  void add_crossing(std::uint32_t i, std::uint32_t x, std::uint32_t y, std::vector<Endpoint>& ends,
                    SphereResult& out) const {
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

  // Exact: is the vertex where circles j and k (cap indices) cross, on side s of
  // D_j x D_k, inside ball l (+1), on its sphere (0) or outside (-1)?
  int vertex_inside(std::uint32_t i, const SphereResult& out, std::uint32_t j, std::uint32_t k, int s,
                    std::uint32_t l, DecisionCounter& decisions) const {
    ++decisions.exact;
    const std::uint32_t aj = out.caps[j].other, ak = out.caps[k].other, al = out.caps[l].other;
    const auto p = arrangement::circle_pair<mpq_class>(c_[i], r_[i], c_[aj], r_[aj], c_[ak], r_[ak]);
    const auto dl = arrangement::difference<mpq_class>(c_[al], c_[i]);
    const mpq_class el = arrangement::sphere_term(dl, r_[i], r_[al]);
    const mpq_class xq = p.g * (dot(dl, p.y0) - el * p.g);
    const mpq_class yq = mpq_class(s) * dot(dl, p.w);
    return arrangement::sign_plus_root(xq, yq, p.q * p.g);
  }

  // Step 3 for circle j (cap index).
  void exposed_arcs(std::uint32_t i, std::uint32_t j, std::span<const Endpoint> ends, SphereResult& out) const {
    const Cap& cap = out.caps[j];
    if (ends.empty()) {
      LocalArc arc;
      arc.cap = j;
      arc.whole = true;
      arc.theta = 0;
      arc.delta = kTwoPi;
      out.arcs.push_back(arc);
      return;
    }
    // Each crossing cap's interval [entry, exit] counter-clockwise; ends come in pairs.
    struct Interval {
      double from, length, margin_from, margin_to;
      std::uint32_t cap, in_end, ex_end;
    };
    thread_local std::vector<Interval> intervals;
    intervals.clear();
    for (std::size_t e = 0; e < ends.size(); e += 2) {
      const auto in_end = static_cast<std::uint32_t>(ends[e].s < 0 ? e : e + 1);
      const auto ex_end = static_cast<std::uint32_t>(ends[e].s < 0 ? e + 1 : e);
      const Endpoint &in = ends[in_end], &ex = ends[ex_end];
      intervals.push_back({in.theta, wrap(ex.theta - in.theta), in.margin, ex.margin, in.cap, in_end, ex_end});
    }
    // Ends found to be the same point (a vertex on a fourth sphere) get the same angle, so
    // that the order below puts a leaving end before an entering one there: the exposed
    // arc between them has length zero.
    thread_local std::vector<double> theta;
    thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> same_point;
    theta.resize(ends.size());
    for (std::size_t e = 0; e < ends.size(); ++e) theta[e] = ends[e].theta;
    same_point.clear();
    // Whether the end `e` lies inside another interval: by angles where they are clearly
    // apart, else by the exact test of the vertex against that ball.
    auto covered_end = [&](std::size_t e) {
      const Endpoint& p = ends[e];
      for (const Interval& iv : intervals) {
        if (iv.cap == p.cap) continue;
        const double rel = wrap(p.theta - iv.from);
        const double to_from = std::min(rel, kTurn - rel), to_end = std::fabs(rel - iv.length);
        const double near = std::min(to_from - iv.margin_from, std::min(to_end, kTurn - to_end) - iv.margin_to);
        if (near > p.margin) {
          if (rel < iv.length) return true;
          continue;
        }
        // s is relative to D_j x D_p.cap: the end of cap p.cap on circle j.
        const int inside = vertex_inside(i, out, j, p.cap, p.s, iv.cap, out.decisions);
        if (inside == 0) {  // on that sphere too: four spheres through a point
          ++out.degenerate;
          const double d_in = wrap(ends[iv.in_end].theta - p.theta), d_ex = wrap(ends[iv.ex_end].theta - p.theta);
          const bool in_nearer = std::min(d_in, kTurn - d_in) <= std::min(d_ex, kTurn - d_ex);
          same_point.emplace_back(static_cast<std::uint32_t>(e), in_nearer ? iv.in_end : iv.ex_end);
        }
        if (inside > 0) return true;
      }
      return false;
    };
    // A sweep counter-clockwise over the ends counts the intervals around each; an end next
    // to another within their rounding, and every end of a circle with an interval whose
    // ends are that close (nearly tangent circles), is decided one by one instead.
    // The ends by angle, as compact (angle, index) pairs: sorted in place, not through the
    // ends themselves.
    struct Position {
      double theta;
      std::uint32_t end;
      bool operator<(const Position& o) const { return theta != o.theta ? theta < o.theta : end < o.end; }
    };
    thread_local std::vector<Position> sorted;
    thread_local std::vector<std::uint32_t> order;
    sorted.resize(ends.size());
    for (std::uint32_t e = 0; e < ends.size(); ++e) sorted[e] = {ends[e].theta, e};
    std::sort(sorted.begin(), sorted.end());
    order.resize(ends.size());
    for (std::size_t k = 0; k < ends.size(); ++k) order[k] = sorted[k].end;
    const std::size_t n_ends = ends.size();
    bool careful = false;
    int depth = 0;
    for (const Interval& iv : intervals) {
      careful |= std::min(iv.length, kTurn - iv.length) <= iv.margin_from + iv.margin_to;
      depth += iv.from + iv.length >= kTurn;  // active at the sweep's start
    }
    const int start_depth = depth;
    thread_local std::vector<char> exposed_end;
    exposed_end.assign(n_ends, 0);
    // Entering (s = -1): exposed when no interval is open before it; leaving (s = +1): when
    // none is open after it. Without a branch on the kind, which is unpredictable.
    for (std::size_t k = 0; k < n_ends; ++k) {
      const int s = ends[order[k]].s;
      const int before = depth;
      depth -= s;
      exposed_end[order[k]] = (s < 0 ? before : depth) == 0;
    }
    for (std::size_t k = 0; k < n_ends; ++k) {
      const Endpoint& p = ends[order[k]];
      const Endpoint& before = ends[order[(k + n_ends - 1) % n_ends]];
      const Endpoint& after = ends[order[(k + 1) % n_ends]];
      auto close = [&](const Endpoint& q) {
        const double d = wrap(q.theta - p.theta);
        return std::min(d, kTurn - d) <= p.margin + q.margin;
      };
      if (careful || depth != start_depth || close(before) || close(after)) exposed_end[order[k]] = !covered_end(order[k]);
    }
    // Most circles are covered whole (the union of the crossing caps' arcs).
    if (std::find(exposed_end.begin(), exposed_end.end(), 1) == exposed_end.end()) return;
    auto key_of = [&](std::uint32_t e) { return vertex_key(i, cap.other, out.caps[ends[e].cap].other, ends[e].s); };
    thread_local std::vector<std::uint32_t> group;  // ends at one point, by union-find
    group.resize(ends.size());
    std::iota(group.begin(), group.end(), 0u);
    auto root = [&](std::uint32_t e) {
      while (group[e] != e) e = group[e] = group[group[e]];
      return e;
    };
    for (const auto& [a, b] : same_point) {
      group[std::max(root(a), root(b))] = std::min(root(a), root(b));
      out.aliases.emplace_back(key_of(a), key_of(b));
    }
    for (std::size_t e = 0; e < ends.size(); ++e) theta[e] = ends[root(static_cast<std::uint32_t>(e))].theta;
    struct Exposed {
      double theta;
      int s;
      std::size_t end;
    };
    thread_local std::vector<Exposed> exposed;
    exposed.clear();
    for (std::size_t e = 0; e < n_ends; ++e)
      if (exposed_end[e]) exposed.push_back({theta[e], ends[e].s, e});
    if (exposed.empty()) return;  // the whole circle is covered by the union of the crossing caps
    // Counter-clockwise, exposed arcs run from a leaving end (s = +1) to the next entering
    // one; at equal angles the leaving end first (the point alone is exposed).
    std::sort(exposed.begin(), exposed.end(), [](const Exposed& a, const Exposed& b) {
      if (a.theta != b.theta) return a.theta < b.theta;
      return a.s != b.s ? a.s > b.s : a.end < b.end;
    });
    // Ends of one kind at one point (several caps entered, or left, together) make one end.
    std::size_t kept = 0;
    for (std::size_t k = 0; k < exposed.size(); ++k) {
      const bool twin = kept > 0 && exposed[kept - 1].theta == exposed[k].theta && exposed[kept - 1].s == exposed[k].s &&
                        root(static_cast<std::uint32_t>(exposed[kept - 1].end)) ==
                            root(static_cast<std::uint32_t>(exposed[k].end));
      if (!twin) exposed[kept++] = exposed[k];
    }
    exposed.resize(kept);
    const std::size_t n = exposed.size();
    for (std::size_t a = 0; a < n; ++a) {
      if (exposed[a].s < 0) continue;
      // The next entering end, counter-clockwise; leaving ends in between (rounding at a
      // degenerate point) are passed over.
      std::size_t b = (a + 1) % n;
      std::size_t steps = 1;
      while (exposed[b].s > 0 && steps < n) {
        b = (b + 1) % n;
        ++steps;
      }
      if (exposed[b].s > 0) {
        out.broken = true;
        continue;
      }
      if (steps > 1) out.broken = true;
      const Endpoint &leave = ends[exposed[a].end], &enter = ends[exposed[b].end];
      LocalArc arc;
      arc.cap = j;
      // True angles for the exposed ends only (the integrals need them).
      const double from = cap.frame.angle_of(enter.y), to = cap.frame.angle_of(leave.y);
      double delta = from - to;
      if (b == a) {
        delta = kTwoPi;
      } else if (theta[exposed[b].end] == theta[exposed[a].end]) {
        delta = 0;  // one exposed point
      } else {
        delta = delta < 0 ? delta + kTwoPi : delta;  // from `to` counter-clockwise to `from`
        delta = delta >= kTwoPi ? delta - kTwoPi : delta;
      }
      arc.theta = from;
      arc.delta = delta;
      arc.from = vertex_key(i, cap.other, out.caps[enter.cap].other, enter.s);
      arc.to = vertex_key(i, cap.other, out.caps[leave.cap].other, 1);
      arc.from_point = enter.y;
      out.arcs.push_back(arc);
    }
  }

  // Steps 4 and 5 on one sphere: area, vector area, cycles and patches.
  void measure(std::uint32_t i, SphereResult& out) const {
    const double r2 = r_[i] * r_[i];
    if (out.caps.empty() || out.arcs.empty()) {
      // No boundary: the whole sphere is exposed, or nothing is (every circle covered).
      const bool whole = out.caps.empty();
      out.area = whole ? 4 * kPi * r2 : 0;
      if (whole) out.patches.push_back({out.area, {}, {}});
      return;
    }
    for (const LocalArc& arc : out.arcs)
      out.vector_area += r2 * arrangement::half_moment(out.caps[arc.cap].frame, arc.theta, -arc.delta);
    out.area = r2 * single_pole_area(out);

    // Cycles: each arc continues with the arc that starts where it ends (at a point with
    // several keys, any of them).
    auto canonical = [&](Key k) {
      for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [x, y] : out.aliases)
          if ((x == k && y < k) || (y == k && x < k)) {
            k = std::min(x, y);
            changed = true;
          }
      }
      return k;
    };
    const std::size_t m = out.arcs.size();
    std::vector<Key> from(m), to(m);
    for (std::size_t a = 0; a < m; ++a) {
      from[a] = out.aliases.empty() ? out.arcs[a].from : canonical(out.arcs[a].from);
      to[a] = out.aliases.empty() ? out.arcs[a].to : canonical(out.arcs[a].to);
    }
    // A zero-length arc from a point back to itself (with aliases: a point where four or
    // more spheres meet) links nothing: dropped.
    if (!out.aliases.empty()) {
      std::size_t kept = 0;
      for (std::size_t a = 0; a < m; ++a)
        if (out.arcs[a].whole || out.arcs[a].delta != 0 || from[a] != to[a]) {
          out.arcs[kept] = out.arcs[a];
          from[kept] = from[a];
          to[kept++] = to[a];
        }
      out.arcs.resize(kept);
      from.resize(kept);
      to.resize(kept);
      if (kept == 0) return;  // exposed at single points only
    }
    const std::size_t m_kept = out.arcs.size();
    std::vector<std::int64_t> next(m_kept, -1);
    for (std::size_t a = 0; a < m_kept; ++a) {
      if (out.arcs[a].whole) {
        next[a] = static_cast<std::int64_t>(a);
        continue;
      }
      for (std::size_t b = 0; b < m_kept; ++b)
        if (!out.arcs[b].whole && from[b] == to[a]) {
          if (next[a] >= 0) out.broken = true;  // two arcs leave one vertex
          next[a] = static_cast<std::int64_t>(b);
        }
      if (next[a] < 0) out.broken = true;
    }
    std::vector<std::vector<std::uint32_t>> cycles;
    std::vector<std::int64_t> cycle_of(m_kept, -1);
    for (std::size_t a = 0; a < m_kept && !out.broken; ++a) {
      if (cycle_of[a] >= 0) continue;
      std::vector<std::uint32_t> cycle;
      std::size_t b = a;
      while (cycle_of[b] < 0) {
        cycle_of[b] = static_cast<std::int64_t>(cycles.size());
        cycle.push_back(static_cast<std::uint32_t>(b));
        b = static_cast<std::size_t>(next[b]);
      }
      if (b != a) out.broken = true;  // joined a cycle in its middle
      cycles.push_back(std::move(cycle));
    }
    if (!out.broken) drop_point_cycles(cycles, out);
    if (out.arcs.empty()) return;  // exposed at single points only
    if (out.broken || cycles.size() == 1) {
      // One patch (or, at a degenerate point the cycles do not close, the whole sphere's
      // exposed part taken as one patch).
      LocalPatch patch{out.area, out.vector_area, {}};
      for (LocalArc& arc : out.arcs) arc.patch = 0;
      out.patches.push_back(std::move(patch));
      add_keys(i, out);
      return;
    }
    group_cycles(r2, cycles, out);
    add_keys(i, out);
  }

  // A cycle of arcs of length zero is a single exposed point (where four or more spheres
  // meet and nothing around is exposed): it bounds no area and joins no shells.
  static void drop_point_cycles(std::vector<std::vector<std::uint32_t>>& cycles, SphereResult& out) {
    std::vector<char> keep(out.arcs.size(), 1);
    bool any = false;
    std::erase_if(cycles, [&](const std::vector<std::uint32_t>& cycle) {
      for (std::uint32_t a : cycle)
        if (out.arcs[a].delta != 0) return false;
      for (std::uint32_t a : cycle) keep[a] = 0;
      return any = true;
    });
    if (!any) return;
    std::vector<std::uint32_t> index(out.arcs.size());
    std::size_t kept = 0;
    for (std::size_t a = 0; a < out.arcs.size(); ++a)
      if (keep[a]) {
        index[a] = static_cast<std::uint32_t>(kept);
        out.arcs[kept++] = out.arcs[a];
      }
    out.arcs.resize(kept);
    for (std::vector<std::uint32_t>& cycle : cycles)
      for (std::uint32_t& a : cycle) a = index[a];
  }

  // The sphere's exposed area on the unit sphere, with one pole for all arcs: a pole whose
  // antipode lies far from every circle, so that whether it is exposed is certain.
  static double single_pole_area(const SphereResult& out) {
    double best = -1;
    Vec3 best_q;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          if (x == 0 && y == 0 && z == 0) continue;
          const Vec3 q = normalized(Vec3{double(x), double(y), double(z)});
          const double clearance = clearance_from_circles(out, q);
          if (clearance > best) {
            best = clearance;
            best_q = q;
          }
        }
    for (int t = 0; best < 1e-6 && t < 256; ++t) {  // a spiral of further candidates
      const double zc = 1 - (2 * t + 1) / 256.0, rho = std::sqrt(1 - zc * zc), phi = t * 2.399963229728653;
      const Vec3 q{rho * std::cos(phi), rho * std::sin(phi), zc};
      const double clearance = clearance_from_circles(out, q);
      if (clearance > best) {
        best = clearance;
        best_q = q;
      }
    }
    bool q_exposed = true;
    for (const Cap& cap : out.caps) q_exposed &= dot(cap.frame.n, best_q) <= cap.frame.c0;
    const Vec3 p = -best_q;
    double area = q_exposed ? 4 * kPi : 0;
    for (const LocalArc& arc : out.arcs)
      area += arrangement::pole_form_integral(out.caps[arc.cap].frame, p, arc.theta, -arc.delta);
    return std::clamp(area, 0.0, 4 * kPi);
  }

  static double clearance_from_circles(const SphereResult& out, const Vec3& q) {
    double clearance = 2;
    for (const Cap& cap : out.caps) clearance = std::min(clearance, std::fabs(dot(cap.frame.n, q) - cap.frame.c0));
    return clearance;
  }

  // The area on the exposed side of a cycle (unit sphere), taking the pole's antipode in a
  // cap on the cycle's other side, as far from the cycle's circles as the caps allow.
  static double cycle_area(const SphereResult& out, const std::vector<std::uint32_t>& cycle) {
    double best = -1;
    Vec3 best_q;
    for (std::uint32_t a : cycle) {
      const Vec3 q = out.caps[out.arcs[a].cap].frame.n;
      double clearance = 2;
      for (std::uint32_t b : cycle) {
        const CircleFrame& f = out.caps[out.arcs[b].cap].frame;
        clearance = std::min(clearance, std::fabs(dot(f.n, q) - f.c0));
      }
      if (clearance > best) {
        best = clearance;
        best_q = q;
      }
    }
    return cycle_integral(out, cycle, -best_q);
  }

  static double cycle_integral(const SphereResult& out, const std::vector<std::uint32_t>& cycle, const Vec3& p) {
    double sum = 0;
    for (std::uint32_t a : cycle) {
      const LocalArc& arc = out.arcs[a];
      sum += arrangement::pole_form_integral(out.caps[arc.cap].frame, p, arc.theta, -arc.delta);
    }
    return sum;
  }

  // Cycles a and b bound the same exposed region when each lies on the other's exposed
  // side and no third cycle separates them (the regions and cycles of a sphere form a tree).
  static void group_cycles(double r2, const std::vector<std::vector<std::uint32_t>>& cycles, SphereResult& out) {
    const std::size_t n = cycles.size();
    std::vector<double> side_area(n);
    for (std::size_t a = 0; a < n; ++a) side_area[a] = cycle_area(out, cycles[a]);
    // in[a][b]: a point of cycle b lies on cycle a's exposed side.
    std::vector<char> in(n * n, 1);
    for (std::size_t b = 0; b < n; ++b)
      for (std::size_t a = 0; a < n; ++a) {
        if (a == b) continue;
        // A point of cycle b as far from cycle a's circles as a few tries find (a point
        // where two circles touch would make the integral singular).
        Vec3 x;
        double best = -1;
        for (std::size_t k = 0; k < std::min<std::size_t>(cycles[b].size(), 4); ++k)
          for (const double f : {0.5, 0.25, 0.75}) {
            const LocalArc& arc = out.arcs[cycles[b][k]];
            const Vec3 candidate = out.caps[arc.cap].frame.point(arc.theta - f * arc.delta);
            double clearance = 2;
            for (std::uint32_t e : cycles[a]) {
              const CircleFrame& circle = out.caps[out.arcs[e].cap].frame;
              clearance = std::min(clearance, std::fabs(dot(circle.n, candidate) - circle.c0));
            }
            if (clearance > best) {
              best = clearance;
              x = candidate;
            }
          }
        in[a * n + b] = side_area[a] - cycle_integral(out, cycles[a], -x) > 2 * kPi;
      }
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::size_t v) {
      while (parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) {
        if (!in[a * n + b] || !in[b * n + a]) continue;
        bool separated = false;
        for (std::size_t c = 0; c < n && !separated; ++c)
          if (c != a && c != b) separated = in[c * n + a] != in[c * n + b];
        if (!separated) parent[find(a)] = find(b);
      }
    std::vector<std::int64_t> patch_of(n, -1);
    std::vector<std::size_t> cycles_in;
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t root = find(a);
      if (patch_of[root] < 0) {
        patch_of[root] = static_cast<std::int64_t>(out.patches.size());
        out.patches.push_back({});
        cycles_in.push_back(0);
      }
      const auto p = static_cast<std::size_t>(patch_of[root]);
      out.patches[p].area += side_area[a];
      ++cycles_in[p];
      for (std::uint32_t arc : cycles[a]) {
        out.arcs[arc].patch = static_cast<std::uint32_t>(p);
        const LocalArc& la = out.arcs[arc];
        out.patches[p].vector_area +=
            r2 * arrangement::half_moment(out.caps[la.cap].frame, la.theta, -la.delta);
      }
    }
    for (std::size_t p = 0; p < out.patches.size(); ++p)
      out.patches[p].area = r2 * std::clamp(out.patches[p].area - (cycles_in[p] - 1.0) * 4 * kPi, 0.0, 4 * kPi);
  }

  // The boundary keys of each patch: its arcs' vertices and whole circles.
  void add_keys(std::uint32_t i, SphereResult& out) const {
    for (const LocalArc& arc : out.arcs) {
      std::vector<Key>& keys = out.patches[arc.patch].keys;
      if (arc.whole) {
        keys.push_back(circle_key(i, out.caps[arc.cap].other));
      } else {
        keys.push_back(arc.from);
      }
    }
  }

  std::span<const Vec3> c_;
  std::span<const double> r_;
  const arrangement::PowerNeighbours& neighbours_;
};

}  // namespace

SphereArrangement arrange_spheres(std::span<const Vec3> centres, std::span<const double> radii,
                                  const ArrangementOptions& options) {
  if (centres.size() != radii.size()) throw std::invalid_argument("arrange_spheres: one radius per centre");
  if (centres.size() >= kWholeCircle) throw std::invalid_argument("arrange_spheres: too many spheres");
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3& c = centres[i];
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(radii[i]) ||
        radii[i] < 0)
      throw std::invalid_argument("arrange_spheres: sphere " + std::to_string(i) +
                                  " has a coordinate or radius that is not finite, or a negative radius");
  }
  const ThreadCountScope threads(options.threads);
  SphereArrangement result;
  const std::size_t n = centres.size();
  result.area_per_sphere.assign(n, 0);
  result.stats.spheres = n;
  if (n == 0) return result;
  // A sphere inside another's closed ball is buried and cuts nothing; of copies (same
  // centre and radius) the lowest index counts, so that a circle's spheres are alike on
  // every sphere. Settled before the neighbours: a thousand atoms at one centre would
  // otherwise each be every other's neighbour.
  const std::vector<std::uint32_t> container = arrangement::sphere_containers(centres, radii);
  std::vector<char> copy(n, 0), held(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    held[i] = container[i] != i;
    copy[i] = held[i] && centres[container[i]] == centres[i] && radii[container[i]] == radii[i];
  }
  std::vector<char> include(n);
  for (std::size_t i = 0; i < n; ++i) include[i] = radii[i] > 0 && !held[i];
  const arrangement::PowerNeighbours neighbours = arrangement::power_neighbours(centres, radii, include);
  const SphereArranger arranger(centres, radii, neighbours);
  std::vector<SphereResult> spheres(n);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
    errors.run(i, [&] {
      if (held[i]) {
        spheres[i].buried = true;
        spheres[i].duplicate = copy[i];
        return;
      }
      spheres[i] = arranger.arrange(static_cast<std::uint32_t>(i));
    });
  errors.rethrow();

  // Vertices: every arc's ends, once each, in key order.
  std::vector<std::pair<Key, Vec3>> seen;
  for (std::uint32_t i = 0; i < n; ++i)
    for (const LocalArc& arc : spheres[i].arcs)
      if (!arc.whole) seen.emplace_back(arc.from, centres[i] + arc.from_point);
  std::sort(seen.begin(), seen.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Key> vertex_keys;
  for (const auto& [key, point] : seen)
    if (vertex_keys.empty() || vertex_keys.back() != key) {
      vertex_keys.push_back(key);
      result.vertices.push_back({{key.a, key.b, key.c}, key.side, point});
    }
  auto vertex_index = [&](const Key& key) -> std::int64_t {
    const auto it = std::lower_bound(vertex_keys.begin(), vertex_keys.end(), key);
    return it != vertex_keys.end() && *it == key ? it - vertex_keys.begin() : -1;
  };

  // Arcs and patches in global numbering; shells by the keys the patches share.
  std::vector<std::pair<Key, std::uint32_t>> patch_keys;
  for (std::uint32_t i = 0; i < n; ++i) {
    SphereResult& s = spheres[i];
    result.area_per_sphere[i] = s.area;
    result.stats.buried += s.buried;
    result.stats.duplicate += s.duplicate;
    result.stats.circles += s.circles;
    result.stats.exact_decisions += s.decisions.exact;
    result.stats.degenerate_points += s.degenerate;
    const auto first_patch = static_cast<std::uint32_t>(result.patches.size());
    for (const LocalArc& arc : s.arcs) {
      ArrangementArc a;
      a.sphere = i;
      a.other = arc.other;
      a.from = arc.whole ? -1 : vertex_index(arc.from);
      a.to = arc.whole ? -1 : vertex_index(arc.to);
      a.angle = arc.delta;
      a.patch = first_patch + arc.patch;
      result.arcs.push_back(a);
    }
    for (const LocalPatch& p : s.patches) {
      const auto index = static_cast<std::uint32_t>(result.patches.size());
      result.patches.push_back({i, p.area, p.vector_area, 0});
      for (const Key& key : p.keys) patch_keys.emplace_back(key, index);
    }
  }
  // Shells: patches joined through the keys on their boundaries, keys through their aliases
  // (union-find over patches, then keys).
  std::vector<Key> keys;
  keys.reserve(patch_keys.size());
  for (const auto& pk : patch_keys) keys.push_back(pk.first);
  std::vector<std::pair<Key, Key>> aliases;
  for (const SphereResult& s : spheres) aliases.insert(aliases.end(), s.aliases.begin(), s.aliases.end());
  for (const auto& [x, y] : aliases) {
    keys.push_back(x);
    keys.push_back(y);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const std::size_t patches = result.patches.size();
  auto key_node = [&](const Key& k) {
    return static_cast<std::uint32_t>(patches + (std::lower_bound(keys.begin(), keys.end(), k) - keys.begin()));
  };
  std::vector<std::uint32_t> parent(patches + keys.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  auto unite = [&](std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    parent[std::max(a, b)] = std::min(a, b);
  };
  for (const auto& [key, patch] : patch_keys) unite(patch, key_node(key));
  for (const auto& [x, y] : aliases) unite(key_node(x), key_node(y));

  // Shell measures, each about its own first sphere's centre (the divergence theorem's
  // origin is free; a near one keeps the sum's cancellation small).
  std::vector<std::int64_t> shell_of(patches, -1);
  std::vector<Vec3> origin;
  std::vector<ArrangementShell> shells;
  // A bound on each shell volume's rounding: a patch's area and vector area come from
  // integrals of order r^2 on the unit sphere, each some 1e-15 r^2 off, summed over its arcs.
  std::vector<double> volume_error;
  for (std::uint32_t p = 0; p < patches; ++p) {
    const std::uint32_t root = find(p);
    if (shell_of[root] < 0) {
      shell_of[root] = static_cast<std::int64_t>(shells.size());
      shells.emplace_back();
      origin.push_back(centres[result.patches[p].sphere]);
      volume_error.push_back(0);
    }
    const auto s = static_cast<std::size_t>(shell_of[root]);
    ArrangementPatch& patch = result.patches[p];
    const std::uint32_t i = patch.sphere;
    ArrangementShell& shell = shells[s];
    shell.area += patch.area;
    shell.volume += (radii[i] * patch.area + dot(centres[i] - origin[s], patch.vector_area)) / 3;
    shell.centroid += (centres[i] - origin[s]) * patch.area + radii[i] * patch.vector_area;
    volume_error[s] += 1e-12 * radii[i] * radii[i] * (radii[i] + norm(centres[i] - origin[s]));
    if (shell.spheres.empty() || shell.spheres.back() != i) shell.spheres.push_back(i);
    patch.shell = static_cast<std::uint32_t>(s);
  }
  for (std::size_t s = 0; s < shells.size(); ++s) {
    ArrangementShell& shell = shells[s];
    shell.centroid = shell.area > 0 ? origin[s] + shell.centroid / shell.area : origin[s];
    if (std::fabs(shell.volume) > volume_error[s]) continue;
    // A shell too small for its volume's sign (a void of 1e-13 A^3 where four spheres nearly
    // meet). An outer shell holds whole balls, so its area is at least that of its smallest
    // sphere (a surface around a ball is no smaller than the ball's sphere): a shell with
    // less is a cavity. Otherwise (not seen) its centroid decides: outside its balls, a void.
    double smallest = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (std::uint32_t i : shell.spheres) {
      smallest = std::min(smallest, radii[i]);
      const Vec3 d = shell.centroid - centres[i];
      inside |= dot(d, d) < radii[i] * radii[i];
    }
    if (shell.area < 4 * kPi * smallest * smallest) inside = false;
    shell.volume = inside ? std::fabs(shell.volume) : -std::fabs(shell.volume);
    if (shell.volume == 0) shell.volume = inside ? 0.0 : -0.0;
  }
  // The largest outer shell first, then by area.
  std::vector<std::size_t> order(shells.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if (shells[x].cavity() != shells[y].cavity()) return !shells[x].cavity();
    return shells[x].area > shells[y].area;
  });
  std::vector<std::uint32_t> rank(shells.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    rank[order[k]] = static_cast<std::uint32_t>(k);
    result.shells.push_back(std::move(shells[order[k]]));
  }
  for (ArrangementPatch& patch : result.patches) patch.shell = rank[patch.shell];
  for (ArrangementShell& shell : result.shells) {
    std::sort(shell.spheres.begin(), shell.spheres.end());
    shell.spheres.erase(std::unique(shell.spheres.begin(), shell.spheres.end()), shell.spheres.end());
    result.volume += shell.volume;
  }
  for (double a : result.area_per_sphere) result.area += a;
  return result;
}

}  // namespace molsurf
