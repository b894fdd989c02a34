// Step 3 of the arrangement on one sphere: on each circle, the arcs between the caps that
// cross it, outside every cap. An end is decided by its angle when that is farther from
// every other cap's ends than the angles' rounding, and otherwise by the exact test of the
// vertex against the ball (whose answer all three spheres through the vertex share).
#include "arrangement/sphere_arranger.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace molsurf::arrangement {

// Exact: is the vertex where circles j and k (cap indices) cross, on side s of
// D_j x D_k, inside ball l (+1), on its sphere (0) or outside (-1)?
int SphereArranger::vertex_inside(std::uint32_t i, const SphereResult& out, std::uint32_t j, std::uint32_t k,
                                  int s, std::uint32_t l, DecisionCounter& decisions) const {
  ++decisions.exact;
  const std::uint32_t aj = out.caps[j].other, ak = out.caps[k].other, al = out.caps[l].other;
  const auto p = arrangement::circle_pair<mpq_class>(c_[i], r_[i], c_[aj], r_[aj], c_[ak], r_[ak]);
  const auto dl = arrangement::difference<mpq_class>(c_[al], c_[i]);
  const mpq_class el = arrangement::sphere_term(dl, r_[i], r_[al]);
  const mpq_class xq = p.g * (dot(dl, p.y0) - el * p.g);
  const mpq_class yq = mpq_class(s) * dot(dl, p.w);
  return arrangement::sign_plus_root(xq, yq, p.q * p.g);
}

// Exact: does the centre of circle j (cap index) lie on cap k's side of cap k's plane
// (+1), on the plane (0) or on the other side (-1)?
int SphereArranger::centre_in_cap(std::uint32_t i, SphereResult& out, std::uint32_t j, std::uint32_t k) const {
  const Vec3 &ci = c_[i], &cj = c_[out.caps[j].other], &ck = c_[out.caps[k].other];
  const double ri = r_[i], rj = r_[out.caps[j].other], rk = r_[out.caps[k].other];
  return exact_sign([&]<class T>() -> T {
    const auto dj = arrangement::difference<T>(cj, ci), dk = arrangement::difference<T>(ck, ci);
    const T ej = arrangement::sphere_term(dj, ri, rj), ek = arrangement::sphere_term(dk, ri, rk);
    return ej * dot(dk, dj) - ek * dot(dj, dj);
  }, out.decisions);
}

// Step 3 for circle j (cap index).
void SphereArranger::exposed_arcs(std::uint32_t i, std::uint32_t j, std::span<const Endpoint> ends,
                                  SphereResult& out) const {
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
  // Where circle j and a cap's circle are nearly tangent, the cap's two ends on circle j are
  // closer than their rounding, and their rounded order can run the interval the wrong way
  // round: a whole turn for a point, or a point for a whole turn. A chord leaves the longer
  // arc on the side of the circle's centre, so the interval is the longer one exactly when
  // circle j's centre lies on the cap's side of its plane. (A ring of spheres all through
  // one point, a probe's exact threshold, has such pairs at that point: every circle was
  // taken as covered and every sphere as whole.)
  thread_local std::vector<char> point_end;  // the ends of an interval of (nearly) no length
  point_end.assign(ends.size(), 0);
  for (Interval& iv : intervals) {
    const double shorter = std::min(iv.length, kTurn - iv.length);
    if (shorter > iv.margin_from + iv.margin_to) continue;
    if (centre_in_cap(i, out, j, iv.cap) > 0) {
      iv.length = kTurn - shorter;
    } else {
      iv.length = shorter;
      point_end[iv.in_end] = point_end[iv.ex_end] = 1;
    }
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
  // one; at equal angles the leaving end first (the point alone is exposed), but a cap that
  // only touches the circle there is entered before it is left (its interval is the point).
  const auto rank = [&](const Exposed& e) { return point_end[e.end] ? (e.s < 0 ? 1 : 2) : (e.s > 0 ? 0 : 3); };
  const auto by_angle = [&](const Exposed& a, const Exposed& b) {
    if (a.theta != b.theta) return a.theta < b.theta;
    return rank(a) != rank(b) ? rank(a) < rank(b) : a.end < b.end;
  };
  std::sort(exposed.begin(), exposed.end(), by_angle);
  // Exposed ends closer than their angles' rounding are one point too. Where several spheres
  // nearly meet at one point (a symmetric placement whose coordinates were rounded), their
  // exact order along the circle is below the angles' resolution; the exact tests still say
  // which are exposed, and an exposed end sits outside every other cap, so each cap open
  // across the point has ended at an exposed leaving end before an exposed entering one
  // begins: leaving first, as at a point found exactly (a rounded order that put an entering
  // end first ran the exposed arc from the leaving end all the way round to the next point).
  const auto close = [&](const Exposed& a, const Exposed& b, double turn) {
    return std::fabs(b.theta + turn - a.theta) <= ends[a.end].margin + ends[b.end].margin;
  };
  bool merged = false;
  for (std::size_t k = 1; k < exposed.size(); ++k)
    if (exposed[k].theta != exposed[k - 1].theta && close(exposed[k - 1], exposed[k], 0)) {
      exposed[k].theta = exposed[k - 1].theta;
      merged = true;
    }
  // Across the start of the angles: the last ends join the first point.
  for (std::size_t k = exposed.size(); k-- > 1 && exposed[k].theta != exposed[0].theta &&
                                       close(exposed[k], exposed[0], kTurn);) {
    exposed[k].theta = exposed[0].theta;
    merged = true;
  }
  if (merged) {
    for (const Exposed& e : exposed) theta[e.end] = e.theta;
    std::sort(exposed.begin(), exposed.end(), by_angle);
  }
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
      delta = b > a ? 0 : kTwoPi;  // one exposed point, or all the way round back to it
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

}  // namespace molsurf::arrangement
