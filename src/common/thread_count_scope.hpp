#pragma once
// The OpenMP team size for the duration of a scope: the one place where the thread count
// is set. Library calls that take a thread count (compute_surface, check_mesh,
// write_mesh) set it here, so that nested parallel regions (the engine's, the check's)
// use it too, and the caller's setting is restored afterwards. 0 keeps the caller's.
#include <omp.h>

namespace molsurf {

class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) : previous_(omp_get_max_threads()) {
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~ThreadCountScope() { omp_set_num_threads(previous_); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_;
};

}  // namespace molsurf
