#include "surface/one_pass_union.hpp"

#include <omp.h>
#include <parallel/algorithm>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "boolean/intersect.hpp"
#include "boolean/repair_rounding.hpp"
#include "molsurf/error.hpp"
#include "molsurf/resource_limits.hpp"
#include "boolean/advancing_front.hpp"
#include "boolean/ear_clipping.hpp"
#include "boolean/face_points.hpp"
#include "boolean/split.hpp"
#include "common/parallel_exceptions.hpp"
#include "geometry/implicit_point.hpp"
#include "geometry/predicates.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/point_definition.hpp"

namespace molsurf::surface_detail {

namespace {

using geometry::ImplicitPoint;
using Clock = std::chrono::steady_clock;

// Molecular inputs cross a face with a few traces (each neighbour that reaches it adds one
// or two). Hundreds mean spheres that nearly coincide, whose union's boundary has a number
// of pieces quadratic in them on every face: refused plainly instead of running for hours.
constexpr std::size_t kMaxTracesPerFace = 256;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

BoundingBox box_of(const Vec3& a, const Vec3& b, const Vec3& c) {
  BoundingBox box;
  box.extend(a);
  box.extend(b);
  box.extend(c);
  return box;
}

// A neighbour's polyhedron as the trimmed atom sees it: its faces that can reach the
// trimmed atom's boundary (the lens), with their boxes. Vertices are computed when needed,
// by the same expression as everywhere (the same doubles).
struct Neighbour {
  std::uint32_t atom = 0;
  Vec3 centre;
  double scale = 0, inradius = 0, circumradius = 0;
  const PolyhedronTemplate* shape = nullptr;
  std::vector<std::uint32_t> lens;
  std::vector<BoundingBox> lens_boxes;
  // The lens grouped by block of the icosahedron: where each group ends in `lens`, and the
  // box of the group's faces, so a face is tested against the few groups it can reach.
  std::vector<std::uint32_t> group_end;
  std::vector<BoundingBox> group_box;
  bool lens_found = false;  // found on first use: most neighbours only bury faces whole
  BoundingBox box;

  Vec3 vertex(Index v) const { return centre + shape->unit.vertices[v] * scale; }
  std::array<Vec3, 3> face(std::uint32_t g) const {
    const Triangle& t = shape->unit.faces[g];
    return {vertex(t[0]), vertex(t[1]), vertex(t[2])};
  }
};

// The closed box meets the closed ball: a face that misses a neighbour's circumscribed
// ball is outside its polyhedron. The radius is widened far beyond the rounding of the
// distance (relative to the coordinates' size).
bool box_meets_ball(const BoundingBox& b, const Vec3& c, double r) {
  double d2 = 0;
  for (int axis = 0; axis < 3; ++axis) {
    // The distance beyond the box on this axis (0 inside it, and for a NaN), without branches.
    const double x = c[axis], e = std::max(0.0, std::max(b.min[axis] - x, x - b.max[axis]));
    d2 += e * e;
  }
  const double reach = r + 1e-9 * (r + std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)}));
  return d2 <= reach * reach;
}

// x in the closed cone from the centre o over the triangle (a, b, c), counter-clockwise
// seen from outside: o lies strictly inside, so for x in the triangle's plane this is x
// in the closed triangle.
template <class Point>
bool in_cone(const Vec3& o, const std::array<Vec3, 3>& t, const Point& x) {
  for (int k = 0; k < 3; ++k)
    if (geometry::orient3d(o, t[k], t[(k + 1) % 3], x) < 0) return false;
  return true;
}

// Exact, before any point is constructed: the line through p and q, whose ends lie strictly
// on opposite sides of the triangle's plane, meets the closed triangle. The line passes
// each edge (a, b) on the side given by orient3d(p, q, a, b); it meets the triangle iff no
// two edges see it on opposite sides, and it meets edge k's line iff that sign is zero
// (`on_edge`: 0 there, 1 elsewhere).
bool line_meets_triangle(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& t,
                         std::array<int, 3>* on_edge = nullptr) {
  bool positive = false, negative = false;
  std::array<int, 3> side;
  for (int k = 0; k < 3; ++k) {
    side[k] = geometry::orient3d(p, q, t[k], t[(k + 1) % 3]);
    positive |= side[k] > 0;
    negative |= side[k] < 0;
  }
  if (positive && negative) return false;
  if (on_edge)
    for (int k = 0; k < 3; ++k) (*on_edge)[k] = side[k] != 0;
  return true;
}

// Exact: x in the closed polyhedron. The polyhedron is convex and star-shaped from its
// centre, so x is inside iff it is behind the face that the ray from the centre through
// x meets.
bool inside_closed(const ImplicitPoint& x, const Neighbour& n) {
  if (const auto settled = settled_by_balls({x.coordinate(0), x.coordinate(1), x.coordinate(2)}, n.centre,
                                            n.inradius, n.circumradius))
    return *settled;
  const Vec3 m{x.coordinate(0).mid(), x.coordinate(1).mid(), x.coordinate(2).mid()};
  const Vec3 d = m - n.centre;
  auto try_face = [&](std::uint32_t g, bool& inside) {
    const auto t = n.face(g);
    if (!in_cone(n.centre, t, x)) return false;
    inside = geometry::orient3d(t[0], t[1], t[2], x) <= 0;
    return true;
  };
  // The face towards x is found directly; rounding can only move that guess to a face
  // around it, and the full search is a last resort that the exact test keeps correct.
  bool inside = false;
  const PolyhedronTemplate& shape = *n.shape;
  const std::uint32_t guess = shape.face_towards(d);
  if (try_face(guess, inside)) return inside;
  for (Index v : shape.unit.faces[guess])
    for (std::uint32_t k = shape.vertex_faces_first[v]; k < shape.vertex_faces_first[v + 1]; ++k)
      if (shape.vertex_faces[k] != guess && try_face(shape.vertex_faces[k], inside)) return inside;
  for (std::uint32_t g = 0; g < shape.unit.faces.size(); ++g)
    if (try_face(g, inside)) return inside;
  throw std::logic_error("one-pass union: a point in no face's cone");
}

// Points are merged by definition (PointDefinition: the same input elements name the same
// point), so the faces and atoms that meet at a point find it without arithmetic. Points
// that are equal with different definitions (degenerate contacts) are merged after the
// join by exact value.
struct DefinitionHash {
  std::size_t operator()(const PointDefinition& d) const { return static_cast<std::size_t>(d.hash()); }
};

enum class Plane : std::uint8_t { cuts, coplanar_same, coplanar_opposite };

// Where a point lies on the face being trimmed: corner k, inside edge k (corner k to
// k + 1), or in the interior.
struct Place {
  boolean_engine::Where where = boolean_engine::Where::interior;
  std::uint8_t index = 0;
};

struct Segment {
  std::uint32_t s = 0, t = 0;  // local point ids
  std::uint32_t neighbour = 0;  // index into the atom's neighbour list
  std::uint32_t plane = 0;      // the neighbour's face whose plane holds it
  std::vector<std::uint32_t> crossings;  // points where other traces cross it
};

