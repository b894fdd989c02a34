#pragma once
// The names of AtomicFile's temporaries, and the removal of those a killed run left.
//
// A temporary is ".NAME.tmp-PID-N" beside its target NAME. When that would exceed the
// longest name a directory entry may have (NAME_MAX, 255 bytes on Linux), NAME is replaced
// by a hash of it (".molsurf-HHHHHHHHHHHHHHHH.tmp-PID-N"): the temporary's name must never be
// what makes a legal output name fail. Either way the name depends only on the target and
// the writer's process, so a later run can recognise the leftovers of a dead one.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>

namespace molsurf::detail {

// ".NAME.tmp-" or ".molsurf-HASH.tmp-": every temporary of `target_name` starts so.
std::string temporary_prefix(std::string_view target_name);
// The temporary's whole name: prefix, then "PID-N".
std::string temporary_name(std::string_view target_name, pid_t pid, int attempt);
// The PID in `entry` when it is a temporary of `target_name` (prefix, digits, '-', digits).
std::optional<pid_t> temporary_owner(std::string_view entry, std::string_view target_name);

// Removes the temporaries of `target` (its directory, its name) whose process no longer
// exists: what SIGKILL or a power cut left. A temporary whose process is alive (or that
// this process may not signal, another user's) is left alone. Never throws.
void remove_stale_temporaries(const std::filesystem::path& target) noexcept;

// The entries of one directory that may be temporaries, listed once: a job that writes
// thousands of files into one directory (the pieces of a .pvtp) would otherwise read the
// whole directory again for each. A temporary left after the listing was taken is removed
// by a later run.
class TemporaryListing {
 public:
  explicit TemporaryListing(const std::filesystem::path& directory) noexcept;
  // Nothing listed: for a temporary made and removed at once, which the write that follows
  // lists the directory for anyway.
  TemporaryListing() = default;
  // remove_stale_temporaries for a target (its name) in this directory. Never throws.
  void remove_stale_of(std::string_view target_name) noexcept;

 private:
  std::filesystem::path directory_;
  std::vector<std::string> names_;  // begin with '.' and hold ".tmp-"
};

}  // namespace molsurf::detail
