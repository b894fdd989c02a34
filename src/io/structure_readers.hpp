#pragma once
// Internal: the format readers behind read_structure(). Each reader turns a file into the
// atom records of one model, unfiltered; selection and radii are decided in one place
// (read_structure.cpp) so every format follows the same rules.
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/bounded_read.hpp"
#include "io/coordinate_range.hpp"
#include "io/text_fields.hpp"
#include "molsurf/atoms.hpp"

namespace gemmi {
struct Structure;
}

namespace molsurf::detail {

struct AtomRecord {
  Atom atom;          // radius is set only by formats that carry one (PQR, xyzr)
  char altloc = '\0';  // '\0' when the atom has a single conformer
};

struct ModelRecords {
  std::vector<AtomRecord> records;  // the chosen model, in file order
  std::vector<int> model_numbers;   // every model in the file, as written, in file order
  int model_used = 1;
};

// Each reader holds at most `max_text` bytes of text (bounded_read.hpp).
// PDB or mmCIF, plain or gzipped. The only translation unit that includes gemmi.
ModelRecords read_with_gemmi(const std::filesystem::path& path, StructureFormat format,
                             std::optional<int> model, std::uint64_t max_text);
// Every model's records, the file parsed once (the first model first, then in file order).
std::vector<ModelRecords> read_all_with_gemmi(const std::filesystem::path& path, StructureFormat format,
                                              std::uint64_t max_text);
// gemmi keeps residue numbers in an int; a file's numbers beyond 32 bits are handed to it as
// stand-ins (unused numbers) and restored from this map (stand-in -> the file's number).
using WideResidueNumbers = std::map<int, std::int64_t>;
// The records of one model of a structure gemmi holds in memory; `source` names it in messages.
ModelRecords records_from_gemmi(const gemmi::Structure& structure, const std::filesystem::path& source,
                                std::optional<int> model, const WideResidueNumbers& wide = {});
ModelRecords read_pqr(const std::filesystem::path& path, std::optional<int> model, std::uint64_t max_text);
// Spheres as given: x y z r [name]; radii are already set.
std::vector<Atom> read_xyzr(const std::filesystem::path& path, std::uint64_t max_text);

// The radius table `options` ask for, for a format without radii of its own (none for PQR, xyzr).
std::optional<RadiusTable> radius_table_for(StructureFormat format, const ReadOptions& options);
// The selection rules and the radii applied to one model's records: what read_structure
// returns for a file of that format. `path` names the input in messages and the report.
Structure select_atoms(ModelRecords model, const std::filesystem::path& path, StructureFormat format,
                       const ReadOptions& options, const std::optional<RadiusTable>& table);

// Small text helpers shared by the PQR, xyzr and radius-table parsers.
using text::split_fields;

// The data lines of a whitespace-separated text file: '#' starts a comment, blank lines
// are skipped, and line numbers (1-based) are kept for error messages.
class DataLines {
 public:
  explicit DataLines(std::string_view text) : rest_(text) {}
  bool next() {
    while (!rest_.empty()) {
      const std::size_t end = rest_.find('\n');
      std::string_view line = rest_.substr(0, end);
      rest_.remove_prefix(end == std::string_view::npos ? rest_.size() : end + 1);
      ++line_number_;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      fields_ = split_fields(line);
      if (!fields_.empty()) return true;
    }
    return false;
  }
  std::size_t line_number() const { return line_number_; }
  const std::vector<std::string_view>& fields() const { return fields_; }

 private:
  std::string_view rest_;
  std::size_t line_number_ = 0;
  std::vector<std::string_view> fields_;
};
std::optional<double> parse_double(std::string_view field);  // whole field, finite, '+' allowed
// The same, NaN and infinities too: for values whose non-finite spelling gets its own message
// (coordinates and radii: coordinate_problem, radius_problem).
std::optional<double> parse_real(std::string_view field);
// A whole field as an integer of type Int ('+' allowed); nullopt when it is not one or
// does not fit.
template <class Int = int>
std::optional<Int> parse_int(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  Int value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}


// Element (upper case) from an atom name when the file gives none, following gemmi's rule
// for PDB names with the alignment lost (PQR, xyzr): see read_structure.cpp.
std::string infer_element(std::string_view atom_name, std::string_view residue_name);

// A field of a file quoted for a message: at most 24 characters, with anything but
// printable ASCII shown as \xNN, so a binary file never reaches the terminal raw.
std::string excerpt(std::string_view field);
// The same without the quotes, for fields that read as words or numbers in a sentence.
std::string escaped(std::string_view field);

// "model 3 not found; models in the file: 1, 2" style failure.
[[noreturn]] void fail_unknown_model(const std::filesystem::path& path, int requested,
                                     const std::vector<int>& available);

}  // namespace molsurf::detail
