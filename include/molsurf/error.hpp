#pragma once
// One exception type for every user-facing failure. The message is complete and
// printable as is: it names the file (and line, where there is one) and the problem.
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace molsurf {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "FILE: problem" or "FILE:LINE: problem" (line is 1-based; 0 means no line).
[[noreturn]] void fail(const std::filesystem::path& file, std::size_t line, const std::string& problem);
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem);

}  // namespace molsurf
