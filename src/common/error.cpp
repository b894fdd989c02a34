#include "molsurf/error.hpp"

namespace molsurf {

void fail(const std::filesystem::path& file, std::size_t line, const std::string& problem) {
  std::string message = file.string();
  if (line > 0) {
    message += ':';
    message += std::to_string(line);
  }
  message += ": ";
  message += problem;
  throw Error(message);
}

void fail(const std::filesystem::path& file, const std::string& problem) { fail(file, 0, problem); }

}  // namespace molsurf
