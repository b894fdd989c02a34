#include "geometry/triangle_intersection.hpp"

#include <algorithm>

#include <array>

#include "geometry/predicates.hpp"

namespace molsurf::geometry {

namespace {

struct Point2 {
  double x, y;
};

// Which coordinate a coplanar configuration is projected along. Dropping axis k keeps
// the orientation sign equal to the sign of the normal's k-th component (the cyclic
// order (y,z), (z,x), (x,y) matches normal_sign_x / _y / _z).
enum class DroppedAxis { x, y, z };

Point2 project(const Vec3& v, DroppedAxis axis) {
  switch (axis) {
    case DroppedAxis::x: return {v.y, v.z};
    case DroppedAxis::y: return {v.z, v.x};
    case DroppedAxis::z: break;
  }
  return {v.x, v.y};
}

int orient(const Point2& a, const Point2& b, const Point2& c) {
  return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

// An axis along which the triangle's normal is exactly nonzero, so the projection is a
// proper triangle. A degenerate triangle has none; z is returned and callers get an
// unspecified (but safe) answer.
DroppedAxis projection_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  if (normal_sign_z(a, b, c) != 0) return DroppedAxis::z;
  if (normal_sign_x(a, b, c) != 0) return DroppedAxis::x;
  if (normal_sign_y(a, b, c) != 0) return DroppedAxis::y;
  return DroppedAxis::z;
}

// Lexicographic order: along a line it is the order of the points on the line (or its
// reverse), which is all a collinear overlap test needs.
bool lex_less(const Point2& a, const Point2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

bool segments_meet_2d(const Point2& p, const Point2& q, const Point2& a, const Point2& b) {
  const int oa = orient(p, q, a), ob = orient(p, q, b);
  if (oa * ob > 0) return false;
  const int op = orient(a, b, p), oq = orient(a, b, q);
  if (op * oq > 0) return false;
  if (oa != 0 || ob != 0 || op != 0 || oq != 0) return true;
  // All four collinear: the closed intervals along the line must overlap.
  const Point2& pq_lo = lex_less(q, p) ? q : p;
  const Point2& pq_hi = lex_less(q, p) ? p : q;
  const Point2& ab_lo = lex_less(b, a) ? b : a;
  const Point2& ab_hi = lex_less(b, a) ? a : b;
  return !lex_less(pq_hi, ab_lo) && !lex_less(ab_hi, pq_lo);
}

// `sign` is the orientation of abc (nonzero).
bool in_closed_triangle_2d(const Point2& p, const Point2& a, const Point2& b, const Point2& c, int sign) {
  return sign * orient(a, b, p) >= 0 && sign * orient(b, c, p) >= 0 && sign * orient(c, a, p) >= 0;
}

bool segment_meets_triangle_2d(const Point2& p, const Point2& q, const Point2& a, const Point2& b,
                               const Point2& c) {
  const int sign = orient(a, b, c);
  if (sign == 0) return false;  // degenerate triangle: outside the contract
  if (in_closed_triangle_2d(p, a, b, c, sign) || in_closed_triangle_2d(q, a, b, c, sign)) return true;
  // Both endpoints outside: the segment meets the triangle iff it meets its boundary.
  return segments_meet_2d(p, q, a, b) || segments_meet_2d(p, q, b, c) || segments_meet_2d(p, q, c, a);
}

// Whether the line through edge (e0, e1) of a triangle with orientation `sign` weakly
// separates the triangle from the points `other` (all in the closed outer half-plane).
bool edge_line_separates(const Point2& e0, const Point2& e1, int sign, const std::array<Point2, 3>& other) {
  for (const Point2& x : other)
    if (sign * orient(e0, e1, x) > 0) return false;
  return true;
}

// How two coplanar triangles with overlapping interiors face each other.
enum class CoplanarOverlap { none, same_facing, opposite_facing };

// Coplanar triangles: their interiors overlap (positive-area intersection) iff no edge
// line of either triangle weakly separates them. This is the separating-axis theorem for
// convex polygons: the Minkowski difference's edge normals are the two triangles' edge
// normals, so if the interiors are disjoint one of those six lines separates.
// Facing: both are projected along the same axis, so equal projected orientations mean
// equal normals.
CoplanarOverlap coplanar_interiors_overlap(const std::array<Vec3, 3>& t1, const std::array<Vec3, 3>& t2) {
  const DroppedAxis axis = projection_axis(t1[0], t1[1], t1[2]);
  const std::array<Point2, 3> u{project(t1[0], axis), project(t1[1], axis), project(t1[2], axis)};
  const std::array<Point2, 3> v{project(t2[0], axis), project(t2[1], axis), project(t2[2], axis)};
  const int su = orient(u[0], u[1], u[2]), sv = orient(v[0], v[1], v[2]);
  if (su == 0 || sv == 0) return CoplanarOverlap::none;
  for (int k = 0; k < 3; ++k) {
    if (edge_line_separates(u[k], u[(k + 1) % 3], su, v)) return CoplanarOverlap::none;
    if (edge_line_separates(v[k], v[(k + 1) % 3], sv, u)) return CoplanarOverlap::none;
  }
  return su == sv ? CoplanarOverlap::same_facing : CoplanarOverlap::opposite_facing;
}

std::array<Vec3, 3> corners(const Mesh& mesh, const Triangle& t) {
  return {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
}

// Strictly positive product: both strictly on the same side.
bool strictly_same_side(int s, int t) { return s * t > 0; }

TrianglePairRelation classify_shared_edge(const Vec3& u, const Vec3& v, const Vec3& a, const Vec3& b) {
  if (orient3d(u, v, a, b) != 0) return TrianglePairRelation::apart;
  const DroppedAxis axis = projection_axis(u, v, a);
  const Point2 pu = project(u, axis), pv = project(v, axis);
  const int side_a = orient(pu, pv, project(a, axis));
  const int side_b = orient(pu, pv, project(b, axis));
  return strictly_same_side(side_a, side_b) ? TrianglePairRelation::intersecting : TrianglePairRelation::apart;
}

TrianglePairRelation classify_shared_vertex(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c,
                                            const Vec3& d) {
  const int side_c = orient3d(v, a, b, c), side_d = orient3d(v, a, b, d);
  if (strictly_same_side(side_c, side_d)) return TrianglePairRelation::apart;
  if (strictly_same_side(orient3d(v, c, d, a), orient3d(v, c, d, b))) return TrianglePairRelation::apart;
  const SegmentTriangleMeeting ab_in_t2 = segment_meets_triangle(a, b, v, c, d);
  const SegmentTriangleMeeting cd_in_t1 = segment_meets_triangle(c, d, v, a, b);
  if (!ab_in_t2.meets && !cd_in_t1.meets) return TrianglePairRelation::apart;
  // They meet beyond v. Only an opposite edge can cross the other face properly (an edge
  // through v starts on the other face's plane).
  if (ab_in_t2.proper || cd_in_t1.proper) return TrianglePairRelation::intersecting;
  if (side_c == 0 && side_d == 0 &&
      coplanar_interiors_overlap({v, a, b}, {v, c, d}) == CoplanarOverlap::same_facing)
    return TrianglePairRelation::intersecting;
  // Touching along a segment from v (e.g. where a Boolean result's sheets touch along
  // an edge that ends where they join), or coplanar faces pressed face to face.
  return TrianglePairRelation::contact;
}

TrianglePairRelation classify_disjoint_indices(const std::array<Vec3, 3>& t1, const std::array<Vec3, 3>& t2) {
  // Cheapest rejection: closed boxes apart (comparisons of doubles, exact). Callers with a
  // coarse spatial index (the cleanup's hash grid) hand over many such pairs.
  for (int axis = 0; axis < 3; ++axis) {
    const double lo1 = std::min({t1[0][axis], t1[1][axis], t1[2][axis]});
    const double hi1 = std::max({t1[0][axis], t1[1][axis], t1[2][axis]});
    const double lo2 = std::min({t2[0][axis], t2[1][axis], t2[2][axis]});
    const double hi2 = std::max({t2[0][axis], t2[1][axis], t2[2][axis]});
    if (hi1 < lo2 || hi2 < lo1) return TrianglePairRelation::apart;
  }
  // Then one triangle strictly on one side of the other's plane.
  std::array<int, 3> side_of_t2{}, side_of_t1{};
  for (int k = 0; k < 3; ++k) side_of_t2[k] = orient3d(t1[0], t1[1], t1[2], t2[k]);
  if (strictly_same_side(side_of_t2[0], side_of_t2[1]) && strictly_same_side(side_of_t2[1], side_of_t2[2]))
    return TrianglePairRelation::apart;
  for (int k = 0; k < 3; ++k) side_of_t1[k] = orient3d(t2[0], t2[1], t2[2], t1[k]);
  if (strictly_same_side(side_of_t1[0], side_of_t1[1]) && strictly_same_side(side_of_t1[1], side_of_t1[2]))
    return TrianglePairRelation::apart;

  bool meets = false, proper = false;
  for (int k = 0; k < 3; ++k) {
    const SegmentTriangleMeeting m1 = segment_meets_triangle(t1[k], t1[(k + 1) % 3], t2[0], t2[1], t2[2]);
    const SegmentTriangleMeeting m2 = segment_meets_triangle(t2[k], t2[(k + 1) % 3], t1[0], t1[1], t1[2]);
    meets = meets || m1.meets || m2.meets;
    proper = proper || m1.proper || m2.proper;
  }
  if (!meets) return TrianglePairRelation::apart;
  if (proper) return TrianglePairRelation::intersecting;
  const bool coplanar = side_of_t2[0] == 0 && side_of_t2[1] == 0 && side_of_t2[2] == 0;
  // Overlapping coplanar faces that face the same way put both solids on the same side:
  // their volumes overlap. Facing opposite ways, the solids lie on opposite sides and
  // only touch (two solids pressed face to face).
  if (coplanar && coplanar_interiors_overlap(t1, t2) == CoplanarOverlap::same_facing)
    return TrianglePairRelation::intersecting;
  return TrianglePairRelation::contact;
}

}  // namespace

SegmentTriangleMeeting segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                              const Vec3& c) {
  const int side_p = orient3d(a, b, c, p);
  const int side_q = orient3d(a, b, c, q);
  if (strictly_same_side(side_p, side_q)) return {};
  if (side_p != 0 || side_q != 0) {
    const int e_ab = orient3d(p, q, a, b), e_bc = orient3d(p, q, b, c), e_ca = orient3d(p, q, c, a);
    const bool meets = (e_ab >= 0 && e_bc >= 0 && e_ca >= 0) || (e_ab <= 0 && e_bc <= 0 && e_ca <= 0);
    const bool proper = side_p * side_q < 0 && e_ab != 0 && e_ab == e_bc && e_bc == e_ca;
    return {meets, proper};
  }
  const DroppedAxis axis = projection_axis(a, b, c);
  return {segment_meets_triangle_2d(project(p, axis), project(q, axis), project(a, axis), project(b, axis),
                                    project(c, axis)),
          false};
}

bool is_degenerate_face(const Mesh& mesh, std::size_t face) {
  const Triangle& t = mesh.faces[face];
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
  return collinear3d(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

TrianglePairRelation classify_triangle_pair(const Mesh& mesh, std::size_t face_i, std::size_t face_j) {
  return classify_triangle_pair(mesh, mesh.faces[face_i], mesh.faces[face_j]);
}

namespace {

// The vertex indices two faces share: position_in_j[k] is where corner k of face i occurs
// in face j, or -1.
struct SharedCorners {
  std::array<int, 3> position_in_j{-1, -1, -1};
  int count = 0;
  int first_shared() const {
    int k = 0;
    while (position_in_j[k] < 0) ++k;
    return k;
  }
};

SharedCorners shared_corners(const Triangle& ti, const Triangle& tj) {
  SharedCorners s;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      if (ti[k] == tj[l]) {
        s.position_in_j[k] = l;
        ++s.count;
      }
  return s;
}

}  // namespace

TrianglePairRelation classify_triangle_pair(const Mesh& mesh, const Triangle& ti, const Triangle& tj) {
  const SharedCorners shared = shared_corners(ti, tj);
  const auto& position_in_j = shared.position_in_j;
  const auto& vs = mesh.vertices;
  switch (shared.count) {
    case 0: return classify_disjoint_indices(corners(mesh, ti), corners(mesh, tj));
    case 1: {
      const int k = shared.first_shared();
      const int l = position_in_j[k];
      return classify_shared_vertex(vs[ti[k]], vs[ti[(k + 1) % 3]], vs[ti[(k + 2) % 3]], vs[tj[(l + 1) % 3]],
                                    vs[tj[(l + 2) % 3]]);
    }
    case 2: {
      int k = 0;  // the corner of face i that is not shared
      while (position_in_j[k] >= 0) ++k;
      const int l = 3 - position_in_j[(k + 1) % 3] - position_in_j[(k + 2) % 3];  // same in face j
      return classify_shared_edge(vs[ti[(k + 1) % 3]], vs[ti[(k + 2) % 3]], vs[ti[k]], vs[tj[l]]);
    }
    default: return TrianglePairRelation::duplicate;
  }
}

bool folded_flat(const Mesh& mesh, const Triangle& ti, const Triangle& tj) {
  const SharedCorners shared = shared_corners(ti, tj);
  if (shared.count != 1) return false;
  const int k = shared.first_shared(), l = shared.position_in_j[k];
  const auto& vs = mesh.vertices;
  const Vec3 &v = vs[ti[k]], &a = vs[ti[(k + 1) % 3]], &b = vs[ti[(k + 2) % 3]];
  const Vec3 &c = vs[tj[(l + 1) % 3]], &d = vs[tj[(l + 2) % 3]];
  if (orient3d(v, a, b, c) != 0 || orient3d(v, a, b, d) != 0) return false;
  return coplanar_interiors_overlap({v, a, b}, {v, c, d}) == CoplanarOverlap::opposite_facing;
}

}  // namespace molsurf::geometry