// Everything one face's trimming builds, reused from face to face (no allocation in the
// steady state).
struct FaceWork {
  std::vector<ImplicitPoint> points;
  std::vector<PointDefinition> definitions;  // of points
  std::vector<Place> places;
  // Per point: neighbours whose boundary holds it. Longer than `points` when an earlier face
  // had more: the lists are emptied and reused, not freed (one allocation per point else).
  std::vector<std::vector<std::uint32_t>> on_neighbour;
  std::vector<Segment> segments;
  std::vector<std::uint32_t> near;   // neighbours whose boxes meet the face's
  std::vector<std::uint32_t> relevant;
  std::vector<Plane> plane_kind;     // per neighbour (valid for relevant ones)
  // Buffers of split and classify.
  std::array<std::vector<std::uint32_t>, 3> edge_run;
  std::vector<std::uint32_t> scratch;
  std::vector<std::uint8_t> on_segment;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> unique_segments;
  std::vector<std::vector<std::uint32_t>> unique_crossings;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::int8_t> inside;
  boolean_engine::FaceToSplit face;
  boolean_engine::PolylineWork polylines;
  // The points on the trimmed atom's own edges, built once: each edge is shared by two of
  // its faces, which meet the same neighbour faces there. Emptied per atom.
  std::uint32_t atom = 0;
  std::unordered_map<PointDefinition, ImplicitPoint, DefinitionHash> own_edge_points;

  void clear() {
    points.clear();
    definitions.clear();
    places.clear();
    segments.clear();
    near.clear();
    relevant.clear();
  }

  const ImplicitPoint& own_edge_point(const PointDefinition& d, const AtomPolyhedra& polyhedra) {
    if (const auto it = own_edge_points.find(d); it != own_edge_points.end()) return it->second;
    return own_edge_points.emplace(d, construct(d, polyhedra)).first->second;
  }

  // The id of the point d defines, merged with an equal point already there.
  std::uint32_t add(const PointDefinition& d, const AtomPolyhedra& polyhedra, Place place, std::uint32_t neighbour) {
    auto merge = [&](std::uint32_t k) {
      // The simplest place wins (a corner over an edge over the interior).
      if (place.where < places[k].where) places[k] = place;
      auto& on = on_neighbour[k];
      if (neighbour != ~0u && std::find(on.begin(), on.end(), neighbour) == on.end()) on.push_back(neighbour);
      return k;
    };
    for (std::uint32_t k = 0; k < points.size(); ++k)
      if (definitions[k] == d) return merge(k);
    // A point is copied once, into `points` (it is large: its defining points and its box).
    auto add_new = [&](const ImplicitPoint& x) {
      for (std::uint32_t k = 0; k < points.size(); ++k)
        if (geometry::same_point(points[k], x)) return merge(k);
      points.push_back(x);
      definitions.push_back(d);
      places.push_back(place);
      if (on_neighbour.size() < points.size()) on_neighbour.emplace_back();
      auto& on = on_neighbour[points.size() - 1];
      on.clear();
      if (neighbour != ~0u) on.push_back(neighbour);
      return static_cast<std::uint32_t>(points.size() - 1);
    };
    if (d.kind == PointDefinition::Kind::line_plane && d.id[0] == atom) return add_new(own_edge_point(d, polyhedra));
    return add_new(construct(d, polyhedra));
  }
};

Place place_from_sides(const std::array<int, 3>& side) {
  // side[k]: orientation of x against the plane through the centre and edge k; zero on it.
  const int zeros = (side[0] == 0) + (side[1] == 0) + (side[2] == 0);
  if (zeros == 0) return {boolean_engine::Where::interior, 0};
  if (zeros == 1)
    for (std::uint8_t k = 0; k < 3; ++k)
      if (side[k] == 0) return {boolean_engine::Where::edge, k};
  // On edges k and k - 1: corner k.
  for (std::uint8_t k = 0; k < 3; ++k)
    if (side[k] == 0 && side[(k + 2) % 3] == 0) return {boolean_engine::Where::corner, k};
  throw std::logic_error("one-pass union: a point on all three edges of a face");
}

// The double coordinates written out: the filter box's midpoint when the box is a few
// ulps wide (within about an ulp of the exact value), the exact value truncated otherwise.
// Without the exact path: NaN when the box is wider (the exact rounding costs some 15 000
// instructions; it is left to the join, once per distinct point).
Vec3 output_coordinates_if_tight(const ImplicitPoint& p) {
  if (p.is_explicit()) return p.explicit_value();
  Vec3 mid{p.coordinate(0).mid(), p.coordinate(1).mid(), p.coordinate(2).mid()};
  for (int axis = 0; axis < 3; ++axis) {
    const auto& i = p.coordinate(axis);
    if (!(i.hi - i.lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(i.lo), std::fabs(i.hi))))
      return Vec3{std::numeric_limits<double>::quiet_NaN(), 0, 0};
  }
  return mid;
}

// The output of one atom: its kept pieces, with points merged by exact value.
struct AtomPieces {
  std::vector<PointDefinition> points;
  std::vector<Vec3> coordinates;  // of points, as written; NaN x: not yet known (output_coordinates_if_tight)
  std::size_t implicit_points = 0;
  std::vector<Triangle> triangles;
  std::size_t faces_inside = 0, faces_whole = 0, faces_cut = 0, crossings = 0;
};

class PointTable {
 public:
  std::uint32_t add(const PointDefinition& d, const ImplicitPoint& x, AtomPieces& out) {
    auto [it, inserted] = ids_.try_emplace(d, static_cast<std::uint32_t>(out.points.size()));
    if (inserted) {
      out.points.push_back(d);
      out.coordinates.push_back(output_coordinates_if_tight(x));
    }
    return it->second;
  }

 private:
  std::unordered_map<PointDefinition, std::uint32_t, DefinitionHash> ids_;
};

class AtomTrimmer {
 public:
  AtomTrimmer(const AtomPolyhedra& polyhedra, const NeighbourList& neighbours)
      : polyhedra_(polyhedra), neighbours_(neighbours) {}

  AtomPieces trim(std::uint32_t atom);

 private:
  void load_neighbours(std::uint32_t atom);
  void find_lens(Neighbour& n);
  void find_covering();
  // The trace of neighbour face g on face f: adds the points of f ∩ g and, when they span a
  // segment, the segment. Returns false if they do not meet.
  bool trace(std::uint32_t n, std::uint32_t g);
  void add_crossings();
  void emit(const std::array<std::uint32_t, 3>& local, AtomPieces& out, PointTable& table);
  void split_and_classify(AtomPieces& out, PointTable& table);

  const AtomPolyhedra& polyhedra_;
  const NeighbourList& neighbours_;
  std::uint32_t atom_ = 0;
  Vec3 centre_;
  std::vector<Vec3> vertices_;
  // Per block of faces: the neighbours whose inscribed balls hold the block's centre most
  // deeply (~0 where fewer reach it), and whether the first holds the whole block.
  static constexpr int kCovering = 3;
  std::array<std::array<std::uint32_t, kCovering>, 20> covering_{};
  std::array<std::uint8_t, 20> buried_{};
  std::vector<std::uint32_t> corner_id_;  // per vertex: its id among the atom's points, or ~0
  std::vector<std::uint32_t> lens_candidates_;  // find_lens's buffer
  std::vector<std::uint32_t> reaching_;   // trim's buffer: the neighbours that can reach a face
  std::vector<std::uint32_t> lens_hits_;  // trim's buffer: a lens group's faces whose boxes meet the face's
  std::vector<Neighbour> nbr_;
  std::size_t nbr_count_ = 0;
  // The face being trimmed.
  std::array<Vec3, 3> f_;
  std::array<Index, 3> f_index_{};
  std::uint32_t face_ = 0;
  BoundingBox f_box_;
  FaceWork work_;
  std::size_t crossings_ = 0;
};

