#include "geometry/face_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "common/parallel_exceptions.hpp"
#include "common/parallel_threshold.hpp"
#include "geometry/float_bounds.hpp"

namespace molsurf::geometry {

namespace {

// Box centre along one axis; NaN becomes 0 so nth_element always sees a strict weak order.
float centre(const BoundingBox& b, int axis) {
  const double c = 0.5 * b.min[axis] + 0.5 * b.max[axis];
  return std::isnan(c) ? 0.0f : static_cast<float>(std::clamp(c, -1e38, 1e38));
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
  min_x[i] = float_below(b.min.x);
  min_y[i] = float_below(b.min.y);
  min_z[i] = float_below(b.min.z);
  max_x[i] = float_above(b.max.x);
  max_y[i] = float_above(b.max.y);
  max_z[i] = float_above(b.max.z);
}

void BoxBvh::Bounds::set_union(std::size_t i, const Bounds& from, std::size_t first, std::size_t end) {
  float lo[3] = {from.min_x[first], from.min_y[first], from.min_z[first]};
  float hi[3] = {from.max_x[first], from.max_y[first], from.max_z[first]};
  for (std::size_t k = first + 1; k < end; ++k) {
    lo[0] = std::min(lo[0], from.min_x[k]);
    lo[1] = std::min(lo[1], from.min_y[k]);
    lo[2] = std::min(lo[2], from.min_z[k]);
    hi[0] = std::max(hi[0], from.max_x[k]);
    hi[1] = std::max(hi[1], from.max_y[k]);
    hi[2] = std::max(hi[2], from.max_z[k]);
  }
  min_x[i] = lo[0];
  min_y[i] = lo[1];
  min_z[i] = lo[2];
  max_x[i] = hi[0];
  max_y[i] = hi[1];
  max_z[i] = hi[2];
}

BoxBvh::BoxBvh(std::span<const BoundingBox> boxes) {
  std::vector<std::uint32_t> ids(boxes.size());
  std::iota(ids.begin(), ids.end(), 0u);
  build([boxes](std::uint32_t id) { return boxes[id]; }, std::move(ids));
}

BoxBvh BoxBvh::for_faces(const Mesh& mesh, std::span<const std::uint8_t> include) {
  std::vector<std::uint32_t> ids;
  ids.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (include.empty() || include[f]) ids.push_back(static_cast<std::uint32_t>(f));
  // A face's box is recomputed from its corners where needed (twice per face) instead of
  // being stored: on a 10 M-face surface that saves the largest array of the build.
  BoxBvh bvh;
  bvh.build([&mesh](std::uint32_t f) { return face_box(mesh, f); }, std::move(ids));
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
// selections stream through contiguous memory. Single precision is enough to order
// centres (any order gives a correct tree) and halves the memory.
struct SortItem {
  float centre[3];
  std::uint32_t id;
};

}  // namespace

// Node `node` covers items [begin, end); its children are the pair at `next`, and their
// descendants follow: the left child's first, then the right child's. A leaf writes its
// items and their boxes in their final positions; an inner node's box is the union of its
// children's, computed after them.
template <class BoxOf>
struct BoxBvh::Builder {
  const BoxOf& box_of;
  std::vector<SortItem>& items;
  BoxBvh& tree;

  // Ranges smaller than this are built by the task that reached them.
  static constexpr std::uint32_t kTaskItems = 8192;

  void build(std::uint32_t node, std::uint32_t next, std::uint32_t begin, std::uint32_t end) {
    if (end - begin <= kLeafSize) {
      tree.first_[node] = begin;
      tree.count_[node] = end - begin;
      tree.item_end_[node] = end;
      for (std::uint32_t k = begin; k < end; ++k) {
        tree.items_[k] = items[k].id;
        tree.item_bounds_.set(k, box_of(items[k].id));
      }
      tree.node_bounds_.set_union(node, tree.item_bounds_, begin, end);
      return;
    }
    float lo[3] = {items[begin].centre[0], items[begin].centre[1], items[begin].centre[2]};
    float hi[3] = {lo[0], lo[1], lo[2]};
    for (std::uint32_t k = begin + 1; k < end; ++k)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], items[k].centre[a]);
        hi[a] = std::max(hi[a], items[k].centre[a]);
      }
    const float ex = hi[0] - lo[0], ey = hi[1] - lo[1], ez = hi[2] - lo[2];
    const int axis = ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [axis](const SortItem& a, const SortItem& b) { return a.centre[axis] < b.centre[axis]; });
    tree.first_[node] = next;
    tree.count_[node] = 0;
    tree.item_end_[node] = end;
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
    tree.node_bounds_.set_union(node, tree.node_bounds_, next, next + 2);
  }
};

template <class BoxOf>
void BoxBvh::build(const BoxOf& box_of, std::vector<std::uint32_t> ids) {
  item_count_ = ids.size();
  if (ids.empty()) return;
  const auto n = static_cast<std::int64_t>(ids.size());

  std::vector<SortItem> items(ids.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::int64_t k = 0; k < n; ++k) {
    const BoundingBox b = box_of(ids[k]);
    items[k] = {{centre(b, 0), centre(b, 1), centre(b, 2)}, ids[k]};
  }
  ids = {};
  node_count_ = subtree_nodes(static_cast<std::uint32_t>(items.size()));
  first_.assign(node_count_, 0);
  count_.assign(node_count_, 0);
  item_end_.assign(node_count_, 0);
  node_bounds_.resize(node_count_);
  items_.resize(items.size());
  item_bounds_.resize(items.size());
  Builder<BoxOf> builder{box_of, items, *this};
#pragma omp parallel if (n >= kParallelMinItems)
#pragma omp single
  builder.build(0, 1, 0, static_cast<std::uint32_t>(items.size()));

  for (std::uint32_t node = 0; node < node_count_; ++node)
    if (count_[node] > 0) leaves_.push_back(node);
  std::sort(leaves_.begin(), leaves_.end(), [&](std::uint32_t a, std::uint32_t b) { return first_[a] < first_[b]; });
}

void BoxBvh::set_keys(const std::function<Keys(std::uint32_t item)>& keys_of) {
  // Bottom up: a node's children have higher indices than it (Builder's layout).
  node_keys_.assign(node_count_, Keys{kNoKey, kNoKey, kNoKey});
  auto common = [](const Keys& a, const Keys& b) {
    Keys both{kNoKey, kNoKey, kNoKey};
    int n = 0;
    for (const std::uint32_t k : a)
      if (k != kNoKey && (k == b[0] || k == b[1] || k == b[2])) both[n++] = k;
    return both;  // sorted, as `a` is
  };
  for (std::uint32_t node = node_count_; node-- > 0;) {
    if (count_[node] == 0) {
      node_keys_[node] = common(node_keys_[first_[node]], node_keys_[first_[node] + 1]);
      continue;
    }
    Keys keys = keys_of(items_[first_[node]]);
    for (std::uint32_t k = first_[node] + 1; k < first_[node] + count_[node] && keys[0] != kNoKey; ++k)
      keys = common(keys, keys_of(items_[k]));
    node_keys_[node] = keys;
  }
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
        const BoundingBox query = item_bounds_.get(static_cast<std::size_t>(k));
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
