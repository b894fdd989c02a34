#include "boolean/intersect.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/predicates.hpp"

namespace molsurf::boolean_engine {

using geometry::orient2d;
using geometry::orient3d;

Projection face_projection(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Prefer the largest normal component (best conditioned); its exact sign decides the
  // orientation. The cyclic axis pairs (y,z), (z,x), (x,y) make that sign the 2D one.
  const Vec3 n = cross(b - a, c - a);
  const double magnitude[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return magnitude[i] > magnitude[j]; });
  for (int k : order) {
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    const int s = orient2d(a[u], a[v], b[u], b[v], c[u], c[v]);
    if (s > 0) return {u, v};
    if (s < 0) return {v, u};
  }
  throw std::invalid_argument("boolean: a degenerate (zero-area) face in an operand");
}

namespace {

struct Face {
  std::array<std::uint32_t, 3> vertex;
  std::array<std::uint32_t, 3> edge;
  std::array<Vec3, 3> p;
};

Face load_face(const Operands& ops, std::uint32_t f) {
  Face face{ops.face(f), ops.face_edges(f), {}};
  for (int i = 0; i < 3; ++i) face.p[i] = ops.vertex(face.vertex[i]);
  return face;
}

int orient2d_projected(const Vec3& a, const Vec3& b, const Vec3& c, const Projection& pr) {
  return orient2d(a[pr.u], a[pr.v], b[pr.u], b[pr.v], c[pr.u], c[pr.v]);
}

// A point in the plane of triangle t (exactly), located in the closed triangle.
bool locate_in_plane(const Vec3& x, const Face& t, const Projection& pr, Location& where) {
  const std::array<int, 3> s = {orient2d_projected(t.p[0], t.p[1], x, pr),
                                orient2d_projected(t.p[1], t.p[2], x, pr),
                                orient2d_projected(t.p[2], t.p[0], x, pr)};
  return locate_from_signs(s, where);
}

class PairBuilder {
 public:
  PairBuilder(const Operands& ops, std::uint32_t fa, std::uint32_t fb) : ops_(ops) {
    result_.face_a = fa;
    result_.face_b = fb;
  }

  // A point of a's face `at_a` (as seen from a) and b's face `at_b`.
  void add(const PointKey& key, Location at_a, Location at_b) {
    for (const PairPoint& p : result_.points)
      if (p.key == key) return;
    result_.points.push_back({key, at_a, at_b});
  }

  // Key of a vertex of one face located on the other face; coincident vertices are keyed
  // by a's vertex and remembered.
  PointKey vertex_key(std::uint32_t v, int operand, const Location& on_other, const Face& other) {
    if (on_other.where == Where::corner) {
      const std::uint32_t w = other.vertex[on_other.index];
      const std::uint32_t va = operand == 0 ? v : w, vb = operand == 0 ? w : v;
      result_.coincident_vertices.emplace_back(va, vb);
      return {PointKind::vertex, va, 0};
    }
    return {PointKind::vertex, v, 0};
  }

  PairIntersection& result() { return result_; }

