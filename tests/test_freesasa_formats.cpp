// FreeSASA's text formats (rsa, seq, res): their layout, the sums they carry, the relative
// values against Tien et al. 2013.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "molsurf/freesasa_formats.hpp"

namespace molsurf {
namespace {

Atom atom(const std::string& chain, const std::string& residue, int number, const std::string& name,
          const std::string& element) {
  Atom a;
  a.chain = chain;
  a.residue_name = residue;
  a.residue_number = number;
  a.atom_name = name;
  a.element = element;
  return a;
}

// ALA A1 (N, CA, CB, O), GLY A2 (N, CA), and a haem iron in chain B.
const std::vector<Atom> kAtoms{atom("A", "ALA", 1, "N", "N"),  atom("A", "ALA", 1, "CA", "C"),
                               atom("A", "ALA", 1, "CB", "C"), atom("A", "ALA", 1, "O", "O"),
                               atom("A", "GLY", 2, "N", "N"),  atom("A", "GLY", 2, "CA", "C"),
                               atom("B", "HEM", 1, "FE", "FE")};
const std::vector<double> kArea{1, 2, 4, 8, 16, 32, 64};

std::vector<std::string> lines_starting(const std::string& text, const std::string& head) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(head, 0) == 0) out.push_back(line);
  return out;
}

TEST(FreeSasaFormats, RsaColumnsSumsAndRelativeValues) {
  const std::string rsa = rsa_text(kAtoms, kArea, {.source = "x.pdb", .radii = "protor", .probe = 1.4});
  const std::vector<std::string> res = lines_starting(rsa, "RES ");
  ASSERT_EQ(res.size(), 3u) << rsa;
  // ALA: all 15; side chain CB 4, main chain 11; apolar CA+CB 6, polar N+O 9; Tien's ALA maximum 129.
  char expected[160];
  std::snprintf(expected, sizeof expected, "RES ALA A   1    15.00%6.1f   4.00   N/A  11.00   N/A   6.00   N/A   9.00   N/A",
                100 * 15 / 129.0);
  EXPECT_EQ(res[0], expected);
  EXPECT_EQ(res[2].substr(0, 22), "RES HEM B   1    64.00");
  EXPECT_NE(res[2].find("   N/A"), std::string::npos);  // no maximum for a haem
  const std::vector<std::string> chains = lines_starting(rsa, "CHAIN");
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_EQ(chains[0], "CHAIN  1 A       63.0          4.0         59.0         38.0         25.0");
  EXPECT_EQ(lines_starting(rsa, "TOTAL").at(0),
            "TOTAL           127.0         68.0         59.0        102.0         25.0");
  EXPECT_NE(rsa.find("REM  Probe-radius: 1.40"), std::string::npos);
  const std::string empirical =
      rsa_text(kAtoms, kArea, {.source = "x.pdb", .radii = "protor", .probe = 1.4, .scale = MaxAreaScale::empirical});
  EXPECT_NE(lines_starting(empirical, "RES ALA").at(0), res[0]);  // another maximum
}

TEST(FreeSasaFormats, SequenceAndResidueTypes) {
  const std::vector<std::string> seq = lines_starting(residue_sequence_text(kAtoms, kArea, "x.pdb"), "SEQ");
  ASSERT_EQ(seq.size(), 3u);
  EXPECT_EQ(seq[0], "SEQ A    1  ALA :   15.00");
  EXPECT_EQ(seq[1], "SEQ A    2  GLY :   48.00");
  const std::vector<std::string> res = lines_starting(residue_type_text(kAtoms, kArea, "x.pdb"), "RES");
  ASSERT_EQ(res.size(), 21u);  // the twenty amino acids and the haem
  EXPECT_EQ(res[0], "RES ALA :      15.00");
  EXPECT_EQ(res[1], "RES ARG :       0.00");
  EXPECT_NE(std::find(res.begin(), res.end(), "RES HEM :      64.00"), res.end());
  EXPECT_THROW(residue_type_text(kAtoms, std::vector<double>{1}, "x.pdb"), std::invalid_argument);
}

}  // namespace
}  // namespace molsurf
