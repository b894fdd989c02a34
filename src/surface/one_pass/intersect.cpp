// Intersect (paper §2.2.2) for the one-pass trim: the traces of the neighbours' faces on
// the face being trimmed, by exact signed volumes on the input doubles. Their points are
// implicit (an edge crossing a plane, or three planes where two neighbours' traces cross
// inside the face) and named by their definitions, so every atom meeting at a point finds
// the same one.
#include <algorithm>
#include <cmath>
#include <limits>

#include "boolean/face_points.hpp"
#include "boolean/intersect.hpp"
#include "surface/one_pass/atom_trimmer.hpp"

namespace molsurf::surface_detail::one_pass {

using geometry::ImplicitPoint;

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

// Called for every lens face whose box meets the face's, from intersect() alone. Forced
// inline: the compiler keeps a member of a class with external linkage out of line, and the
// call cost 1 % of the union's instructions (1ubq, callgrind).
[[gnu::always_inline]] inline bool AtomTrimmer::trace(std::uint32_t ni, std::uint32_t g) {
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
      Place on_g;
      if (!boolean_engine::locate_crossing(p, q, t, on_g)) continue;
      note(work_.add(PointDefinition::edge_plane(atom_, f_index_[k], f_index_[k1], n.atom, g), polyhedra_,
                     {Where::edge, k}, ni));
    }
  }
  const Triangle& tri = n.shape->unit.faces[g];
  for (int m = 0; m < 3; ++m) {
    Place on_f;
    if (sg[m] == 0) {
      // In f's plane: where the cone from the centre over f holds it.
      std::array<int, 3> side;
      for (int k = 0; k < 3; ++k) side[k] = geometry::orient3d(centre_, f_[k], f_[(k + 1) % 3], t[m]);
      if (boolean_engine::locate_from_signs(side, on_f))
        note(work_.add(PointDefinition::vertex(n.atom, tri[m]), polyhedra_, on_f, ni));
    }
    const int m1 = (m + 1) % 3;
    if (sg[m] * sg[m1] < 0) {
      const bool forward = tri[m] < tri[m1];
      const Vec3 &p = forward ? t[m] : t[m1], &q = forward ? t[m1] : t[m];
      if (!boolean_engine::locate_crossing(p, q, f_, on_f)) continue;
      note(work_.add(PointDefinition::edge_plane(n.atom, tri[m], tri[m1], atom_, face_), polyhedra_, on_f, ni));
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

bool AtomTrimmer::intersect() {
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
    if (inside_closed(ImplicitPoint::explicit_point(f_[0]), n)) return false;
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

}  // namespace molsurf::surface_detail::one_pass
