#include "molsurf/input_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "common/message_text.hpp"
#include "molsurf/error.hpp"

namespace molsurf {

std::string array_entry_name(std::string_view name, std::size_t flat, std::span<const std::size_t> shape) {
  std::string index;
  std::size_t stride = 1;
  for (const std::size_t extent : shape) stride *= extent;
  for (const std::size_t extent : shape) {
    stride /= std::max<std::size_t>(extent, 1);  // an empty array has no entry to name
    index += (index.empty() ? "" : ", ") + std::to_string(flat / stride);
    flat %= stride;
  }
  return std::string(name) + "[" + index + "]";
}

std::string coordinate_problem(double value) {
  if (std::abs(value) < kMaxCoordinate) return {};
  if (!std::isfinite(value)) return detail::number_text(value) + " is not a finite number";
  return detail::number_text(value) + " is out of range (its magnitude must be below 1e16 angstrom)";
}

std::string radius_problem(double value) {
  if (std::string text = coordinate_problem(value); !text.empty()) return text;
  if (value < 0)
    return detail::number_text(value) + " is negative; a radius is 0 or more (angstrom, without the probe)";
  return {};
}

std::string vertex_index_problem(long long index, std::size_t vertex_count, int first_index) {
  if (index >= first_index && static_cast<unsigned long long>(index - first_index) < vertex_count) return {};
  return "vertex index " + std::to_string(index) + " out of range (" + std::to_string(first_index) + ".." +
         std::to_string(static_cast<long long>(vertex_count) - 1 + first_index) + ")";
}

std::string integer_text_problem(std::string_view text) {
  return "expected an integer, found " + detail::quoted_text(text, 40);
}

void check_coordinate_array(std::string_view name, std::span<const double> values,
                            std::span<const std::size_t> shape) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::string text = coordinate_problem(values[i]); !text.empty())
      throw Error(array_entry_name(name, i, shape) + ": " + text);
}

void check_radius_array(std::string_view name, std::span<const double> radii) {
  const std::size_t shape[] = {radii.size()};
  for (std::size_t i = 0; i < radii.size(); ++i)
    if (std::string text = radius_problem(radii[i]); !text.empty())
      throw Error(array_entry_name(name, i, shape) + ": " + text);
}

void check_face_array(std::string_view name, std::span<const std::int64_t> indices, std::size_t vertex_count) {
  const std::size_t shape[] = {indices.size() / 3, 3};
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (std::string text = vertex_index_problem(indices[i], vertex_count); !text.empty())
      throw Error(array_entry_name(name, i, shape) + ": " + text);
}

}  // namespace molsurf
