#include "io/temporary_registry.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace molsurf::detail {

namespace {

// Slot states: a slot is claimed (free -> writing) by compare-exchange, filled, then
// published (ready). The handler only reads ready slots, whose bytes are complete.
enum SlotState : int { kFree = 0, kWriting = 1, kReady = 2 };
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

// The registry itself: globals because a signal handler can reach nothing else.
std::atomic<int> g_state[kTemporarySlots];
char g_path[kTemporarySlots][kTemporaryPathBytes];

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction g_previous[sizeof kSignals / sizeof kSignals[0]];

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (int slot = 0; slot < kTemporarySlots; ++slot)
    if (g_state[slot].load(std::memory_order_acquire) == kReady) ::unlink(g_path[slot]);
  // Give the signal back its previous disposition and deliver it again: the process ends
  // (or the previous handler runs) exactly as it would have without us.
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i)
    if (kSignals[i] == signal_number) ::sigaction(signal_number, &g_previous[i], nullptr);
  ::raise(signal_number);
}

}  // namespace

int register_temporary(const std::filesystem::path& path) noexcept {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  if (error) return -1;
  const std::string& text = absolute.native();
  if (text.size() + 1 > kTemporaryPathBytes) return -1;
  for (int slot = 0; slot < kTemporarySlots; ++slot) {
    int expected = kFree;
    if (!g_state[slot].compare_exchange_strong(expected, kWriting, std::memory_order_acq_rel)) continue;
    std::memcpy(g_path[slot], text.c_str(), text.size() + 1);
    g_state[slot].store(kReady, std::memory_order_release);
    return slot;
  }
  return -1;
}

void unregister_temporary(int slot) noexcept {
  if (slot >= 0 && slot < kTemporarySlots) g_state[slot].store(kFree, std::memory_order_release);
}

int registered_temporaries() noexcept {
  int count = 0;
  for (const std::atomic<int>& state : g_state) count += state.load() == kReady;
  return count;
}

void remove_temporaries_on_signals() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
      struct sigaction current {};
      if (::sigaction(kSignals[i], nullptr, &current) != 0) continue;
      if (current.sa_handler == SIG_IGN) continue;  // e.g. SIGHUP under nohup: stay ignored
      g_previous[i] = current;
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      for (int other : kSignals) sigaddset(&action.sa_mask, other);  // one cleanup at a time
      action.sa_flags = 0;
      ::sigaction(kSignals[i], &action, nullptr);
    }
  });
}

}  // namespace molsurf::detail
