// PDB and mmCIF (plain or gzipped) through gemmi. This is the only file that includes
// gemmi: its headers are slow to compile, and keeping them here keeps rebuilds cheap.
// gemmi headers that pull gemmi/sprintf.hpp (to_pdb, to_mmcif, select...) must not be
// included: Debian does not ship the stb_sprintf.h they need.
#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <cmath>
#include <charconv>
#include <exception>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include <gemmi/cif.hpp>
#include <gemmi/mmread.hpp>

#include "io/structure_readers.hpp"
#include "io/text_fields.hpp"
#include "molsurf/error.hpp"
#include "molsurf/gemmi_structure.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf::detail {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool starts_with_ci(std::string_view line, std::string_view prefix) {
  if (line.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(line[i])) != prefix[i]) return false;
  return true;
}

// gemmi reads PDB columns leniently (a garbled coordinate silently becomes 0 or NaN), so
// the coordinate columns of ATOM/HETATM records are checked here, where the line number
// is known.
void check_pdb_atom_records(const std::filesystem::path& path, std::string_view text) {
  std::size_t line_number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    // gemmi recognises records by their first four letters, case-insensitively.
    if (!starts_with_ci(line, "ATOM") && !starts_with_ci(line, "HETA")) continue;
    const std::string record(trimmed(line.substr(0, 6)));
    if (line.size() < 54)
      fail(path, line_number,
           record + " record too short (" + std::to_string(line.size()) +
               " columns; coordinates need columns 31-54)");
    constexpr const char* axis_names[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view field = trimmed(line.substr(30 + 8 * axis, 8));
      double value = 0;
      const auto [end_ptr, error] = std::from_chars(field.data(), field.data() + field.size(), value);
      if (field.empty() || error != std::errc() || end_ptr != field.data() + field.size() ||
          !std::isfinite(value))
        fail(path, line_number,
             record + " record: " + axis_names[axis] + " coordinate " + excerpt(field) +
                 " (columns " + std::to_string(31 + 8 * axis) + "-" +
                 std::to_string(38 + 8 * axis) + ") is not a number");
      check_coordinate_range(path, line_number, value, record + " record: " + axis_names[axis] + " coordinate");
    }
  }
}

int model_number(const gemmi::Model& model, std::size_t index) {
  int number = 0;
  const std::string& name = model.name;
  const auto [end_ptr, error] = std::from_chars(name.data(), name.data() + name.size(), number);
  if (error != std::errc() || end_ptr != name.data() + name.size())
    return static_cast<int>(index) + 1;  // unnamed models are numbered as they come
  return number;
}

std::string message_with_file(const std::filesystem::path& path, const std::string& what) {
  // gemmi often names the file itself; do not repeat it.
  const std::string file = path.string();
  if (what.rfind(file, 0) == 0) return what;
  return file + ": " + what;
}

bool has_gz_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".gz";
}

// mmCIF without coordinates (a dictionary, a restraint file, a model without _atom_site
// coordinates) reads as a structure with no atoms; say what is missing instead.
void check_mmcif_coordinates(const std::filesystem::path& path, gemmi::cif::Document& document) {
  if (document.blocks.empty()) fail(path, "no data block: not an mmCIF file");
  gemmi::cif::Block& block = document.blocks.front();
  if (!block.find_values("_atom_site.group_PDB") && !block.find_values("_atom_site.id") &&
      !block.find_values("_atom_site.type_symbol") && !block.find_values("_atom_site.Cartn_x"))
    fail(path, "no _atom_site table in data block '" + block.name + "': the file has no atoms");
  for (const char* tag : {"_atom_site.Cartn_x", "_atom_site.Cartn_y", "_atom_site.Cartn_z"})
    if (!block.find_values(tag))
      fail(path, std::string("the _atom_site table has no ") + tag +
                     " column: no Cartesian coordinates (fractional-only or incomplete files are not read)");
}