 private:
  const Operands& ops_;
  PairIntersection result_;
};

PointKey edge_point_key(std::uint32_t edge_of_self, int self_operand, const Location& on_other, const Face& other,
                        std::uint32_t other_face) {
  switch (on_other.where) {
    case Where::interior:
      return {PointKind::edge_face, edge_of_self, other_face};
    case Where::edge: {
      const std::uint32_t e_other = other.edge[on_other.index];
      return self_operand == 0 ? PointKey{PointKind::edge_edge, edge_of_self, e_other}
                               : PointKey{PointKind::edge_edge, e_other, edge_of_self};
    }
    case Where::corner:
      return {PointKind::vertex, other.vertex[on_other.index], 0};
  }
  return {};
}

// Non-coplanar pair: edges of `self` crossing the other's plane, and vertices of `self`
// lying in it, located on the other face.
void collect_crossings(PairBuilder& out, int self_operand, const Face& self, const int side[3], const Face& other,
                       std::uint32_t other_face, const Projection& other_projection) {
  auto emit = [&](const PointKey& key, Location on_self, Location on_other) {
    if (self_operand == 0)
      out.add(key, on_self, on_other);
    else
      out.add(key, on_other, on_self);
  };
  for (int i = 0; i < 3; ++i) {
    if (side[i] == 0) {
      Location where;
      if (locate_in_plane(self.p[i], other, other_projection, where)) {
        const PointKey key = out.vertex_key(self.vertex[i], self_operand, where, other);
        emit(key, {Where::corner, static_cast<std::uint8_t>(i)}, where);
      }
    }
    const int j = (i + 1) % 3;
    if (side[i] * side[j] < 0) {
      Location where;
      if (locate_crossing(self.p[i], self.p[j], other.p, where)) {
        const PointKey key = edge_point_key(self.edge[i], self_operand, where, other, other_face);
        emit(key, {Where::edge, static_cast<std::uint8_t>(i)}, where);
      }
    }
  }
}

// Coplanar pair, in a's projection: vertices of each inside the other, and proper
// crossings of their edges.
void collect_coplanar(PairBuilder& out, const Face& a, const Face& b, std::uint32_t fa, std::uint32_t fb,
                      const Projection& pr) {
  (void)fa;
  (void)fb;
  // Orientation tests in a's projection; b may be clockwise there (opposite normal).
  auto locate = [&](const Vec3& x, const Face& t, Location& where) {
    std::array<int, 3> s;
    for (int i = 0; i < 3; ++i) s[i] = orient2d_projected(t.p[i], t.p[(i + 1) % 3], x, pr);
    if (orient2d_projected(t.p[0], t.p[1], t.p[2], pr) < 0)
      for (int& v : s) v = -v;
    return locate_from_signs(s, where);
  };
  for (int i = 0; i < 3; ++i) {
    Location where;
    if (locate(a.p[i], b, where))
      out.add(out.vertex_key(a.vertex[i], 0, where, b), {Where::corner, static_cast<std::uint8_t>(i)}, where);
    if (locate(b.p[i], a, where))
      out.add(out.vertex_key(b.vertex[i], 1, where, a), where, {Where::corner, static_cast<std::uint8_t>(i)});
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 &p = a.p[i], &q = a.p[(i + 1) % 3], &r = b.p[j], &s = b.p[(j + 1) % 3];
      const int o1 = orient2d_projected(p, q, r, pr), o2 = orient2d_projected(p, q, s, pr);
      const int o3 = orient2d_projected(r, s, p, pr), o4 = orient2d_projected(r, s, q, pr);
      if (o1 * o2 < 0 && o3 * o4 < 0)
        out.add({PointKind::edge_edge, a.edge[i], b.edge[j]}, {Where::edge, static_cast<std::uint8_t>(i)},
                {Where::edge, static_cast<std::uint8_t>(j)});
    }
}

bool on_edge_of(const Location& loc, int edge) {
  if (loc.where == Where::edge) return loc.index == edge;
  if (loc.where == Where::corner) return loc.index == edge || loc.index == (edge + 1) % 3;
  return false;
}

// Coplanar pair: the parts of `other`'s edges inside `self` become constraints of self.
// The points on one edge of `other` inside the (convex) face lie on one segment.
void coplanar_segments(const Operands& ops, const std::vector<PairPoint>& points, bool self_is_a,
                       std::vector<std::pair<PointKey, PointKey>>& segments) {
  for (int edge = 0; edge < 3; ++edge) {
    std::vector<const PairPoint*> on_edge;
    for (const PairPoint& p : points)
      if (on_edge_of(self_is_a ? p.on_b : p.on_a, edge)) on_edge.push_back(&p);
    if (on_edge.size() < 2) continue;
    if (on_edge.size() > 2) {
      // Order along the edge by the coordinate along which it changes most (exactly).
      std::vector<std::pair<geometry::ImplicitPoint, const PairPoint*>> pts;
      for (const PairPoint* p : on_edge) pts.emplace_back(make_point(ops, p->key), p);
      const Vec3 d = pts.back().first.rounded() - pts.front().first.rounded();
      const int axis = std::fabs(d.x) >= std::fabs(d.y) && std::fabs(d.x) >= std::fabs(d.z) ? 0
                       : std::fabs(d.y) >= std::fabs(d.z)                                 ? 1
                                                                                           : 2;
      std::sort(pts.begin(), pts.end(), [&](const auto& l, const auto& r) {
        return l.first.exact()[axis] < r.first.exact()[axis];
      });
      on_edge.clear();
      for (auto& [point, p] : pts) on_edge.push_back(p);
    }
    for (std::size_t k = 0; k + 1 < on_edge.size(); ++k) segments.emplace_back(on_edge[k]->key, on_edge[k + 1]->key);
  }
}

}  // namespace

PairIntersection intersect_faces(const Operands& ops, std::uint32_t fa, std::uint32_t fb) {
  const Face a = load_face(ops, fa), b = load_face(ops, fb);
  int side_a[3], side_b[3];  // a's corners against b's plane, and b's against a's
  for (int i = 0; i < 3; ++i) side_a[i] = orient3d(b.p[0], b.p[1], b.p[2], a.p[i]);
  auto strictly_one_side = [](const int s[3]) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
  };
  PairBuilder out(ops, fa, fb);
  if (strictly_one_side(side_a)) return std::move(out.result());
  for (int i = 0; i < 3; ++i) side_b[i] = orient3d(a.p[0], a.p[1], a.p[2], b.p[i]);
  if (strictly_one_side(side_b)) return std::move(out.result());

  PairIntersection& r = out.result();
  if (side_a[0] == 0 && side_a[1] == 0 && side_a[2] == 0) {
    const Projection pr = face_projection(a.p[0], a.p[1], a.p[2]);
    r.coplanar = true;
    r.same_orientation = orient2d_projected(b.p[0], b.p[1], b.p[2], pr) > 0;
    collect_coplanar(out, a, b, fa, fb, pr);
    coplanar_segments(ops, r.points, true, r.segments_a);
    coplanar_segments(ops, r.points, false, r.segments_b);
    return std::move(r);
  }
  collect_crossings(out, 0, a, side_a, b, fb, face_projection(b.p[0], b.p[1], b.p[2]));
  collect_crossings(out, 1, b, side_b, a, fa, face_projection(a.p[0], a.p[1], a.p[2]));
  if (r.points.size() > 2)
    throw std::logic_error("boolean: faces " + std::to_string(fa) + " and " + std::to_string(fb) +
                           " meet in more than two points; is an operand self-intersecting?");
  if (r.points.size() == 2) {
    r.segments_a.emplace_back(r.points[0].key, r.points[1].key);
    r.segments_b.emplace_back(r.points[0].key, r.points[1].key);
    auto along_an_edge = [](const Location& p, const Location& q) {
      for (int edge = 0; edge < 3; ++edge)
        if (on_edge_of(p, edge) && on_edge_of(q, edge)) return true;
      return false;
    };
    r.transversal = !along_an_edge(r.points[0].on_a, r.points[1].on_a) &&
                    !along_an_edge(r.points[0].on_b, r.points[1].on_b);
  }
  return std::move(r);
}

}  // namespace molsurf::boolean_engine
