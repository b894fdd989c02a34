// Split (paper §2.3) and classify (§2.4) for the one-pass trim: the face re-triangulated in
// its own plane along the traces, each split at every point of the face on it; a piece is
// kept iff it lies outside every neighbour, and by convexity it lies inside a neighbour iff
// its three corners do. The triangulations are the union engine's (src/boolean/): ear
// clipping first, the advancing front where it refuses.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "boolean/advancing_front.hpp"
#include "boolean/ear_clipping.hpp"
#include "boolean/face_points.hpp"
#include "surface/one_pass/atom_trimmer.hpp"

namespace molsurf::surface_detail::one_pass {

using geometry::ImplicitPoint;

namespace {

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

}  // namespace

std::uint32_t PointTable::add(const PointDefinition& d, const ImplicitPoint& x, AtomPieces& out) {
  auto [it, inserted] = ids_.try_emplace(d, static_cast<std::uint32_t>(out.points.size()));
  if (inserted) {
    out.points.push_back(d);
    out.coordinates.push_back(output_coordinates_if_tight(x));
  }
  return it->second;
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
  for (int k = 0; k < 3; ++k) {
    auto& inside = w.scratch;
    inside.clear();
    for (std::uint32_t p = 0; p < w.points.size(); ++p)
      if (w.places[p].where == Where::edge && w.places[p].index == k) inside.push_back(p);
    face.add_edge(k, corner[k], corner[(k + 1) % 3], inside, f_[k], f_[(k + 1) % 3], w.points);
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
      if (!face.on_one_edge(s, t)) face.constraints.emplace_back(s, t);
    if (face.constraints.empty() && face.boundary.size() == 3) {
      triangles.push_back({corner[0], corner[1], corner[2]});
    } else if (auto clipped = boolean_engine::triangulate_chords(face.boundary, face.edge_runs, face.constraints,
                                                                 w.points, face.projection)) {
      triangles = std::move(*clipped);
    }
    face.constraints.clear();
  }
  if (triangles.empty()) {
    std::vector<std::uint32_t> ids = face.boundary;
    ids.insert(ids.end(), face.interior.begin(), face.interior.end());
    const boolean_engine::FacePoints points(ids, w.points, face.projection);
    for (const auto& run : face.edge_runs) face.collinear_sets.push_back(run);
    const auto pieces = boolean_engine::split_segments_at_points(
        segments, points, face.collinear_sets, std::span(crossings).first(segments.size()));
    for (auto [s, t] : pieces)
      if (!face.on_one_edge(s, t)) face.constraints.emplace_back(std::min(s, t), std::max(s, t));
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

}  // namespace molsurf::surface_detail::one_pass
