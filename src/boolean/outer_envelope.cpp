#include "boolean/outer_envelope.hpp"

#include <algorithm>
#include <array>
#include <gmpxx.h>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "boolean/intersect.hpp"
#include "geometry/predicates.hpp"
#include "mesh/topology.hpp"

namespace molsurf::boolean_engine {

namespace {

using QVec = std::array<mpq_class, 3>;

QVec minus(const QVec& a, const QVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
mpq_class dot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
QVec cross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// sign det[t, a, b] = sign t . (a x b): +1 when b lies counter-clockwise of a around t.
int turn(const QVec& t, const QVec& a, const QVec& b) { return sgn(dot(t, cross(a, b))); }

// Sign of X . v for the perturbed direction X = (1, e, e^2): the first nonzero component.
int lex_sign(int x, int y, int z) { return x != 0 ? x : (y != 0 ? y : z); }

// Compares the unit vectors a/|a| and b/|b| lexicographically (x, then y, then z), that is
// X . a/|a| against X . b/|b|: -1, 0 or +1. Exact: squares instead of square roots.
int compare_directions(const QVec& a, const QVec& b) {
  const mpq_class aa = dot(a, a), bb = dot(b, b);
  for (int k = 0; k < 3; ++k) {
    const int sa = sgn(a[k]), sb = sgn(b[k]);
    if (sa != sb) return sa < sb ? -1 : 1;
    if (sa == 0) continue;
    const int c = cmp(a[k] * a[k] * bb, b[k] * b[k] * aa);  // |a_k|/|a| against |b_k|/|b|
    if (c != 0) return (c < 0 ? -1 : 1) * sa;
  }
  return 0;
}

// Exact rational coordinates of arrangement points, computed on first use.
class ExactPoints {
 public:
  explicit ExactPoints(const Arrangement& arr) : arr_(arr), value_(arr.points.size()), known_(arr.points.size(), 0) {}
  const QVec& operator[](std::uint32_t p) {
    if (!known_[p]) {
      const geometry::ExactPoint e = arr_.points[p].exact();
      value_[p] = {e.x, e.y, e.z};
      known_[p] = 1;
    }
    return value_[p];
  }

 private:
  const Arrangement& arr_;
  std::vector<QVec> value_;
  std::vector<std::uint8_t> known_;
};

// Lexicographic order of two points (x, then y, then z): -1, 0 or +1.
int compare_points(const Arrangement& arr, ExactPoints& exact, std::uint32_t p, std::uint32_t q) {
  if (p == q) return 0;
  const geometry::ImplicitPoint &a = arr.points[p], &b = arr.points[q];
  for (int axis = 0; axis < 3; ++axis) {
    if (a.is_explicit() && b.is_explicit()) {
      const double x = a.explicit_value()[axis], y = b.explicit_value()[axis];
      if (x != y) return x < y ? -1 : 1;
      continue;
    }
    const geometry::Interval &i = a.coordinate(axis), &j = b.coordinate(axis);
    if (i.hi < j.lo) return -1;
    if (i.lo > j.hi) return 1;
    if (const int c = cmp(exact[p][axis], exact[q][axis]); c != 0) return c < 0 ? -1 : 1;
  }
  return 0;
}

struct OrientedPiece {
  std::uint32_t sub_face;
  int back;  // 0: seen from the side its normal points to, 1: from the other side
};

class Flood {
 public:
  Flood(const Operands& ops, const Arrangement& arr, const std::vector<SubFace>& subs,
        const std::vector<std::uint8_t>& live)
      : ops_(ops), arr_(arr), subs_(subs), exact_(arr), seen_(subs.size(), 0) {
    for (std::uint32_t s = 0; s < subs.size(); ++s) {
      if (!live[s]) continue;
      const auto& p = subs[s].points;
      for (int i = 0; i < 3; ++i) around_[undirected_edge_key(p[i], p[(i + 1) % 3])].push_back(s);
    }
  }

  const std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>& pieces_by_edge() const { return around_; }
  // Bit 1: seen from the normal side, bit 2: from the back.
  std::uint8_t seen(std::uint32_t s) const { return seen_[s]; }
  ExactPoints& exact() { return exact_; }

  // The lexicographically largest point of some pieces.
  std::uint32_t extreme_point(const std::vector<std::uint32_t>& pieces) {
    std::uint32_t best = subs_[pieces.front()].points[0];
    for (std::uint32_t s : pieces)
      for (std::uint32_t p : subs_[s].points)
        if (compare_points(arr_, exact_, p, best) > 0) best = p;
    return best;
  }

  // A piece of the envelope at the extreme point v of `pieces`, seen from outside.
  OrientedPiece seed(const std::vector<std::uint32_t>& pieces, std::uint32_t v) {
    // The edge at v whose direction is closest to X = (1, e, e^2). Every other point is
    // lexicographically below v, so X . d < 0 for each edge direction d, and over a face
    // at v the largest X . d/|d| is at one of its edges: this edge is on the envelope.
    const QVec pv = exact_[v];
    std::uint32_t best_w = ~0u;
    QVec best_d;
    for (std::uint32_t s : pieces) {
      const auto& p = subs_[s].points;
      for (int i = 0; i < 3; ++i) {
        if (p[i] != v) continue;
        for (std::uint32_t w : {p[(i + 1) % 3], p[(i + 2) % 3]}) {
          if (w == best_w) continue;
          QVec d = minus(exact_[w], pv);
          const int c = best_w == ~0u ? 1 : compare_directions(d, best_d);
          if (c == 0) throw std::logic_error("outer envelope: two edges leave the extreme point in one direction");
          if (c > 0) {
            best_w = w;
            best_d = std::move(d);
          }
        }
      }
    }
    // Around that edge, the piece whose half-plane is closest to X's component
    // perpendicular to the edge bounds the sector X points into (the outside).
    const QVec& t = best_d;
    const mpq_class tt = dot(t, t);
    std::uint32_t best_s = ~0u;
    QVec best_h;
    for (std::uint32_t s : around_.at(undirected_edge_key(v, best_w))) {
      const QVec u = minus(exact_[wing(s, v, best_w)], pv);
      const mpq_class ut = dot(u, t);
      QVec h{tt * u[0] - ut * t[0], tt * u[1] - ut * t[1], tt * u[2] - ut * t[2]};  // tt * (u without its t part)
      const int c = best_s == ~0u ? 1 : compare_directions(h, best_h);
      if (c == 0) throw std::logic_error("outer envelope: two pieces share a half-plane at the extreme edge");
      if (c > 0) {
        best_s = s;
        best_h = std::move(h);
      }
    }
    // Seen from the side of X: the sign of X . normal (the piece's normal is its source face's).
    const auto& f = ops_.face(subs_[best_s].face);
    const Vec3 &a = ops_.vertex(f[0]), &b = ops_.vertex(f[1]), &c = ops_.vertex(f[2]);
    const int side = lex_sign(geometry::normal_sign_x(a, b, c), geometry::normal_sign_y(a, b, c),
                              geometry::normal_sign_z(a, b, c));
    return {best_s, side > 0 ? 0 : 1};
  }

  // Every oriented piece reachable from `start`; returns false when it was reached before.
  bool fill(OrientedPiece start) {
    if (!mark(start)) return false;
    std::vector<OrientedPiece> queue{start};
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const OrientedPiece o = queue[k];
      std::array<std::uint32_t, 3> c = subs_[o.sub_face].points;
      if (o.back) std::swap(c[1], c[2]);
      for (int i = 0; i < 3; ++i) {
        const OrientedPiece next = next_around(o.sub_face, c[i], c[(i + 1) % 3], c[(i + 2) % 3]);
        if (mark(next)) queue.push_back(next);
      }
    }
    return true;
  }

 private:
  bool mark(OrientedPiece o) {
    const auto bit = static_cast<std::uint8_t>(1u << o.back);
    if (seen_[o.sub_face] & bit) return false;
    seen_[o.sub_face] |= bit;
    return true;
  }

  std::uint32_t wing(std::uint32_t s, std::uint32_t a, std::uint32_t b) const {
    for (std::uint32_t p : subs_[s].points)
      if (p != a && p != b) return p;
    return ~0u;
  }

  // Whether piece s, as stored, runs from a to b.
  bool runs(std::uint32_t s, std::uint32_t a, std::uint32_t b) const {
    const auto& p = subs_[s].points;
    for (int i = 0; i < 3; ++i)
      if (p[i] == a) return p[(i + 1) % 3] == b;
    return false;
  }

  // The oriented piece s runs a -> b with wing w, so its outer side is counter-clockwise of
  // it around t = b - a (its normal is t x (w - a)). Sweeping that way, the first piece met
  // bounds the same outer sector; it must run b -> a to face the sector.
  OrientedPiece next_around(std::uint32_t s, std::uint32_t a, std::uint32_t b, std::uint32_t w) {
    const std::vector<std::uint32_t>& pieces = around_.at(undirected_edge_key(a, b));
    std::uint32_t g = s;  // a free edge: the same piece, from its other side
    if (pieces.size() == 2) {
      g = pieces[0] == s ? pieces[1] : pieces[0];
    } else if (pieces.size() > 2) {
      const QVec& pa = exact_[a];
      const QVec t = minus(exact_[b], pa), ref = minus(exact_[w], pa);
      const mpq_class tt = dot(t, t), ref_t = dot(ref, t);
      QVec best_u;
      bool best_upper = false;
      g = ~0u;
      for (std::uint32_t h : pieces) {
        if (h == s) continue;
        QVec u = minus(exact_[wing(h, a, b)], pa);
        const int sine = turn(t, ref, u);
        if (sine == 0 && sgn(tt * dot(ref, u) - ref_t * dot(u, t)) > 0)
          throw std::logic_error("outer envelope: two pieces overlap around an edge");
        const bool upper = sine > 0;  // angle in (0, pi); else [pi, 2 pi)
        bool better = g == ~0u || (upper && !best_upper);
        if (!better && upper == best_upper) {
          const int order = turn(t, u, best_u);
          if (order == 0) throw std::logic_error("outer envelope: two pieces overlap around an edge");
          better = order > 0;
        }
        if (better) {
          g = h;
          best_u = std::move(u);
          best_upper = upper;
        }
      }
    }
    return {g, runs(g, a, b) ? 1 : 0};
  }

  const Operands& ops_;
  const Arrangement& arr_;
  const std::vector<SubFace>& subs_;
  ExactPoints exact_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> around_;
  std::vector<std::uint8_t> seen_;
};

// Whether the ray from point `u` along X = (1, e, e^2) crosses piece s. The point is not
// on the piece; the perturbed ray meets no edge or vertex, so neighbours agree.
bool ray_crosses(const Operands& ops, const Arrangement& arr, const SubFace& s, const geometry::ImplicitPoint& u) {
  const auto& f = ops.face(s.face);
  const Vec3 &a = ops.vertex(f[0]), &b = ops.vertex(f[1]), &c = ops.vertex(f[2]);
  // The ray moves in x (and infinitesimally in y, z): a face strictly behind or beside it is not met.
  const double max_x = std::max({a.x, b.x, c.x});
  const double min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  const double min_z = std::min({a.z, b.z, c.z}), max_z = std::max({a.z, b.z, c.z});
  if (max_x < u.coordinate(0).lo || max_y < u.coordinate(1).lo || min_y > u.coordinate(1).hi ||
      max_z < u.coordinate(2).lo || min_z > u.coordinate(2).hi)
    return false;
  // Ahead: u is on the side of the plane that X points away from. On the plane: the
  // ray leaves it at once (X is in no plane), so it meets nothing there.
  const int side = geometry::orient3d(a, b, c, u);
  const int toward = lex_sign(geometry::normal_sign_x(a, b, c), geometry::normal_sign_y(a, b, c),
                              geometry::normal_sign_z(a, b, c));
  if (side == 0 || side == toward) return false;
  // The line u + X r passes inside the piece when X . ((p - u) x (q - u)) has one sign
  // over its three edges pq (u is off the plane, so no such vector is zero).
  auto edge_sign = [&](std::uint32_t p, std::uint32_t q) {
    const geometry::ImplicitPoint &pp = arr.points[p], &pq = arr.points[q];
    return lex_sign(geometry::orient2d(u, pp, pq, 1, 2), geometry::orient2d(u, pp, pq, 2, 0),
                    geometry::orient2d(u, pp, pq, 0, 1));
  };
  const int first = edge_sign(s.points[0], s.points[1]);
  return edge_sign(s.points[1], s.points[2]) == first && edge_sign(s.points[2], s.points[0]) == first;
}

}  // namespace

EnvelopeSelection select_outer_envelope(const Operands& ops, const Arrangement& arr, const SplitResult& split) {
  const std::vector<SubFace>& subs = split.sub_faces;
  const auto n = static_cast<std::uint32_t>(subs.size());
  EnvelopeSelection result;
  result.keep.assign(n, Keep::drop);

  // A coincident piece is one sheet with a's copy: b's goes.
  std::vector<std::uint8_t> live(n, 1);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (ops.operand_of_face(subs[s].face) != 1) continue;
    for (const Arrangement::Partner& partner : arr.coplanar_partners[subs[s].face])
      if (inside_partner(ops, arr, subs[s], partner.face)) {
        live[s] = 0;
        break;
      }
  }

