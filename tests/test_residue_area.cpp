// area_per_residue(): atoms grouped by chain, number, insertion code and name, in order
// of first appearance; the per-residue CSV is its rendering.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/surface_report.hpp"

namespace molsurf {
namespace {

Atom labelled(const std::string& chain, const std::string& residue, int number, char icode = ' ') {
  Atom a;
  a.chain = chain;
  a.residue_name = residue;
  a.residue_number = number;
  a.insertion_code = icode;
  return a;
}

TEST(ResidueArea, SumsAtomsInOrderOfFirstAppearance) {
  const std::vector<Atom> atoms{labelled("B", "GLY", 5), labelled("A", "ALA", 1), labelled("B", "GLY", 5),
                                labelled("A", "ALA", 1, 'A'), labelled("A", "ALA", 1)};
  const std::vector<double> area{1.0, 2.0, 4.0, 8.0, 16.0};
  const std::vector<ResidueArea> rows = area_per_residue(atoms, area);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].chain, "B");
  EXPECT_EQ(rows[0].residue_name, "GLY");
  EXPECT_EQ(rows[0].residue_number, 5);
  EXPECT_EQ(rows[0].atoms, 2u);
  EXPECT_EQ(rows[0].area, 5.0);
  EXPECT_EQ(rows[1].chain, "A");
  EXPECT_EQ(rows[1].insertion_code, ' ');
  EXPECT_EQ(rows[1].atoms, 2u);
  EXPECT_EQ(rows[1].area, 18.0);
  EXPECT_EQ(rows[2].insertion_code, 'A');  // an insertion code makes another residue
  EXPECT_EQ(rows[2].area, 8.0);
}

TEST(ResidueArea, CsvRendersTheRows) {
  const std::vector<Atom> atoms{labelled("A", "ALA", 1), labelled("A", "ALA", 1), labelled("A", "HEM", 142, 'B')};
  const std::vector<double> area{1.5, 2.25 + 1e-13, 0.0};
  // Areas to the last bit: the shortest text that reads back to the same double.
  EXPECT_EQ(per_residue_csv(atoms, area),
            "chain,residue_name,residue_number,insertion_code,atoms,area\n"
            "A,ALA,1,_,2,3.7500000000001\n"
            "A,HEM,142,B,1,0\n");
}

TEST(ResidueArea, OneAreaPerAtomIsRequired) {
  const std::vector<Atom> atoms{labelled("A", "ALA", 1)};
  const std::vector<double> area{1.0, 2.0};
  EXPECT_THROW(area_per_residue(atoms, area), std::invalid_argument);
}

}  // namespace
}  // namespace molsurf
