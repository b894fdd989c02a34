#include "cli/validators.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace molsurf::cli {

namespace {

std::string g(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The value as typed, short and printable (it is echoed in the message).
std::string shown(const std::string& value) {
  std::string text;
  for (char c : value.substr(0, 32)) text += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return "'" + text + (value.size() > 32 ? "...'" : "'");
}

}  // namespace

CLI::Validator finite_number(double low, double high, bool low_open) {
  const std::string range = (low_open ? "(" : "[") + g(low) + ", " + g(high) + "]";
  return CLI::Validator(
      [=](std::string& value) -> std::string {
        std::string_view text = value;
        if (!text.empty() && text.front() == '+') text.remove_prefix(1);
        double number = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
        if (text.empty() || end != text.data() + text.size() ||
            (error != std::errc() && error != std::errc::result_out_of_range))
          return shown(value) + " is not a number";
        if (error == std::errc::result_out_of_range || !std::isfinite(number))
          return shown(value) + " is not a finite number; expected one in " + range;
        if (number < low || (low_open && number == low) || number > high)
          return g(number) + " is out of range; expected a number in " + range;
        return {};
      },
      "NUMBER in " + range);
}

CLI::Validator whole_number(long long low, long long high) {
  const std::string range = std::to_string(low) + ".." + std::to_string(high);
  return CLI::Validator(
      [=](std::string& value) -> std::string {
        std::string_view text = value;
        if (!text.empty() && text.front() == '+') text.remove_prefix(1);
        long long number = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
        if (text.empty() || end != text.data() + text.size() ||
            (error != std::errc() && error != std::errc::result_out_of_range))
          return shown(value) + " is not a whole number; expected one in " + range;
        if (error == std::errc::result_out_of_range || number < low || number > high)
          return shown(value) + " is out of range; expected a whole number in " + range;
        return {};
      },
      "INTEGER in " + range);
}

CLI::Validator readable_file() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        if (value.empty()) return "an empty file name";
        struct stat status {};
        if (::stat(value.c_str(), &status) != 0) {
          const int error = errno;
          if (error == ENOENT) return value + ": file not found";
          if (error == ELOOP) return value + ": cannot open: a symbolic link loop (too many levels of links)";
          return value + ": cannot open: " + std::strerror(error);
        }
        if (S_ISDIR(status.st_mode)) return value + ": is a directory, not a file";
        if (::access(value.c_str(), R_OK) != 0) return value + ": cannot open: " + std::strerror(errno);
        return {};
      },
      "FILE");
}

}  // namespace molsurf::cli
