// read_structure(): atom counts on the whole corpus, selection rules, radius assignment
// and the error messages for bad input.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"
#include "molsurf/report.hpp"
#include "molsurf/resource_limits.hpp"

namespace molsurf {
namespace {

const std::filesystem::path pdb_dir = std::filesystem::path(MOLSURF_DATA_DIR) / "pdb";
const std::filesystem::path test_dir =
    std::filesystem::path(MOLSURF_DATA_DIR) / ".." / "tests" / "data" / "structure";

std::size_t total_dropped(const ReadReport& r) {
  return r.dropped_water + r.dropped_hydrogen + r.dropped_altloc + r.dropped_hetatm + r.dropped_chain +
         r.dropped_zero_radius;
}

// The message of the Error that reading `path` throws ("" when nothing is thrown).
std::string read_error(const std::filesystem::path& path, const ReadOptions& options = {}) {
  try {
    read_structure(path, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

const Atom* find_atom(const Structure& s, const std::string& chain, int residue, const std::string& name) {
  for (const Atom& a : s.atoms)
    if (a.chain == chain && a.residue_number == residue && a.atom_name == name) return &a;
  return nullptr;
}

// ---- corpus counts: the manifest's "spheres" column ------------------------------------

struct CorpusCase {
  const char* file;
  std::size_t spheres;
};

class CorpusCount : public testing::TestWithParam<CorpusCase> {};

TEST_P(CorpusCount, SphereCountMatchesManifest) {
  const Structure s = read_structure(pdb_dir / GetParam().file);
  EXPECT_EQ(s.atoms.size(), GetParam().spheres);
  EXPECT_EQ(s.report.kept, GetParam().spheres);
  EXPECT_EQ(s.report.records, s.report.kept + total_dropped(s.report));
  EXPECT_EQ(s.report.radius_default, 0u) << "the manifest says no element falls back to the default";
  for (const Atom& a : s.atoms) {
    ASSERT_GT(a.radius, 1.0) << a.residue_name << " " << a.atom_name;
    ASSERT_LT(a.radius, 2.5) << a.residue_name << " " << a.atom_name;
    ASSERT_NE(a.element, "H");
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusCount,
                         testing::Values(CorpusCase{"1crn.pdb", 327}, CorpusCase{"1crn.cif.gz", 327},
                                         CorpusCase{"1ubq.pdb", 602}, CorpusCase{"1j8k.cif", 720},
                                         CorpusCase{"3pqr.cif", 2858}, CorpusCase{"2hhb.pdb", 4558},
                                         CorpusCase{"2hhb.cif", 4558}, CorpusCase{"4hhb.cif", 4558},
                                         CorpusCase{"7cth.cif", 16647}, CorpusCase{"4yvs.cif", 26430},
                                         CorpusCase{"2btv.pdb", 49061},
                                         CorpusCase{"1f2n_assembly1.cif.gz", 271860}),
                         [](const testing::TestParamInfo<CorpusCase>& info) {
                           std::string name = info.param.file;
                           std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                           return name;
                         });

TEST(Corpus, CrambinPdbAndGzippedCifGiveIdenticalSpheres) {
  const Structure pdb = read_structure(pdb_dir / "1crn.pdb");
  const Structure cif = read_structure(pdb_dir / "1crn.cif.gz");
  ASSERT_EQ(pdb.atoms.size(), cif.atoms.size());
  for (std::size_t i = 0; i < pdb.atoms.size(); ++i) {
    const Atom& a = pdb.atoms[i];
    const Atom& b = cif.atoms[i];
    EXPECT_EQ(a.centre, b.centre) << i;
    EXPECT_EQ(a.radius, b.radius) << i;
    EXPECT_EQ(a.element, b.element) << i;
    EXPECT_EQ(a.atom_name, b.atom_name) << i;
    EXPECT_EQ(a.residue_name, b.residue_name) << i;
    EXPECT_EQ(a.residue_number, b.residue_number) << i;
    EXPECT_EQ(a.chain, b.chain) << i;
  }
  EXPECT_EQ(pdb.report.format, StructureFormat::pdb);
  EXPECT_EQ(cif.report.format, StructureFormat::mmcif);
}

TEST(Corpus, HaemoglobinPdbAndCifGiveTheSameSet) {
  using Sphere = std::tuple<std::string, int, std::string, double, double, double, double>;
  const auto spheres = [](const Structure& s) {
    std::vector<Sphere> out;
    for (const Atom& a : s.atoms)
      out.emplace_back(a.chain, a.residue_number, a.atom_name, a.centre.x, a.centre.y, a.centre.z, a.radius);
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<Sphere> from_pdb = spheres(read_structure(pdb_dir / "2hhb.pdb"));
  const std::vector<Sphere> from_cif = spheres(read_structure(pdb_dir / "2hhb.cif"));
  ASSERT_EQ(from_pdb.size(), 4558u);
  EXPECT_TRUE(from_pdb == from_cif);
}

// ---- radii -------------------------------------------------------------------------------

TEST(Radii, ProtOrOnKnownAtoms) {
  const Structure s = read_structure(pdb_dir / "1crn.pdb");
  // 1CRN residue 9 is ALA, residue 1 THR.
  const Atom* cb = find_atom(s, "A", 9, "CB");
  ASSERT_NE(cb, nullptr);
  EXPECT_EQ(cb->residue_name, "ALA");
  EXPECT_DOUBLE_EQ(cb->radius, 1.88);
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "O")->radius, 1.42);   // carbonyl O1H0
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "C")->radius, 1.61);   // C3H0
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "N")->radius, 1.64);
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "OG1")->radius, 1.46); // hydroxyl O2H1
  EXPECT_EQ(s.report.radius_set, "protor");
  EXPECT_EQ(s.report.radius_from_element, 0u);  // crambin: only standard residues
  EXPECT_TRUE(s.report.fallback_examples.empty());
}

