// structure_from_gemmi(): a structure gemmi holds in memory gives the same atoms, radii and
// report as read_structure() on its file, under the same selection options.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <gemmi/mmread.hpp>

#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"
#include "molsurf/gemmi_structure.hpp"

namespace molsurf {
namespace {

const std::filesystem::path pdb_dir = std::filesystem::path(MOLSURF_DATA_DIR) / "pdb";

void expect_same_atoms(const Structure& a, const Structure& b) {
  ASSERT_EQ(a.atoms.size(), b.atoms.size());
  for (std::size_t i = 0; i < a.atoms.size(); ++i) {
    const Atom& x = a.atoms[i];
    const Atom& y = b.atoms[i];
    EXPECT_EQ(x.centre, y.centre) << i;
    EXPECT_EQ(x.radius, y.radius) << i;
    EXPECT_EQ(x.element, y.element) << i;
    EXPECT_EQ(x.atom_name, y.atom_name) << i;
    EXPECT_EQ(x.residue_name, y.residue_name) << i;
    EXPECT_EQ(x.residue_number, y.residue_number) << i;
    EXPECT_EQ(x.chain, y.chain) << i;
    EXPECT_EQ(x.serial, y.serial) << i;
    EXPECT_EQ(x.hetero, y.hetero) << i;
  }
  const ReadReport& r = a.report;
  const ReadReport& s = b.report;
  EXPECT_EQ(r.format, s.format);
  EXPECT_EQ(r.models_in_file, s.models_in_file);
  EXPECT_EQ(r.model_used, s.model_used);
  EXPECT_EQ(r.records, s.records);
  EXPECT_EQ(r.kept, s.kept);
  EXPECT_EQ(r.dropped_water, s.dropped_water);
  EXPECT_EQ(r.dropped_hydrogen, s.dropped_hydrogen);
  EXPECT_EQ(r.dropped_altloc, s.dropped_altloc);
  EXPECT_EQ(r.dropped_hetatm, s.dropped_hetatm);
  EXPECT_EQ(r.dropped_chain, s.dropped_chain);
  EXPECT_EQ(r.radius_set, s.radius_set);
  EXPECT_EQ(r.radius_from_element, s.radius_from_element);
}

TEST(GemmiStructure, CrambinEqualsItsFile) {
  const std::filesystem::path path = pdb_dir / "1crn.pdb";
  const gemmi::Structure st = gemmi::read_structure_file(path.string());
  const Structure from_memory = structure_from_gemmi(st, {}, path);
  expect_same_atoms(from_memory, read_structure(path));
  EXPECT_EQ(from_memory.report.file, path);
  EXPECT_EQ(from_memory.report.format, StructureFormat::pdb);
}

TEST(GemmiStructure, SelectionOptionsApplyAsToTheFile) {
  const std::filesystem::path path = pdb_dir / "2hhb.cif";
  const gemmi::Structure st = gemmi::read_structure_file(path.string());
  ReadOptions options;
  options.chains = {"A", "C"};
  options.keep_hetatm = false;
  options.keep_water = true;
  options.radius_set = "bondi";
  expect_same_atoms(structure_from_gemmi(st, options, path), read_structure(path, options));
}

TEST(GemmiStructure, ModelsAreChosenByNumber) {
  const std::filesystem::path path = pdb_dir / "1j8k.cif";
  const gemmi::Structure st = gemmi::read_structure_file(path.string());
  ReadOptions options;
  options.model = 3;
  const Structure third = structure_from_gemmi(st, options, path);
  expect_same_atoms(third, read_structure(path, options));
  EXPECT_EQ(third.report.model_used, 3);
  options.model = 999;
  try {
    structure_from_gemmi(st, options, path);
    FAIL() << "model 999 does not exist";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("model 999 not found"), std::string::npos) << e.what();
  }
}

TEST(GemmiStructure, EmptyStructureIsAnErrorNamingTheSource) {
  gemmi::Structure st;
  st.name = "empty";
  try {
    structure_from_gemmi(st);
    FAIL() << "no models";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "empty: no atom records");
  }
}

}  // namespace
}  // namespace molsurf
