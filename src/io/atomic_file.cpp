#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "io/temporary_name.hpp"
#include "io/temporary_registry.hpp"
#include "molsurf/error.hpp"

namespace molsurf {

namespace {

constexpr int kMaxNameAttempts = 1000;

std::string reason(int error_number) {
  return error_number != 0 ? std::strerror(error_number) : "unknown error";
}

}  // namespace

void check_replaceable(const std::filesystem::path& target) {
  struct stat status {};
  if (::lstat(target.c_str(), &status) != 0) {
    if (errno == ENOENT) return;  // a new file
    if (errno == ELOOP) fail(target, "cannot write: a symbolic link loop");
    if (errno == ENOTDIR) fail(target, "cannot write: a part of the path is not a directory");
    return;  // other reasons (permissions) surface when the temporary is created
  }
  if (S_ISREG(status.st_mode)) return;
  if (S_ISLNK(status.st_mode))
    fail(target, "cannot write: it is a symbolic link; molsurf does not replace links or write through "
                 "them (name the file the link points to instead)");
  if (S_ISDIR(status.st_mode)) fail(target, "cannot write: it is a directory");
  fail(target, "cannot write: it is a device, pipe or socket, not a regular file; molsurf only replaces "
               "regular files (to discard a report, leave its option out)");
}

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) { reserve_temporary(nullptr); }

AtomicFile::AtomicFile(std::filesystem::path target, detail::TemporaryListing& listing) : target_(std::move(target)) {
  reserve_temporary(&listing);
}

void AtomicFile::reserve_temporary(detail::TemporaryListing* listing) {
  if (target_.filename().empty()) fail(target_, "cannot write: not a file name");
  check_replaceable(target_);
  const std::filesystem::path directory = target_.parent_path();
  const std::string name = target_.filename().string();
  // The temporary's name is short whatever the target's, so the target's own length is
  // checked here: found at the final rename, it would come after all the work.
  const long name_max = ::pathconf(directory.empty() ? "." : directory.c_str(), _PC_NAME_MAX);
  if (name_max > 0 && name.size() > static_cast<std::size_t>(name_max))
    fail(target_, "cannot write: File name too long (" + std::to_string(name.size()) + " bytes, more than the " +
                      std::to_string(name_max) + " its file system allows)");
  if (listing != nullptr)
    listing->remove_stale_of(name);
  else
    detail::remove_stale_temporaries(target_);
  // O_EXCL reserves the name: two threads or processes writing the same target each get
  // their own temporary, without a shared counter.
  for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
    const std::string temporary = detail::temporary_name(name, ::getpid(), attempt);
    std::filesystem::path candidate = directory / temporary;
    // Registered before it exists, so no signal can fall between creation and
    // registration; unlinking a name that is not there yet is harmless.
    const int slot = detail::register_temporary(directory, temporary);
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      temp_ = std::move(candidate);
      registry_slot_ = slot;
      return;
    }
    const int error_number = errno;
    detail::unregister_temporary(slot);
    if (error_number != EEXIST) fail_with_errno(error_number);
  }
  fail(target_, "cannot write: no free temporary file name");
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !temp_.empty()) {
    if (stream_.is_open()) stream_.close();
    std::error_code ignored;  // a destructor must not throw; a leftover temp is harmless
    std::filesystem::remove(temp_, ignored);
  }
  detail::unregister_temporary(registry_slot_);
}

std::ofstream& AtomicFile::stream() {
  if (!stream_.is_open()) {
    errno = 0;
    stream_.open(temp_, std::ios::binary | std::ios::trunc);
    if (!stream_) fail_with_errno(errno);
  }
  return stream_;
}

void AtomicFile::write(std::string_view data) {
  std::ofstream& out = stream();
  errno = 0;
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
  if (!out) fail_with_errno(errno);
}

void AtomicFile::finish() {
  if (committed_ || !stream_.is_open()) return;
  errno = 0;
  stream_.flush();
  stream_.close();
  if (stream_.fail()) fail_with_errno(errno);
}

void AtomicFile::commit() {
  if (committed_) return;
  finish();
  check_replaceable(target_);  // again: the target may have changed while we computed
  std::error_code error;
  std::filesystem::rename(temp_, target_, error);
  if (error) fail(target_, "cannot write: " + error.message());
  committed_ = true;
  detail::unregister_temporary(registry_slot_);
  registry_slot_ = -1;
}

void AtomicFile::fail_with_errno(int error_number) const {
  fail(target_, "cannot write: " + reason(error_number));
}

AtomicFile& AtomicFileSet::add(std::filesystem::path target) {
  auto it = listings_.find(target.parent_path());
  if (it == listings_.end())
    it = list_directories_ ? listings_.try_emplace(target.parent_path(), target.parent_path()).first
                           : listings_.try_emplace(target.parent_path()).first;
  files_.push_back(std::make_unique<AtomicFile>(std::move(target), it->second));
  return *files_.back();
}

std::vector<std::filesystem::path> AtomicFileSet::targets() const {
  std::vector<std::filesystem::path> result;
  for (const auto& file : files_) result.push_back(file->target());
  return result;
}

void AtomicFileSet::finish() {
  for (const auto& file : files_) file->finish();
}

void AtomicFileSet::commit() {
  finish();  // every temporary complete first
  for (std::size_t i = 0; i < files_.size(); ++i) {
    try {
      files_[i]->commit();
    } catch (const Error& error) {
      if (i == 0) throw;
      std::string replaced, left;
      for (std::size_t k = 0; k < files_.size(); ++k) {
        if (k == i) continue;
        std::string& list = k < i ? replaced : left;
        list += (list.empty() ? "" : ", ") + files_[k]->target().string();
      }
      throw Error(std::string(error.what()) + "; already written: " + replaced +
                  (left.empty() ? "" : "; not written: " + left));
    }
  }
}

void write_file_atomically(const std::filesystem::path& target, std::string_view content) {
  AtomicFile file(target);
  file.write(content);
  file.commit();
}

}  // namespace molsurf