TEST(Radii, HaemIronFallsBackToItsElement) {
  const Structure s = read_structure(pdb_dir / "2hhb.pdb");
  const auto fe = std::find_if(s.atoms.begin(), s.atoms.end(),
                               [](const Atom& a) { return a.residue_name == "HEM" && a.atom_name == "FE"; });
  ASSERT_NE(fe, s.atoms.end());
  EXPECT_EQ(fe->element, "FE");
  EXPECT_DOUBLE_EQ(fe->radius, 1.26);
  EXPECT_TRUE(fe->hetero);
  // 4 HEM x 43 atoms + 2 PO4 (2HHB has only their P) are not in the ProtOr table; none
  // needs the default.
  EXPECT_EQ(s.report.radius_from_element, 4u * 43 + 2);
  EXPECT_EQ(s.report.radius_default, 0u);
  // One example per (residue, element), in file order.
  EXPECT_EQ(s.report.fallback_examples,
            (std::vector<std::string>{"HEM CHA (C)", "HEM O1A (O)", "HEM NA (N)", "HEM FE (FE)", "PO4 P (P)"}));
  EXPECT_EQ(s.report.kept_by_element.at("FE"), 4u);
  EXPECT_EQ(s.report.kept_by_element.at("P"), 2u);
}

TEST(Radii, BondiIsByElement) {
  ReadOptions options;
  options.radius_set = "bondi";
  const Structure s = read_structure(pdb_dir / "2hhb.pdb", options);
  EXPECT_EQ(s.report.radius_set, "bondi");
  for (const Atom& a : s.atoms) {
    if (a.element == "C") ASSERT_DOUBLE_EQ(a.radius, 1.70);
    if (a.element == "N") ASSERT_DOUBLE_EQ(a.radius, 1.55);
    if (a.element == "O") ASSERT_DOUBLE_EQ(a.radius, 1.52);
    if (a.element == "S") ASSERT_DOUBLE_EQ(a.radius, 1.80);
  }
  EXPECT_EQ(s.report.radius_from_element, s.atoms.size());  // Bondi has no per-atom lines
  EXPECT_EQ(s.report.radius_default, 0u);
}

TEST(Radii, UserRadiusFileCountsFallbacks) {
  ReadOptions options;
  options.radius_file = test_dir / "custom_radii.txt";
  const Structure s = read_structure(pdb_dir / "1crn.pdb", options);
  EXPECT_EQ(s.report.radius_set, options.radius_file.string());
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 9, "CB")->radius, 1.23);  // ALA CB line
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "CA")->radius, 1.11);  // ANY CA line
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "CB")->radius, 1.5);   // THR CB: element C
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "N")->radius, 2.0);    // no N line: default
  std::size_t residue_atom = 0, carbon = 0, other = 0;
  for (const Atom& a : s.atoms) {
    if (a.atom_name == "CA" || (a.residue_name == "ALA" && a.atom_name == "CB")) ++residue_atom;
    else if (a.element == "C") ++carbon;
    else ++other;
  }
  EXPECT_EQ(s.report.radius_from_element, carbon);
  EXPECT_EQ(s.report.radius_default, other);
  EXPECT_EQ(residue_atom + carbon + other, s.atoms.size());
  EXPECT_EQ(s.report.fallback_examples.size(), 5u);
}

