#include "boolean/face_points.hpp"

#include "geometry/exact_integers.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>


namespace molsurf::boolean_engine {

using geometry::ImplicitPoint;

namespace {

// Exact comparison of one coordinate of two implicit points.
int compare_coordinate(const ImplicitPoint& p, const ImplicitPoint& q, int axis) {
  const geometry::Interval &a = p.coordinate(axis), &b = q.coordinate(axis);
  if (const int order = geometry::certain_order(a, b)) return order;
  const int e = geometry::common_exponent_of({&p, &q});
  const int s = geometry::compare_homogeneous(p.small_homogeneous(e), q.small_homogeneous(e), axis);
  if (s != geometry::kSmallOverflow) return s;
  return geometry::compare_homogeneous(p.homogeneous(e), q.homogeneous(e), axis);
}

}  // namespace

void sort_along_segment(std::vector<std::uint32_t>& ids, const Vec3& from, const Vec3& to,
                        std::span<const ImplicitPoint> points) {
  const Vec3 d = to - from;
  const int axis = std::fabs(d.x) >= std::fabs(d.y) && std::fabs(d.x) >= std::fabs(d.z) ? 0
                   : std::fabs(d.y) >= std::fabs(d.z)                                 ? 1
                                                                                       : 2;
  const bool ascending = d[axis] > 0;
  std::sort(ids.begin(), ids.end(), [&](std::uint32_t i, std::uint32_t j) {
    const int c = compare_coordinate(points[i], points[j], axis);
    return ascending ? c < 0 : c > 0;
  });
}

void FaceToSplit::add_edge(int k, std::uint32_t from, std::uint32_t to, std::vector<std::uint32_t>& inside,
                           const Vec3& a, const Vec3& b, std::span<const ImplicitPoint> points) {
  sort_along_segment(inside, a, b, points);
  std::vector<std::uint32_t>& run = edge_runs[k];
  run.clear();
  run.push_back(from);
  run.insert(run.end(), inside.begin(), inside.end());
  run.push_back(to);
  boundary.push_back(from);
  boundary.insert(boundary.end(), inside.begin(), inside.end());
}

bool FaceToSplit::on_one_edge(std::uint32_t s, std::uint32_t t) const {
  for (const auto& run : edge_runs)
    if (std::find(run.begin(), run.end(), s) != run.end() && std::find(run.begin(), run.end(), t) != run.end())
      return true;
  return false;
}

FacePoints::FacePoints(std::vector<std::uint32_t> ids, std::span<const ImplicitPoint> all, Projection projection)
    : ids_(std::move(ids)),
      all_(all),
      projection_(projection),
      exponent_(INT_MAX) {
  if (ids_.empty()) return;
  const auto [lowest, highest] = std::minmax_element(ids_.begin(), ids_.end());
  first_id_ = *lowest;
  // Ids close together (the one-pass union numbers each face's points from 0): a table
  // indexed by id; spread out (the pairwise engine's global ids): a sorted list.
  if (*highest - *lowest < 4 * ids_.size() + 64) {
    dense_.assign(*highest - *lowest + 1, -1);
    for (int i = 0; i < static_cast<int>(ids_.size()); ++i)
      if (int& slot = dense_[ids_[i] - first_id_]; slot < 0) slot = i;
    return;
  }
  local_.reserve(ids_.size());
  for (int i = 0; i < static_cast<int>(ids_.size()); ++i) local_.emplace_back(ids_[i], i);
  std::sort(local_.begin(), local_.end());
}

int FacePoints::local(std::uint32_t id) const {
  if (!dense_.empty()) {
    if (id >= first_id_ && id - first_id_ < dense_.size())
      if (const int i = dense_[id - first_id_]; i >= 0) return i;
  } else {
    const auto it = std::lower_bound(local_.begin(), local_.end(), std::pair<std::uint32_t, int>{id, INT_MIN});
    if (it != local_.end() && it->first == id) return it->second;
  }
  throw std::out_of_range("boolean: a point that is not on this face");
}

int FacePoints::exponent() const {
  if (exponent_ == INT_MAX) {
    int lowest = INT_MAX;
    for (std::uint32_t id : ids_) lowest = std::min(lowest, geometry::common_exponent(all_[id].defining_values()));
    exponent_ = lowest == INT_MAX ? 0 : lowest;
  }
  return exponent_;
}

const geometry::SmallHomogeneousPoint& FacePoints::small(int i) const {
  if (small_.empty()) small_.resize(ids_.size());  // most faces never need an exact form
  if (!small_[i]) small_[i] = point(i).small_homogeneous(exponent());
  return *small_[i];
}

const geometry::HomogeneousPoint& FacePoints::exact(int i) const {
  if (exact_.empty()) exact_.resize(ids_.size());
  if (!exact_[i]) exact_[i] = point(i).homogeneous(exponent());
  return *exact_[i];
}

int FacePoints::orient(int a, int b, int c) const {
  const ImplicitPoint &pa = point(a), &pb = point(b), &pc = point(c);
  const int u = projection_.u, v = projection_.v;
  if (pa.is_explicit() && pb.is_explicit() && pc.is_explicit()) return geometry::orient2d(pa, pb, pc, u, v);
  const geometry::Interval filtered = (pb.coordinate(u) - pa.coordinate(u)) * (pc.coordinate(v) - pa.coordinate(v)) -
                                      (pb.coordinate(v) - pa.coordinate(v)) * (pc.coordinate(u) - pa.coordinate(u));
  if (const int s = filtered.certain_sign()) return s;
  if (const int s = geometry::orient2d_homogeneous(small(a), small(b), small(c), u, v); s != geometry::kSmallOverflow)
    return s;
  return geometry::orient2d_homogeneous(exact(a), exact(b), exact(c), u, v);
}

int FacePoints::compare(int a, int b, int axis) const {
  const geometry::Interval &x = point(a).coordinate(axis), &y = point(b).coordinate(axis);
  if (const int order = geometry::certain_order(x, y)) return order;
  if (const int s = geometry::compare_homogeneous(small(a), small(b), axis); s != geometry::kSmallOverflow) return s;
  return geometry::compare_homogeneous(exact(a), exact(b), axis);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> split_segments_at_points(
    std::span<const std::pair<std::uint32_t, std::uint32_t>> segments, const FacePoints& points,
    std::vector<std::vector<std::uint32_t>>& collinear_sets, std::span<const std::vector<std::uint32_t>> known_inside) {
  const Projection& pr = points.projection();
  auto strictly_between = [&](int p, int x, int q) {  // on the common line of p, x, q
    for (int axis : {pr.u, pr.v}) {
      const int pq = points.compare(p, q, axis);
      if (pq == 0) continue;
      return points.compare(p, x, axis) == pq && points.compare(x, q, axis) == pq;
    }
    return false;
  };
  const int n = static_cast<int>(points.ids().size());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pieces;
  std::vector<std::uint8_t> known(n, 0);
  for (std::size_t segment = 0; segment < segments.size(); ++segment) {
    const auto [s_id, t_id] = segments[segment];
    const int s = points.local(s_id), t = points.local(t_id);
    std::vector<int> inside;
    if (!known_inside.empty())
      for (std::uint32_t id : known_inside[segment]) {
        const int c = points.local(id);
        if (!known[c]) inside.push_back(c);
        known[c] = 1;
      }
    // A point strictly inside the segment lies in its box: intervals rule most out.
    auto outside_box = [&](int c) {
      for (int axis : {pr.u, pr.v}) {
        const auto &is = points.point(s).coordinate(axis), &it = points.point(t).coordinate(axis);
        const auto& ic = points.point(c).coordinate(axis);
        if (ic.hi < std::min(is.lo, it.lo) || ic.lo > std::max(is.hi, it.hi)) return true;
      }
      return false;
    };
    for (int c = 0; c < n; ++c) {
      if (c == s || c == t || known[c] || outside_box(c)) continue;
      if (points.orient(s, t, c) != 0) continue;
      if (strictly_between(s, c, t)) inside.push_back(c);
    }
    for (int c : inside) known[c] = 0;
    std::vector<std::uint32_t>& line = collinear_sets.emplace_back();
    for (int c : inside) line.push_back(points.ids()[c]);
    line.push_back(s_id);
    line.push_back(t_id);
    if (inside.empty()) {
      pieces.emplace_back(s_id, t_id);
      continue;
    }
    // Order along s -> t on an axis where they differ.
    const int axis = points.compare(s, t, pr.u) != 0 ? pr.u : pr.v;
    const int direction = points.compare(s, t, axis);
    std::sort(inside.begin(), inside.end(), [&](int i, int j) { return points.compare(i, j, axis) == direction; });
    std::uint32_t previous = s_id;
    for (int c : inside) {
      const std::uint32_t id = points.ids()[c];
      pieces.emplace_back(std::min(previous, id), std::max(previous, id));
      previous = id;
    }
    pieces.emplace_back(std::min(previous, t_id), std::max(previous, t_id));
  }
  std::sort(pieces.begin(), pieces.end());
  pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
  return pieces;
}

}  // namespace molsurf::boolean_engine
