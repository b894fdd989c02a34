#pragma once
// The OpenMP team size for the duration of a scope. Library calls that take a thread
// count set it here, so that nested parallel regions (the engine's, the check's) use it
// too, and the caller's setting is restored afterwards.
#include <omp.h>

namespace molsurf {

class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) : previous_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~ThreadCountScope() { omp_set_num_threads(previous_); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_;
};

}  // namespace molsurf