TEST(Radii, UnknownBuiltinSetIsAnError) {
  ReadOptions options;
  options.radius_set = "nonesuch";
  const std::string message = read_error(pdb_dir / "1crn.pdb", options);
  // The library's word for every front end (parameters.hpp), before the file is read.
  EXPECT_EQ(message, "radius_set: 'nonesuch' is not one of: bondi, naccess, protor");
}

// ---- selection ---------------------------------------------------------------------------

TEST(Selection, NmrFirstModelWithoutHydrogens) {
  const Structure s = read_structure(pdb_dir / "1j8k.cif");
  EXPECT_EQ(s.report.models_in_file, 20u);
  EXPECT_EQ(s.report.model_used, 1);
  EXPECT_EQ(s.report.records, 1402u);
  EXPECT_EQ(s.report.dropped_hydrogen, 682u);
  EXPECT_EQ(s.atoms.size(), 720u);
  EXPECT_EQ(s.report.kept_by_element.count("H"), 0u);
}

TEST(Selection, NmrOtherModelAndHydrogens) {
  ReadOptions options;
  options.model = 2;
  const Structure second = read_structure(pdb_dir / "1j8k.cif", options);
  const Structure first = read_structure(pdb_dir / "1j8k.cif");
  EXPECT_EQ(second.report.model_used, 2);
  EXPECT_EQ(second.atoms.size(), 720u);
  EXPECT_NE(second.atoms[0].centre, first.atoms[0].centre);  // NMR models differ

  options.model.reset();
  options.keep_hydrogens = true;
  const Structure with_h = read_structure(pdb_dir / "1j8k.cif", options);
  EXPECT_EQ(with_h.atoms.size(), 1402u);
  EXPECT_EQ(with_h.report.kept_by_element.at("H"), 682u);
  EXPECT_EQ(with_h.report.dropped_hydrogen, 0u);
}

TEST(Selection, UnknownModelListsTheAvailableOnes) {
  ReadOptions options;
  options.model = 21;
  const std::string message = read_error(pdb_dir / "1j8k.cif", options);
  EXPECT_NE(message.find("1j8k.cif"), std::string::npos) << message;
  EXPECT_NE(message.find("model 21 not found"), std::string::npos) << message;
  EXPECT_NE(message.find("1, 2, 3"), std::string::npos) << message;

  options.model = 2;  // models.pdb has models 1 and 3
  const std::string gap = read_error(test_dir / "models.pdb", options);
  EXPECT_NE(gap.find("models in the file: 1, 3"), std::string::npos) << gap;
  options.model = 3;
  EXPECT_EQ(read_structure(test_dir / "models.pdb", options).atoms.size(), 2u);
}

TEST(Selection, AltlocsAndWaterIn3pqr) {
  const Structure s = read_structure(pdb_dir / "3pqr.cif");
  EXPECT_EQ(s.report.dropped_altloc, 23u);
  EXPECT_EQ(s.report.dropped_water, 23u);
  EXPECT_EQ(s.report.records, 2904u);

  ReadOptions options;
  options.keep_water = true;
  const Structure wet = read_structure(pdb_dir / "3pqr.cif", options);
  EXPECT_EQ(wet.atoms.size(), 2858u + 23);
  EXPECT_EQ(wet.report.dropped_water, 0u);
  const std::size_t waters = std::count_if(wet.atoms.begin(), wet.atoms.end(),
                                           [](const Atom& a) { return a.residue_name == "HOH"; });
  EXPECT_EQ(waters, 23u);
}

TEST(Selection, AltlocPicksHighestOccupancyThenFirst) {
  const Structure s = read_structure(test_dir / "altloc.pdb");
  // 10 records: CB A/B (0.4/0.6), OG A/B (0.5/0.5), GLY N blank + A.
  EXPECT_EQ(s.report.dropped_altloc, 3u);
  ASSERT_EQ(s.atoms.size(), 7u);
  const Atom* cb = find_atom(s, "A", 1, "CB");
  ASSERT_NE(cb, nullptr);
  EXPECT_DOUBLE_EQ(cb->centre.y, -1.0);  // B, occupancy 0.60
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 1, "OG")->centre.y, 1.0);  // tie: first (A)
  EXPECT_DOUBLE_EQ(find_atom(s, "A", 2, "N")->centre.x, 3.0);   // blank copy beats A
}

