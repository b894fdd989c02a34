#include "molsurf/sasa_structure.hpp"

// The writers' code lives in gemmi's headers behind this macro, once per program (this is
// the only file that includes them). Numbers formatted by the C library: Debian's gemmi
// headers expect a stb_sprintf.h that no package here installs.
#define GEMMI_WRITE_IMPLEMENTATION
#define USE_STD_SNPRINTF
#include <gemmi/model.hpp>
#include <gemmi/polyheur.hpp>
#include <gemmi/to_cif.hpp>
#include <gemmi/to_mmcif.hpp>
#include <gemmi/to_pdb.hpp>

#include <sstream>
#include <stdexcept>

#include "molsurf/error.hpp"

namespace molsurf {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

gemmi::Structure make_structure(std::span<const Atom> atoms, std::span<const double> area) {
  gemmi::Structure st;
  st.name = "molsurf";
  st.models.emplace_back("1");
  gemmi::Model& model = st.models.back();
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    if (model.chains.empty() || model.chains.back().name != a.chain) model.chains.emplace_back(a.chain);
    gemmi::Chain& chain = model.chains.back();
    const gemmi::SeqId seqid(residue_number_32(a.residue_number), a.insertion_code);
    if (chain.residues.empty() || chain.residues.back().seqid != seqid || chain.residues.back().name != a.residue_name) {
      gemmi::Residue r;
      r.name = a.residue_name;
      r.seqid = seqid;
      r.het_flag = a.hetero ? 'H' : 'A';
      chain.residues.push_back(std::move(r));
    }
    gemmi::Atom at;
    at.name = a.atom_name;
    at.element = gemmi::Element(a.element);
    at.pos = gemmi::Position(a.centre.x, a.centre.y, a.centre.z);
    at.occ = static_cast<float>(a.radius);
    at.b_iso = static_cast<float>(area[i]);
    at.serial = a.serial > 0 ? a.serial : static_cast<int>(i + 1);
    chain.residues.back().atoms.push_back(std::move(at));
  }
  gemmi::setup_entities(st);
  return st;
}

}  // namespace

bool is_sasa_structure_path(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".pdb" || ext == ".ent" || ext == ".cif" || ext == ".mmcif";
}

std::string sasa_structure_text(const std::filesystem::path& path, std::span<const Atom> atoms,
                                std::span<const double> area) {
  if (area.size() != atoms.size()) throw std::invalid_argument("sasa_structure_text: one area per atom");
  if (!is_sasa_structure_path(path))
    throw Error("--sasa-structure: " + path.string() + " must end in .pdb, .ent, .cif or .mmcif");
  const gemmi::Structure st = make_structure(atoms, area);
  std::ostringstream out;
  const std::string ext = lower_extension(path);
  if (ext == ".pdb" || ext == ".ent") {
    gemmi::PdbWriteOptions options;
    options.seqres_records = options.ssbond_records = options.cryst1_record = false;
    options.link_records = options.cispep_records = false;
    gemmi::write_pdb(st, out, options);
  } else {
    gemmi::cif::write_cif_to_stream(out, gemmi::make_mmcif_document(st), gemmi::cif::Style::Pdbx);
  }
  return out.str();
}

}  // namespace molsurf
