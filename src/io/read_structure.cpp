// read_structure(): format dispatch, then the selection rules and the radius assignment,
// decided here once for every format so PDB, mmCIF and PQR files behave alike.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>

#include "io/structure_readers.hpp"
#include "io/text_fields.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf {
namespace detail {

std::optional<double> parse_real(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

std::optional<double> parse_double(std::string_view field) {
  const std::optional<double> value = parse_real(field);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::string infer_element(std::string_view atom_name, std::string_view residue_name) {
  std::string name;
  for (char c : atom_name) name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  // Old-style hydrogen names put a digit first ("1HB"); MD files do it for others too.
  const auto first_letter = std::find_if(name.begin(), name.end(),
                                         [](unsigned char c) { return std::isalpha(c); });
  if (first_letter == name.end()) return "X";
  std::string letters;
  for (auto it = first_letter; it != name.end() && std::isalpha(static_cast<unsigned char>(*it)); ++it)
    letters += *it;
  // Monatomic ions are residues named after their element (ZN/ZN, CA/CA, CL/CL).
  std::string residue;
  for (char c : residue_name) residue += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (letters == residue && letters.size() <= 2) return letters;
  // Two-letter elements whose symbols are not also protein/nucleic atom names (unlike CD,
  // NE, HG, which are carbon, nitrogen and hydrogen in amino acids): FE, FE1, SE, CL2...
  static const std::set<std::string, std::less<>> two_letter = {"FE", "ZN", "MG", "MN", "CU", "CO",
                                                                "NI", "CL", "BR", "SE"};
  if (two_letter.contains(letters)) return letters;
  return std::string(1, letters.front());  // H, D (deuterium), C, N, O, S, P...
}

std::string excerpt(std::string_view field) { return "'" + escaped(field) + "'"; }

std::string escaped(std::string_view field) {
  constexpr std::size_t kMaxShown = 24;
  std::string text;
  for (std::size_t i = 0; i < field.size() && i < kMaxShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(field[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      text += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      text += hex;
    }
  }
  if (field.size() > kMaxShown) text += "...";
  return text;
}

void fail_unknown_model(const std::filesystem::path& path, int requested,
                        const std::vector<int>& available) {
  std::string list;
  for (std::size_t i = 0; i < available.size(); ++i) {
    if (i == 20 && available.size() > 21) {
      list += ", ... " + std::to_string(available.back());
      break;
    }
    list += (i == 0 ? "" : ", ") + std::to_string(available[i]);
  }
  fail(path, "model " + std::to_string(requested) + " not found; models in the file: " + list);
}

}  // namespace detail

namespace {

std::string upper(const std::string& s) {
  std::string out = s;
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool is_water(const std::string& residue_name) {
  // Crystallographic and MD spellings of water (and heavy water).
  static const std::set<std::string, std::less<>> water = {
      "HOH", "WAT", "H2O", "DOD", "D2O", "HOD", "DIS", "SOL", "TIP", "TIP3",
      "TIP4", "TIP5", "T3P", "T4P", "T5P", "SPC", "SPCE", "OHH", "HHO"};
  return water.contains(upper(residue_name));
}

bool is_hydrogen(const std::string& element) { return element == "H" || element == "D"; }

// Alternate conformers of one atom share chain, residue and atom name. The residue name is
// left out on purpose: with micro-heterogeneity (one residue, two amino acids as altlocs A
// and B) the shared backbone atoms then still come out once.
std::string conformer_key(const Atom& atom) {
  std::string key = atom.chain;
  key += '\t';
  key += std::to_string(atom.residue_number);
  key += atom.insertion_code;
  key += '\t';
  key += atom.atom_name;
  return key;
}

// Indices of the records to keep: every single-conformer atom, and of each atom with
// alternates the highest-occupancy one (ties: the first in the file). An atom that also
// appears without altloc keeps that copy.
std::vector<std::size_t> choose_conformers(const std::vector<detail::AtomRecord>& records,
                                           const std::vector<std::size_t>& candidates) {
  std::unordered_map<std::string, std::size_t> chosen;  // key -> index into records
  for (std::size_t index : candidates) {
    const detail::AtomRecord& record = records[index];
    if (record.altloc == '\0') continue;
    const auto [it, inserted] = chosen.try_emplace(conformer_key(record.atom), index);
    if (!inserted && record.atom.occupancy > records[it->second].atom.occupancy) it->second = index;
  }
  if (chosen.empty()) return candidates;
  for (std::size_t index : candidates) {
    const detail::AtomRecord& record = records[index];
    if (record.altloc != '\0') continue;
    if (const auto it = chosen.find(conformer_key(record.atom)); it != chosen.end())
      it->second = index;  // the blank-altloc copy wins
  }
  std::vector<std::size_t> kept;
  kept.reserve(candidates.size());
  for (std::size_t index : candidates) {
    const detail::AtomRecord& record = records[index];
    if (record.altloc == '\0' || chosen.at(conformer_key(record.atom)) == index) kept.push_back(index);
  }
  return kept;
}

std::string dropped_summary(const ReadReport& report) {
  std::string summary;
  const auto add = [&summary](std::size_t count, const char* what) {
    if (count == 0) return;
    summary += (summary.empty() ? "" : ", ") + std::to_string(count) + " " + what;
  };
  add(report.dropped_chain, "not in the selected chains");
  add(report.dropped_water, "water");
  add(report.dropped_hetatm, "hetero (ligand/ion)");
  add(report.dropped_hydrogen, "hydrogen");
  add(report.dropped_altloc, "alternate conformers");
  add(report.dropped_zero_radius, "of radius 0 (they add nothing to the surface)");
  return summary.empty() ? "nothing dropped" : "dropped: " + summary;
}

void count_elements(const std::vector<Atom>& atoms, ReadReport& report) {
  for (const Atom& atom : atoms) ++report.kept_by_element[atom.element];
  report.kept = atoms.size();
}

Structure read_sphere_list(const std::filesystem::path& path, const ReadOptions& options) {
  if (!options.chains.empty())
    fail(path, ".xyzr files have no chain identifiers; a chain selection cannot be applied");
  if (options.model && *options.model != 1) detail::fail_unknown_model(path, *options.model, {1});
  Structure structure;
  structure.atoms = detail::read_xyzr(path, detail::max_text_bytes(options.max_memory));
  ReadReport& report = structure.report;
  report.file = path;
  report.format = StructureFormat::xyzr;
  report.records = structure.atoms.size();
  report.radius_set = "file";
  // A sphere of radius 0 adds nothing to a union of balls: dropped, and counted.
  report.dropped_zero_radius =
      std::erase_if(structure.atoms, [](const Atom& atom) { return atom.radius == 0; });
  if (structure.atoms.empty())
    fail(path, "no spheres left: all " + std::to_string(report.records) +
                   " have radius 0, and a sphere of radius 0 adds nothing to a surface");
  count_elements(structure.atoms, report);
  return structure;
}

}  // namespace

Structure read_structure(const std::filesystem::path& path, const ReadOptions& options) {
  validate(options);
  detail::require_regular_file(path);
  // Checked here because gemmi reports an empty file as a failed read.
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) == 0 && !ec) fail(path, "file is empty");
  const StructureFormat format = structure_format_from_path(path);
  if (format == StructureFormat::xyzr) return read_sphere_list(path, options);

  // The table is read first so a bad radius file fails before a long structure read.
  const std::optional<RadiusTable> table = detail::radius_table_for(format, options);
  const std::uint64_t max_text = detail::max_text_bytes(options.max_memory);
  detail::ModelRecords model = format == StructureFormat::pqr
                                   ? detail::read_pqr(path, options.model, max_text)
                                   : detail::read_with_gemmi(path, format, options.model, max_text);
  return detail::select_atoms(std::move(model), path, format, options, table);
}

std::vector<Structure> read_all_models(const std::filesystem::path& path, const ReadOptions& options) {
  validate(options);
  const StructureFormat format = structure_format_from_path(path);
  if (format != StructureFormat::pdb && format != StructureFormat::mmcif) {
    // One model or few (PQR, xyzr): model by model.
    const Structure first = read_structure(path, options);
    std::vector<Structure> models{first};
    for (const int number : first.report.model_numbers)
      if (number != first.report.model_used) {
        ReadOptions one = options;
        one.model = number;
        models.push_back(read_structure(path, one));
      }
    return models;
  }
  read_structure(path, [&] {  // the checks and the first model's errors, as a single read gives them
    ReadOptions first = options;
    first.model.reset();
    return first;
  }());
  const std::optional<RadiusTable> table = detail::radius_table_for(format, options);
  std::vector<Structure> models;
  for (detail::ModelRecords& records : detail::read_all_with_gemmi(path, format, detail::max_text_bytes(options.max_memory)))
    models.push_back(detail::select_atoms(std::move(records), path, format, options, table));
  return models;
}

namespace detail {

std::optional<RadiusTable> radius_table_for(StructureFormat format, const ReadOptions& options) {
  if (format == StructureFormat::pqr || format == StructureFormat::xyzr) return std::nullopt;
  return options.radius_file.empty() ? RadiusTable::builtin(options.radius_set)
                                     : RadiusTable::from_file(options.radius_file);
}

Structure select_atoms(ModelRecords model, const std::filesystem::path& path, StructureFormat format,
                       const ReadOptions& options, const std::optional<RadiusTable>& table) {
  Structure structure;
  ReadReport& report = structure.report;
  report.file = path;
  report.format = format;
  report.models_in_file = model.model_numbers.size();
  report.model_numbers = model.model_numbers;
  report.model_used = model.model_used;
  report.records = model.records.size();

  // Each dropped record is counted under the first rule that drops it, in this order, so
  // records == kept + the sum of the dropped_* counters.
  const std::set<std::string, std::less<>> chains(options.chains.begin(), options.chains.end());
  std::vector<std::size_t> candidates;
  candidates.reserve(model.records.size());
  for (std::size_t i = 0; i < model.records.size(); ++i) {
    const Atom& atom = model.records[i].atom;
    const bool water = is_water(atom.residue_name);
    if (!chains.empty() && !chains.contains(atom.chain)) ++report.dropped_chain;
    else if (water && !options.keep_water) ++report.dropped_water;
    else if (atom.hetero && !water && !options.keep_hetatm) ++report.dropped_hetatm;
    else if (is_hydrogen(atom.element) && !options.keep_hydrogens) ++report.dropped_hydrogen;
    else candidates.push_back(i);
  }
  std::vector<std::size_t> kept = choose_conformers(model.records, candidates);
  report.dropped_altloc = candidates.size() - kept.size();
  // Radii from the file (PQR): an atom of radius 0 (pdb2pqr gives AMBER's hydroxyl hydrogens
  // radius 0) adds nothing to a union of balls, so it is dropped and counted, not refused.
  if (!table)
    report.dropped_zero_radius =
        std::erase_if(kept, [&](std::size_t index) { return model.records[index].atom.radius == 0; });

  if (kept.empty()) {
    if (report.records == 0)
      fail(path, "no atom records in model " + std::to_string(report.model_used));
    fail(path, "no atoms left after filtering (" + std::to_string(report.records) +
                   " atom records in model " + std::to_string(report.model_used) + "; " +
                   dropped_summary(report) + ")");
  }

  structure.atoms.reserve(kept.size());
  for (std::size_t index : kept) structure.atoms.push_back(std::move(model.records[index].atom));

  if (table) {
    report.radius_set = options.radius_file.empty() ? options.radius_set : options.radius_file.string();
    constexpr std::size_t max_examples = 5;
    std::set<std::pair<std::string, std::string>> example_kinds;
    for (Atom& atom : structure.atoms) {
      const RadiusTable::Lookup lookup =
          table->radius(upper(atom.residue_name), upper(atom.atom_name), atom.element);
      atom.radius = lookup.radius;
      atom.polarity = lookup.polarity;
      if (lookup.source == RadiusTable::Source::residue_atom) continue;
      ++(lookup.source == RadiusTable::Source::element ? report.radius_from_element
                                                        : report.radius_default);
      // One example per (residue, element) says more than five carbons of the same haem.
      if (report.fallback_examples.size() < max_examples &&
          example_kinds.emplace(atom.residue_name, atom.element).second)
        report.fallback_examples.push_back(atom.residue_name + " " + atom.atom_name + " (" +
                                           atom.element + ")");
    }
  } else {
    report.radius_set = "file";
  }
  count_elements(structure.atoms, report);
  return structure;
}

}  // namespace detail

}  // namespace molsurf