  Flood flood(ops, arr, subs, live);
  // Components: pieces joined across edges; numbered by their lowest piece.
  DisjointSets sets(n);
  for (const auto& [key, pieces] : flood.pieces_by_edge())
    for (std::size_t k = 1; k < pieces.size(); ++k) sets.unite(pieces[0], pieces[k]);
  std::vector<std::uint32_t> component_of_root(n, ~0u);
  std::vector<std::vector<std::uint32_t>> members;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (!live[s]) continue;
    std::uint32_t& c = component_of_root[sets.find(s)];
    if (c == ~0u) {
      c = static_cast<std::uint32_t>(members.size());
      members.emplace_back();
    }
    members[c].push_back(s);
  }
  const auto count = static_cast<std::uint32_t>(members.size());
  result.components = count;

  // Points used by more than one component (where components touch).
  constexpr std::uint32_t none = ~0u, several = ~0u - 1;
  std::vector<std::uint32_t> owner(arr.points.size(), none);
  for (std::uint32_t c = 0; c < count; ++c)
    for (std::uint32_t s : members[c])
      for (std::uint32_t p : subs[s].points) owner[p] = owner[p] == none || owner[p] == c ? c : several;

  // A component can only be enclosed by one reaching further along X: take them in
  // order of decreasing extreme point.
  std::vector<std::uint32_t> extreme(count), order(count);
  for (std::uint32_t c = 0; c < count; ++c) extreme[c] = flood.extreme_point(members[c]);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    return compare_points(arr, flood.exact(), extreme[x], extreme[y]) > 0;
  });
  std::vector<std::uint32_t> one_sided;  // kept pieces seen from one side: the envelopes so far
  for (std::uint32_t c : order) {
    if (!one_sided.empty()) {
      std::uint32_t probe = none;
      for (std::size_t k = 0; k < members[c].size() && probe == none; ++k)
        for (std::uint32_t p : subs[members[c][k]].points)
          if (owner[p] == c) {
            probe = p;
            break;
          }
      if (probe == none)
        throw std::logic_error("outer envelope: a component has no point of its own to test for enclosure");
      bool inside = false;
      for (std::uint32_t s : one_sided) inside ^= ray_crosses(ops, arr, subs[s], arr.points[probe]);
      if (inside) continue;
    }
    flood.fill(flood.seed(members[c], extreme[c]));
    ++result.components_kept;
    for (std::uint32_t s : members[c]) {
      const std::uint8_t seen = flood.seen(s);
      if (seen == 1 || seen == 2) one_sided.push_back(s);
    }
  }

  for (std::uint32_t s = 0; s < n; ++s) {
    const std::uint8_t seen = flood.seen(s);
    if (seen == 0) continue;
    result.keep[s] = seen == 2 ? Keep::keep_flipped : Keep::keep;
    result.two_sided_faces += seen == 3;
  }
  return result;
}

}  // namespace molsurf::boolean_engine
