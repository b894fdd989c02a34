#include "io/temporary_name.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>

namespace molsurf::detail {

namespace {

constexpr std::size_t kNameMax = 255;           // NAME_MAX on Linux's file systems
constexpr std::string_view kSuffixDigits = "4194304-999";  // the longest "PID-N" (pid_max 2^22)

// FNV-1a: stable across runs and builds, which std::hash is not promised to be.
std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

bool all_digits(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text)
    if (c < '0' || c > '9') return false;
  return true;
}

}  // namespace

std::string temporary_prefix(std::string_view target_name) {
  std::string prefix = "." + std::string(target_name) + ".tmp-";
  if (prefix.size() + kSuffixDigits.size() <= kNameMax) return prefix;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(target_name)));
  return std::string(".molsurf-") + hash + ".tmp-";
}

std::string temporary_name(std::string_view target_name, pid_t pid, int attempt) {
  return temporary_prefix(target_name) + std::to_string(pid) + "-" + std::to_string(attempt);
}

namespace {

// The PID in `entry` when it is `prefix` followed by "PID-N".
std::optional<pid_t> owner_after(std::string_view entry, std::string_view prefix) {
  if (!entry.starts_with(prefix)) return std::nullopt;
  const std::string_view rest = entry.substr(prefix.size());
  const std::size_t dash = rest.find('-');
  if (dash == std::string_view::npos) return std::nullopt;
  const std::string_view pid_text = rest.substr(0, dash);
  if (!all_digits(pid_text) || !all_digits(rest.substr(dash + 1))) return std::nullopt;
  pid_t pid = 0;
  const auto [end, error] = std::from_chars(pid_text.data(), pid_text.data() + pid_text.size(), pid);
  if (error != std::errc() || end != pid_text.data() + pid_text.size() || pid <= 0) return std::nullopt;
  return pid;
}

}  // namespace

std::optional<pid_t> temporary_owner(std::string_view entry, std::string_view target_name) {
  return owner_after(entry, temporary_prefix(target_name));
}

void remove_stale_temporaries(const std::filesystem::path& target) noexcept {
  TemporaryListing(target.parent_path()).remove_stale_of(target.filename().string());
}

TemporaryListing::TemporaryListing(const std::filesystem::path& directory) noexcept : directory_(directory) {
  DIR* listing = ::opendir(directory_.empty() ? "." : directory_.c_str());
  if (listing == nullptr) return;
  try {
    while (const dirent* entry = ::readdir(listing)) {
      const std::string_view name = entry->d_name;
      if (name.starts_with('.') && name.find(".tmp-") != std::string_view::npos) names_.emplace_back(name);
    }
  } catch (...) {  // out of memory: nothing is removed, which is harmless
    names_.clear();
  }
  ::closedir(listing);
}

void TemporaryListing::remove_stale_of(std::string_view target_name) noexcept {
  if (names_.empty()) return;
  try {
    const int fd = ::open(directory_.empty() ? "." : directory_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    const std::string prefix = temporary_prefix(target_name);
    const pid_t self = ::getpid();
    for (std::string& name : names_) {
      const std::optional<pid_t> owner = owner_after(name, prefix);
      if (!owner || *owner == self) continue;
      // Signal 0 asks only whether the process exists; EPERM means it does (another user's).
      if (::kill(*owner, 0) == 0 || errno != ESRCH) continue;
      struct stat status {};
      if (::fstatat(fd, name.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(status.st_mode)) continue;
      ::unlinkat(fd, name.c_str(), 0);
      name.clear();  // starts with no prefix: never matched again
    }
    ::close(fd);
  } catch (...) {  // out of memory building the prefix: nothing removed
  }
}

}  // namespace molsurf::detail
