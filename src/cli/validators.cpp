#include "cli/validators.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>

#include "common/message_text.hpp"

namespace molsurf::cli {

namespace {

// The value as typed, short and printable (it is echoed in the message).
std::string shown(const std::string& value) { return detail::quoted_text(value, 32); }

std::string_view without_plus(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  return text;
}

}  // namespace

CLI::Validator number_in(const NumberParameter& parameter) {
  return CLI::Validator(
      [parameter](std::string& value) -> std::string {
        const std::string_view text = without_plus(value);
        double number = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
        if (text.empty() || end != text.data() + text.size() ||
            (error != std::errc() && error != std::errc::result_out_of_range))
          return shown(value) + " is not a number";
        // Beyond the doubles: 1e999 is an infinity and 1e-999 zero, which the range then judges.
        if (error == std::errc::result_out_of_range) number = std::strtod(std::string(text).c_str(), nullptr);
        return problem(parameter, number);
      },
      "NUMBER in " + range_text(parameter));
}

CLI::Validator whole_number_in(const WholeParameter& parameter) {
  return CLI::Validator(
      [parameter](std::string& value) -> std::string {
        const std::string_view text = without_plus(value);
        long long number = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
        if (text.empty() || end != text.data() + text.size() ||
            (error != std::errc() && error != std::errc::result_out_of_range))
          return shown(value) + " is not a whole number; expected one in " + range_text(parameter);
        if (error == std::errc::result_out_of_range)
          return shown(value) + " is out of range; expected a whole number in " + range_text(parameter);
        return problem(parameter, number);
      },
      "INTEGER in " + range_text(parameter));
}

CLI::Validator one_of(std::span<const std::string_view> names) {
  std::string list;
  for (const std::string_view name : names) list += (list.empty() ? "" : ",") + std::string(name);
  return CLI::Validator([names](std::string& value) { return choice_problem(value, names); }, "{" + list + "}");
}

CLI::Validator radius_set_name() {
  std::string list;
  for (const std::string& name : RadiusTable::builtin_names()) list += (list.empty() ? "" : ",") + name;
  return CLI::Validator([](std::string& value) { return radius_set_problem(value); }, "{" + list + "}");
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

std::string option_spelling(std::string_view parameter) {
  std::string option = "--" + std::string(parameter);
  for (char& c : option)
    if (c == '_') c = '-';
  return option;
}

}  // namespace molsurf::cli