void AtomTrimmer::load_neighbours(std::uint32_t atom) {
  const auto row = neighbours_.of(atom);
  if (nbr_.size() < row.size()) nbr_.resize(row.size());
  if (reaching_.size() < row.size()) reaching_.resize(row.size());
  nbr_count_ = row.size();
  for (std::size_t k = 0; k < row.size(); ++k) {
    Neighbour& n = nbr_[k];
    n.atom = row[k];
    n.centre = polyhedra_.centre(n.atom);
    n.scale = polyhedra_.scale(n.atom);
    n.inradius = polyhedra_.inradius(n.atom);
    n.circumradius = polyhedra_.circumradius(n.atom);
    n.shape = &polyhedra_.shape(n.atom);
    n.box = BoundingBox{};
    n.box.extend(n.centre - Vec3{n.circumradius, n.circumradius, n.circumradius});
    n.box.extend(n.centre + Vec3{n.circumradius, n.circumradius, n.circumradius});
    n.lens_found = false;
  }
}

void AtomTrimmer::find_lens(Neighbour& n) {
  n.lens.clear();
  n.lens_boxes.clear();
  n.group_end.clear();
  n.group_box.clear();
  n.lens_found = true;
  const double outer = polyhedra_.circumradius(atom_), inner = polyhedra_.inradius(atom_);
  // A face can meet this atom's faces only where it meets the shell between this atom's
  // inscribed and circumscribed balls (every face of the atom lies in it): tested on a
  // ball around the face, widened by the vertices' rounding.
  const double error = polyhedra_.vertex_error(n.atom);
  auto misses_shell = [&](const Vec3& unit_centre, double unit_radius) {
    const Vec3 d = n.centre + unit_centre * n.scale - centre_;
    const double r = unit_radius * n.scale + 2 * error, dist2 = dot(d, d);
    return (dist2 > (outer + r) * (outer + r)) | ((r < inner) & (dist2 < (inner - r) * (inner - r)));
  };
  const PolyhedronTemplate& shape = *n.shape;
  // Then on the face's corners: all three inside the inscribed ball put the face inside it
  // (convexity); a point of a face is no nearer the centre than the square root of its
  // corners' least squared distance less a third of its longest edge squared (the
  // barycentric identity |x - o|^2 = sum l_i |v_i - o|^2 - sum_{i<j} l_i l_j |v_i - v_j|^2).
  const double below = std::max(0.0, inner - 2 * error), below2 = below * below;
  const double edge = shape.max_edge * n.scale, beyond = outer + 2 * error;
  const double beyond2 = (beyond * beyond + edge * edge / 3) * (1 + 1e-12);
  auto misses_shell_by_corners = [&](const std::array<Vec3, 3>& t) {
    double least = std::numeric_limits<double>::infinity(), most = 0;
    for (const Vec3& v : t) {
      const Vec3 d = v - centre_;
      const double d2 = dot(d, d);
      least = std::min(least, d2);
      most = std::max(most, d2);
    }
    return (most < below2 * (1 - 1e-12)) | (least > beyond2);
  };
  const auto block_faces = static_cast<std::uint32_t>(shape.frequency * shape.frequency);
  for (std::uint32_t b = 0; b < 20; ++b) {
    if (misses_shell(shape.block_centre[b], shape.block_radius[b])) continue;
    BoundingBox group;
    const std::size_t first = n.lens.size();
    // The faces whose balls meet the shell, listed without a branch per face (which faces
    // do is unpredictable), then tested on their corners.
    lens_candidates_.resize(block_faces);
    if (lens_hits_.size() < block_faces) lens_hits_.resize(block_faces);  // a group lies in one block
    std::uint32_t candidates = 0;
    for (std::uint32_t g = b * block_faces; g < (b + 1) * block_faces; ++g) {
      lens_candidates_[candidates] = g;
      candidates += !misses_shell(shape.face_centre[g], shape.face_radius[g]);
    }
    std::uint32_t kept = 0;
    for (std::uint32_t k = 0; k < candidates; ++k) {
      lens_candidates_[kept] = lens_candidates_[k];
      kept += !misses_shell_by_corners(n.face(lens_candidates_[k]));
    }
    for (std::uint32_t k = 0; k < kept; ++k) {
      const auto t = n.face(lens_candidates_[k]);
      n.lens.push_back(lens_candidates_[k]);
      n.lens_boxes.push_back(box_of(t[0], t[1], t[2]));
      group.extend(n.lens_boxes.back());
    }
    if (n.lens.size() == first) continue;
    n.group_end.push_back(static_cast<std::uint32_t>(n.lens.size()));
    n.group_box.push_back(group);
  }
}

void AtomTrimmer::find_covering() {
  const PolyhedronTemplate& shape = polyhedra_.shape(atom_);
  const double scale = polyhedra_.scale(atom_), error = polyhedra_.vertex_error(atom_);
  for (std::uint32_t b = 0; b < 20; ++b) {
    const Vec3 centre = centre_ + shape.block_centre[b] * scale;
    // Every vertex of the block lies within `radius` of `centre` (rounding included).
    const double radius = shape.block_radius[b] * scale + 2 * error;
    std::array<double, kCovering> best_depth;
    best_depth.fill(-std::numeric_limits<double>::infinity());
    covering_[b].fill(~0u);
    for (std::uint32_t ni = 0; ni < nbr_count_; ++ni) {
      const Vec3 d = centre - nbr_[ni].centre;
      const double reach = nbr_[ni].inradius + radius, dist2 = dot(d, d);
      if (!(dist2 < reach * reach)) continue;  // its inscribed ball holds no vertex of the block
      const double depth = nbr_[ni].inradius - std::sqrt(dist2);
      if (!(depth > best_depth[kCovering - 1])) continue;
      int k = kCovering - 1;
      for (; k > 0 && depth > best_depth[k - 1]; --k) {
        best_depth[k] = best_depth[k - 1];
        covering_[b][k] = covering_[b][k - 1];
      }
      best_depth[k] = depth;
      covering_[b][k] = ni;
    }
    // The block's ball inside the first one's inscribed ball, with a margin far beyond the
    // rounding of the distance, so that every corner passes the cull's own test too.
    const double size = radius + std::max({std::fabs(centre.x), std::fabs(centre.y), std::fabs(centre.z)});
    buried_[b] = best_depth[0] > radius + 1e-12 * size;
  }
}