TEST(Selection, ChainsFilterOnHaemoglobin) {
  ReadOptions options;
  options.chains = {"A", "C"};
  const Structure s = read_structure(pdb_dir / "2hhb.pdb", options);
  const Structure all = read_structure(pdb_dir / "2hhb.pdb");
  std::size_t in_a_or_c = 0;
  for (const Atom& a : all.atoms) in_a_or_c += (a.chain == "A" || a.chain == "C");
  EXPECT_GT(in_a_or_c, 2000u);
  EXPECT_EQ(s.atoms.size(), in_a_or_c);
  for (const Atom& a : s.atoms) ASSERT_TRUE(a.chain == "A" || a.chain == "C") << a.chain;
  EXPECT_GT(s.report.dropped_chain, 0u);
  EXPECT_EQ(s.report.records, s.report.kept + total_dropped(s.report));

  options.chains = {"Z"};
  const std::string message = read_error(pdb_dir / "2hhb.pdb", options);
  EXPECT_NE(message.find("no atoms left after filtering"), std::string::npos) << message;
  EXPECT_NE(message.find("4779 not in the selected chains"), std::string::npos) << message;
}

TEST(Selection, NoHetatmDropsHaemAndPhosphate) {
  ReadOptions options;
  options.keep_hetatm = false;
  const Structure s = read_structure(pdb_dir / "2hhb.pdb", options);
  EXPECT_EQ(s.report.dropped_hetatm, 4u * 43 + 2);  // the PO4 groups are P only in 2HHB
  EXPECT_EQ(s.atoms.size(), 4558u - 174);
  for (const Atom& a : s.atoms) ASSERT_TRUE(a.residue_name != "HEM" && a.residue_name != "PO4");
  EXPECT_EQ(s.report.radius_from_element, 0u);
  EXPECT_EQ(s.report.dropped_water, 221u);  // waters stay counted as water, not as hetero
}

TEST(Selection, ElementInferredWhenTheColumnIsEmpty) {
  const Structure s = read_structure(test_dir / "no_element.pdb");
  EXPECT_EQ(s.report.dropped_hydrogen, 4u);  // HA, 1HB, HB2, HB12
  EXPECT_EQ(s.report.dropped_water, 1u);
  ASSERT_EQ(s.atoms.size(), 3u);
  EXPECT_EQ(s.atoms[0].element, "N");
  EXPECT_EQ(s.atoms[1].element, "C");
  EXPECT_EQ(s.atoms[2].element, "FE");
  EXPECT_DOUBLE_EQ(s.atoms[2].radius, 1.26);
}

// ---- PQR and xyzr ------------------------------------------------------------------------

TEST(Pqr, RadiusAndChargeColumns) {
  const Structure s = read_structure(test_dir / "small.pqr");
  EXPECT_EQ(s.report.format, StructureFormat::pqr);
  EXPECT_EQ(s.report.radius_set, "file");
  EXPECT_EQ(s.report.records, 6u);
  EXPECT_EQ(s.report.dropped_hydrogen, 1u);
  EXPECT_EQ(s.report.dropped_water, 1u);
  ASSERT_EQ(s.atoms.size(), 4u);
  EXPECT_DOUBLE_EQ(s.atoms[0].radius, 1.8240);
  EXPECT_DOUBLE_EQ(s.atoms[0].charge, -0.3);
  EXPECT_EQ(s.atoms[0].chain, "A");
  EXPECT_EQ(s.atoms[2].residue_number, 52);
  EXPECT_EQ(s.atoms[2].insertion_code, 'A');
  EXPECT_EQ(s.atoms[3].element, "ZN");
  EXPECT_DOUBLE_EQ(s.atoms[3].charge, 2.0);
  EXPECT_DOUBLE_EQ(s.atoms[3].radius, 1.1);
  EXPECT_TRUE(s.atoms[3].hetero);
  EXPECT_EQ(s.report.radius_from_element + s.report.radius_default, 0u);
}

