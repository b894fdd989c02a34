#pragma once
// Temporary files that must not outlive a run ended by a signal. AtomicFile registers each
// temporary here while it exists; when a signal whose default action ends the process
// arrives (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ, SIGXCPU, SIGALRM, SIGUSR1,
// SIGUSR2, SIGABRT, SIGSEGV, SIGBUS, ...), the handler unlinks every registered temporary
// and then lets the signal do what it did before (end the process), so neither a Ctrl-C
// nor a file size limit leaves a ".NAME.tmp-PID-N" file behind. SIGKILL cannot be caught:
// what it leaves is removed by the next run that writes the same target
// (remove_stale_temporaries, temporary_name.hpp).
//
// A signal handler may only touch lock-free atomics and call async-signal-safe functions
// (unlinkat, sigaction, raise), and it cannot reach objects: the registry is therefore a
// fixed-size static table, the one global state of the library's writers. Each slot holds
// an open descriptor of the temporary's directory and the file's own name, so a path of
// any depth (beyond PATH_MAX from the root) is removed. A temporary that finds no free slot
// (more than kTemporarySlots at once) is written normally but not cleaned up by a signal.
#include <cstddef>
#include <filesystem>
#include <string_view>

namespace molsurf::detail {

constexpr int kTemporarySlots = 64;
constexpr std::size_t kTemporaryNameBytes = 256;  // NAME_MAX + 1

// Registers the temporary `name` in `directory` (empty: the current directory); returns its
// slot, or -1 when none is free or the directory cannot be opened.
int register_temporary(const std::filesystem::path& directory, std::string_view name) noexcept;
// Forgets a slot (the file was renamed or removed); -1 is ignored.
void unregister_temporary(int slot) noexcept;
// Number of registered temporaries (for tests).
int registered_temporaries() noexcept;

// Installs the cleanup handler for every signal that ends the process by default and whose
// disposition is still the default: a signal the process ignores (SIGHUP under nohup,
// SIGPIPE and SIGXFSZ in Python) or handles itself (Python's SIGINT) is left alone.
// Idempotent.
void remove_temporaries_on_signals();

}  // namespace molsurf::detail
