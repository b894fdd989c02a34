#include "io/coordinate_range.hpp"

#include "molsurf/error.hpp"
#include "molsurf/input_checks.hpp"

namespace molsurf::detail {

void check_coordinate_range(const std::filesystem::path& path, std::size_t line, double value,
                            const std::string& what) {
  if (std::string problem = coordinate_problem(value); !problem.empty()) fail(path, line, what + ": " + problem);
}

}  // namespace molsurf::detail
