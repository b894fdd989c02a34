#include "geometry/face_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "common/parallel_exceptions.hpp"

namespace molsurf::geometry {

namespace {

BoundingBox union_of(const BoundingBox& a, const BoundingBox& b) {
  BoundingBox u;
  u.min = {std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y), std::min(a.min.z, b.min.z)};
  u.max = {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y), std::max(a.max.z, b.max.z)};
  return u;
}

// Box centre along one axis; NaN becomes 0 so nth_element always sees a strict weak order.
double centre(const BoundingBox& b, int axis) {
  const double c = 0.5 * b.min[axis] + 0.5 * b.max[axis];
  return std::isnan(c) ? 0.0 : c;
}

}  // namespace

BoundingBox face_box(const Mesh& mesh, std::size_t face) {
  const Triangle& t = mesh.faces[face];
  const Vec3& a = mesh.vertices[t[0]];
  const Vec3& b = mesh.vertices[t[1]];
  const Vec3& c = mesh.vertices[t[2]];
  BoundingBox box;
  box.min = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
  box.max = {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
  return box;
}

void BoxBvh::Bounds::resize(std::size_t n) {
  for (auto* v : {&min_x, &min_y, &min_z, &max_x, &max_y, &max_z}) v->resize(n);
}

void BoxBvh::Bounds::set(std::size_t i, const BoundingBox& b) {
  min_x[i] = b.min.x;
  min_y[i] = b.min.y;
  min_z[i] = b.min.z;
  max_x[i] = b.max.x;
  max_y[i] = b.max.y;
  max_z[i] = b.max.z;
}

BoxBvh::BoxBvh(std::span<const BoundingBox> boxes) {
  std::vector<std::uint32_t> ids(boxes.size());
  std::iota(ids.begin(), ids.end(), 0u);
  build(boxes, std::move(ids));
}

BoxBvh BoxBvh::for_faces(const Mesh& mesh, std::span<const std::uint8_t> include) {
  std::vector<BoundingBox> boxes(mesh.faces.size());
  std::vector<std::uint32_t> ids;
  ids.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    boxes[f] = face_box(mesh, f);
    if (include.empty() || include[f]) ids.push_back(static_cast<std::uint32_t>(f));
  }
  BoxBvh bvh;
  bvh.build(boxes, std::move(ids));
  return bvh;
}

void BoxBvh::build(std::span<const BoundingBox> boxes, std::vector<std::uint32_t> ids) {
  item_count_ = ids.size();
  if (ids.empty()) return;

  std::vector<BoundingBox> node_boxes;
  node_boxes.reserve(2 * ids.size() / kLeafSize + 2);
  first_.reserve(node_boxes.capacity());
  count_.reserve(node_boxes.capacity());

  // Box centres once, not in every comparison of every level.
  std::vector<Vec3> centres_of(boxes.size());
  for (const std::uint32_t id : ids) {
    const BoundingBox& b = boxes[id];
    centres_of[id] = {centre(b, 0), centre(b, 1), centre(b, 2)};
  }

  struct Range {
    std::uint32_t node, begin, end;
  };
  std::vector<Range> work{{0, 0, static_cast<std::uint32_t>(ids.size())}};
  node_boxes.emplace_back();
  first_.push_back(0);
  count_.push_back(0);

  while (!work.empty()) {
    const Range r = work.back();
    work.pop_back();
    BoundingBox box, centres;
    for (std::uint32_t k = r.begin; k < r.end; ++k) {
      const BoundingBox& b = boxes[ids[k]];
      box = union_of(box, b);
      const Vec3& c = centres_of[ids[k]];
      centres = union_of(centres, BoundingBox{c, c});
    }
    node_boxes[r.node] = box;
    if (r.end - r.begin <= kLeafSize) {
      first_[r.node] = r.begin;
      count_[r.node] = r.end - r.begin;
      continue;
    }
    const Vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = r.begin + (r.end - r.begin) / 2;
    std::nth_element(ids.begin() + r.begin, ids.begin() + mid, ids.begin() + r.end,
                     [&](std::uint32_t i, std::uint32_t j) { return centres_of[i][axis] < centres_of[j][axis]; });
    const auto left = static_cast<std::uint32_t>(node_boxes.size());
    for (int child = 0; child < 2; ++child) {
      node_boxes.emplace_back();
      first_.push_back(0);
      count_.push_back(0);
    }
    first_[r.node] = left;
    count_[r.node] = 0;
    work.push_back({left, r.begin, mid});
    work.push_back({left + 1, mid, r.end});
  }

  node_count_ = node_boxes.size();
  node_bounds_.resize(node_count_);
  for (std::size_t n = 0; n < node_count_; ++n) node_bounds_.set(n, node_boxes[n]);
  items_ = std::move(ids);
  item_bounds_.resize(items_.size());
  for (std::size_t k = 0; k < items_.size(); ++k) item_bounds_.set(k, boxes[items_[k]]);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> BoxBvh::overlapping_pairs() const {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const auto n = static_cast<std::int64_t>(items_.size());
  ParallelExceptions errors;
#pragma omp parallel
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> local;
#pragma omp for schedule(dynamic, 1024) nowait
    for (std::int64_t k = 0; k < n; ++k)
      errors.run(k, [&] {
        const std::uint32_t i = items_[k];
        BoundingBox query;
        query.min = {item_bounds_.min_x[k], item_bounds_.min_y[k], item_bounds_.min_z[k]};
        query.max = {item_bounds_.max_x[k], item_bounds_.max_y[k], item_bounds_.max_z[k]};
        for_each_overlap(query, [&](std::uint32_t j) {
          if (i < j) local.emplace_back(i, j);
        });
      });
#pragma omp critical(molsurf_bvh_pairs)
    errors.run(n, [&] { pairs.insert(pairs.end(), local.begin(), local.end()); });
  }
  errors.rethrow();
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace molsurf::geometry
