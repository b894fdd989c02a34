// libFuzzer target for the reports' text: any bytes as names (chain, residue, atom,
// element: mmCIF allows nearly any text there, and file names any byte but '/' and NUL)
// must give a JSON string that a real parser reads back, equal to the name when the name is
// valid UTF-8, and CSV tables that an RFC 4180 reader reads back field for field. A parse
// failure or a changed field is a finding (abort).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_writer.hpp"
#include "molsurf/surface_report.hpp"
#include "rfc4180.hpp"

namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

// Valid UTF-8, as nlohmann (an independent implementation) judges it: its strict dump
// refuses anything else.
bool valid_utf8(const std::string& text) {
  try {
    (void)nlohmann::json(text).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

void check_json(const std::vector<std::string>& names) {
  molsurf::io::JsonWriter writer;
  writer.begin_object();
  for (std::size_t i = 0; i < names.size(); ++i) writer.key(std::to_string(i)).value(names[i]);
  writer.key("name " + names.front()).value(true);  // a name as a key (never one of the digits above)
  writer.end_object();
  nlohmann::json parsed;
  try {
    parsed = nlohmann::json::parse(writer.str());
  } catch (const nlohmann::json::exception&) {
    std::abort();  // the report does not parse
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string back = parsed.at(std::to_string(i)).get<std::string>();
    if (valid_utf8(names[i])) require(back == names[i]);
  }
}

void check_csv(const std::vector<std::string>& names) {
  std::vector<molsurf::Atom> atoms(2);
  for (std::size_t k = 0; k < atoms.size(); ++k) {
    molsurf::Atom& a = atoms[k];
    a.chain = names[k % names.size()];
    a.residue_name = names[(k + 1) % names.size()];
    a.atom_name = names[(k + 2) % names.size()];
    a.element = names[(k + 3) % names.size()];
    a.insertion_code = names.back().empty() ? ' ' : names.back().front();
    a.residue_number = static_cast<std::int64_t>(names.front().size()) - 3'000'000'000LL;
  }
  const std::vector<double> area{1.25, 0.5};
  try {
    const auto rows = molsurf::testing::read_rfc4180(molsurf::per_atom_csv(atoms, area));
    require(rows.size() == atoms.size() + 1);
    for (std::size_t k = 0; k < atoms.size(); ++k) {
      require(rows[k + 1].size() == rows[0].size());
      require(rows[k + 1][2] == atoms[k].chain && rows[k + 1][3] == atoms[k].residue_name);
      require(rows[k + 1][4] == std::to_string(atoms[k].residue_number));
      require(rows[k + 1][6] == atoms[k].atom_name && rows[k + 1][7] == atoms[k].element);
    }
    for (const std::string& table : {molsurf::per_residue_csv(atoms, area), molsurf::per_chain_csv(atoms, area),
                                     molsurf::csv_with_model_column(molsurf::per_atom_csv(atoms, area), 3, false)}) {
      const auto other = molsurf::testing::read_rfc4180(table);
      for (const auto& row : other) require(row.size() == other.front().size());
    }
  } catch (const std::runtime_error&) {
    std::abort();  // a table that does not read back
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Up to four names, split at NUL bytes.
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> names;
  std::size_t start = 0;
  while (names.size() < 4) {
    const std::size_t end = input.find('\0', start);
    names.emplace_back(input.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  check_json(names);
  check_csv(names);
  return 0;
}