TEST(Pqr, WithoutChainColumnAndWithModels) {
  const Structure s = read_structure(test_dir / "no_chain.pqr");
  ASSERT_EQ(s.atoms.size(), 3u);
  EXPECT_EQ(s.atoms[2].chain, "");
  EXPECT_DOUBLE_EQ(s.atoms[2].centre.y, 1.4);
  EXPECT_DOUBLE_EQ(s.atoms[2].charge, 0.5973);

  ReadOptions options;
  EXPECT_EQ(read_structure(test_dir / "models.pqr", options).atoms.size(), 1u);
  options.model = 2;
  const Structure second = read_structure(test_dir / "models.pqr", options);
  EXPECT_EQ(second.atoms.size(), 2u);
  EXPECT_EQ(second.report.models_in_file, 2u);
}

TEST(Xyzr, WithAndWithoutNames) {
  const Structure named = read_structure(test_dir / "named.xyzr");
  EXPECT_EQ(named.report.format, StructureFormat::xyzr);
  ASSERT_EQ(named.atoms.size(), 3u);
  EXPECT_EQ(named.atoms[1].atom_name, "N");
  EXPECT_DOUBLE_EQ(named.atoms[1].radius, 1.55);
  EXPECT_DOUBLE_EQ(named.atoms[2].centre.x, 3.0);
  EXPECT_EQ(named.report.radius_set, "file");

  const Structure plain = read_structure(test_dir / "plain.xyzr");
  ASSERT_EQ(plain.atoms.size(), 2u);
  EXPECT_EQ(plain.atoms[0].atom_name, "");
  EXPECT_DOUBLE_EQ(plain.atoms[0].radius, 1.7);
  EXPECT_EQ(plain.report.kept, 2u);
}

// ---- formats and errors ------------------------------------------------------------------

TEST(Format, FromPath) {
  EXPECT_EQ(structure_format_from_path("a/1abc.pdb"), StructureFormat::pdb);
  EXPECT_EQ(structure_format_from_path("pdb1abc.ent.gz"), StructureFormat::pdb);
  EXPECT_EQ(structure_format_from_path("1ABC.CIF"), StructureFormat::mmcif);
  EXPECT_EQ(structure_format_from_path("1abc.mmcif.gz"), StructureFormat::mmcif);
  EXPECT_EQ(structure_format_from_path("x.pqr"), StructureFormat::pqr);
  EXPECT_EQ(structure_format_from_path("x.xyzr"), StructureFormat::xyzr);
  EXPECT_THROW(structure_format_from_path("x.mol2"), Error);
  EXPECT_THROW(structure_format_from_path("x.pqr.gz"), Error);
}

struct BadInput {
  const char* file;
  const char* expected;  // the message must contain this
};

class BadInputs : public testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, GiveTheDocumentedError) {
  const std::filesystem::path path = test_dir / GetParam().file;
  const std::string message = read_error(path);
  ASSERT_FALSE(message.empty()) << "no error for " << GetParam().file;
  EXPECT_EQ(message.rfind(path.string(), 0), 0u) << "message must start with the file name: " << message;
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Errors, BadInputs,
    testing::Values(BadInput{"missing.pdb", ": file not found"},
                    BadInput{"structure.txt", ": unknown structure format"},
                    BadInput{"bad_coordinate.pdb", ":4: ATOM record: y coordinate '1.0x1'"},
                    BadInput{"short_record.pdb", ":3: ATOM record too short"},
                    BadInput{"bad_fields.pqr", ":3: ATOM record: residue number 'A' is not a number (is a column missing?"},
                    BadInput{"too_many_fields.pqr", ":1: ATOM record has 12 fields; PQR expects 10 or 11"},
                    BadInput{"bad_number.pqr", ":2: ATOM record: radius '1.9O80' is not a number"},
                    BadInput{"bad_fields.xyzr", ":3: expected 'x y z r [name]', found 3 fields"},
                    BadInput{"bad_radius.xyzr", ":2: radius: -"},
                    BadInput{"broken.cif", "broken.cif:"},
                    BadInput{"only_water.pdb", ": no atoms left after filtering (3 atom records in model 1; dropped: 3 water)"}),
    [](const testing::TestParamInfo<BadInput>& info) {
      std::string name = info.param.file;
      std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
      return name;
    });

TEST(Errors, BadRadiusFileNamesFileAndLine) {
  ReadOptions options;
  options.radius_file = test_dir / "bad_radii.txt";
  const std::string message = read_error(pdb_dir / "1crn.pdb", options);
  EXPECT_NE(message.find(options.radius_file.string() + ":3: radius 'one.five' is not a number"),
            std::string::npos)
      << message;
}

