#include "io/temporary_registry.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
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
int g_directory[kTemporarySlots];
char g_name[kTemporarySlots][kTemporaryNameBytes];

// Every signal whose default action ends the process and that a handler can catch
// (SIGKILL and SIGSTOP cannot be; SIGTRAP belongs to debuggers).
constexpr int kSignals[] = {SIGHUP,  SIGINT,  SIGQUIT,   SIGILL,  SIGABRT, SIGBUS, SIGFPE,
                            SIGUSR1, SIGSEGV, SIGUSR2,   SIGPIPE, SIGALRM, SIGTERM, SIGXCPU,
                            SIGXFSZ, SIGVTALRM, SIGPROF, SIGIO,   SIGPWR,  SIGSYS};
constexpr std::size_t kSignalCount = sizeof kSignals / sizeof kSignals[0];
struct sigaction g_previous[kSignalCount];

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  const int saved_errno = errno;
  for (int slot = 0; slot < kTemporarySlots; ++slot)
    if (g_state[slot].load(std::memory_order_acquire) == kReady) ::unlinkat(g_directory[slot], g_name[slot], 0);
  // Give the signal back its previous disposition and deliver it again: it is blocked until
  // this handler returns, and then ends the process exactly as it would have without us.
  for (std::size_t i = 0; i < kSignalCount; ++i)
    if (kSignals[i] == signal_number) ::sigaction(signal_number, &g_previous[i], nullptr);
  ::raise(signal_number);
  errno = saved_errno;
}

}  // namespace

int register_temporary(const std::filesystem::path& directory, std::string_view name) noexcept {
  if (name.size() + 1 > kTemporaryNameBytes) return -1;
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return -1;
  for (int slot = 0; slot < kTemporarySlots; ++slot) {
    int expected = kFree;
    if (!g_state[slot].compare_exchange_strong(expected, kWriting, std::memory_order_acq_rel)) continue;
    g_directory[slot] = fd;
    std::memcpy(g_name[slot], name.data(), name.size());
    g_name[slot][name.size()] = '\0';
    g_state[slot].store(kReady, std::memory_order_release);
    return slot;
  }
  ::close(fd);
  return -1;
}

void unregister_temporary(int slot) noexcept {
  if (slot < 0 || slot >= kTemporarySlots) return;
  const int fd = g_directory[slot];
  // Claimed before the descriptor is closed, so no other registration can reuse the slot
  // while it still names the old directory.
  int expected = kReady;
  if (!g_state[slot].compare_exchange_strong(expected, kWriting, std::memory_order_acq_rel)) return;
  ::close(fd);
  g_state[slot].store(kFree, std::memory_order_release);
}

int registered_temporaries() noexcept {
  int count = 0;
  for (const std::atomic<int>& state : g_state) count += state.load() == kReady;
  return count;
}

void remove_temporaries_on_signals() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    for (std::size_t i = 0; i < kSignalCount; ++i) {
      struct sigaction current {};
      if (::sigaction(kSignals[i], nullptr, &current) != 0) continue;
      if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != SIG_DFL) continue;
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
