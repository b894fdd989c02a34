#include "boolean/advancing_front.hpp"

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

class AdvancingFront {
 public:
  AdvancingFront(const FaceToSplit& face, const FacePoints& points) : face_(face), points_(points) {
    const int n = static_cast<int>(points.ids().size());
    n_ = points.ids().size();
    if (n_ <= kMemoPoints) memo_.assign(n_ * n_ * n_, kUnknown);
    for (int i = 0; i < n; ++i) {
      const ImplicitPoint& p = points.point(i);
      const auto &iu = p.coordinate(face.projection.u), &iv = p.coordinate(face.projection.v);
      approx_.push_back({iu.mid(), iv.mid()});
      box_.push_back({iu.lo, iu.hi, iv.lo, iv.hi});
    }
    lines_.assign(n, 0);
    for (std::size_t k = 0; k < face.collinear_sets.size() && k < 64; ++k)
      for (std::uint32_t id : face.collinear_sets[k]) lines_[points.local(id)] |= std::uint64_t{1} << k;
    const int nb = static_cast<int>(face.boundary.size());
    for (int i = 0; i < nb; ++i) add_edge(points.local(face.boundary[i]), points.local(face.boundary[(i + 1) % nb]));
    for (auto [s, t] : face.constraints) {
      const int a = points.local(s), b = points.local(t);
      add_edge(a, b);
      add_edge(b, a);
    }
  }

  std::vector<std::array<std::uint32_t, 3>> run() {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    const std::size_t limit = 4 * points_.ids().size() + 4 * face_.constraints.size() + 16;
    while (!front_.empty()) {
      // The shortest front edge (ties by its ends: deterministic).
      std::size_t next = 0;
      for (std::size_t k = 1; k < front_.size(); ++k)
        if (std::tie(front_[k].length, front_[k].a, front_[k].b) <
            std::tie(front_[next].length, front_[next].a, front_[next].b))
          next = k;
      const int a = front_[next].a, b = front_[next].b;
      const int p = best_apex(a, b);
      if (p < 0)
        throw std::logic_error("boolean: the advancing front found no valid triangle on a front edge (" +
                               std::to_string(points_.ids().size()) + " points)");
      const auto& ids = points_.ids();
      triangles.push_back({ids[a], ids[b], ids[p]});
      if (triangles.size() > limit) throw std::logic_error("boolean: the advancing front does not terminate");
      remove_edge(a, b);
      close_or_open(b, p);
      close_or_open(p, a);
    }
    return triangles;
  }

 private:
  struct FrontEdge {
    double length;
    int a, b;
  };

  // Orientation of three local points, each triple evaluated once (the front asks for the
  // same triples over and over, in every order).
  int orient(int a, int b, int c) const {
    if (lines_[a] & lines_[b] & lines_[c]) return 0;  // collinear by construction
    if (memo_.empty()) return points_.orient(a, b, c);
    int sign = 1;
    if (a > b) std::swap(a, b), sign = -sign;
    if (b > c) std::swap(b, c), sign = -sign;
    if (a > b) std::swap(a, b), sign = -sign;
    std::int8_t& known = memo_[(static_cast<std::size_t>(a) * n_ + b) * n_ + c];
    if (known == kUnknown) known = static_cast<std::int8_t>(points_.orient(a, b, c));
    return sign * known;
  }

  double approx_length(int a, int b) const {
    const double dx = approx_[b][0] - approx_[a][0], dy = approx_[b][1] - approx_[a][1];
    return std::sqrt(dx * dx + dy * dy);
  }

  std::size_t find_edge(int a, int b) const {
    for (std::size_t k = 0; k < front_.size(); ++k)
      if (front_[k].a == a && front_[k].b == b) return k;
    return front_.size();
  }
  void add_edge(int a, int b) {
    if (find_edge(a, b) == front_.size()) front_.push_back({approx_length(a, b), a, b});
  }
  void remove_edge(int a, int b) {
    const std::size_t k = find_edge(a, b);
    front_[k] = front_.back();
    front_.pop_back();
  }
  // The new triangle's edge from -> to: closes the front edge (from, to) if the front has
  // it (the region there is now filled), otherwise opens (to, from) on the far side.
  void close_or_open(int from, int to) {
    if (find_edge(from, to) != front_.size())
      remove_edge(from, to);
    else
      add_edge(to, from);
  }