// gemmi reads an _atom_site table only when it has every column it treats as required, and
// silently reads no atom otherwise; but occupancy, B-factor, label_asym_id and the other
// columns below are optional for a surface (coordinate-only files from modelling tools lack
// them). Each missing one is added, with gemmi's own default for an unknown value ('?':
// occupancy 1, B-factor 50) or the value of its auth_/label_ twin.
void add_missing_atom_site_columns(gemmi::cif::Block& block) {
  struct Fill {
    const char* tag;
    const char* twin;      // a column whose value stands in, when present
    const char* fallback;  // otherwise this value
  };
  constexpr Fill fills[] = {{"_atom_site.id", nullptr, "?"},
                            {"_atom_site.type_symbol", nullptr, "?"},
                            {"_atom_site.label_alt_id", nullptr, "."},
                            {"_atom_site.label_asym_id", "_atom_site.auth_asym_id", "?"},
                            {"_atom_site.occupancy", nullptr, "?"},
                            {"_atom_site.B_iso_or_equiv", nullptr, "?"},
                            {"_atom_site.auth_seq_id", "_atom_site.label_seq_id", "?"}};
  for (gemmi::cif::Item& item : block.items) {
    if (item.type != gemmi::cif::ItemType::Loop || item.loop.find_tag("_atom_site.Cartn_x") < 0) continue;
    gemmi::cif::Loop& loop = item.loop;
    for (const Fill& fill : fills) {
      if (loop.find_tag(fill.tag) >= 0) continue;
      const int twin = fill.twin ? loop.find_tag(fill.twin) : -1;
      const std::size_t width = loop.width(), rows = loop.length();
      std::vector<std::string> values;
      values.reserve(rows * (width + 1));
      for (std::size_t row = 0; row < rows; ++row) {
        for (std::size_t column = 0; column < width; ++column) values.push_back(loop.val(row, column));
        values.push_back(twin >= 0 ? loop.val(row, static_cast<std::size_t>(twin)) : std::string(fill.fallback));
      }
      loop.tags.emplace_back(fill.tag);
      loop.values = std::move(values);
    }
    return;
  }
  // A single atom is written as tag-value pairs rather than a loop.
  if (!block.find_value("_atom_site.Cartn_x")) return;
  for (const Fill& fill : fills) {
    if (block.find_value(fill.tag)) continue;
    const std::string* twin = fill.twin ? block.find_value(fill.twin) : nullptr;
    block.set_pair(fill.tag, twin ? *twin : std::string(fill.fallback));
  }
}

// gemmi parses a residue number into an int and wraps one beyond 32 bits (3000000000 becomes
// negative); mmCIF allows any integer. Each such number of _atom_site.auth_seq_id is
// replaced by a stand-in that the file does not use (counted up from INT_MIN + 1: INT_MIN is
// gemmi's "no number"), which keeps residues apart as the numbers did, and the map restores
// the number in records_from_gemmi.
WideResidueNumbers replace_wide_residue_numbers(gemmi::cif::Block& block) {
  WideResidueNumbers wide;
  gemmi::cif::Column column = block.find_values("_atom_site.auth_seq_id");
  if (!column) return wide;
  std::set<std::int64_t> used;
  std::map<std::int64_t, int> stand_in;  // the file's number -> its stand-in
  for (const std::string& value : column) {
    const std::optional<std::int64_t> number = parse_int<std::int64_t>(trimmed(value));
    if (!number) continue;
    if (*number >= INT_MIN + 1 && *number <= INT_MAX) used.insert(*number);
    else stand_in.emplace(*number, 0);
  }
  if (stand_in.empty()) return wide;
  std::int64_t next = INT_MIN + 1;
  for (auto& [number, replacement] : stand_in) {
    while (used.contains(next)) ++next;
    replacement = static_cast<int>(next++);
    wide.emplace(replacement, number);
  }
  for (std::string& value : column) {
    const std::optional<std::int64_t> number = parse_int<std::int64_t>(trimmed(value));
    if (const auto found = number ? stand_in.find(*number) : stand_in.end(); found != stand_in.end())
      value = std::to_string(found->second);
  }
  return wide;
}

}  // namespace