TEST(Errors, EmptyFileAndDirectory) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "molsurf_structure_test";
  std::filesystem::create_directories(dir / "folder.pdb");
  const std::filesystem::path empty = dir / "empty.cif";
  { std::ofstream create(empty); }
  EXPECT_EQ(read_error(empty), empty.string() + ": file is empty");
  EXPECT_EQ(read_error(dir / "folder.pdb"), (dir / "folder.pdb").string() + ": is a directory, not a file");
  std::filesystem::remove_all(dir);
}

TEST(Errors, XyzrHasNoChains) {
  ReadOptions options;
  options.chains = {"A"};
  const std::string message = read_error(test_dir / "plain.xyzr", options);
  EXPECT_NE(message.find("no chain identifiers"), std::string::npos) << message;
}

// ---- issue 12, items 5 and 8: input errors name the file, the line and the problem -------

class InputErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (std::filesystem::temp_directory_path() / "molsurf_input_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path put(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

// Issue 31: pdb2pqr's AMBER PQR gives hydroxyl hydrogens radius 0. A ball of radius 0 adds
// nothing to a union of balls: such atoms are dropped and counted, not refused.
TEST_F(InputErrors, PqrAtomsOfRadiusZeroAreDroppedAndCounted) {
  const auto pqr = put("ser.pqr",
                       "REMARK   1 PQR file generated by PDB2PQR\n"
                       "ATOM      1  CB  SER A   1       1.000   0.000   0.000  0.0212 1.9080\n"
                       "ATOM      2  OG  SER A   1       2.400   0.000   0.000 -0.6546 1.7210\n"
                       "ATOM      3  HG  SER A   1       2.800   0.900   0.000  0.4275 0.0000\n"
                       "ATOM      4  HB2 SER A   1       0.600   1.000   0.000  0.0352 1.3870\n"
                       "HETATM    5  H1  HOH W   2       9.000   0.000   0.000  0.4170 0.0000\n"
                       "ATOM      6  H   SER A   1       0.500  -0.900   0.000  0.2719 0.0\n");
  ReadOptions options;
  options.keep_hydrogens = true;
  options.keep_water = true;
  const Structure s = read_structure(pqr, options);
  EXPECT_EQ(s.report.records, 6u);
  EXPECT_EQ(s.report.dropped_zero_radius, 3u);
  ASSERT_EQ(s.atoms.size(), 3u);
  EXPECT_EQ(s.report.kept, 3u);
  EXPECT_EQ(s.report.records, s.report.kept + total_dropped(s.report));
  EXPECT_EQ(s.atoms[0].atom_name, "CB");
  EXPECT_EQ(s.atoms[1].atom_name, "OG");
  EXPECT_EQ(s.atoms[2].atom_name, "HB2");
  for (const Atom& a : s.atoms) EXPECT_GT(a.radius, 0.0);
  EXPECT_NE(format_read_report(s.report).find("3 atoms of radius 0 (they add nothing to the surface)"),
            std::string::npos)
      << format_read_report(s.report);

  // Without --hydrogens the hydrogens are dropped as hydrogens first: each record counted once.
  const Structure heavy = read_structure(pqr);
  EXPECT_EQ(heavy.report.dropped_hydrogen, 3u);
  EXPECT_EQ(heavy.report.dropped_zero_radius, 0u);
  EXPECT_EQ(heavy.report.records, heavy.report.kept + total_dropped(heavy.report));
  EXPECT_EQ(format_read_report(heavy.report).find("radius 0"), std::string::npos)
      << "no line about radius 0 when none was dropped";
}

TEST_F(InputErrors, PqrNegativeOrNonNumericRadiusIsStillRefused) {
  const auto negative = put("neg.pqr", "ATOM      1  CA  ALA A   1       1.0     2.0     3.0  0.00 1.80\n"
                                       "ATOM      2  CB  ALA A   1       2.0     2.0     3.0  0.00 -1.5\n");
  EXPECT_EQ(read_error(negative), negative.string() +
                                      ":2: ATOM record: radius: -1.5 is negative; a radius is 0 or more (angstrom, "
                                      "without the probe)");
  const auto nan = put("nan.pqr", "ATOM      1  CA  ALA A   1       1.0     2.0     3.0  0.00 nan\n");
  EXPECT_EQ(read_error(nan), nan.string() + ":1: ATOM record: radius: nan is not a finite number");
}

TEST_F(InputErrors, PqrWhoseEveryAtomHasRadiusZeroIsOneClearError) {
  const auto pqr = put("zero.pqr", "ATOM      1  HG  SER A   1       1.0     2.0     3.0  0.43 0.0000\n"
                                   "ATOM      2  HH  TYR A   2       4.0     2.0     3.0  0.40 0.0000\n");
  ReadOptions options;
  options.keep_hydrogens = true;
  const std::string message = read_error(pqr, options);
  EXPECT_NE(message.find(pqr.string() + ": no atoms left"), std::string::npos) << message;
  EXPECT_NE(message.find("2 of radius 0"), std::string::npos) << message;
}

TEST_F(InputErrors, XyzrSpheresOfRadiusZeroAreDroppedAndCounted) {
  const auto xyzr = put("h.xyzr", "0 0 0 1.7 OG\n0.96 0 0 0 HG\n# comment\n3 0 0 1.9 CB\n5 0 0 0.0000\n");
  const Structure s = read_structure(xyzr);
  EXPECT_EQ(s.report.records, 4u);
  EXPECT_EQ(s.report.dropped_zero_radius, 2u);
  ASSERT_EQ(s.atoms.size(), 2u);
  EXPECT_EQ(s.report.kept, 2u);
  EXPECT_EQ(s.atoms[0].atom_name, "OG");
  EXPECT_EQ(s.atoms[1].atom_name, "CB");
  EXPECT_NE(format_read_report(s.report).find("2 atoms of radius 0 (they add nothing to the surface)"),
            std::string::npos)
      << format_read_report(s.report);

  const auto negative = put("neg.xyzr", "0 0 0 1.7\n1 0 0 -0.5\n");
  EXPECT_EQ(read_error(negative),
            negative.string() + ":2: radius: -0.5 is negative; a radius is 0 or more (angstrom, without the probe)");
  const auto nan = put("nan.xyzr", "0 0 0 nan\n");
  EXPECT_EQ(read_error(nan), nan.string() + ":1: radius: nan is not a finite number");

  const auto zero = put("zero.xyzr", "0 0 0 0\n1 0 0 0.0\n");
  EXPECT_EQ(read_error(zero), zero.string() +
                                  ": no spheres left: all 2 have radius 0, and a sphere of radius 0 adds "
                                  "nothing to a surface");
}

TEST_F(InputErrors, CoordinatesBeyond1e16AreRefusedWithFileAndLine) {
  const auto xyzr = put("far.xyzr", "0 0 0 1.5\n0 -1e16 0 1.5\n");
  EXPECT_EQ(read_error(xyzr), xyzr.string() + ":2: y: -1e+16 is out of range (its magnitude must be below 1e16 angstrom)");
  const auto radius = put("wide.xyzr", "0 0 0 2e16\n");
  EXPECT_NE(read_error(radius).find("wide.xyzr:1: radius: 2e+16 is out of range"), std::string::npos)
      << read_error(radius);
  const auto pqr = put("far.pqr", "ATOM      1  CA  ALA A   1       1.0     2.0     3.0  0.00 1.80\n"
                                  "ATOM      2  CB  ALA A   1       2.0     2.0     3e300  0.00 1.80\n");
  EXPECT_EQ(read_error(pqr),
            pqr.string() + ":2: ATOM record: z coordinate: 3e+300 is out of range (its magnitude must be below 1e16 "
                           "angstrom)");
  const auto pdb = put("far.pdb", "ATOM      1  CA  ALA A   1    -1.0e+17   2.000   3.000  1.00  0.00           C\n");
  EXPECT_NE(read_error(pdb).find("far.pdb:1: ATOM record: x coordinate: -1e+17 is out of range"), std::string::npos)
      << read_error(pdb);
  // Just below the limit is a coordinate like any other.
  const auto near = put("near.xyzr", "9.9e15 0 0 1.5\n");
  EXPECT_EQ(read_error(near), "");
}

TEST_F(InputErrors, TruncatedGzipSaysSoInOneLine) {
  std::ifstream in(pdb_dir / "1crn.cif.gz", std::ios::binary);
  const std::string gz((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto cut = put("cut.cif.gz", gz.substr(0, gz.size() / 2));
  const std::string message = read_error(cut);
  EXPECT_EQ(message.rfind(cut.string() + ": truncated gzip file", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  const auto garbage = put("garbage.pdb.gz", "\x1f\x8b\x08\x00garbage that is not deflate data");
  EXPECT_NE(read_error(garbage).find("garbage.pdb.gz: "), std::string::npos);
  EXPECT_EQ(read_error(garbage).find('\n'), std::string::npos) << read_error(garbage);
}

// Issue 34: a gzip bomb grew until an allocation failed. The text is bounded by the memory
// limit (ReadOptions::max_memory / kBytesPerTextByte) as it is decompressed: 8 MB of valid
// PDB records under a 16 MB limit (1 MB of text) are refused in one line, and read whole
// under the default limit.
TEST_F(InputErrors, GzipBombStopsAtTheMemoryLimit) {
  const std::string line = "ATOM      1  CA  ALA A   1       1.000   2.000   3.000  1.00  0.00           C  \n";
  const std::filesystem::path bomb = dir_ / "bomb.pdb.gz";
  gzFile out = gzopen(bomb.c_str(), "wb9");
  ASSERT_NE(out, nullptr);
  const std::size_t copies = 8'000'000 / line.size();
  for (std::size_t k = 0; k < copies; ++k) gzwrite(out, line.data(), static_cast<unsigned>(line.size()));
  gzclose(out);
  ASSERT_LT(std::filesystem::file_size(bomb), 1'000'000u);
  ReadOptions limited;
  limited.max_memory = kBytesPerTextByte * 1'000'000;  // 1 MB of text
  const std::string message = read_error(bomb, limited);
  EXPECT_EQ(message.rfind(bomb.string() + ": decompressed, the file holds more than", 0), 0u) << message;
  EXPECT_NE(message.find("raise the limit with --max-memory"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(read_structure(bomb).report.records, copies);
  // A plain file beyond the bound is refused before it is read.
  const auto plain = put("big.xyzr", std::string(2'000'000, ' ') + "0 0 0 1.5\n");
  EXPECT_NE(read_error(plain, limited).find("big.xyzr: the file holds 0.002 GB of text; a structure read may hold 0.001 GB under the memory limit"),
            std::string::npos)
      << read_error(plain, limited);
  EXPECT_EQ(read_error(plain), "");
}

// /dev/zero has no end: devices and pipes are refused before they are opened (a pipe's
// open would wait for a writer), whatever their name says.
TEST_F(InputErrors, DevicesAndPipesAreRefused) {
  const std::filesystem::path zero = dir_ / "zero.pdb";
  std::filesystem::create_symlink("/dev/zero", zero);
  EXPECT_EQ(read_error(zero), zero.string() + ": cannot read: it is a device, pipe or socket, not a regular file; "
                                               "give a file");
  const std::filesystem::path pipe = dir_ / "pipe.cif.gz";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_NE(read_error(pipe).find("pipe.cif.gz: cannot read: it is a device, pipe or socket"), std::string::npos);
  EXPECT_NE(read_error("/dev/zero").find("/dev/zero: cannot read: it is a device"), std::string::npos);
}

TEST_F(InputErrors, MmcifWithoutCartesianCoordinatesSaysWhatIsMissing) {
  std::ifstream in(pdb_dir / "3pqr.cif", std::ios::binary);
  std::string cif((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "_atom_site.Cartn_y ";
  cif.replace(cif.find(from), from.size(), "_atom_site.Fract_y ");
  const auto file = put("no_y.cif", cif);
  EXPECT_EQ(read_error(file), file.string() +
                                  ": the _atom_site table has no _atom_site.Cartn_y column: no Cartesian coordinates "
                                  "(fractional-only or incomplete files are not read)");
  const auto no_atoms = put("no_atoms.cif", "data_x\n_cell.length_a 10\n");
  EXPECT_NE(read_error(no_atoms).find("no _atom_site table"), std::string::npos) << read_error(no_atoms);
}

TEST_F(InputErrors, GarbageRadiusFileIsQuotedEscapedAndShort) {
  const auto radii = put("radii.txt", "default 1.8\n\x01\x02\xff\x1b[31m" + std::string(200, 'A') + " 1 2\n");
  ReadOptions options;
  options.radius_file = radii;
  const std::string message = read_error(pdb_dir / "1crn.pdb", options);
  EXPECT_EQ(message.rfind(radii.string() + ":2: unknown line kind '\\x01\\x02\\xff\\x1b[31mAAAAAAAAAAAAAAAA...'", 0),
            0u)
      << message;
  for (unsigned char c : message) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << message;
}

}  // namespace
}  // namespace molsurf
