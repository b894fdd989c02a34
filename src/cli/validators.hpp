#pragma once
// Option checks with one-line messages. The ranges and names, and the words that refuse a
// value, are the library's (molsurf/parameters.hpp), so the command and Python refuse the
// same values alike; here only the text is parsed, strictly: no trailing text, and NaN and
// infinity are numbers the range then refuses.
#include <CLI/CLI.hpp>
#include <span>
#include <string>
#include <string_view>

#include "molsurf/parameters.hpp"

namespace molsurf::cli {

// A number in the range of `parameter`.
CLI::Validator number_in(const NumberParameter& parameter);
// A whole number in the range of `parameter`.
CLI::Validator whole_number_in(const WholeParameter& parameter);
// One of `names`.
CLI::Validator one_of(std::span<const std::string_view> names);
// A built-in radius set's name.
CLI::Validator radius_set_name();
// A file that can be read: names the reason (not found, a symbolic link loop, a
// directory, permission denied) instead of CLI11's "File does not exist".
CLI::Validator readable_file();

// How the command spells a library parameter: "max_faces" -> "--max-faces".
std::string option_spelling(std::string_view parameter);

}  // namespace molsurf::cli
