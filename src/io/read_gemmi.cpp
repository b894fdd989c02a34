// PDB and mmCIF (plain or gzipped) through gemmi. This is the only file that includes
// gemmi: its headers are slow to compile, and keeping them here keeps rebuilds cheap.
// gemmi headers that pull gemmi/sprintf.hpp (to_pdb, to_mmcif, select...) must not be
// included: Debian does not ship the stb_sprintf.h they need.
#include <cctype>
#include <cmath>
#include <charconv>
#include <exception>
#include <string>
#include <string_view>

#include <gemmi/gz.hpp>
#include <gemmi/mmread.hpp>

#include "io/structure_readers.hpp"
#include "molsurf/error.hpp"

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
             record + " record: " + axis_names[axis] + " coordinate '" + std::string(field) +
                 "' (columns " + std::to_string(31 + 8 * axis) + "-" +
                 std::to_string(38 + 8 * axis) + ") is not a number");
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

}  // namespace

ModelRecords read_with_gemmi(const std::filesystem::path& path, StructureFormat format,
                             std::optional<int> model) {
  gemmi::Structure structure;
  try {
    gemmi::MaybeGzipped input(path.string());
    gemmi::CharArray buffer = gemmi::read_into_buffer(input);
    if (format == StructureFormat::pdb) {
      check_pdb_atom_records(path, std::string_view(buffer.data(), buffer.size()));
      structure = gemmi::read_pdb_from_memory(buffer.data(), buffer.size(), path.string());
    } else {
      structure = gemmi::make_structure(
          gemmi::cif::read_memory(buffer.data(), buffer.size(), path.string().c_str()));
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(message_with_file(path, e.what()));
  }

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
      for (const gemmi::Atom& atom : residue.atoms) {
        AtomRecord record;
        Atom& a = record.atom;
        a.centre = {atom.pos.x, atom.pos.y, atom.pos.z};
        if (!std::isfinite(a.centre.x) || !std::isfinite(a.centre.y) || !std::isfinite(a.centre.z))
          fail(path, "atom " + std::to_string(atom.serial) + " (" + residue.name + " " +
                         std::to_string(residue.seqid.num.value) + " " + atom.name + ", chain " +
                         chain.name + ") has no valid coordinates");
        a.atom_name = atom.name;
        a.residue_name = residue.name;
        a.element = atom.element == gemmi::El::X ? infer_element(atom.name, residue.name)
                                                 : std::string(atom.element.uname());
        a.residue_number = residue.seqid.num.has_value() ? residue.seqid.num.value : 0;
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
