#include "molsurf/threads.hpp"

#include <pthread.h>

#include <cctype>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace molsurf {

namespace {

// OMP_STACKSIZE (or GOMP_STACKSIZE) as libgomp reads it: a number with an optional B, K, M
// or G suffix, kilobytes without one; 0 when unset or unreadable (the default stack).
std::size_t openmp_stack_size() {
  for (const char* name : {"OMP_STACKSIZE", "GOMP_STACKSIZE"}) {
    const char* text = std::getenv(name);
    if (!text || !*text) continue;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 10);
    while (*end == ' ') ++end;
    std::size_t unit = 1024;
    switch (std::toupper(static_cast<unsigned char>(*end))) {
      case 'B': unit = 1; break;
      case 'K': unit = 1024; break;
      case 'M': unit = 1024 * 1024; break;
      case 'G': unit = std::size_t{1} << 30; break;
      case '\0': break;
      default: return 0;
    }
    return static_cast<std::size_t>(value) * unit;
  }
  return 0;
}

// Threads that wait until all are started (a team is alive at once), then end.
class WaitingThreads {
 public:
  // Starts up to `count`; stops at the first that cannot start.
  WaitingThreads(int count, std::size_t stack) {
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    if (stack > 0) pthread_attr_setstacksize(&attributes, stack);
    for (int k = 0; k < count; ++k) {
      pthread_t thread;
      if (pthread_create(&thread, &attributes, &WaitingThreads::wait, this) != 0) break;
      started_.push_back(thread);
    }
    pthread_attr_destroy(&attributes);
  }
  ~WaitingThreads() {
    {
      const std::lock_guard lock(mutex_);
      released_ = true;
    }
    released_signal_.notify_all();
    for (const pthread_t thread : started_) pthread_join(thread, nullptr);
  }
  WaitingThreads(const WaitingThreads&) = delete;
  WaitingThreads& operator=(const WaitingThreads&) = delete;
  int started() const { return static_cast<int>(started_.size()); }

 private:
  static void* wait(void* self) {
    auto& threads = *static_cast<WaitingThreads*>(self);
    std::unique_lock lock(threads.mutex_);
    threads.released_signal_.wait(lock, [&] { return threads.released_; });
    return nullptr;
  }

  std::mutex mutex_;
  std::condition_variable released_signal_;
  bool released_ = false;
  std::vector<pthread_t> started_;
};

}  // namespace

ThreadCount startable_threads(int requested) {
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  if (requested <= 0 || requested <= cores) return {requested, {}};
  // The calling thread is one of the team: the others must start beside it.
  const int startable = 1 + WaitingThreads(requested - 1, openmp_stack_size()).started();
  if (startable >= requested) return {requested, {}};
  // Half: what limits the threads (address space, processes) is what the work needs too.
  // Under a 4 GB address space 480 threads start, and with all their stacks the surface of
  // a small protein then ran out of memory.
  const int used = std::max(1, startable / 2);
  return {used, std::to_string(requested) + " threads asked for, but this process can start only " +
                    std::to_string(startable) + " at once (a limit on its virtual memory or processes): using " +
                    std::to_string(used) + ", half of them, to leave room for the work"};
}

}  // namespace molsurf
