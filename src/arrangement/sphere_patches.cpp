// Step 4 of the arrangement on one sphere: the exposed arcs joined into cycles at their
// vertices, the cycles grouped into patches (the connected exposed regions of the sphere:
// cycles on each other's exposed side with no third between), each patch's area by
// Stokes' theorem and its vector area (arc_integrals.hpp), and the keys on its boundary
// that join it into shells.
#include "arrangement/sphere_arranger.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace molsurf::arrangement {

namespace {

double clearance_from_circles(const SphereResult& out, const Vec3& q) {
  double clearance = 2;
  for (const Cap& cap : out.caps) clearance = std::min(clearance, std::fabs(dot(cap.frame.n, q) - cap.frame.c0));
  return clearance;
}

double cycle_integral(const SphereResult& out, const std::vector<std::uint32_t>& cycle, const Vec3& p) {
  double sum = 0;
  for (std::uint32_t a : cycle) {
    const LocalArc& arc = out.arcs[a];
    sum += arrangement::pole_form_integral(out.caps[arc.cap].frame, p, arc.theta, -arc.delta);
  }
  return sum;
}

// A cycle of arcs of length zero is a single exposed point (where four or more spheres
// meet and nothing around is exposed): it bounds no area and joins no shells.
void drop_point_cycles(std::vector<std::vector<std::uint32_t>>& cycles, SphereResult& out) {
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
double single_pole_area(const SphereResult& out) {
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

// The area on the exposed side of a cycle (unit sphere), taking the pole's antipode in a
// cap on the cycle's other side, as far from the cycle's circles as the caps allow.
double cycle_area(const SphereResult& out, const std::vector<std::uint32_t>& cycle) {
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

// Cycles a and b bound the same exposed region when each lies on the other's exposed
// side and no third cycle separates them (the regions and cycles of a sphere form a tree).
void group_cycles(double r2, const std::vector<std::vector<std::uint32_t>>& cycles, SphereResult& out) {
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

}  // namespace

// Steps 4 and 5 on one sphere: area, vector area, cycles and patches.
void SphereArranger::measure(std::uint32_t i, SphereResult& out) const {
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

// The boundary keys of each patch: its arcs' vertices and whole circles.
void SphereArranger::add_keys(std::uint32_t i, SphereResult& out) const {
  for (const LocalArc& arc : out.arcs) {
    std::vector<Key>& keys = out.patches[arc.patch].keys;
    if (arc.whole) {
      keys.push_back(circle_key(i, out.caps[arc.cap].other));
    } else {
      keys.push_back(arc.from);
    }
  }
}

}  // namespace molsurf::arrangement
