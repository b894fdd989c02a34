#pragma once
// The checks on the numbers of an input, worded once: a structure or mesh file's reader puts
// FILE:LINE (and the field) in front of the problem, Python the array entry. So a NaN centre
// reads "nan.xyzr:1: x: nan is not a finite number" from a file and
// "centres[0, 0]: nan is not a finite number" from NumPy.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace molsurf {

// Coordinates and radii must be below this in magnitude. Beyond it the spacing of doubles
// exceeds 1 angstrom, so no atom is resolved any more: such numbers are input errors (a
// units mix-up, a corrupt column), not something to compute with.
inline constexpr double kMaxCoordinate = 1e16;

// Each returns what is wrong with the value, or an empty string when nothing is.
// "nan is not a finite number", "1e+16 is out of range (its magnitude must be below 1e16 angstrom)".
std::string coordinate_problem(double value);
// The same, and "-1 is negative; a radius is 0 or more (angstrom, without the probe)".
std::string radius_problem(double value);
// "vertex index 7 out of range (0..3)": indices from `first_index` (0, or 1 for OBJ and MSMS).
std::string vertex_index_problem(long long index, std::size_t vertex_count, int first_index = 0);
// "expected an integer, found '1.5'" (the text shown at most 40 characters, unprintable ones as '?').
std::string integer_text_problem(std::string_view text);

// "NAME[i, j]": entry `flat` of a row-major array of `shape`, as NumPy indexes it.
std::string array_entry_name(std::string_view name, std::size_t flat, std::span<const std::size_t> shape);

// Arrays as a caller without a file hands them over (row-major, with their shape): each
// throws molsurf::Error naming the first bad entry NumPy's way, "NAME[i, j]: PROBLEM".
void check_coordinate_array(std::string_view name, std::span<const double> values,
                            std::span<const std::size_t> shape);
void check_radius_array(std::string_view name, std::span<const double> radii);
// (F, 3) vertex indices of a mesh with `vertex_count` vertices.
void check_face_array(std::string_view name, std::span<const std::int64_t> indices, std::size_t vertex_count);

}  // namespace molsurf
