// Valid text input is read whatever its encoding details: a UTF-8 byte-order mark, old Mac
// OS line ends (CR alone), mmCIF tables without the columns a surface does not need, and
// residue numbers beyond 32 bits.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"

namespace molsurf {
namespace {

namespace fs = std::filesystem;
const fs::path kPdb = fs::path(MOLSURF_DATA_DIR) / "pdb";
const fs::path kTestData = fs::path(MOLSURF_DATA_DIR) / ".." / "tests" / "data" / "structure";
const std::string kBom = "\xEF\xBB\xBF";

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class StructureText : public ::testing::Test {
 protected:
  fs::path put(const std::string& name, const std::string& content) const {
    std::ofstream(dir_.path() / name, std::ios::binary) << content;
    return dir_.path() / name;
  }
  testing::TempDir dir_;
};

// The same atoms, coordinates, names and radii.
void expect_same_atoms(const Structure& a, const Structure& b) {
  ASSERT_EQ(a.atoms.size(), b.atoms.size());
  ASSERT_FALSE(a.atoms.empty());
  for (std::size_t i = 0; i < a.atoms.size(); ++i) {
    EXPECT_EQ(a.atoms[i].centre.x, b.atoms[i].centre.x) << i;
    EXPECT_EQ(a.atoms[i].centre.z, b.atoms[i].centre.z) << i;
    EXPECT_EQ(a.atoms[i].atom_name, b.atoms[i].atom_name) << i;
    EXPECT_EQ(a.atoms[i].residue_number, b.atoms[i].residue_number) << i;
    EXPECT_EQ(a.atoms[i].radius, b.atoms[i].radius) << i;
  }
}

TEST_F(StructureText, AByteOrderMarkIsIgnoredInEveryTextInput) {
  for (const fs::path& original : {kPdb / "1crn.pdb", kPdb / "3pqr.cif", kTestData / "plain.xyzr",
                                   kTestData / "small.pqr"}) {
    const fs::path marked = put("bom" + original.extension().string(), kBom + slurp(original));
    expect_same_atoms(read_structure(marked), read_structure(original));
  }
  ReadOptions plain, marked;
  plain.radius_file = kTestData / "custom_radii.txt";
  marked.radius_file = put("radii.txt", kBom + slurp(plain.radius_file));
  expect_same_atoms(read_structure(kPdb / "1crn.pdb", marked), read_structure(kPdb / "1crn.pdb", plain));
}

TEST_F(StructureText, CarriageReturnLineEndsAreLineEnds) {
  for (const fs::path& original : {kPdb / "1crn.pdb", kPdb / "3pqr.cif", kTestData / "plain.xyzr",
                                   kTestData / "small.pqr"}) {
    std::string text = slurp(original);
    std::string crlf;
    for (char& c : text) {
      if (c == '\n') crlf += '\r';
      crlf += c;
      if (c == '\n') c = '\r';
    }
    expect_same_atoms(read_structure(put("cr" + original.extension().string(), text)), read_structure(original));
    expect_same_atoms(read_structure(put("crlf" + original.extension().string(), crlf)), read_structure(original));
  }
  // Line numbers still count lines.
  const std::string bad = "ATOM      1  N   THR A   1      17.047  14.099   3.625\rATOM      2  CA  THR A   1      "
                          "1x.859  12.784   4.338  1.00 13.79           C\r";
  try {
    read_structure(put("bad.pdb", bad));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.pdb:2:"), std::string::npos) << e.what();
  }
}

const char* kAtomsWithoutOptionalColumns = R"(data_test
loop_
_atom_site.group_PDB
_atom_site.type_symbol
_atom_site.label_atom_id
_atom_site.label_comp_id
_atom_site.auth_asym_id
_atom_site.auth_seq_id
_atom_site.Cartn_x
_atom_site.Cartn_y
_atom_site.Cartn_z
ATOM N N  ALA B 7 0.0 0.0 0.0
ATOM C CA ALA B 7 1.5 0.0 0.0
ATOM C C  ALA B 7 2.0 1.4 0.0
)";

TEST_F(StructureText, MmcifWithoutOccupancyBFactorOrLabelAsymIdIsRead) {
  const Structure s = read_structure(put("bare.cif", kAtomsWithoutOptionalColumns));
  ASSERT_EQ(s.atoms.size(), 3u);
  for (const Atom& a : s.atoms) {
    EXPECT_EQ(a.chain, "B");
    EXPECT_EQ(a.residue_name, "ALA");
    EXPECT_EQ(a.residue_number, 7);
    EXPECT_EQ(a.occupancy, 1.0);  // gemmi's defaults for an unknown value
    EXPECT_EQ(a.b_factor, 50.0);
  }
  EXPECT_EQ(s.atoms[1].atom_name, "CA");
  EXPECT_EQ(s.atoms[1].element, "C");
  EXPECT_EQ(s.atoms[1].centre.x, 1.5);
  // The same atoms with every column give the same structure.
  const std::string full = R"(data_test
loop_
_atom_site.group_PDB
_atom_site.id
_atom_site.type_symbol
_atom_site.label_atom_id
_atom_site.label_alt_id
_atom_site.label_comp_id
_atom_site.label_asym_id
_atom_site.auth_asym_id
_atom_site.auth_seq_id
_atom_site.Cartn_x
_atom_site.Cartn_y
_atom_site.Cartn_z
_atom_site.occupancy
_atom_site.B_iso_or_equiv
ATOM 1 N N  . ALA B B 7 0.0 0.0 0.0 1 50
ATOM 2 C CA . ALA B B 7 1.5 0.0 0.0 1 50
ATOM 3 C C  . ALA B B 7 2.0 1.4 0.0 1 50
)";
  expect_same_atoms(s, read_structure(put("full.cif", full)));
  // One atom is written as tag-value pairs rather than a loop.
  const Structure one = read_structure(put("one.cif", "data_one\n_atom_site.group_PDB ATOM\n_atom_site.type_symbol C\n"
                                                     "_atom_site.label_atom_id CA\n_atom_site.label_comp_id GLY\n"
                                                     "_atom_site.auth_asym_id A\n_atom_site.auth_seq_id 3\n"
                                                     "_atom_site.Cartn_x 1\n_atom_site.Cartn_y 2\n_atom_site.Cartn_z 3\n"));
  ASSERT_EQ(one.atoms.size(), 1u);
  EXPECT_EQ(one.atoms[0].residue_number, 3);
  EXPECT_EQ(one.atoms[0].centre.z, 3.0);
}

