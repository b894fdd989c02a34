#include "molsurf/error.hpp"

namespace molsurf {

void fail(const std::filesystem::path& file, std::size_t line, const std::string& problem) {
  std::string where = file.string();
  if (line > 0) where += ":" + std::to_string(line);
  throw Error(where + ": " + problem);
}

void fail(const std::filesystem::path& file, const std::string& problem) { fail(file, 0, problem); }

}  // namespace molsurf
