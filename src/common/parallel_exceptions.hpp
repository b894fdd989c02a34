#pragma once
// An exception may not leave an OpenMP parallel region: the runtime calls std::terminate,
// and the user sees "terminate called without an active exception" instead of the error
// (an allocation that fails on a large structure, or an internal check). Loop bodies run
// through ParallelExceptions::run, which keeps the exception (of the lowest iteration, when
// several threw before the others noticed) and lets the remaining iterations skip their
// work; rethrow() after the region throws it on the calling thread.
#include <atomic>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>

namespace molsurf {

class ParallelExceptions {
 public:
  template <class Body>
  void run(std::int64_t iteration, Body&& body) noexcept {
    if (failed_.load(std::memory_order_relaxed)) return;
    try {
      body();
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_ || iteration < iteration_) {
        error_ = std::current_exception();
        iteration_ = iteration;
      }
      failed_.store(true, std::memory_order_relaxed);
    }
  }

  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::atomic<bool> failed_{false};
  std::mutex mutex_;
  std::exception_ptr error_;
  std::int64_t iteration_ = std::numeric_limits<std::int64_t>::max();
};

}  // namespace molsurf