bool AtomTrimmer::trace(std::uint32_t ni, std::uint32_t g) {
  using boolean_engine::Where;
  const Neighbour& n = nbr_[ni];
  const auto t = n.face(g);
  std::array<int, 3> sg, sf;
  for (int m = 0; m < 3; ++m) sg[m] = geometry::orient3d(f_[0], f_[1], f_[2], t[m]);
  if (sg[0] == sg[1] && sg[1] == sg[2]) {
    if (sg[0] != 0) return false;
    // Coplanar: the shared part is settled by the rule on orientations (classify); its
    // outline comes from the neighbouring faces of g, which cross the plane.
    work_.plane_kind[ni] = geometry::orient3d(f_[0], f_[1], f_[2], n.centre) < 0 ? Plane::coplanar_same
                                                                                   : Plane::coplanar_opposite;
    return true;
  }
  for (int k = 0; k < 3; ++k) sf[k] = geometry::orient3d(t[0], t[1], t[2], f_[k]);
  if (sf[0] == sf[1] && sf[1] == sf[2] && sf[0] != 0) return false;

  std::array<std::uint32_t, 6> found{};
  int count = 0;
  auto note = [&](std::uint32_t id) {
    for (int k = 0; k < count; ++k)
      if (found[k] == id) return;
    found[count++] = id;
  };
  for (std::uint8_t k = 0; k < 3; ++k) {
    if (sf[k] == 0 && in_cone(n.centre, t, f_[k]))
      note(work_.add(PointDefinition::vertex(atom_, f_index_[k]), polyhedra_, {Where::corner, k}, ni));
    const int k1 = (k + 1) % 3;
    if (sf[k] * sf[k1] < 0) {
      // Canonical edge direction (lower vertex first), as the point's definition has it.
      const bool forward = f_index_[k] < f_index_[k1];
      const Vec3 &p = forward ? f_[k] : f_[k1], &q = forward ? f_[k1] : f_[k];
      if (!line_meets_triangle(p, q, t)) continue;
      note(work_.add(PointDefinition::edge_plane(atom_, f_index_[k], f_index_[k1], n.atom, g), polyhedra_,
                     {Where::edge, k}, ni));
    }
  }
  const Triangle& tri = n.shape->unit.faces[g];
  for (int m = 0; m < 3; ++m) {
    std::array<int, 3> side;
    if (sg[m] == 0) {
      for (int k = 0; k < 3; ++k) side[k] = geometry::orient3d(centre_, f_[k], f_[(k + 1) % 3], t[m]);
      if (side[0] >= 0 && side[1] >= 0 && side[2] >= 0)
        note(work_.add(PointDefinition::vertex(n.atom, tri[m]), polyhedra_, place_from_sides(side), ni));
    }
    const int m1 = (m + 1) % 3;
    if (sg[m] * sg[m1] < 0) {
      const bool forward = tri[m] < tri[m1];
      const Vec3 &p = forward ? t[m] : t[m1], &q = forward ? t[m1] : t[m];
      if (!line_meets_triangle(p, q, f_, &side)) continue;
      note(work_.add(PointDefinition::edge_plane(n.atom, tri[m], tri[m1], atom_, face_), polyhedra_,
                     place_from_sides(side), ni));
    }
  }
  if (count == 0) return false;
  if (count >= 2) {
    // f ∩ g is a segment; with more than two points found on it, its ends are the extremes.
    std::uint32_t s = found[0], e = found[1];
    if (count > 2) {
      std::vector<std::uint32_t> ids(found.begin(), found.begin() + count);
      const Vec3 a = work_.points[ids[0]].rounded(), b = work_.points[ids[1]].rounded();
      boolean_engine::sort_along_segment(ids, a, b, work_.points);
      s = ids.front();
      e = ids.back();
    }
    work_.segments.push_back({s, e, ni, g, {}});
  }
  return true;
}

void AtomTrimmer::add_crossings() {
  // Two neighbours' traces crossing inside the face: the point where the face's plane and
  // the two neighbours' planes meet (transversal crossings only; touching ends and overlaps
  // are points of the other segment, found when the segments are split).
  const std::size_t count = work_.segments.size();
  for (std::size_t a = 0; a < count; ++a) {
    const Segment& sa = work_.segments[a];
    const auto pa = nbr_[sa.neighbour].face(sa.plane);
    for (std::size_t b = a + 1; b < count; ++b) {
      const Segment& sb = work_.segments[b];
      if (sb.neighbour == sa.neighbour) continue;
      const auto pb = nbr_[sb.neighbour].face(sb.plane);
      const int o1 = geometry::orient3d(pa[0], pa[1], pa[2], work_.points[sb.s]);
      const int o2 = geometry::orient3d(pa[0], pa[1], pa[2], work_.points[sb.t]);
      if (o1 * o2 >= 0) continue;
      const int o3 = geometry::orient3d(pb[0], pb[1], pb[2], work_.points[sa.s]);
      const int o4 = geometry::orient3d(pb[0], pb[1], pb[2], work_.points[sa.t]);
      if (o3 * o4 >= 0) continue;
      const PointDefinition x = PointDefinition::three_planes(
          {{{atom_, face_}, {nbr_[sa.neighbour].atom, sa.plane}, {nbr_[sb.neighbour].atom, sb.plane}}});
      // On both neighbours' boundaries: added under each (the second call finds the first).
      work_.add(x, polyhedra_, {boolean_engine::Where::interior, 0}, sa.neighbour);
      const std::uint32_t id = work_.add(x, polyhedra_, {boolean_engine::Where::interior, 0}, sb.neighbour);
      work_.segments[a].crossings.push_back(id);
      work_.segments[b].crossings.push_back(id);
      ++crossings_;
    }
  }
}

void AtomTrimmer::emit(const std::array<std::uint32_t, 3>& local, AtomPieces& out, PointTable& table) {
  Triangle tri;
  for (int k = 0; k < 3; ++k) {
    const Place place = work_.places[local[k]];
    if (place.where == boolean_engine::Where::corner) {
      // The atom's own vertices by index, without hashing.
      std::uint32_t& id = corner_id_[f_index_[place.index]];
      if (id == ~0u) {
        id = static_cast<std::uint32_t>(out.points.size());
        out.points.push_back(PointDefinition::vertex(atom_, f_index_[place.index]));
        out.coordinates.push_back(f_[place.index]);
      }
      tri[k] = id;
    } else {
      tri[k] = table.add(work_.definitions[local[k]], work_.points[local[k]], out);
    }
  }
  out.triangles.push_back(tri);
}

