#include <omp.h>

#include <algorithm>
#include <exception>
#include <stdexcept>

#include "arrangement/sphere_arrangement.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/error.hpp"
#include "molsurf/surface_report.hpp"

namespace molsurf {

namespace {

// Frames up to this many atoms run one per thread: their arrangements are too small for
// the threads to share one well, and each takes memory in proportion to its atoms only.
constexpr std::size_t kSmallFrameAtoms = 50'000;

FrameAreas areas_of_frame(std::span<const Atom> atoms, const SphereOptions& spheres, bool outer_only, int threads) {
  const ComputedAreas computed = compute_areas(atoms, spheres, threads);
  const ExactReport exact = make_exact_report(computed.arrangement, {}, outer_only);
  FrameAreas out;
  out.area = exact.area;
  out.volume = exact.volume;
  for (const ShellReport& shell : exact.shells) out.cavities += shell.cavity;
  out.atom_area = exact_atom_area(computed.arrangement, outer_only);
  out.seconds = computed.seconds;
  return out;
}

}  // namespace

std::vector<FrameAreas> compute_frame_areas(std::size_t frames,
                                            const std::function<void(std::size_t, std::vector<Atom>&)>& atoms_of,
                                            const SphereOptions& spheres, bool outer_only, int threads,
                                            const std::function<std::string(std::size_t)>& frame_name) {
  std::vector<FrameAreas> out(frames);
  if (frames == 0) return out;
  std::vector<std::exception_ptr> failed(frames);
  const auto compute = [&](std::size_t f, std::vector<Atom>& atoms, int frame_threads) {
    try {
      if (f > 0) atoms_of(f, atoms);
      out[f] = areas_of_frame(atoms, spheres, outer_only, frame_threads);
    } catch (...) {
      failed[f] = std::current_exception();
    }
  };
  std::vector<Atom> first;
  atoms_of(0, first);
  const int max_threads = threads > 0 ? threads : omp_get_max_threads();
  const int team = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(max_threads), frames));
  if (first.size() > kSmallFrameAtoms || team <= 1) {
    for (std::size_t f = 0; f < frames; ++f) compute(f, first, max_threads);
  } else {
    compute(0, first, 1);
    const auto count = static_cast<std::int64_t>(frames);
#pragma omp parallel num_threads(team)
    {
      std::vector<Atom> atoms = first;  // the frames share everything but what atoms_of sets
#pragma omp for schedule(dynamic, 1)
      for (std::int64_t f = 1; f < count; ++f) compute(static_cast<std::size_t>(f), atoms, 1);
    }
  }
  for (std::size_t f = 0; f < frames; ++f) {
    if (!failed[f]) continue;
    const std::string name = frame_name ? frame_name(f) : "frame " + std::to_string(f);
    try {
      std::rethrow_exception(failed[f]);
    } catch (const Error& e) {
      throw Error(name + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw Error(name + ": " + e.what());  // arrange_spheres' refusals (too many spheres, bad numbers)
    }
  }
  return out;
}

}  // namespace molsurf