TEST_F(StructureText, ResidueNumbersBeyond32BitsKeepTheirValue) {
  std::string cif = kAtomsWithoutOptionalColumns;
  const std::string numbers[] = {"3000000000", "-5000000000", "2147483648"};
  for (int row = 0; row < 3; ++row) {
    const std::size_t at = cif.find(" B 7 ");
    cif.replace(at, 5, " B " + numbers[row] + " ");
  }
  const Structure s = read_structure(put("wide.cif", cif));
  ASSERT_EQ(s.atoms.size(), 3u);
  EXPECT_EQ(s.atoms[0].residue_number, 3'000'000'000LL);
  EXPECT_EQ(s.atoms[1].residue_number, -5'000'000'000LL);
  EXPECT_EQ(s.atoms[2].residue_number, 2'147'483'648LL);

  const std::string pqr = "ATOM      1  N   ALA A 3000000000  -0.500   0.000   0.000 -0.3000 1.8240\n"
                          "ATOM      2  CA  ALA A 3000000000   1.000   0.000   0.000  0.0337 1.9080\n";
  const Structure p = read_structure(put("wide.pqr", pqr));
  ASSERT_EQ(p.atoms.size(), 2u);
  EXPECT_EQ(p.atoms[0].residue_number, 3'000'000'000LL);
}

}  // namespace
}  // namespace molsurf
