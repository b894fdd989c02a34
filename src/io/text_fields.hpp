#pragma once
// Whitespace-separated fields of one line of a text file: shared by the structure readers
// (PQR, xyzr, radius tables) and the text mesh formats.
#include <string_view>
#include <vector>

namespace molsurf::text {

// The fields of `line` split on blanks (space, tab, CR, VT, FF), views into it.
std::vector<std::string_view> split_fields(std::string_view line);

}  // namespace molsurf::text
