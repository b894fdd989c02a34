#pragma once
// Option checks with one-line messages that name the value as given: numbers are parsed
// strictly (no NaN, no infinity, no trailing text) and ranges print with %g, never as
// 309 digits of the largest double.
#include <CLI/CLI.hpp>
#include <string>

namespace molsurf::cli {

// A finite number in [low, high] (or (low, high] when low_open).
CLI::Validator finite_number(double low, double high, bool low_open = false);
// A whole number in [low, high].
CLI::Validator whole_number(long long low, long long high);
// A file that can be read: names the reason (not found, a symbolic link loop, a
// directory, permission denied) instead of CLI11's "File does not exist".
CLI::Validator readable_file();

}  // namespace molsurf::cli
