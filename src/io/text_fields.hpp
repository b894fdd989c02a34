#pragma once
// Text files' lines and whitespace-separated fields: shared by the structure readers
// (PDB, mmCIF, PQR, xyzr, radius tables) and the text mesh formats.
#include <string>
#include <string_view>
#include <vector>

namespace molsurf::text {

// A text file's content as the line readers expect it: without a UTF-8 byte-order mark
// (Windows editors write one), and with old Mac OS line ends (CR alone) turned into LF so
// that lines and their numbers come out right; CRLF is left as it is (readers drop the CR).
void normalize_text(std::string& text);

// The fields of `line` split on blanks (space, tab, CR, VT, FF), views into it.
std::vector<std::string_view> split_fields(std::string_view line);

}  // namespace molsurf::text
