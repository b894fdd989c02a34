#include "surface/cleanup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <omp.h>

#include "common/parallel_exceptions.hpp"
#include "common/parallel_threshold.hpp"
#include "mesh/topology.hpp"
#include "surface/cleanup_worker.hpp"

namespace molsurf {

namespace {

using surface_cleanup::Cleaner;
using surface_cleanup::CleanupShared;
using surface_cleanup::WorkRegion;
using surface_cleanup::WorkResult;

// The passes of the cleanup. Each pass takes the distorted faces, worst first, and gives
// each the best valid edit. The edits run in parallel with a result that does not depend
// on the thread count: the faces are sorted into the cells of a coarse grid, coloured like
// a 3-d chessboard by the parity of their coordinates (eight colours). Two cells of one
// colour are at least a cell's side apart, which is more than an edit's region on each
// side (`margin`) and how far beyond it a worker reads (`reach`). The colours run one
// after another; within a colour, the cells run in parallel, each worker in its cell's
// region, its faces in the pass's order. A face whose edits would leave the region waits
// for a serial sweep after the eighth colour. The budgets (area, each component's volume)
// are shared out at the start of each colour among the cells that may use them, and the
// cells' changes are added up in cell order.
class Sweep {
 public:
  explicit Sweep(CleanupShared& shared) : s_(shared) {
    const int threads = std::max(1, omp_get_max_threads());
    for (int t = 0; t < threads; ++t) workers_.push_back(std::make_unique<Cleaner>(shared));
    volume_sharers_.assign(shared.initial_volume.size(), 0);
    sharer_stamp_.assign(shared.initial_volume.size(), kNoCell);
  }

  void run(CleanupStats& stats) {
    const Mesh& m = s_.m;
    Cleaner& serial = *workers_.front();
    // A margin of a millionth, far above the rounding of atan2 and of the tangent.
    const double tan_goal = std::tan(s_.options.min_angle_deg * std::numbers::pi / 180) * (1 + 1e-6);
    // The first pass measures every face; a later one only the faces the one before
    // listed or changed: no other face's corners moved, so its angle holds.
    std::vector<std::pair<double, std::uint32_t>> distorted;
    // Faces face_of(0 .. n-1) whose smallest angle is below the goal, in that order: measured
    // in parallel, atan2 only where the tangent leaves it in doubt.
    auto list_distorted = [&](std::size_t n, auto&& face_of) {
      std::vector<double> angle(n);
      const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (count >= kParallelMinItems / 4)
      for (std::int64_t k = 0; k < count; ++k) {
        const std::uint32_t f = face_of(static_cast<std::size_t>(k));
        angle[k] = s_.editable.alive(f) && !serial.surely_at_least(f, tan_goal) ? serial.min_angle(f) : 180;
      }
      for (std::size_t k = 0; k < n; ++k)
        if (angle[k] < s_.options.min_angle_deg) distorted.emplace_back(angle[k], face_of(k));
    };
    for (int pass = 0; pass < s_.options.passes; ++pass) {
      if (pass == 0) {
        list_distorted(m.faces.size(), [](std::size_t k) { return static_cast<std::uint32_t>(k); });
      } else {
        for (const auto& listed : distorted) touched_.push_back(listed.second);
        std::sort(touched_.begin(), touched_.end());
        touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
        distorted.clear();
        list_distorted(touched_.size(), [&](std::size_t k) { return touched_[k]; });
      }
      touched_.clear();
      if (distorted.empty()) break;
      std::sort(distorted.begin(), distorted.end());
      const auto face_centre = [&](std::size_t q) { return centroid(distorted[q].second); };
      const auto face_component = [&](std::size_t q) { return s_.component_of[distorted[q].second]; };
      const auto improve = [&](Cleaner& worker, std::size_t q) {
        worker.improve(distorted[q].second, static_cast<std::uint32_t>(q));
      };
      if (sweep(distorted.size(), face_centre, face_component, improve, Shares::even, stats) == 0) break;
    }
    if (s_.options.min_edge_fraction > 0 || s_.options.min_edge_length > 0) shorten_edges(stats);
  }

 private:
  static constexpr std::uint64_t kNoCell = ~std::uint64_t{0};

  // How a colour's cells share the area budget left: evenly, or in proportion to the items
  // each holds (where the items themselves change the area the same way, as collapses of
  // short edges on a curved surface all shrink it, an even share would stop the cells with
  // the most items first).
  enum class Shares { even, by_items };

  Vec3 centroid(std::uint32_t f) const {
    const Triangle& t = s_.m.faces[f];
    return (s_.m.vertices[t[0]] + s_.m.vertices[t[1]] + s_.m.vertices[t[2]]) / 3.0;
  }

