#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "molsurf/error.hpp"

namespace molsurf {

namespace {

constexpr int kMaxNameAttempts = 1000;

std::string reason(int error_number) {
  return error_number != 0 ? std::strerror(error_number) : "unknown error";
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  if (target_.filename().empty()) fail(target_, "cannot write: not a file name");
  const std::filesystem::path directory = target_.parent_path();
  std::string prefix(".");
  prefix.append(target_.filename().string()).append(".tmp-").append(std::to_string(::getpid())).append("-");
  // O_EXCL reserves the name: two threads or processes writing the same target each get
  // their own temporary, without a shared counter.
  for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
    std::filesystem::path candidate = directory / (prefix + std::to_string(attempt));
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      temp_ = std::move(candidate);
      return;
    }
    if (errno != EEXIST) fail_with_errno(errno);
  }
  fail(target_, "cannot write: no free temporary file name");
}

AtomicFile::~AtomicFile() {
  if (committed_ || temp_.empty()) return;
  if (stream_.is_open()) stream_.close();
  std::error_code ignored;  // a destructor must not throw; a leftover temp is harmless
  std::filesystem::remove(temp_, ignored);
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

void AtomicFile::commit() {
  if (committed_) return;
  if (stream_.is_open()) {
    errno = 0;
    stream_.flush();
    stream_.close();
    if (stream_.fail()) fail_with_errno(errno);
  }
  std::error_code error;
  std::filesystem::rename(temp_, target_, error);
  if (error) fail(target_, "cannot write: " + error.message());
  committed_ = true;
}

void AtomicFile::fail_with_errno(int error_number) const {
  fail(target_, "cannot write: " + reason(error_number));
}

void write_file_atomically(const std::filesystem::path& target, std::string_view content) {
  AtomicFile file(target);
  file.write(content);
  file.commit();
}

}  // namespace molsurf