void AtomTrimmer::split_and_classify(AtomPieces& out, PointTable& table) {
  using boolean_engine::Where;
  auto& w = work_;
  boolean_engine::FaceToSplit& face = w.face;
  face.boundary.clear();
  face.interior.clear();
  face.constraints.clear();
  face.collinear_sets.clear();
  face.projection = boolean_engine::face_projection(f_[0], f_[1], f_[2]);
  std::array<std::uint32_t, 3> corner;
  for (std::uint8_t k = 0; k < 3; ++k)
    corner[k] = w.add(PointDefinition::vertex(atom_, f_index_[k]), polyhedra_, {Where::corner, k}, ~0u);
  auto& edge_run = w.edge_run;
  for (int k = 0; k < 3; ++k) {
    auto& inside = w.scratch;
    inside.clear();
    edge_run[k].clear();
    for (std::uint32_t p = 0; p < w.points.size(); ++p)
      if (w.places[p].where == Where::edge && w.places[p].index == k) inside.push_back(p);
    boolean_engine::sort_along_segment(inside, f_[k], f_[(k + 1) % 3], w.points);
    edge_run[k].push_back(corner[k]);
    edge_run[k].insert(edge_run[k].end(), inside.begin(), inside.end());
    edge_run[k].push_back(corner[(k + 1) % 3]);
    face.boundary.push_back(corner[k]);
    face.boundary.insert(face.boundary.end(), inside.begin(), inside.end());
  }
  // Interior points on a trace (a point where a neighbour only touches the face's
  // interior splits nothing, unless it lies on another neighbour's trace: that neighbour's
  // face, across the trace, sees the same point on the same trace and splits it there).
  auto& on_segment = w.on_segment;
  on_segment.assign(w.points.size(), 0);
  for (const Segment& s : w.segments) on_segment[s.s] = on_segment[s.t] = 1;
  auto inside_a_trace = [&](std::uint32_t p) {
    for (const Segment& s : w.segments) {
      if (s.s == s.t || s.s == p || s.t == p) continue;
      const auto& on = w.on_neighbour[p];
      if (std::find(on.begin(), on.end(), s.neighbour) != on.end()) continue;
      const auto g = nbr_[s.neighbour].face(s.plane);
      if (geometry::orient3d(g[0], g[1], g[2], w.points[p]) != 0) continue;  // p is on f's plane: on the trace's line
      std::vector<std::uint32_t> ids{s.s, p, s.t};
      boolean_engine::sort_along_segment(ids, w.points[s.s].rounded(), w.points[s.t].rounded(), w.points);
      if (ids[1] == p) return true;
    }
    return false;
  };
  for (std::uint32_t p = 0; p < w.points.size(); ++p)
    if (w.places[p].where == Where::interior &&
        (on_segment[p] || w.on_neighbour[p].size() >= 2 || inside_a_trace(p)))
      face.interior.push_back(p);
  // Segments without repeats (coplanar neighbour faces can trace the same one), each with
  // the crossings built on it.
  auto& segments = w.unique_segments;
  auto& crossings = w.unique_crossings;
  segments.clear();
  for (auto& known : crossings) known.clear();
  {
    auto& order = w.scratch;
    order.clear();
    for (std::uint32_t k = 0; k < w.segments.size(); ++k)
      if (w.segments[k].s != w.segments[k].t) order.push_back(k);
    auto ends = [&](std::uint32_t k) {
      return std::pair(std::min(w.segments[k].s, w.segments[k].t), std::max(w.segments[k].s, w.segments[k].t));
    };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return ends(a) < ends(b); });
    for (std::uint32_t k : order) {
      if (segments.empty() || segments.back() != ends(k)) {
        segments.push_back(ends(k));
        if (crossings.size() < segments.size()) crossings.emplace_back();
      }
      auto& known = crossings[segments.size() - 1];
      for (std::uint32_t id : w.segments[k].crossings)
        if (std::find(known.begin(), known.end(), id) == known.end()) known.push_back(id);
    }
  }
  auto on_boundary = [&](std::uint32_t s, std::uint32_t t) {
    for (const auto& run : edge_run)
      if (std::find(run.begin(), run.end(), s) != run.end() && std::find(run.begin(), run.end(), t) != run.end())
        return true;
    return false;
  };
  // Classify (§2.4): a piece lies wholly inside or wholly outside each neighbour (no trace
  // crosses it), and inside a convex polyhedron iff all its corners are.
  auto& inside = w.inside;
  inside.assign(w.points.size() * w.relevant.size(), -1);
  auto corner_inside = [&](std::uint32_t p, std::size_t r) {
    std::int8_t& known = inside[p * w.relevant.size() + r];
    if (known < 0) {
      const std::uint32_t ni = w.relevant[r];
      const auto& on = w.on_neighbour[p];
      known = std::find(on.begin(), on.end(), ni) != on.end() ? 1 : inside_closed(w.points[p], nbr_[ni]);
    }
    return known == 1;
  };
  auto outside_all = [&](std::span<const std::uint32_t> corners) {
    for (std::size_t r = 0; r < w.relevant.size(); ++r) {
      const std::uint32_t ni = w.relevant[r];
      if (w.plane_kind[ni] == Plane::coplanar_same && nbr_[ni].atom > atom_) continue;
      if (std::all_of(corners.begin(), corners.end(), [&](std::uint32_t p) { return corner_inside(p, r); }))
        return false;
    }
    return true;
  };
  auto& triangles = w.triangles;
  triangles.clear();
  bool classified = false;  // triangles holds only the pieces outside every neighbour
  if (face.interior.empty()) {
    // Every trace runs from edge to edge: chords, which cannot cross (a crossing would be
    // a three-plane point in the interior) and hold no point inside them, so the face is
    // cut into convex pieces without a predicate.
    for (auto [s, t] : segments)
      if (!on_boundary(s, t)) face.constraints.emplace_back(s, t);
    if (face.constraints.empty() && face.boundary.size() == 3) {
      triangles.push_back({corner[0], corner[1], corner[2]});
    } else if (auto clipped = boolean_engine::triangulate_chords(face.boundary, edge_run, face.constraints, w.points,
                                                                 face.projection)) {
      triangles = std::move(*clipped);
    }
    face.constraints.clear();
  }
  if (triangles.empty()) {
    std::vector<std::uint32_t> ids = face.boundary;
    ids.insert(ids.end(), face.interior.begin(), face.interior.end());
    const boolean_engine::FacePoints points(ids, w.points, face.projection);
    for (const auto& run : edge_run) face.collinear_sets.push_back(run);
    const auto pieces = boolean_engine::split_segments_at_points(
        segments, points, face.collinear_sets, std::span(crossings).first(segments.size()));
    for (auto [s, t] : pieces)
      if (!on_boundary(s, t)) face.constraints.emplace_back(std::min(s, t), std::max(s, t));
    std::sort(face.constraints.begin(), face.constraints.end());
    face.constraints.erase(std::unique(face.constraints.begin(), face.constraints.end()), face.constraints.end());
    if (face.constraints.empty() && face.interior.empty() && face.boundary.size() == 3) {
      triangles.push_back({corner[0], corner[1], corner[2]});
    } else {
      // Pieces inside a neighbour are dropped before they are clipped.
      if (auto clipped = boolean_engine::triangulate_polylines(face, points, w.polylines, std::ref(outside_all))) {
        triangles = std::move(*clipped);
        classified = true;
      } else {
        triangles = boolean_engine::retriangulate_face(face, points);
      }
    }
  }
  for (const auto& tri : triangles)
    if (classified || outside_all(tri)) emit(tri, out, table);
}

