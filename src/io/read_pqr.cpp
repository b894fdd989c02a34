// PQR: PDB-like records, but whitespace-separated (column positions are not reliable in
// files written by pdb2pqr, APBS tools or MD converters) and with the occupancy and
// B-factor columns replaced by the partial charge and the radius.
//   ATOM/HETATM serial name resName [chain] resSeq[icode] x y z charge radius
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/structure_readers.hpp"
#include "molsurf/error.hpp"
#include "molsurf/input_checks.hpp"

namespace molsurf::detail {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

struct ResidueNumber {
  std::int64_t number = 0;
  char insertion_code = ' ';
};

// "52" or "52A": PQR writers glue the insertion code to the number.
std::optional<ResidueNumber> parse_residue_number(std::string_view field) {
  ResidueNumber result;
  if (!field.empty() && std::isalpha(static_cast<unsigned char>(field.back()))) {
    result.insertion_code = field.back();
    field.remove_suffix(1);
  }
  const std::optional<std::int64_t> number = parse_int<std::int64_t>(field);
  if (!number) return std::nullopt;
  result.number = *number;
  return result;
}

}  // namespace

ModelRecords read_pqr(const std::filesystem::path& path, std::optional<int> model, std::uint64_t max_text) {
  const std::string text = read_text_file(path, max_text);
  ModelRecords result;
  std::optional<int> current_model;  // set by MODEL records; files without them have model 1
  std::optional<int> chosen_model = model;
  std::size_t line_number = 0;
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    const std::string_view line = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    ++line_number;
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) continue;
    const std::string record = upper(fields[0]);
    if (record == "MODEL") {
      const std::optional<int> number = fields.size() >= 2 ? parse_int(fields[1]) : std::nullopt;
      if (!number) fail(path, line_number, "MODEL record without a model number");
      current_model = *number;
      result.model_numbers.push_back(*number);
      continue;
    }
    if (record != "ATOM" && record != "HETATM") continue;  // REMARK, TER, END...

    if (fields.size() != 10 && fields.size() != 11)
      fail(path, line_number,
           record + " record has " + std::to_string(fields.size()) +
               " fields; PQR expects 10 or 11: " + record +
               " serial name residue [chain] number x y z charge radius");
    const bool has_chain = fields.size() == 11;
    const std::size_t number_field = has_chain ? 5 : 4;
    const auto field_error = [&](const std::string& what, std::string_view value) {
      fail(path, line_number,
           record + " record: " + what + " " + excerpt(value) + " is not a number");
    };

    if (!current_model) {
      current_model = 1;
      result.model_numbers.push_back(1);
    }
    if (!chosen_model) chosen_model = *current_model;

    AtomRecord parsed;
    Atom& atom = parsed.atom;
    const std::optional<int> serial = parse_int(fields[1]);
    if (!serial) field_error("serial", fields[1]);
    atom.serial = *serial;
    atom.atom_name = std::string(fields[2]);
    atom.residue_name = upper(fields[3]);
    if (has_chain) atom.chain = std::string(fields[4]);
    const std::optional<ResidueNumber> residue = parse_residue_number(fields[number_field]);
    if (!residue)
      fail(path, line_number,
           record + " record: residue number " + excerpt(fields[number_field]) +
               " is not a number" +
               (has_chain ? std::string()
                          : " (is a column missing? PQR expects " + record +
                                " serial name residue [chain] number x y z charge radius)"));
    atom.residue_number = residue->number;
    atom.insertion_code = residue->insertion_code;
    double values[5];
    constexpr const char* value_names[] = {"x coordinate", "y coordinate", "z coordinate",
                                           "charge", "radius"};
    for (std::size_t i = 0; i < 5; ++i) {
      const std::string_view field = fields[number_field + 1 + i];
      // Coordinates and the radius may spell NaN or infinity: refused below, in their own words.
      const std::optional<double> value = i == 3 ? parse_double(field) : parse_real(field);
      if (!value) field_error(value_names[i], field);
      values[i] = *value;
    }
    for (std::size_t i : {0, 1, 2})
      check_coordinate_range(path, line_number, values[i], record + " record: " + value_names[i]);
    if (const std::string problem = radius_problem(values[4]); !problem.empty())
      fail(path, line_number, record + " record: radius: " + problem);
    atom.centre = {values[0], values[1], values[2]};
    atom.charge = values[3];
    atom.radius = values[4];
    atom.element = infer_element(atom.atom_name, atom.residue_name);
    atom.hetero = record == "HETATM";
    if (*current_model == *chosen_model) result.records.push_back(std::move(parsed));
  }
  if (result.records.empty()) {
    if (model && std::find(result.model_numbers.begin(), result.model_numbers.end(), *model) ==
                     result.model_numbers.end())
      fail_unknown_model(path, *model, result.model_numbers);
    fail(path, model ? "no ATOM or HETATM records in model " + std::to_string(*model)
                     : std::string("no ATOM or HETATM records"));
  }
  result.model_used = *chosen_model;
  return result;
}

}  // namespace molsurf::detail
