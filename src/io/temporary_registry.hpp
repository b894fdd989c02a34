#pragma once
// Temporary files that must not outlive an interrupted run. AtomicFile registers each
// temporary here while it exists; when SIGINT, SIGTERM or SIGHUP arrives, the handler
// unlinks every registered temporary and then lets the signal do what it did before
// (by default: end the process), so a Ctrl-C during a long write leaves no
// ".NAME.tmp-PID-N" file behind.
//
// A signal handler may only touch lock-free atomics and call async-signal-safe
// functions (unlink, sigaction, raise), and it cannot reach objects: the registry is
// therefore a fixed-size static table of path buffers, the one global state of the
// library's writers. A temporary that finds no free slot (more than kSlots at once) or
// whose absolute path is longer than kPathBytes is written normally but not cleaned up
// by a signal.
#include <cstddef>
#include <filesystem>

namespace molsurf::detail {

constexpr int kTemporarySlots = 64;
constexpr std::size_t kTemporaryPathBytes = 4096;

// Registers a temporary's path; returns its slot, or -1 when none is free.
int register_temporary(const std::filesystem::path& path) noexcept;
// Forgets a slot (the file was renamed or removed); -1 is ignored.
void unregister_temporary(int slot) noexcept;
// Number of registered temporaries (for tests).
int registered_temporaries() noexcept;

// Installs the cleanup handler for SIGINT, SIGTERM and SIGHUP, except where the process
// ignores the signal (nohup). Idempotent.
void remove_temporaries_on_signals();

}  // namespace molsurf::detail
