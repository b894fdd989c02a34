#pragma once
// Values as messages show them: numbers with %g ("1e+16", "nan"; never 309 digits of the
// largest double), and text from a user or a file quoted, cut short and made printable, so
// a binary file never reaches the terminal raw.
#include <cctype>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace molsurf::detail {

inline std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// 'TEXT': at most `max_shown` characters ("...'" when cut), each unprintable one as '?'.
inline std::string quoted_text(std::string_view text, std::size_t max_shown) {
  std::string shown(text.substr(0, max_shown));
  for (char& c : shown)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return "'" + shown + (text.size() > max_shown ? "...'" : "'");
}

}  // namespace molsurf::detail
