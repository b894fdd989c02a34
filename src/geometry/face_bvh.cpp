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
  const auto nf = static_cast<std::int64_t>(mesh.faces.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t f = 0; f < nf; ++f) boxes[f] = face_box(mesh, static_cast<std::size_t>(f));
  std::vector<std::uint32_t> ids;
  ids.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (include.empty() || include[f]) ids.push_back(static_cast<std::uint32_t>(f));
  BoxBvh bvh;
  bvh.build(boxes, std::move(ids));
  return bvh;
}

namespace {

// The number of nodes over `items` items: it depends on the count alone, because every
// split is at the middle position. It lets every subtree know its node indices before it
// is built, so subtrees are built in parallel into one array, in the same layout as a
// serial build.
std::uint32_t subtree_nodes(std::uint32_t items) {
  if (items <= BoxBvh::kLeafSize) return 1;
  return 1 + subtree_nodes(items / 2) + subtree_nodes(items - items / 2);
}

// An item being sorted into leaf order: its centre travels with it, so the median
// selections stream through contiguous memory.
struct SortItem {
  double centre[3];
  std::uint32_t id;
};

}  // namespace

// Node `node` covers items [begin, end); its children are the pair at `next`, and their
// descendants follow: the left child's first, then the right child's. A node's box is the
// union of its children's, computed after them.
struct BoxBvh::Builder {
  std::span<const BoundingBox> boxes;
  std::vector<SortItem>& items;
  std::vector<BoundingBox>& node_boxes;
  std::vector<std::uint32_t>& first;
  std::vector<std::uint32_t>& count;
  std::vector<std::uint32_t>& item_end;

  // Ranges smaller than this are built by the task that reached them.
  static constexpr std::uint32_t kTaskItems = 8192;

  void build(std::uint32_t node, std::uint32_t next, std::uint32_t begin, std::uint32_t end) {
    if (end - begin <= kLeafSize) {
      first[node] = begin;
      count[node] = end - begin;
      item_end[node] = end;
      BoundingBox box;
      for (std::uint32_t k = begin; k < end; ++k) box = union_of(box, boxes[items[k].id]);
      node_boxes[node] = box;
      return;
    }
    BoundingBox centres;
    for (std::uint32_t k = begin; k < end; ++k) {
      const Vec3 c{items[k].centre[0], items[k].centre[1], items[k].centre[2]};
      centres = union_of(centres, BoundingBox{c, c});
    }
    const Vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [axis](const SortItem& a, const SortItem& b) { return a.centre[axis] < b.centre[axis]; });
    first[node] = next;
    count[node] = 0;
    item_end[node] = end;
    const std::uint32_t left_next = next + 2;
    const std::uint32_t right_next = left_next + subtree_nodes(mid - begin) - 1;
    if (end - begin >= kTaskItems) {
#pragma omp task default(shared) firstprivate(next, left_next, begin, mid)
      build(next, left_next, begin, mid);
      build(next + 1, right_next, mid, end);
#pragma omp taskwait
    } else {
      build(next, left_next, begin, mid);
      build(next + 1, right_next, mid, end);
    }
    node_boxes[node] = union_of(node_boxes[next], node_boxes[next + 1]);
  }
};

void BoxBvh::build(std::span<const BoundingBox> boxes, std::vector<std::uint32_t> ids) {
  item_count_ = ids.size();
  if (ids.empty()) return;
  const auto n = static_cast<std::int64_t>(ids.size());

  std::vector<SortItem> items(ids.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < n; ++k) {
    const BoundingBox& b = boxes[ids[k]];
    items[k] = {{centre(b, 0), centre(b, 1), centre(b, 2)}, ids[k]};
  }
  node_count_ = subtree_nodes(static_cast<std::uint32_t>(ids.size()));
  std::vector<BoundingBox> node_boxes(node_count_);
  first_.assign(node_count_, 0);
  count_.assign(node_count_, 0);
  item_end_.assign(node_count_, 0);
  Builder builder{boxes, items, node_boxes, first_, count_, item_end_};
#pragma omp parallel
#pragma omp single
  builder.build(0, 1, 0, static_cast<std::uint32_t>(ids.size()));

  node_bounds_.resize(node_count_);
  items_.resize(items.size());
  item_bounds_.resize(items.size());
  const auto nodes = static_cast<std::int64_t>(node_count_);
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (std::int64_t k = 0; k < nodes; ++k) node_bounds_.set(static_cast<std::size_t>(k), node_boxes[k]);
#pragma omp for schedule(static) nowait
    for (std::int64_t k = 0; k < n; ++k) {
      items_[k] = items[k].id;
      item_bounds_.set(static_cast<std::size_t>(k), boxes[items[k].id]);
    }
  }
  for (std::uint32_t node = 0; node < node_count_; ++node)
    if (count_[node] > 0) leaves_.push_back(node);
  std::sort(leaves_.begin(), leaves_.end(), [&](std::uint32_t a, std::uint32_t b) { return first_[a] < first_[b]; });
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
