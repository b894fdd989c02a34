#pragma once
// Step 3, split (paper §2.3): a cut face's points in its own plane, with exact predicates,
// and its constraint segments split at the points on them. The triangulations that use
// them: ear_clipping.hpp (tried first) and advancing_front.hpp (the fallback).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "boolean/intersect.hpp"
#include "geometry/implicit_point.hpp"

namespace molsurf::boolean_engine {

struct FaceToSplit {
  // Boundary points counter-clockwise in the projection: corner 0, the points inside edge
  // 0 in order, corner 1, ... (point ids).
  std::vector<std::uint32_t> boundary;
  std::vector<std::uint32_t> interior;  // points strictly inside the face
  // Constraint segments not on the boundary, with no point strictly inside any of them.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> constraints;
  // Sets of points collinear by construction (the points on one edge of the face, the
  // points on one intersection segment): any three of a set have orient2d = 0, known
  // without arithmetic (their exact evaluation is the expensive case of the filter).
  std::vector<std::vector<std::uint32_t>> collinear_sets;
  Projection projection;
  // Each edge's points from its first corner to its second, corners included.
  std::array<std::vector<std::uint32_t>, 3> edge_runs;

  // Edge k, from the point `from` (corner k) to `to`, with the points strictly inside it
  // (`inside`, sorted here exactly along the edge from a to b): its run, and its part of
  // the boundary. The edges are added in order, 0 to 2.
  void add_edge(int k, std::uint32_t from, std::uint32_t to, std::vector<std::uint32_t>& inside, const Vec3& a,
                const Vec3& b, std::span<const geometry::ImplicitPoint> points);
  // s and t lie on one edge: a segment between them runs along the boundary (no constraint).
  bool on_one_edge(std::uint32_t s, std::uint32_t t) const;
};

// The points of one face with exact predicates in its projection: the interval filter
// first, then integer homogeneous coordinates at one exponent for the whole face (inline
// fixed-size integers, GMP's mpz when those overflow), each built once (points are shared
// by several predicates, and their exact form is costly).
class FacePoints {
 public:
  FacePoints(std::vector<std::uint32_t> ids, std::span<const geometry::ImplicitPoint> all, Projection projection);
  const std::vector<std::uint32_t>& ids() const { return ids_; }
  int local(std::uint32_t id) const;
  const geometry::ImplicitPoint& point(int i) const { return all_[ids_[i]]; }
  const Projection& projection() const { return projection_; }
  int orient(int a, int b, int c) const;       // local indices
  int compare(int a, int b, int axis) const;   // exact order of one coordinate

 private:
  int exponent() const;
  const geometry::SmallHomogeneousPoint& small(int i) const;  // may have overflowed
  const geometry::HomogeneousPoint& exact(int i) const;

  std::vector<std::uint32_t> ids_;
  std::span<const geometry::ImplicitPoint> all_;
  Projection projection_;
  // The local index of an id: dense_[id - first_id_] (-1: not on the face) when the ids
  // lie close together, else found in local_, (id, local index) pairs sorted.
  std::uint32_t first_id_ = 0;
  std::vector<int> dense_;
  std::vector<std::pair<std::uint32_t, int>> local_;
  mutable std::vector<std::optional<geometry::SmallHomogeneousPoint>> small_;
  mutable std::vector<std::optional<geometry::HomogeneousPoint>> exact_;
  mutable int exponent_;
};

// Sorts `ids` (points strictly inside the segment from -> to) along it, exactly.
void sort_along_segment(std::vector<std::uint32_t>& ids, const Vec3& from, const Vec3& to,
                        std::span<const geometry::ImplicitPoint> points);

// Splits each segment at the face's points lying strictly inside it (exact
// collinearity in `projection` and betweenness), returning the pieces; each segment's
// points (ends included) are appended to `collinear_sets`. `known_inside` (empty, or one
// list per segment) names points the caller built strictly inside a segment (where two
// traces cross): they are taken without a test, whose exact zero is the filter's costly case.
std::vector<std::pair<std::uint32_t, std::uint32_t>> split_segments_at_points(
    std::span<const std::pair<std::uint32_t, std::uint32_t>> segments, const FacePoints& points,
    std::vector<std::vector<std::uint32_t>>& collinear_sets,
    std::span<const std::vector<std::uint32_t>> known_inside = {});

}  // namespace molsurf::boolean_engine
