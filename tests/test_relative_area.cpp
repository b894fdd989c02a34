// Relative solvent accessibility's maxima (Tien et al. 2013) and the per-chain table.
#include <gtest/gtest.h>

#include "atom_fixtures.hpp"
#include "molsurf/atom_classes.hpp"
#include "molsurf/relative_area.hpp"
#include "molsurf/surface_measures.hpp"
#include "molsurf/surface_report.hpp"

namespace molsurf {
namespace {

TEST(RelativeArea, TienMaximaForTheTwentyAminoAcids) {
  EXPECT_EQ(max_residue_area("ALA"), 129);
  EXPECT_EQ(max_residue_area("GLY", MaxAreaScale::empirical), 97);
  EXPECT_EQ(max_residue_area("TRP"), 285);
  EXPECT_EQ(max_residue_area("TRP", MaxAreaScale::empirical), 264);
  for (const char* name : {"ALA", "ARG", "ASN", "ASP", "CYS", "GLN", "GLU", "GLY", "HIS", "ILE", "LEU", "LYS", "MET",
                           "PHE", "PRO", "SER", "THR", "TRP", "TYR", "VAL"}) {
    ASSERT_TRUE(max_residue_area(name)) << name;
    // The empirical maxima are at most the theoretical ones (the paper's Table 1).
    EXPECT_LE(*max_residue_area(name, MaxAreaScale::empirical), *max_residue_area(name)) << name;
  }
  EXPECT_FALSE(max_residue_area("HEM"));
  EXPECT_FALSE(max_residue_area("HOH"));
  EXPECT_FALSE(max_residue_area("ala"));  // names are upper case as the readers give them
}

Atom residue_atom(const std::string& chain, const std::string& name, int number) {
  Atom a = testing::atom_at({0, 0, 0}, 1.5);
  a.chain = chain;
  a.residue_name = name;
  a.residue_number = number;
  return a;
}

TEST(RelativeArea, ResidueTableGetsARelativeColumnAndChainsAddUp) {
  const std::vector<Atom> atoms{residue_atom("A", "ALA", 1), residue_atom("A", "ALA", 1), residue_atom("A", "HEM", 2),
                                residue_atom("B", "GLY", 1)};
  const std::vector<double> area{30.0, 34.5, 10.0, 52.0};
  EXPECT_EQ(per_residue_csv(atoms, area, MaxAreaScale::theoretical),
            "chain,residue_name,residue_number,insertion_code,atoms,area,relative\n"
            "A,ALA,1,_,2,64.5,0.5\n"
            "A,HEM,2,_,1,10,\n"
            "B,GLY,1,_,1,52,0.5\n");
  EXPECT_EQ(per_chain_csv(atoms, area), "chain,atoms,residues,area\nA,3,2,74.5\nB,1,1,52\n");
  const std::vector<ChainArea> chains = area_per_chain(atoms, area);
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_EQ(chains[0].area + chains[1].area, 30.0 + 34.5 + 10.0 + 52.0);
}

TEST(AtomClasses, PolarApolarMainAndSideChainAsFreeSasa) {
  auto atom = [](const std::string& residue, const std::string& name, const std::string& element) {
    Atom a = residue_atom("A", residue, 1);
    a.atom_name = name;
    a.element = element;
    return a;
  };
  const std::vector<Atom> atoms{atom("ALA", "N", "N"),  atom("ALA", "CA", "C"),  atom("ALA", "CB", "C"),
                                atom("SER", "OG", "O"), atom("LYS", "OXT", "O"), atom("HEM", "FE", "FE"),
                                atom("HEM", "NA", "N"), atom("CYS", "SG", "S")};
  const std::vector<double> area{1, 2, 4, 8, 16, 32, 64, 128};
  EXPECT_TRUE(is_polar(atoms[0]));
  EXPECT_FALSE(is_polar(atoms[7]));  // by element, sulphur is apolar
  Atom classed = atoms[7];
  classed.polarity = Polarity::polar;  // a radius table's class comes first
  EXPECT_TRUE(is_polar(classed));
  classed = atoms[0];
  classed.polarity = Polarity::apolar;
  EXPECT_FALSE(is_polar(classed));
  EXPECT_TRUE(is_main_chain(atoms[4]));
  EXPECT_FALSE(is_main_chain(atoms[6]));  // not an amino acid
  const ClassAreas c = class_areas(atoms, area);
  EXPECT_EQ(c.polar, 1 + 8 + 16 + 64);
  EXPECT_EQ(c.apolar, 2 + 4 + 32 + 128);
  EXPECT_EQ(c.main_chain, 1 + 2 + 16);
  EXPECT_EQ(c.side_chain, 4 + 8 + 128);
}

}  // namespace
}  // namespace molsurf