  // Delaunay criterion: the apex whose circumcircle through a, b reaches least far to the
  // left of ab (its centre's signed offset along the left normal). Approximate.
  double delaunay_offset(int a, int b, int p) const {
    const double ax = approx_[a][0], ay = approx_[a][1];
    const double bx = approx_[b][0] - ax, by = approx_[b][1] - ay;
    const double px = approx_[p][0] - ax, py = approx_[p][1] - ay;
    const double d = 2 * (bx * py - by * px);
    if (d <= 0) return std::numeric_limits<double>::infinity();
    const double b2 = bx * bx + by * by, p2 = px * px + py * py;
    const double cx = (py * b2 - by * p2) / d, cy = (bx * p2 - px * b2) / d;
    // Offset of the centre from the midpoint along the left normal (-by, bx) / |b|.
    return ((cx - bx / 2) * -by + (cy - by / 2) * bx) / std::sqrt(b2);
  }

  // Interval boxes that prove a point outside a closed triangle, or two segments apart
  // (most candidates, without their exact orientations).
  bool outside_box(int w, int p, int c, int q) const {
    const auto &bw = box_[w], &bp = box_[p], &bc = box_[c], &bq = box_[q];
    return bw[1] < std::min({bp[0], bc[0], bq[0]}) || bw[0] > std::max({bp[1], bc[1], bq[1]}) ||
           bw[3] < std::min({bp[2], bc[2], bq[2]}) || bw[2] > std::max({bp[3], bc[3], bq[3]});
  }
  bool boxes_apart(int a, int b, int c, int d) const {
    const auto &ba = box_[a], &bb = box_[b], &bc = box_[c], &bd = box_[d];
    return std::max(ba[1], bb[1]) < std::min(bc[0], bd[0]) || std::max(bc[1], bd[1]) < std::min(ba[0], bb[0]) ||
           std::max(ba[3], bb[3]) < std::min(bc[2], bd[2]) || std::max(bc[3], bd[3]) < std::min(ba[2], bb[2]);
  }

  bool properly_crosses(int a, int b, int c, int d) const {
    const int o1 = orient(a, b, c), o2 = orient(a, b, d);
    if (o1 == 0 || o2 == 0 || o1 == o2) return false;
    const int o3 = orient(c, d, a), o4 = orient(c, d, b);
    return o3 != 0 && o4 != 0 && o3 != o4;
  }

  bool valid_triangle(int a, int b, int p) const {
    const int n = static_cast<int>(points_.ids().size());
    for (int q = 0; q < n; ++q) {
      if (q == a || q == b || q == p || outside_box(q, a, b, p)) continue;
      if (orient(a, b, q) >= 0 && orient(b, p, q) >= 0 && orient(p, a, q) >= 0) return false;
    }
    for (const FrontEdge& edge : front_) {
      const int c = edge.a, d = edge.b;
      for (auto [s, t] : {Edge{b, p}, Edge{p, a}}) {
        if (c == s || c == t || d == s || d == t || boxes_apart(s, t, c, d)) continue;
        if (properly_crosses(s, t, c, d)) return false;
      }
    }
    return true;
  }

  int best_apex(int a, int b) const {
    std::vector<std::pair<double, int>>& candidates = candidates_;
    candidates.clear();
    const int n = static_cast<int>(points_.ids().size());
    for (int p = 0; p < n; ++p)
      if (p != a && p != b && orient(a, b, p) > 0) candidates.emplace_back(delaunay_offset(a, b, p), p);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [offset, p] : candidates)
      if (valid_triangle(a, b, p)) return p;
    return -1;
  }

  const FaceToSplit& face_;
  const FacePoints& points_;
  std::vector<std::array<double, 2>> approx_;
  std::vector<std::array<double, 4>> box_;  // u lo, u hi, v lo, v hi
  using Edge = std::pair<int, int>;
  static constexpr std::int8_t kUnknown = 2;
  static constexpr std::size_t kMemoPoints = 32;  // beyond: no memo (n^3 bytes)
  std::vector<std::uint64_t> lines_;  // bit k: on collinear set k
  std::vector<FrontEdge> front_;
  std::size_t n_ = 0;
  mutable std::vector<std::int8_t> memo_;
  mutable std::vector<std::pair<double, int>> candidates_;
};

}  // namespace

std::vector<std::array<std::uint32_t, 3>> retriangulate_face(const FaceToSplit& face, const FacePoints& points) {
  return AdvancingFront(face, points).run();
}

}  // namespace molsurf::boolean_engine
