#pragma once
// Counts and memory sizes as messages print them: "%g"-like, so a limit of 2^64 bytes or
// 1e11 faces never reaches the terminal as a 20-digit number.
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

namespace molsurf::detail {

// Exact below ten million (what a user counts), three significant digits above.
inline std::string count_text(std::uint64_t value) {
  if (value == std::numeric_limits<std::uint64_t>::max()) return "more than 1.8e19";
  char text[32];
  if (value >= 10'000'000) std::snprintf(text, sizeof text, "%.3g", static_cast<double>(value));
  else std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(value));
  return text;
}

inline std::string gigabytes_text(std::uint64_t bytes) {
  if (bytes == std::numeric_limits<std::uint64_t>::max()) return "more than 1e10 GB";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", static_cast<double>(bytes) / 1e9);
  return text;
}

}  // namespace molsurf::detail
