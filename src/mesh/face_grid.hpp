#pragma once
// The editing layer's spatial index of faces: which faces lie near a box, while the faces
// change (src/mesh/mesh_editor.hpp; the cleanup's crossing tests).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "geometry/float_bounds.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {

// Faces by the cells of a uniform grid their boxes touch, with each face's box kept for a
// cheap rejection. The exact crossing test of an edit needs every face near its new
// faces; the faces change as edits go on, but only a few percent of them. So the
// faces as they are at construction sit in flat arrays (cells in a dense grid over the
// mesh's box, one counting pass and one filling pass), and a face that changes leaves
// them for small lists kept per block of 2 x 2 x 2 cells (a block is written only by the
// edits near it, so edits far apart may change faces at the same time; see shard_side).
// Cells outside the dense grid are clamped onto its border, the same way for insertion
// and query, so nothing is missed. Faces appended after construction are not kept.
class FaceGrid {
 public:
  // Cells of side `cell`, enlarged until the grid has at most about 4 cells per face (a
  // surface fills few of a volume's cells; the capsid would otherwise need 64 M) and its
  // entries fit 32-bit offsets. The faces' boxes are stored in single precision, rounded
  // outward (a box only rejects), and the cells' offsets in 32 bits: on the largest
  // surfaces this index is the cleanup's largest array (docs/performance.md, "Memory").
  FaceGrid(const Mesh& m, double cell, std::uint64_t max_entries = kMaxEntries)
      : m_(m), box_(std::make_unique_for_overwrite<StoredBox[]>(m.faces.size())), in_flat_(m.faces.size(), 1) {
    // The faces' boxes, and with them the mesh's (of every face's corners, exactly).
    BoundingBox all;
    const auto nf = static_cast<std::int64_t>(m.faces.size());
#pragma omp parallel
    {
      BoundingBox part;
#pragma omp for schedule(static) nowait
      for (std::int64_t f = 0; f < nf; ++f) {
        const BoundingBox b = bounding_box(m, static_cast<std::size_t>(f));
        box_[f] = StoredBox::of(b);
        part.extend(b);
      }
#pragma omp critical(molsurf_face_grid_box)
      all.extend(part);
    }
    origin_ = all.empty() ? Vec3{} : all.min;
    const Vec3 extent = all.empty() ? Vec3{} : all.max - all.min;
    const double max_cells = 4.0 * static_cast<double>(std::max<std::size_t>(m.faces.size(), 1)) + 64;
    // Counting in parallel, then filling each cell from its end down: the order of a
    // cell's faces depends on the threads, but a query's answer is a set (every caller's
    // result is the same for any order of visits), so no editor's result does.
    for (;; cell *= 1.25) {
      for (int a = 0; a < 3; ++a) size_[a] = static_cast<std::int64_t>(std::floor(extent[a] / cell)) + 1;
      if (static_cast<double>(size_[0]) * static_cast<double>(size_[1]) * static_cast<double>(size_[2]) > max_cells)
        continue;
      inverse_cell_ = 1.0 / cell;
      for (int a = 0; a < 3; ++a) shards_size_[a] = (size_[a] + kShard - 1) / kShard;  // for_cells names blocks
      const std::size_t cells = static_cast<std::size_t>(size_[0] * size_[1] * size_[2]);
      start_.assign(cells + 1, 0);
      std::uint64_t entries = 0;
#pragma omp parallel for schedule(static) reduction(+ : entries)
      for (std::int64_t f = 0; f < nf; ++f)
        for_cells(box(static_cast<std::uint32_t>(f)), [&](std::uint64_t c, std::size_t) {
          std::atomic_ref(start_[c]).fetch_add(1, std::memory_order_relaxed);
          ++entries;
        });
      if (entries > max_entries) continue;  // coarser cells hold each face fewer times
      for (std::size_t c = 1; c < cells; ++c) start_[c] += start_[c - 1];
      start_[cells] = static_cast<std::uint32_t>(entries);
      flat_.resize(entries);
#pragma omp parallel for schedule(static)
      for (std::int64_t f = 0; f < nf; ++f)
        for_cells(box(static_cast<std::uint32_t>(f)), [&](std::uint64_t c, std::size_t) {
          flat_[std::atomic_ref(start_[c]).fetch_sub(1, std::memory_order_relaxed) - 1] = static_cast<std::uint32_t>(f);
        });
      break;
    }
    cell_ = cell;
    moved_.resize(static_cast<std::size_t>(shards_size_[0] * shards_size_[1] * shards_size_[2]));
  }

