#pragma once
// Structure input: atoms with their radii, read from PDB / mmCIF (plain or gzipped),
// PQR or MSMS .xyzr, with the selection rules a structural biologist expects.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf {

// An atom's class for the polar/apolar areas: the radius table's, when it gives one;
// otherwise by element (nitrogen and oxygen polar).
enum class Polarity : std::uint8_t { by_element, polar, apolar };

struct Atom {
  Vec3 centre;
  double radius = 0;         // van der Waals radius (no probe), angstrom
  std::string element;       // upper case, e.g. "C", "FE"
  std::string atom_name;     // e.g. "CA"
  std::string residue_name;  // e.g. "ALA", "HEM"
  std::int64_t residue_number = 0;  // mmCIF allows any integer; no wrap at 32 bits
  char insertion_code = ' ';
  std::string chain;
  int serial = 0;            // atom serial number in the file (0 when the format has none)
  double occupancy = 1;
  double b_factor = 0;
  double charge = 0;         // PQR partial charge; 0 elsewhere
  bool hetero = false;
  Polarity polarity = Polarity::by_element;
};

// For formats whose residue number has 32 bits (VTK's Int32 cell array, gemmi's SeqId when
// a structure is written back): the number clamped to that range.
inline std::int32_t residue_number_32(std::int64_t number) {
  return static_cast<std::int32_t>(number < INT32_MIN ? INT32_MIN : number > INT32_MAX ? INT32_MAX : number);
}

enum class StructureFormat { pdb, mmcif, pqr, xyzr };

struct ReadOptions {
  std::optional<int> model;         // model number as written in the file; default: the first
  std::vector<std::string> chains;  // keep only these chains; empty: all
  bool keep_water = false;
  bool keep_hydrogens = false;      // hydrogen and deuterium
  bool keep_hetatm = true;          // ligands, ions, cofactors
  std::string radius_set = "protor";  // "protor", "bondi" or "naccess"; ignored for PQR / xyzr
  std::filesystem::path radius_file;  // user table; overrides radius_set when not empty
  // The memory limit in bytes (0: the memory this process may use). The file's text is
  // refused beyond limit / kBytesPerTextByte (resource_limits.hpp), before it is read or
  // as it is decompressed.
  std::uint64_t max_memory = 0;
};

// What the reader kept, dropped and guessed: every count a user may want to check.
struct ReadReport {
  std::filesystem::path file;
  StructureFormat format = StructureFormat::pdb;
  std::size_t models_in_file = 1;
  std::vector<int> model_numbers;      // every model in the file, as written, in file order
  int model_used = 1;
  std::size_t records = 0;             // atom records in the model read
  std::size_t kept = 0;
  std::size_t dropped_water = 0;
  std::size_t dropped_hydrogen = 0;
  std::size_t dropped_altloc = 0;      // alternate conformers not chosen
  std::size_t dropped_hetatm = 0;
  std::size_t dropped_chain = 0;
  // PQR / xyzr atoms whose radius in the file is 0 (pdb2pqr's AMBER hydroxyl and water
  // hydrogens): a ball of radius 0 adds nothing to a union of balls. Counted after the rules
  // above, so records == kept + every dropped_* count.
  std::size_t dropped_zero_radius = 0;
  std::map<std::string, std::size_t> kept_by_element;
  std::string radius_set;              // "protor", "bondi", a file name, or "file" for PQR/xyzr
  std::size_t radius_from_element = 0;  // atoms not in the table, given their element's radius
  std::size_t radius_default = 0;       // atoms with an unknown element, given the default radius
  std::vector<std::string> fallback_examples;  // a few "RES ATOM (element)" that fell back
};

struct Structure {
  std::vector<Atom> atoms;
  ReadReport report;
};

// Format from the name: .pdb .ent (.gz), .cif .mmcif (.gz), .pqr, .xyzr.
StructureFormat structure_format_from_path(const std::filesystem::path& path);

// Throws molsurf::Error naming file, line and problem; also when the selection is empty.
Structure read_structure(const std::filesystem::path& path, const ReadOptions& options = {});
// Every model of the file (options.model is ignored), the first as read_structure gives it,
// the others in file order; a PDB or mmCIF file is parsed once.
std::vector<Structure> read_all_models(const std::filesystem::path& path, const ReadOptions& options = {});

// Radius tables are data: built-in sets are compiled in from data/radii/*.txt. A table is
// molsurf's format (docs/radii.md) or a FreeSASA classifier configuration (name:, types:
// and atoms: sections), whose atoms it does not list get the protor set's element radii.
class RadiusTable {
 public:
  static RadiusTable builtin(const std::string& name);          // "protor", "bondi", "naccess"
  static bool is_builtin(const std::string& name);
  static std::vector<std::string> builtin_names();  // in alphabetical order
  static RadiusTable from_file(const std::filesystem::path& path);
  static RadiusTable parse(const std::string& text, const std::string& source_name);

  enum class Source { residue_atom, element, fallback_default };
  struct Lookup { double radius; Source source; Polarity polarity = Polarity::by_element; };
  Lookup radius(const std::string& residue_name, const std::string& atom_name,
                const std::string& element) const;
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  struct Entry {
    double radius;
    Polarity polarity;
  };
  static RadiusTable parse_freesasa(const std::string& text, const std::string& source_name);
  std::map<std::pair<std::string, std::string>, Entry> by_residue_atom_;  // ("ANY", atom) allowed
  std::map<std::string, Entry> by_element_;
  double default_radius_ = 1.8;
};

}  // namespace molsurf
