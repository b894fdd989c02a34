// MSMS sphere lists: "x y z r [name]" per line. Blank lines and '#' comments are allowed;
// anything after the radius is taken as the sphere's name (MSMS .xyzrn files put
// "1 NAME" there, hence the join).
#include <string>
#include <string_view>

#include "io/structure_readers.hpp"
#include "molsurf/error.hpp"
#include "molsurf/input_checks.hpp"

namespace molsurf::detail {

std::vector<Atom> read_xyzr(const std::filesystem::path& path, std::uint64_t max_text) {
  const std::string text = read_text_file(path, max_text);
  std::vector<Atom> atoms;
  std::size_t line_number = 0;
  DataLines lines(text);
  while (lines.next()) {
    line_number = lines.line_number();
    const std::vector<std::string_view>& fields = lines.fields();
    if (fields.size() < 4)
      fail(path, line_number,
           "expected 'x y z r [name]', found " + std::to_string(fields.size()) + " field" +
               (fields.size() == 1 ? "" : "s"));
    double values[4];
    constexpr const char* value_names[] = {"x", "y", "z", "radius"};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::optional<double> value = parse_real(fields[i]);
      if (!value)
        fail(path, line_number,
             std::string(value_names[i]) + " " + excerpt(fields[i]) + " is not a number");
      values[i] = *value;
    }
    for (std::size_t i = 0; i < 3; ++i) check_coordinate_range(path, line_number, values[i], value_names[i]);
    // Radius 0 is accepted here and dropped (and counted) by read_structure: such a sphere
    // adds nothing to a union of balls. A negative radius is a mistake.
    if (const std::string problem = radius_problem(values[3]); !problem.empty())
      fail(path, line_number, "radius: " + problem);
    Atom atom;
    atom.centre = {values[0], values[1], values[2]};
    atom.radius = values[3];
    for (std::size_t i = 4; i < fields.size(); ++i) {
      if (!atom.atom_name.empty()) atom.atom_name += ' ';
      atom.atom_name += fields[i];
    }
    // Without residues, an element guessed from a plain atom name ("CA") could be wrong;
    // it is only informative here since the radius is given.
    atom.element = atom.atom_name.empty() ? "X" : infer_element(fields.back(), "");
    atoms.push_back(std::move(atom));
  }
  if (atoms.empty()) fail(path, "no spheres (expected lines 'x y z r [name]')");
  return atoms;
}

}  // namespace molsurf::detail