AtomPieces AtomTrimmer::trim(std::uint32_t atom) {
  AtomPieces out;
  if (polyhedra_.contained(atom)) return out;
  atom_ = atom;
  work_.atom = atom;
  work_.own_edge_points.clear();
  centre_ = polyhedra_.centre(atom);
  polyhedra_.vertices(atom, vertices_);
  load_neighbours(atom);
  if (work_.plane_kind.size() < nbr_count_) work_.plane_kind.resize(nbr_count_);
  PointTable table;
  const PolyhedronTemplate& shape = polyhedra_.shape(atom);
  crossings_ = 0;
  find_covering();
  const std::uint32_t block_faces = static_cast<std::uint32_t>(shape.frequency * shape.frequency);
  corner_id_.assign(vertices_.size(), ~0u);
  for (std::uint32_t f = 0; f < shape.unit.faces.size(); ++f) {
    const std::uint32_t block = f / block_faces;
    if (buried_[block]) {  // f is the block's first face: the whole block is inside a neighbour
      out.faces_inside += block_faces;
      f += block_faces - 1;
      continue;
    }
    const Triangle& tri = shape.unit.faces[f];
    for (int k = 0; k < 3; ++k) f_[k] = vertices_[tri[k]];
    // Cull (§2.2.1): a face whose corners are inside a neighbour's inscribed ball is
    // inside it (the ball is inside the convex polyhedron).
    bool dropped = false;
    auto deep_inside = [&](const Neighbour& n) {
      const double r2 = n.inradius * n.inradius;
      bool inside = true;  // all three tested: no branch per corner
      for (const Vec3& c : f_) {
        const Vec3 d = c - n.centre;
        inside &= dot(d, d) < r2;
      }
      return inside;
    };
    // The neighbours that hold the face's block most deeply usually hold the face.
    for (int k = 0; k < kCovering && !dropped; ++k) {
      const std::uint32_t ni = covering_[block][k];
      if (ni != ~0u && deep_inside(nbr_[ni])) dropped = true;
    }
    if (dropped) {
      ++out.faces_inside;
      continue;
    }
    face_ = f;
    f_index_ = tri;
    f_box_ = box_of(f_[0], f_[1], f_[2]);
    work_.clear();
    // The neighbours that can reach the face, listed without a branch per neighbour (which
    // ones do is unpredictable); then, in order, one that buries it ends the search.
    std::uint32_t reaching = 0;
    for (std::uint32_t ni = 0; ni < nbr_count_; ++ni) {
      reaching_[reaching] = ni;
      reaching += f_box_.overlaps(nbr_[ni].box) & box_meets_ball(f_box_, nbr_[ni].centre, nbr_[ni].circumradius);
    }
    for (std::uint32_t k = 0; k < reaching && !dropped; ++k) {
      if (deep_inside(nbr_[reaching_[k]])) {
        dropped = true;
      } else {
        work_.near.push_back(reaching_[k]);
      }
    }
    if (dropped) {
      ++out.faces_inside;
      continue;
    }
    // Intersect (§2.2.2): the traces of every near neighbour.
    for (std::uint32_t ni : work_.near) {
      Neighbour& n = nbr_[ni];
      work_.plane_kind[ni] = Plane::cuts;
      if (!n.lens_found) find_lens(n);
      bool meets = false;
      for (std::size_t group = 0, l = 0; group < n.group_end.size(); l = n.group_end[group++]) {
        if (!n.group_box[group].overlaps(f_box_)) continue;
        // The lens faces whose boxes meet the face's, listed without a branch each, traced in order.
        std::uint32_t hits = 0;
        for (; l < n.group_end[group]; ++l) {
          lens_hits_[hits] = n.lens[l];
          hits += n.lens_boxes[l].overlaps(f_box_);
        }
        for (std::uint32_t k = 0; k < hits; ++k) meets |= trace(ni, lens_hits_[k]);
      }
      if (meets) {
        work_.relevant.push_back(ni);
        continue;
      }
      // No face of the neighbour meets f: f is wholly inside or wholly outside it.
      if (inside_closed(ImplicitPoint::explicit_point(f_[0]), n)) {
        dropped = true;
        break;
      }
    }
    if (dropped) {
      ++out.faces_inside;
      continue;
    }
    if (work_.segments.size() > kMaxTracesPerFace)
      throw Error("the union is too complex to build: a face of atom " + std::to_string(atom + 1) +
                  " (counting from 1) is crossed by " + std::to_string(work_.segments.size()) +
                  " faces of its neighbours, more than " + std::to_string(kMaxTracesPerFace) +
                  "; its sphere nearly coincides with many others (a --probe far larger than the atoms' spacing?)");
    if (work_.relevant.empty()) {
      ++out.faces_whole;
      std::array<std::uint32_t, 3> local;
      for (std::uint8_t k = 0; k < 3; ++k)
        local[k] = work_.add(PointDefinition::vertex(atom_, f_index_[k]), polyhedra_, {boolean_engine::Where::corner, k},
                             ~0u);
      emit(local, out, table);
      continue;
    }
    ++out.faces_cut;
    add_crossings();
    split_and_classify(out, table);
  }
  out.crossings = crossings_;
  for (const PointDefinition& d : out.points) out.implicit_points += !d.is_explicit();
  return out;
}

// The union's faces extrapolated from a sample of atoms spread evenly over the index order
// (chain by chain, residue by residue: over the whole structure), each trimmed as the pass
// trims it. 256 atoms put the estimate within a few percent on proteins.
SurfaceSizeEstimate estimate_union_size(const AtomPolyhedra& polyhedra, const NeighbourList& neighbours, int threads) {
  constexpr std::size_t kSample = 256;
  const std::size_t n = polyhedra.size(), m = std::min(n, kSample);
  std::vector<std::size_t> faces(m, 0);
  ParallelExceptions errors;
#pragma omp parallel num_threads(threads)
  {
    AtomTrimmer trimmer(polyhedra, neighbours);
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t k = 0; k < static_cast<std::int64_t>(m); ++k) {
      const auto atom = static_cast<std::uint32_t>((2 * static_cast<std::size_t>(k) + 1) * n / (2 * m));
      errors.run(k, [&] { faces[k] = trimmer.trim(atom).triangles.size(); });
    }
  }
  errors.rethrow();
  SurfaceSizeEstimate estimate;
  estimate.sampled_atoms = m;
  estimate.atoms = n;
  double sum = 0;
  for (std::size_t f : faces) sum += static_cast<double>(f);
  const double total = m > 0 ? sum * static_cast<double>(n) / static_cast<double>(m) : 0.0;
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  estimate.faces = total >= 1.8e19 ? kMax : static_cast<std::uint64_t>(total);
  estimate.bytes = estimate.faces > kMax / kBytesPerSurfaceFace ? kMax : estimate.faces * kBytesPerSurfaceFace;
  return estimate;
}

// Every atom's polyhedron trimmed by its neighbours, all atoms in parallel. `progress` (may
// be empty) is called from thread 0 every 256 atoms, and once at the end.
std::vector<AtomPieces> trim_atoms(const AtomPolyhedra& polyhedra, const NeighbourList& neighbours, int threads,
                                   const std::function<void(std::size_t, std::size_t)>& progress,
                                   const CancelFlag* cancel) {
  const std::size_t atom_count = polyhedra.size();
  const auto n = static_cast<std::int64_t>(atom_count);
  std::vector<AtomPieces> pieces(atom_count);
  ParallelExceptions errors;
  std::atomic<std::size_t> done{0};
#pragma omp parallel num_threads(threads)
  {
    AtomTrimmer trimmer(polyhedra, neighbours);
#pragma omp for schedule(dynamic, 4)
    for (std::int64_t i = 0; i < n; ++i) {
      // Skipped rather than thrown once cancelled: an exception per remaining atom would
      // cost more than the atoms.
      if (cancel_requested(cancel)) continue;
      errors.run(i, [&] { pieces[i] = trimmer.trim(static_cast<std::uint32_t>(i)); });
      const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
      if (progress && omp_get_thread_num() == 0 && finished % 256 == 0) progress(finished, atom_count);
    }
  }
  errors.rethrow();
  throw_if_cancelled(cancel);
  if (progress) progress(atom_count, atom_count);
  return pieces;
}

