#include "io/standard_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "molsurf/error.hpp"

namespace molsurf {

namespace {

[[noreturn]] void fail_standard_output(int error_number) {
  // EBADF is what a closed descriptor gives (guard_standard_streams made it so).
  const std::string reason = error_number == EBADF ? "it is closed"
                             : error_number != 0   ? std::strerror(error_number)
                                                   : "a write failed";
  std::clearerr(stdout);
  throw Error("standard output: cannot write: " + reason + "; the report on it is lost");
}

}  // namespace

void guard_standard_streams() noexcept {
  // Reports go out where they are flushed, not whenever stdio's 4 KiB buffer fills, so a
  // failure is seen by flush_standard_output with its reason (a terminal keeps its lines).
  if (::isatty(STDOUT_FILENO) == 0) std::setvbuf(stdout, nullptr, _IOFBF, std::size_t{1} << 20);
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (null < 0) continue;
    if (null != fd) {
      ::dup2(null, fd);  // dup2 clears O_CLOEXEC on fd, as a standard stream wants
      ::close(null);
    } else {
      ::fcntl(fd, F_SETFD, 0);
    }
  }
}

void write_standard_output(std::string_view text) {
  flush_standard_output();  // what std::cout holds goes first, in order
  errno = 0;
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) fail_standard_output(errno);
  flush_standard_output();
}

void flush_standard_output() {
  // A failed write makes stdio drop its buffer, so its reason is only seen here, in errno
  // right after the flush that failed: callers flush where their text must be out.
  errno = 0;
  std::cout.flush();  // synchronised with stdio: fflush(stdout)
  if (std::fflush(stdout) != 0 || !std::cout || std::ferror(stdout)) fail_standard_output(errno);
}

}  // namespace molsurf
