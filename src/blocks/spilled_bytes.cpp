#include "blocks/spilled_bytes.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "molsurf/error.hpp"

namespace molsurf::blocks {

namespace {

std::string reason(int error) { return std::system_category().message(error); }

}  // namespace

SpilledBytes::SpilledBytes() {
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) throw Error("--blocks: no temporary directory to keep the blocks' seams in (TMPDIR): " + ec.message());
  std::string name = (dir / "molsurf-seams-XXXXXX").string();
  fd_ = ::mkstemp(name.data());
  if (fd_ < 0) throw Error("--blocks: cannot make a temporary file in " + dir.string() + ": " + reason(errno));
  ::unlink(name.c_str());
}

SpilledBytes::~SpilledBytes() {
  if (fd_ >= 0) ::close(fd_);
}

void SpilledBytes::push(std::string_view bytes) {
  std::uint64_t done = 0;
  while (done < bytes.size()) {
    const ::ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<::off_t>(end_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error("--blocks: cannot keep a block's seams in the temporary directory (TMPDIR): " +
                  reason(n < 0 ? errno : ENOSPC));
    done += static_cast<std::uint64_t>(n);
  }
  records_.emplace_back(end_, bytes.size());
  end_ += bytes.size();
}

std::string SpilledBytes::read(std::size_t k) const {
  const auto [offset, length] = records_.at(k);
  std::string bytes(length, '\0');
  std::uint64_t done = 0;
  while (done < length) {
    const ::ssize_t n = ::pread(fd_, bytes.data() + done, length - done, static_cast<::off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error("--blocks: cannot read a block's seams back from the temporary directory: " +
                  reason(n < 0 ? errno : EIO));
    done += static_cast<std::uint64_t>(n);
  }
  return bytes;
}

}  // namespace molsurf::blocks