namespace {

struct GemmiRead {
  gemmi::Structure structure;
  WideResidueNumbers wide;
};

GemmiRead read_gemmi_structure(const std::filesystem::path& path, StructureFormat format, std::uint64_t max_text) {
  GemmiRead read;
  try {
    const std::string buffer = has_gz_extension(path) ? read_gzip_file(path, max_text) : read_text_file(path, max_text);
    if (buffer.empty()) fail(path, "file is empty");
    if (format == StructureFormat::pdb) {
      check_pdb_atom_records(path, buffer);
      read.structure = gemmi::read_pdb_from_memory(buffer.data(), buffer.size(), path.string());
    } else {
      gemmi::cif::Document document = gemmi::cif::read_memory(buffer.data(), buffer.size(), path.string().c_str());
      check_mmcif_coordinates(path, document);
      add_missing_atom_site_columns(document.blocks.front());
      read.wide = replace_wide_residue_numbers(document.blocks.front());
      read.structure = gemmi::make_structure(std::move(document));
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(message_with_file(path, e.what()));
  }
  return read;
}

}  // namespace

ModelRecords read_with_gemmi(const std::filesystem::path& path, StructureFormat format,
                             std::optional<int> model, std::uint64_t max_text) {
  const GemmiRead read = read_gemmi_structure(path, format, max_text);
  return records_from_gemmi(read.structure, path, model, read.wide);
}

std::vector<ModelRecords> read_all_with_gemmi(const std::filesystem::path& path, StructureFormat format,
                                              std::uint64_t max_text) {
  const GemmiRead read = read_gemmi_structure(path, format, max_text);
  std::vector<ModelRecords> models{records_from_gemmi(read.structure, path, std::nullopt, read.wide)};
  const std::vector<int> numbers = models.front().model_numbers;
  for (std::size_t k = 1; k < numbers.size(); ++k)
    models.push_back(records_from_gemmi(read.structure, path, numbers[k], read.wide));
  return models;
}

ModelRecords records_from_gemmi(const gemmi::Structure& structure, const std::filesystem::path& path,
                                std::optional<int> model, const WideResidueNumbers& wide) {
  ModelRecords result;
  const gemmi::Model* chosen = nullptr;
  for (std::size_t i = 0; i < structure.models.size(); ++i) {
    const int number = model_number(structure.models[i], i);
    result.model_numbers.push_back(number);
    if (!chosen && (!model || *model == number)) {
      chosen = &structure.models[i];
      result.model_used = number;
    }
  }
  if (structure.models.empty()) fail(path, "no atom records");
  if (!chosen) fail_unknown_model(path, *model, result.model_numbers);

  for (const gemmi::Chain& chain : chosen->chains) {
    for (const gemmi::Residue& residue : chain.residues) {
      const auto found = wide.find(residue.seqid.num.value);
      const std::int64_t residue_number = !residue.seqid.num.has_value() ? 0
                                          : found != wide.end()          ? found->second
                                                                         : residue.seqid.num.value;
      for (const gemmi::Atom& atom : residue.atoms) {
        AtomRecord record;
        Atom& a = record.atom;
        a.centre = {atom.pos.x, atom.pos.y, atom.pos.z};
        if (!std::isfinite(a.centre.x) || !std::isfinite(a.centre.y) || !std::isfinite(a.centre.z))
          fail(path, "atom " + std::to_string(atom.serial) + " (" + residue.name + " " +
                         std::to_string(residue_number) + " " + atom.name + ", chain " +
                         chain.name + ") has no valid coordinates");
        for (double c : {a.centre.x, a.centre.y, a.centre.z})
          check_coordinate_range(path, 0, c,
                                 "atom " + std::to_string(atom.serial) + " (" + residue.name + " " +
                                     std::to_string(residue_number) + " " + atom.name + ", chain " +
                                     chain.name + "): coordinate");
        a.atom_name = atom.name;
        a.residue_name = residue.name;
        a.element = atom.element == gemmi::El::X ? infer_element(atom.name, residue.name)
                                                 : std::string(atom.element.uname());
        a.residue_number = residue_number;
        a.insertion_code = residue.seqid.icode;
        a.chain = chain.name;
        a.serial = atom.serial;
        a.occupancy = atom.occ;
        a.b_factor = atom.b_iso;
        a.hetero = residue.het_flag == 'H';
        record.altloc = atom.altloc;
        result.records.push_back(std::move(record));
      }
    }
  }
  return result;
}

}  // namespace molsurf::detail

namespace molsurf {

Structure structure_from_gemmi(const gemmi::Structure& structure, const ReadOptions& options,
                               const std::filesystem::path& source) {
  validate(options);
  const std::filesystem::path name = source.empty() ? std::filesystem::path(structure.name) : source;
  const StructureFormat format =
      structure.input_format == gemmi::CoorFormat::Pdb ? StructureFormat::pdb : StructureFormat::mmcif;
  // The radius table first, as read_structure does: a bad table fails before any work.
  const std::optional<RadiusTable> table = detail::radius_table_for(format, options);
  return detail::select_atoms(detail::records_from_gemmi(structure, name, options.model), name, format, options,
                              table);
}

}  // namespace molsurf