  // Before face f changes (or goes): its present cells forget it.
  void erase(std::uint32_t f) {
    if (in_flat_[f]) {
      in_flat_[f] = 0;  // its flat entries are skipped from now on
      return;
    }
    for_cells(box(f), [&](std::uint64_t c, std::size_t shard) { std::erase(*moved_[shard], Moved{c, f}); });
  }
  // After face f changed (or came back): indexed at its present corners.
  void insert(std::uint32_t f) {
    box_[f] = StoredBox::of(bounding_box(m_, f));
    for_cells(box(f), [&](std::uint64_t c, std::size_t shard) {
      auto& list = moved_[shard];
      if (!list) list = std::make_unique<std::vector<Moved>>();
      list->push_back({c, f});
    });
  }

  // Face f's box as indexed: it holds the face's box as it was then.
  BoundingBox box(std::uint32_t f) const {
    BoundingBox b;
    b.min = {box_[f].min[0], box_[f].min[1], box_[f].min[2]};
    b.max = {box_[f].max[0], box_[f].max[1], box_[f].max[2]};
    return b;
  }
  double cell_size() const { return cell_; }
  // Insertions and erasures in one box and queries in another may run at the same time
  // when the two boxes are this far apart on some axis (their cells then fall in
  // different blocks).
  double shard_side() const { return (kShard + 2) * cell_; }

  // Calls visit(f) for every indexed face in a cell `box` touches (a face may come more
  // than once) until visit returns false; returns false if it did.
  template <class Visit>
  bool near(const BoundingBox& box, Visit&& visit) const {
    bool go_on = true;
    for_cells(box, [&](std::uint64_t c, std::size_t shard) {
      if (!go_on) return;
      for (std::uint64_t k = start_[c]; go_on && k < start_[c + 1]; ++k)
        if (in_flat_[flat_[k]]) go_on = visit(flat_[k]);
      if (!go_on) return;
      if (const auto& list = moved_[shard])
        for (const Moved& entry : *list)
          if (entry.cell == c && !(go_on = visit(entry.face))) return;
    });
    return go_on;
  }

 private:
  static constexpr std::int64_t kShard = 2;
  static constexpr std::uint64_t kMaxEntries = std::numeric_limits<std::uint32_t>::max();
  struct Moved {
    std::uint64_t cell;
    std::uint32_t face;
    bool operator==(const Moved&) const = default;
  };
  // Calls f(cell, its block) for every cell of the dense grid that box b touches.
  template <class F>
  void for_cells(const BoundingBox& b, F&& f) const {
    auto cell = [&](double x, int a) {
      const double i = std::floor((x - origin_[a]) * inverse_cell_);
      return !(i > 0) ? std::int64_t{0} : i >= static_cast<double>(size_[a]) ? size_[a] - 1 : static_cast<std::int64_t>(i);
    };
    const std::int64_t i0 = cell(b.min.x, 0), i1 = cell(b.max.x, 0), j0 = cell(b.min.y, 1), j1 = cell(b.max.y, 1),
                       k0 = cell(b.min.z, 2), k1 = cell(b.max.z, 2);
    for (std::int64_t i = i0; i <= i1; ++i)
      for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t k = k0; k <= k1; ++k)
          f(static_cast<std::uint64_t>((i * size_[1] + j) * size_[2] + k),
            static_cast<std::size_t>(((i / kShard) * shards_size_[1] + j / kShard) * shards_size_[2] + k / kShard));
  }

  const Mesh& m_;
  Vec3 origin_;
  double cell_ = 1, inverse_cell_ = 1;
  std::int64_t size_[3] = {1, 1, 1}, shards_size_[3] = {1, 1, 1};
  // A face's box as indexed, in single precision rounded outward. Trivial, so the array
  // is left unwritten until the parallel loop fills it (a serial first write of a large
  // array costs more than its filling: each new page is a fault).
  struct StoredBox {
    std::array<float, 3> min, max;
    static StoredBox of(const BoundingBox& b) {
      using geometry::float_above, geometry::float_below;
      return {{float_below(b.min.x), float_below(b.min.y), float_below(b.min.z)},
              {float_above(b.max.x), float_above(b.max.y), float_above(b.max.z)}};
    }
  };
  std::unique_ptr<StoredBox[]> box_;      // per face
  std::vector<std::uint32_t> start_;      // per cell of the dense grid: its range in flat_
  std::vector<std::uint32_t> flat_;       // the faces as they were at construction
  std::vector<std::uint8_t> in_flat_;     // per face: its flat entries still hold
  // Per block of cells (allocated when first written): faces changed since, with their cell.
  std::vector<std::unique_ptr<std::vector<Moved>>> moved_;
};

}  // namespace molsurf
