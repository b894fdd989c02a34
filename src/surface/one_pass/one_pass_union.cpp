// The one-pass union's driver: every atom trimmed (one_pass/trim.cpp and its steps), all
// atoms in parallel, then joined (one_pass/join.cpp); before the pass, the union's size
// estimated from a sample of atoms so that a job too large for the memory stops in seconds.
#include "surface/one_pass/one_pass_union.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/parallel_exceptions.hpp"
#include "molsurf/resource_limits.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/atom_trimmer.hpp"
#include "surface/one_pass/join.hpp"

namespace molsurf::surface_detail {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The union's faces extrapolated from a sample of atoms spread evenly over the index order
// (chain by chain, residue by residue: over the whole structure), each trimmed as the pass
// trims it. 256 atoms put the estimate within a few percent on proteins.
SurfaceSizeEstimate estimate_union_size(const AtomPolyhedra& polyhedra, const NeighbourList& neighbours, int threads) {
  constexpr std::size_t kSample = 256;
  const std::size_t n = polyhedra.size(), m = std::min(n, kSample);
  std::vector<std::size_t> faces(m, 0);
  ParallelExceptions errors;
#pragma omp parallel num_threads(threads)
  {
    one_pass::AtomTrimmer trimmer(polyhedra, neighbours);
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t k = 0; k < static_cast<std::int64_t>(m); ++k) {
      const auto atom = static_cast<std::uint32_t>((2 * static_cast<std::size_t>(k) + 1) * n / (2 * m));
      errors.run(k, [&] { faces[k] = trimmer.trim(atom).triangles.size(); });
    }
  }
  errors.rethrow();
  SurfaceSizeEstimate estimate;
  estimate.sampled_atoms = m;
  estimate.atoms = n;
  double sum = 0;
  for (std::size_t f : faces) sum += static_cast<double>(f);
  const double total = m > 0 ? sum * static_cast<double>(n) / static_cast<double>(m) : 0.0;
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  estimate.faces = total >= 1.8e19 ? kMax : static_cast<std::uint64_t>(total);
  estimate.bytes = estimate.faces > kMax / kBytesPerSurfaceFace ? kMax : estimate.faces * kBytesPerSurfaceFace;
  return estimate;
}

// Every atom's polyhedron trimmed by its neighbours, all atoms in parallel (only those
// `trimmed` marks when it is not empty). `progress` (may be empty) is called from thread 0
// every 256 atoms, and once at the end.
std::vector<one_pass::AtomPieces> trim_atoms(const AtomPolyhedra& polyhedra, const NeighbourList& neighbours,
                                             int threads,
                                             const std::function<void(std::size_t, std::size_t)>& progress,
                                             const CancelFlag* cancel, std::span<const std::uint8_t> trimmed = {}) {
  const std::size_t atom_count = polyhedra.size();
  const auto n = static_cast<std::int64_t>(atom_count);
  std::vector<one_pass::AtomPieces> pieces(atom_count);
  ParallelExceptions errors;
  std::atomic<std::size_t> done{0};
#pragma omp parallel num_threads(threads)
  {
    one_pass::AtomTrimmer trimmer(polyhedra, neighbours);
#pragma omp for schedule(dynamic, 4)
    for (std::int64_t i = 0; i < n; ++i) {
      // Skipped rather than thrown once cancelled: an exception per remaining atom would
      // cost more than the atoms.
      if (cancel_requested(cancel) || (!trimmed.empty() && !trimmed[i])) continue;
      errors.run(i, [&] { pieces[i] = trimmer.trim(static_cast<std::uint32_t>(i)); });
      const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
      if (progress && omp_get_thread_num() == 0 && finished % 256 == 0) progress(finished, atom_count);
    }
  }
  errors.rethrow();
  throw_if_cancelled(cancel);
  if (progress) progress(atom_count, atom_count);
  return pieces;
}

}  // namespace

OnePassResult one_pass_union(std::span<const Atom> atoms, const SphereOptions& options, int threads,
                             const std::function<void(std::size_t, std::size_t)>& progress,
                             const std::function<void(const SurfaceSizeEstimate&)>& check_size,
                             std::uint64_t estimate_size_above, const CancelFlag* cancel) {
  OnePassResult result;
  auto start = Clock::now();
  const AtomPolyhedra polyhedra(atoms, options);
  const NeighbourList neighbours = find_neighbours(polyhedra);
  if (check_size) {
    const std::uint64_t sphere_faces = polyhedra.face_count();
    if (sphere_faces > estimate_size_above) check_size(estimate_union_size(polyhedra, neighbours, threads));
  }
  std::vector<one_pass::AtomPieces> pieces = trim_atoms(polyhedra, neighbours, threads, progress, cancel);
  result.stats.seconds_trim = seconds_since(start);

  // Join: atoms in index order, points merged by definition, then points equal by exact
  // value but defined differently (degenerate contacts) merged too.
  start = Clock::now();
  one_pass::join_pieces(std::move(pieces), polyhedra, threads, result.mesh, result.stats);
  result.stats.seconds_join = seconds_since(start);
  result.stats.atoms = atoms.size();
  result.stats.contained_atoms = polyhedra.contained_count();
  result.stats.neighbour_pairs = neighbours.atoms.size() / 2;
  result.stats.faces_in = polyhedra.face_count();
  return result;
}

OnePassResult one_pass_partial_union(std::span<const Atom> atoms, std::span<const std::uint8_t> contained,
                                     std::span<const std::uint8_t> trimmed, const SphereOptions& options, int threads) {
  if (contained.size() != atoms.size() || trimmed.size() != atoms.size())
    throw std::invalid_argument("one_pass_partial_union: one containment and one trim flag per atom");
  OnePassResult result;
  auto start = Clock::now();
  const AtomPolyhedra polyhedra(atoms, options, contained);
  const NeighbourList neighbours = find_neighbours(polyhedra);
  std::vector<one_pass::AtomPieces> pieces = trim_atoms(polyhedra, neighbours, threads, {}, nullptr, trimmed);
  result.stats.seconds_trim = seconds_since(start);
  start = Clock::now();
  one_pass::join_pieces(std::move(pieces), polyhedra, threads, result.mesh, result.stats, &result.origins);
  result.stats.seconds_join = seconds_since(start);
  for (std::size_t i = 0; i < atoms.size(); ++i)
    if (trimmed[i]) {
      ++result.stats.atoms;
      result.stats.contained_atoms += polyhedra.contained(i) ? 1 : 0;
      if (!polyhedra.contained(i)) result.stats.faces_in += polyhedra.shape(i).unit.faces.size();
    }
  return result;
}

std::string open_union_message(std::size_t open_edges) {
  return "the one-pass union left " + std::to_string(open_edges) + " open edges (a molsurf bug; please report it)";
}

}  // namespace molsurf::surface_detail