// Each atom's points and faces take a range of one global sequence: atom i's points are
// [point_start[i], point_start[i + 1]), and so on.
struct SequenceRanges {
  std::vector<std::size_t> point_start, face_start, implicit_start;
};

// The ranges, and the trim's counts added into `stats`.
SequenceRanges sequence_ranges(std::span<const AtomPieces> pieces, OnePassStats& stats) {
  SequenceRanges ranges;
  ranges.point_start.assign(pieces.size() + 1, 0);
  ranges.face_start.assign(pieces.size() + 1, 0);
  ranges.implicit_start.assign(pieces.size() + 1, 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const AtomPieces& p = pieces[i];
    stats.faces_inside += p.faces_inside;
    stats.faces_whole += p.faces_whole;
    stats.faces_cut += p.faces_cut;
    stats.crossings += p.crossings;
    ranges.point_start[i + 1] = ranges.point_start[i] + p.points.size();
    ranges.face_start[i + 1] = ranges.face_start[i] + p.triangles.size();
    ranges.implicit_start[i + 1] = ranges.implicit_start[i] + p.implicit_points;
  }
  if (ranges.point_start.back() >= std::numeric_limits<std::uint32_t>::max())
    throw Error("the union is too large to index: more than 4 billion points");
  return ranges;
}

struct HashedPosition {
  std::uint64_t hash;
  std::uint32_t position;
  bool operator<(const HashedPosition& o) const { return hash != o.hash ? hash < o.hash : position < o.position; }
};

// Merge by definition: implicit points sorted by (hash, position); in a run of equal
// hashes, a point's representative is the first point of the run with its definition.
// Per position of the global sequence, the position of its representative.
std::vector<std::uint32_t> representatives_by_definition(std::span<const AtomPieces> pieces,
                                                         const SequenceRanges& ranges, int threads) {
  const auto atom_count = static_cast<std::int64_t>(pieces.size());
  std::vector<const PointDefinition*> sequence(ranges.point_start.back());
  std::vector<std::uint32_t> representative(sequence.size());
  std::vector<HashedPosition> hashed(ranges.implicit_start.back());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::int64_t i = 0; i < atom_count; ++i) {
    const AtomPieces& p = pieces[i];
    std::size_t next_implicit = ranges.implicit_start[i];
    for (std::size_t k = 0; k < p.points.size(); ++k) {
      const auto position = static_cast<std::uint32_t>(ranges.point_start[i] + k);
      sequence[position] = &p.points[k];
      representative[position] = position;
      // An atom's own corners are points of no other atom, unless two atoms have a vertex
      // in common, which the merge by exact value finds.
      if (!p.points[k].is_explicit()) hashed[next_implicit++] = {p.points[k].hash(), position};
    }
  }
  __gnu_parallel::sort(hashed.begin(), hashed.end());
  const auto hashed_count = static_cast<std::int64_t>(hashed.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < hashed_count; ++k) {
    std::int64_t first = k;
    while (first > 0 && hashed[first - 1].hash == hashed[k].hash) --first;
    const PointDefinition& point = *sequence[hashed[k].position];
    for (std::int64_t j = first; j < k; ++j)
      if (*sequence[hashed[j].position] == point) {
        representative[hashed[k].position] = hashed[j].position;
        break;
      }
  }
  return representative;
}

// The points distinct by definition, in order of first appearance.
struct DistinctPoints {
  std::vector<PointDefinition> points;
  std::vector<Vec3> coordinates;        // as written; NaN x: not yet known
  std::vector<std::uint32_t> point_of;  // per position of the global sequence: its point
};

DistinctPoints distinct_points(std::span<const AtomPieces> pieces, std::span<const std::uint32_t> representative) {
  DistinctPoints distinct;
  distinct.point_of.resize(representative.size());
  for (std::size_t i = 0, s = 0; i < pieces.size(); ++i)
    for (std::size_t k = 0; k < pieces[i].points.size(); ++k, ++s) {
      if (representative[s] == s) {
        distinct.point_of[s] = static_cast<std::uint32_t>(distinct.points.size());
        distinct.points.push_back(pieces[i].points[k]);
        distinct.coordinates.push_back(pieces[i].coordinates[k]);
      } else {
        distinct.point_of[s] = distinct.point_of[representative[s]];
      }
    }
  return distinct;
}

// The atoms' triangles into `mesh`, on the distinct points, each tagged with its atom.
void join_faces(std::span<const AtomPieces> pieces, const SequenceRanges& ranges,
                std::span<const std::uint32_t> point_of, int threads, Mesh& mesh) {
  const auto atom_count = static_cast<std::int64_t>(pieces.size());
  mesh.faces.resize(ranges.face_start.back());
  mesh.face_tags.resize(ranges.face_start.back());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::int64_t i = 0; i < atom_count; ++i) {
    const auto& triangles = pieces[i].triangles;
    for (std::size_t j = 0; j < triangles.size(); ++j) {
      Triangle& t = mesh.faces[ranges.face_start[i] + j];
      for (int c = 0; c < 3; ++c) t[c] = point_of[ranges.point_start[i] + triangles[j][c]];
      mesh.face_tags[ranges.face_start[i] + j] = static_cast<std::int32_t>(i);
    }
  }
}

// A written coordinate is within about 2 ulps of the exact one (the filter box's midpoint
// when the box is that tight, the exact value truncated otherwise), so points equal by
// exact value have written coordinates within this reach of each other.
double rounding_reach(double c) {
  return 8 * std::numeric_limits<double>::epsilon() * std::fabs(c) + 8 * std::numeric_limits<double>::denorm_min();
}

// Points equal by exact value but defined differently (degenerate contacts): the implicit
// points are rebuilt and compared exactly only where their written coordinates' windows
// overlap, in a sweep along x. Per point, a lower point equal to it (itself when none);
// the chains end at the lowest. Constructs the coordinates not known yet.
std::vector<std::uint32_t> merge_equal_values(const AtomPolyhedra& polyhedra, int threads, DistinctPoints& distinct) {
  const std::vector<PointDefinition>& points = distinct.points;
  std::vector<Vec3>& coordinates = distinct.coordinates;
  const auto point_count = static_cast<std::int64_t>(points.size());
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (std::int64_t p = 0; p < point_count; ++p)
    if (std::isnan(coordinates[p].x)) coordinates[p] = construct(points[p], polyhedra).rounded();
  auto windows_overlap = [&](std::uint32_t a, std::uint32_t b) {
    for (int axis = 0; axis < 3; ++axis) {
      const double x = coordinates[a][axis], y = coordinates[b][axis];
      if (x + rounding_reach(x) < y - rounding_reach(y) || y + rounding_reach(y) < x - rounding_reach(x)) return false;
    }
    return true;
  };
  std::vector<std::pair<double, std::uint32_t>> order(points.size());
  std::vector<std::uint32_t> same(points.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < point_count; ++p) {
    const double x = coordinates[p].x;
    order[p] = {x - rounding_reach(x), static_cast<std::uint32_t>(p)};
  }
  std::iota(same.begin(), same.end(), 0u);
  __gnu_parallel::sort(order.begin(), order.end());  // a total order: the same for any thread count
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t a = order[k].second;
    const double end = coordinates[a].x + rounding_reach(coordinates[a].x);
    for (std::size_t l = k + 1; l < order.size() && order[l].first <= end; ++l) {
      const std::uint32_t b = order[l].second, x = std::min(a, b), y = std::max(a, b);
      if (same[y] != y || !windows_overlap(a, b) ||
          !geometry::same_point(construct(points[a], polyhedra), construct(points[b], polyhedra)))
        continue;
      std::uint32_t root = x;
      while (same[root] != root) root = same[root];
      same[y] = root;
    }
  }
  return same;
}

