#include "surface/solvent_accessible_surface.hpp"

#include <omp.h>

#include <chrono>
#include <utility>

#include "common/thread_count_scope.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/surface.hpp"
#include "surface/one_pass/one_pass_union.hpp"
#include "surface/pairwise_union.hpp"

namespace molsurf {

SurfaceLevel& SurfaceLevel::operator+=(const BooleanStats& m) {
  return *this += SurfaceLevel{.merges = 1,
                               .faces_in = m.faces_a + m.faces_b,
                               .active_faces = m.active_faces,
                               .faces_out = m.output_faces,
                               .split_faces = m.split_faces,
                               .ray_casts = m.ray_casts,
                               .whole_reruns = m.whole_reruns,
                               .steps = m.seconds};
}

SurfaceLevel& SurfaceLevel::operator+=(const SurfaceLevel& o) {
  merges += o.merges;
  faces_in += o.faces_in;
  active_faces += o.active_faces;
  faces_out += o.faces_out;
  split_faces += o.split_faces;
  ray_casts += o.ray_casts;
  whole_reruns += o.whole_reruns;
  steps += o.steps;
  seconds += o.seconds;
  return *this;
}

const char* surface_method_name(SurfaceMethod method) {
  return method == SurfaceMethod::one_pass ? "one-pass" : "pairwise";
}

SphereUnion solvent_accessible_surface(std::span<const Atom> atoms, const SphereUnionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SphereUnion result;
  if (atoms.empty()) return result;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  // The engine's own parallel loops use the default team size: make it the caller's thread
  // count for the duration (with one outer thread, inner regions would otherwise start
  // spinning workers on every core).
  const ThreadCountScope thread_count(threads);
  result.method = options.method;
  if (options.method == SurfaceMethod::one_pass) {
    surface_detail::OnePassResult one_pass = surface_detail::one_pass_union(
        atoms, options.spheres, threads, options.progress, options.check_size, options.estimate_size_above,
        options.cancel);
    result.one_pass = one_pass.stats;
    result.mesh = std::move(one_pass.mesh);
  } else {
    surface_detail::pairwise_union(atoms, options, threads, result);
  }
  result.seconds.union_levels = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace molsurf