  // The edges far shorter than the surface's typical edge, collapsed, shortest first,
  // swept by cells like the distorted faces; passes until none is left or none gives way.
  void shorten_edges(CleanupStats& stats) {
    Cleaner& serial = *workers_.front();
    const double floor = serial.short_edge_floor();
    if (!(floor > 0)) return;
    std::vector<surface_cleanup::ShortEdge> edges = serial.short_edges(floor);
    stats.short_edges_before = edges.size();
    const auto edge_centre = [&](std::size_t q) {
      const auto [a, b] = edges[q].second;
      return 0.5 * (s_.m.vertices[a] + s_.m.vertices[b]);
    };
    const auto edge_component = [&](std::size_t q) { return serial.vertex_component(edges[q].second[0]); };
    const auto shorten = [&](Cleaner& worker, std::size_t q) {
      const auto [a, b] = edges[q].second;
      worker.shorten(a, b, floor, static_cast<std::uint32_t>(q));
    };
    for (int pass = 0; pass < s_.options.passes && !edges.empty(); ++pass) {
      if (sweep(edges.size(), edge_centre, edge_component, shorten, Shares::by_items, stats) == 0) break;
      edges = serial.short_edges(floor);
    }
    // What a cell's share of the budgets refused, once more with the whole of what is left.
    if (!edges.empty()) {
      serial.begin(nullptr);
      for (std::size_t q = 0; q < edges.size(); ++q) shorten(serial, q);
      WorkResult r = serial.finish();
      add(r, stats);
      if (r.done > 0) edges = serial.short_edges(floor);
    }
    touched_.clear();
    stats.short_edges_after = edges.size();
  }

  // One pass's edits on `count` items, item q at centre_of(q) in component component_of(q),
  // work(worker, q) making its edit; returns how many items got one.
  template <class CentreOf, class ComponentOf, class Work>
  std::size_t sweep(std::size_t count, CentreOf&& centre_of, ComponentOf&& component_of, Work&& work, Shares shares,
                    CleanupStats& stats) {
    const Mesh& m = s_.m;
    // The longest face (on any axis of its box) bounds how far a worker reads beyond the
    // faces it changes; an edit may make no face longer than twice that.
    // The same pass takes the box of every face's corners (the dead faces' too), which the
    // coarse grid below spans.
    double longest = 0;
    BoundingBox all;
    const auto nf = static_cast<std::int64_t>(m.faces.size());
#pragma omp parallel
    {
      double part_longest = 0;
      BoundingBox part;
#pragma omp for schedule(static) nowait
      for (std::int64_t f = 0; f < nf; ++f) {
        const BoundingBox b = bounding_box(m, static_cast<std::size_t>(f));
        part.extend(b);
        if (s_.editable.alive(f))
          part_longest = std::max({part_longest, b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
      }
#pragma omp critical(molsurf_cleanup_extent)
      {
        all.extend(part);
        longest = std::max(longest, part_longest);
      }
    }
    const double max_extent = 2 * longest;
    // An edit changes faces around the distorted face's corners; its region reaches this far
    // beyond the cell. Beyond the region a worker reads up to three rings of faces (the
    // faces around the neighbours of an edit's corners) and the faces in the index's cells
    // its queries touch, and the index's blocks of cells.
    const double margin = max_extent;
    const double cell = s_.editable.grid()->cell_size();
    const double reach = std::max(4 * max_extent + cell, s_.editable.grid()->shard_side() + 2 * cell);
    const double side = 1.25 * (2 * margin + reach);
    std::int64_t n[3];
    for (int a = 0; a < 3; ++a)
      n[a] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::ceil((all.max[a] - all.min[a]) / side)), 1, 1 << 20);
    auto coordinate = [&](double x, int a) {
      const double i = std::floor((x - all.min[a]) / side);
      return !(i > 0) ? std::int64_t{0} : i >= static_cast<double>(n[a]) ? n[a] - 1 : static_cast<std::int64_t>(i);
    };
    // The faces by colour, then cell, then their order in the pass.
    struct Entry {
      std::uint64_t key;  // colour, then cell
      std::uint32_t position;
      std::array<std::int64_t, 3> cell;
    };
    std::vector<Entry> entries(count);
    for (std::size_t q = 0; q < count; ++q) {
      const Vec3 centre = centre_of(q);
      std::array<std::int64_t, 3> c{};
      for (int a = 0; a < 3; ++a) c[a] = coordinate(centre[a], a);
      const std::uint64_t colour = static_cast<std::uint64_t>((c[0] & 1) | (c[1] & 1) << 1 | (c[2] & 1) << 2);
      const auto id = static_cast<std::uint64_t>((c[0] * n[1] + c[1]) * n[2] + c[2]);
      entries[q] = {colour << 60 | id, static_cast<std::uint32_t>(q), c};
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });

    std::size_t done = 0;
    std::vector<std::uint32_t> deferred;
    for (std::size_t begin = 0; begin < entries.size();) {
      // One colour: its cells [cell_start[k], cell_start[k + 1]).
      const std::uint64_t colour = entries[begin].key >> 60;
      std::vector<std::size_t> cell_start;
      std::size_t end = begin;
      for (; end < entries.size() && entries[end].key >> 60 == colour; ++end)
        if (end == begin || entries[end].key != entries[end - 1].key) cell_start.push_back(end);
      cell_start.push_back(end);
      const std::size_t cells = cell_start.size() - 1;
      for (std::size_t k = 0; k < cells; ++k)
        for (std::size_t q = cell_start[k]; q < cell_start[k + 1]; ++q) {
          const std::uint32_t component = component_of(entries[q].position);
          if (sharer_stamp_[component] != k) {
            sharer_stamp_[component] = k;
            ++volume_sharers_[component];
          }
        }
      std::vector<WorkRegion> regions(cells);
      const double area_left = s_.area_budget - std::abs(s_.area_drift);
      for (std::size_t k = 0; k < cells; ++k) {
        const std::array<std::int64_t, 3>& c = entries[cell_start[k]].cell;
        WorkRegion& r = regions[k];
        for (int a = 0; a < 3; ++a) {
          const double infinity = std::numeric_limits<double>::infinity();
          r.box.min[a] = c[a] == 0 ? -infinity : all.min[a] + static_cast<double>(c[a]) * side - margin;
          r.box.max[a] = c[a] == n[a] - 1 ? infinity : all.min[a] + static_cast<double>(c[a] + 1) * side + margin;
        }
        r.max_extent = max_extent;
        r.area_share = shares == Shares::even ? area_left / static_cast<double>(cells)
                                              : area_left * static_cast<double>(cell_start[k + 1] - cell_start[k]) /
                                                    static_cast<double>(count);
        r.volume_sharers = &volume_sharers_;
      }
      // The cells with the most faces first: the threads then end the colour together. The
      // order of the work does not change its result (the cells' regions are apart).
      std::vector<std::size_t> by_size(cells);
      std::iota(by_size.begin(), by_size.end(), std::size_t{0});
      std::stable_sort(by_size.begin(), by_size.end(), [&](std::size_t x, std::size_t y) {
        return cell_start[x + 1] - cell_start[x] > cell_start[y + 1] - cell_start[y];
      });
      std::vector<WorkResult> results(cells);
      ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 1)
      for (std::int64_t i = 0; i < static_cast<std::int64_t>(cells); ++i) {
        const std::size_t k = by_size[static_cast<std::size_t>(i)];
        errors.run(static_cast<std::int64_t>(k), [&] {
          Cleaner& worker = *workers_[static_cast<std::size_t>(omp_get_thread_num())];
          worker.begin(&regions[k]);
          for (std::size_t q = cell_start[k]; q < cell_start[k + 1]; ++q) work(worker, entries[q].position);
          results[k] = worker.finish();
        });
      }
      errors.rethrow();
      for (WorkResult& r : results) {
        done += r.done;
        deferred.insert(deferred.end(), r.deferred.begin(), r.deferred.end());
        add(r, stats);
      }
      for (std::size_t q = begin; q < end; ++q) {
        const std::uint32_t component = component_of(entries[q].position);
        volume_sharers_[component] = 0;
        sharer_stamp_[component] = kNoCell;
      }
      begin = end;
    }
    // The faces left for the serial sweep, in the pass's order, with the whole budgets.
    std::sort(deferred.begin(), deferred.end());
    Cleaner& serial = *workers_.front();
    serial.begin(nullptr);
    for (std::uint32_t q : deferred) work(serial, q);
    WorkResult r = serial.finish();
    done += r.done;
    add(r, stats);
    return done;
  }

  void add(WorkResult& r, CleanupStats& stats) {
    s_.area_drift += r.area_drift;
    for (const auto& [component, change] : r.volume_changes) s_.component_volume[component] += change;
    stats.collapses += r.collapses;
    stats.flips += r.flips;
    stats.moves += r.moves;
    stats.refused += r.refused;
    touched_.insert(touched_.end(), r.touched.begin(), r.touched.end());
  }

  CleanupShared& s_;
  std::vector<std::unique_ptr<Cleaner>> workers_;  // one per thread
  std::vector<std::uint32_t> touched_;             // faces changed during the present pass
  std::vector<std::uint32_t> volume_sharers_;      // per component: cells of the present colour that may change it
  std::vector<std::uint64_t> sharer_stamp_;        // per component: the last cell counted
};

}  // namespace

CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options) { return improve_surface(mesh, options, {}); }

CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options, std::span<const std::uint8_t> frozen) {
  if (!frozen.empty() && frozen.size() != mesh.vertices.size())
    throw std::invalid_argument("improve_surface: one frozen flag per vertex");
  CleanupStats stats;
  stats.before = mesh_quality(mesh);
  stats.area_before = surface_area(mesh);
  if (!mesh.faces.empty()) {
    CleanupShared shared(mesh, options, stats.area_before, frozen);
    Sweep(shared).run(stats);
    if (stats.collapses > 0) {
      keep_alive_faces(mesh, shared.editable.alive_faces());
      drop_unused_vertices(mesh);
    }
  }
  if (options.measure_after) stats.after = mesh_quality(mesh);
  stats.area_after = surface_area(mesh);
  return stats;
}

}  // namespace molsurf