// The mesh's vertices: one per class of equal points, numbered in order of their lowest
// point; the faces renumbered onto them. Per point, its vertex.
std::vector<std::uint32_t> number_vertices(std::span<const std::uint32_t> same, std::span<const Vec3> coordinates,
                                           int threads, Mesh& mesh) {
  const auto point_count = static_cast<std::int64_t>(same.size());
  std::vector<std::uint32_t> vertex_of(same.size());
  std::size_t vertex_count = 0;
  for (std::uint32_t p = 0; p < same.size(); ++p) {
    std::uint32_t root = p;
    while (same[root] != root) root = same[root];
    vertex_of[p] = root == p ? static_cast<std::uint32_t>(vertex_count++) : vertex_of[root];
  }
  mesh.vertices.resize(vertex_count);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < point_count; ++p)
    if (same[p] == static_cast<std::uint32_t>(p)) mesh.vertices[vertex_of[p]] = coordinates[p];
  const auto face_count = static_cast<std::int64_t>(mesh.faces.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t f = 0; f < face_count; ++f)
    for (Index& v : mesh.faces[f]) v = vertex_of[v];
  return vertex_of;
}

// Rounding the points to doubles, after every decision, can make a tiny piece degenerate
// or fold it over its neighbour; the engine's repair fixes that by exact predicates on the
// rounded coordinates, without moving a vertex.
void repair_rounded_points(std::span<const PointDefinition> points, std::span<const std::uint32_t> vertex_of,
                           Mesh& mesh) {
  std::vector<std::uint8_t> rounded(mesh.vertices.size(), 0), operand(mesh.faces.size(), 0);
  for (std::uint32_t p = 0; p < points.size(); ++p)
    if (!points[p].is_explicit()) rounded[vertex_of[p]] = 1;
  std::vector<std::uint32_t> atom_of(mesh.face_tags.begin(), mesh.face_tags.end());
  boolean_engine::repair_rounding(mesh, operand, atom_of, rounded, {});
  mesh.face_tags.assign(atom_of.begin(), atom_of.end());
}

// Directed edges (u, v) without their reverse: 0 for a closed surface. The reverse is
// found among the few edges that leave v (edges bucketed by their first vertex).
// The buckets are counted and filled in parallel: the order within a bucket depends on the
// threads, the count does not.
std::size_t count_open_edges(const Mesh& mesh, int threads) {
  std::vector<std::uint32_t> first(mesh.vertices.size() + 1, 0);
  const auto face_total = static_cast<std::int64_t>(mesh.faces.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t f = 0; f < face_total; ++f)
    for (const Index v : mesh.faces[f]) std::atomic_ref(first[v + 1]).fetch_add(1, std::memory_order_relaxed);
  std::partial_sum(first.begin(), first.end(), first.begin());
  const auto to = std::make_unique_for_overwrite<Index[]>(first.back());  // first written in parallel
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t f = 0; f < face_total; ++f) {
      const Triangle& t = mesh.faces[f];
      for (int k = 0; k < 3; ++k) to[std::atomic_ref(fill[t[k]]).fetch_add(1, std::memory_order_relaxed)] = t[(k + 1) % 3];
    }
  }
  std::size_t open_edges = 0;
  const auto vertex_total = static_cast<std::int64_t>(mesh.vertices.size());
#pragma omp parallel for schedule(static) reduction(+ : open_edges) num_threads(threads)
  for (std::int64_t u = 0; u < vertex_total; ++u)
    for (std::uint32_t k = first[u]; k < first[u + 1]; ++k) {
      const Index v = to[k];
      const Index *begin = to.get() + first[v], *end = to.get() + first[v + 1];
      if (std::find(begin, end, static_cast<Index>(u)) == end) ++open_edges;
    }
  return open_edges;
}

}  // namespace

OnePassResult one_pass_union(std::span<const Atom> atoms, const SphereOptions& options, int threads,
                             const std::function<void(std::size_t, std::size_t)>& progress,
                             const std::function<void(const SurfaceSizeEstimate&)>& check_size,
                             std::uint64_t estimate_size_above, const CancelFlag* cancel) {
  OnePassResult result;
  auto start = Clock::now();
  const AtomPolyhedra polyhedra(atoms, options);
  const NeighbourList neighbours = find_neighbours(polyhedra);
  if (check_size) {
    const std::uint64_t sphere_faces = polyhedra.face_count();
    if (sphere_faces > estimate_size_above) check_size(estimate_union_size(polyhedra, neighbours, threads));
  }
  std::vector<AtomPieces> pieces = trim_atoms(polyhedra, neighbours, threads, progress, cancel);
  result.stats.seconds_trim = seconds_since(start);

  // Join: atoms in index order, points merged by definition, then points equal by exact
  // value but defined differently (degenerate contacts) merged too: only points whose
  // filter boxes overlap are compared exactly. The steps run in parallel where they are
  // not linear scans, and number points as a serial scan would (in order of first
  // appearance), so the mesh is the same for any thread count. Buffers go as soon as
  // their step is done, to keep the peak memory down.
  start = Clock::now();
  Mesh& mesh = result.mesh;
  const SequenceRanges ranges = sequence_ranges(pieces, result.stats);
  DistinctPoints distinct = distinct_points(pieces, representatives_by_definition(pieces, ranges, threads));
  join_faces(pieces, ranges, distinct.point_of, threads, mesh);
  distinct.point_of = {};
  pieces = {};
  const std::vector<std::uint32_t> same = merge_equal_values(polyhedra, threads, distinct);
  const std::vector<std::uint32_t> vertex_of = number_vertices(same, distinct.coordinates, threads, mesh);
  result.stats.merged_points = distinct.points.size() - mesh.vertices.size();
  repair_rounded_points(distinct.points, vertex_of, mesh);
  result.stats.open_edges = count_open_edges(mesh, threads);
  result.stats.seconds_join = seconds_since(start);
  result.stats.atoms = atoms.size();
  result.stats.contained_atoms = polyhedra.contained_count();
  result.stats.neighbour_pairs = neighbours.atoms.size() / 2;
  result.stats.faces_in = polyhedra.face_count();
  return result;
}

}  // namespace molsurf::surface_detail
