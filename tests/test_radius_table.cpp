// RadiusTable: the built-in sets, the text format and its error messages, the lookup order.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"

namespace molsurf {
namespace {

using Source = RadiusTable::Source;

const std::filesystem::path test_dir =
    std::filesystem::path(MOLSURF_DATA_DIR) / ".." / "tests" / "data" / "structure";

std::string parse_error(const std::string& text) {
  try {
    RadiusTable::parse(text, "table.txt");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(RadiusTable, ProtOrResidueAtoms) {
  const RadiusTable protor = RadiusTable::builtin("protor");
  EXPECT_EQ(protor.name(), "protor");
  const auto cb = protor.radius("ALA", "CB", "C");
  EXPECT_DOUBLE_EQ(cb.radius, 1.88);
  EXPECT_EQ(cb.source, Source::residue_atom);
  EXPECT_DOUBLE_EQ(protor.radius("GLY", "O", "O").radius, 1.42);   // O1H0
  EXPECT_DOUBLE_EQ(protor.radius("SER", "OG", "O").radius, 1.46);  // O2H1
  EXPECT_DOUBLE_EQ(protor.radius("PHE", "CZ", "C").radius, 1.76);  // C3H1
  EXPECT_DOUBLE_EQ(protor.radius("ASP", "CG", "C").radius, 1.61);  // C3H0
  EXPECT_DOUBLE_EQ(protor.radius("MET", "SD", "S").radius, 1.77);
  EXPECT_DOUBLE_EQ(protor.radius("LYS", "NZ", "N").radius, 1.64);
  EXPECT_DOUBLE_EQ(protor.radius("MSE", "SE", "SE").radius, 1.90);
  EXPECT_DOUBLE_EQ(protor.radius("DA", "P", "P").radius, 1.80);
  EXPECT_DOUBLE_EQ(protor.radius("U", "O2'", "O").radius, 1.46);
  EXPECT_DOUBLE_EQ(protor.radius("HOH", "O", "O").radius, 1.46);
}

TEST(RadiusTable, ProtOrFallbacks) {
  const RadiusTable protor = RadiusTable::builtin("protor");
  const auto fe = protor.radius("HEM", "FE", "FE");
  EXPECT_EQ(fe.source, Source::element);
  EXPECT_DOUBLE_EQ(fe.radius, 1.26);
  const auto heme_carbon = protor.radius("HEM", "CHA", "C");
  EXPECT_EQ(heme_carbon.source, Source::element);
  EXPECT_DOUBLE_EQ(heme_carbon.radius, 1.76);
  EXPECT_EQ(protor.radius("PO4", "P", "P").source, Source::element);
  const auto unknown = protor.radius("UNL", "Q1", "X");
  EXPECT_EQ(unknown.source, Source::fallback_default);
  EXPECT_DOUBLE_EQ(unknown.radius, 1.80);
  // The ANY backbone rows cover modified residues, but not a calcium ion named CA.
  const auto modified_ca = protor.radius("SEP", "CA", "C");
  EXPECT_EQ(modified_ca.source, Source::residue_atom);
  EXPECT_DOUBLE_EQ(modified_ca.radius, 1.88);
  const auto calcium = protor.radius("CA", "CA", "CA");
  EXPECT_EQ(calcium.source, Source::element);
  EXPECT_DOUBLE_EQ(calcium.radius, 2.31);
}

TEST(RadiusTable, BondiByElement) {
  const RadiusTable bondi = RadiusTable::builtin("bondi");
  EXPECT_DOUBLE_EQ(bondi.radius("ALA", "CB", "C").radius, 1.70);
  EXPECT_EQ(bondi.radius("ALA", "CB", "C").source, Source::element);
  EXPECT_DOUBLE_EQ(bondi.radius("ALA", "N", "N").radius, 1.55);
  EXPECT_DOUBLE_EQ(bondi.radius("ALA", "O", "O").radius, 1.52);
  EXPECT_DOUBLE_EQ(bondi.radius("CYS", "SG", "S").radius, 1.80);
  EXPECT_DOUBLE_EQ(bondi.radius("ALA", "H", "H").radius, 1.20);
  EXPECT_EQ(bondi.radius("HEM", "FE", "FE").source, Source::element);
}

TEST(RadiusTable, UnknownBuiltinNamesTheKnownOnes) {
  try {
    RadiusTable::builtin("oons");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'oons'"), std::string::npos) << message;
    EXPECT_NE(message.find("bondi, naccess, protor"), std::string::npos) << message;
  }
}

// The optional class column: polar or apolar, given to what the lookup returns.
TEST(RadiusTable, ClassColumnGivesPolarity) {
  const RadiusTable t = RadiusTable::parse(
      "atom ALA CB 1.9 apolar\natom ANY SG 1.8 Polar\nelement N 1.6\nelement S 1.8 polar\n", "t.txt");
  EXPECT_EQ(t.radius("ALA", "CB", "C").polarity, Polarity::apolar);
  EXPECT_EQ(t.radius("CYS", "SG", "S").polarity, Polarity::polar);
  EXPECT_EQ(t.radius("HEM", "NA", "N").polarity, Polarity::by_element);
  EXPECT_EQ(t.radius("MET", "SD", "S").polarity, Polarity::polar);
  EXPECT_NE(parse_error("atom ALA CB 1.9 charged\n").find("table.txt:1: class 'charged' is not polar or apolar"),
            std::string::npos)
      << parse_error("atom ALA CB 1.9 charged\n");
  EXPECT_NE(parse_error("default 1.8 polar\n").find("default"), std::string::npos);
  // The built-in protor set carries FreeSASA's classes: carbon apolar, the rest (sulphur too) polar.
  const RadiusTable protor = RadiusTable::builtin("protor");
  EXPECT_EQ(protor.radius("MET", "SD", "S").polarity, Polarity::polar);
  EXPECT_EQ(protor.radius("ALA", "CB", "C").polarity, Polarity::apolar);
  EXPECT_EQ(protor.radius("GLY", "O", "O").polarity, Polarity::polar);
}

// FreeSASA's classifier configuration read as it is: types, atoms, wildcards; what it does
// not list falls back to the protor set's element radii.
TEST(RadiusTable, FreeSasaConfiguration) {
  const RadiusTable t = RadiusTable::parse(
      "# a FreeSASA configuration\n"
      "name: test\n"
      "types:\n"
      "C_ALI 1.87 apolar\n"
      "O 1.40 polar   # oxygen\n"
      "S 1.85 apolar\n"
      "atoms:\n"
      "ANY CA C_ALI\n"
      "ANY O  O\n"
      "CYS SG S\n",
      "test.config");
  EXPECT_DOUBLE_EQ(t.radius("ALA", "CA", "C").radius, 1.87);
  EXPECT_EQ(t.radius("ALA", "CA", "C").polarity, Polarity::apolar);
  EXPECT_EQ(t.radius("ALA", "CA", "C").source, Source::residue_atom);
  EXPECT_DOUBLE_EQ(t.radius("GLY", "O", "O").radius, 1.40);
  EXPECT_EQ(t.radius("CYS", "SG", "S").polarity, Polarity::apolar);
  // Not listed: protor's element radius, classed by element.
  const auto nz = t.radius("LYS", "NZ", "N");
  EXPECT_DOUBLE_EQ(nz.radius, RadiusTable::builtin("protor").radius("HEM", "NZ", "N").radius);
  EXPECT_EQ(nz.source, Source::element);
  EXPECT_EQ(nz.polarity, Polarity::by_element);
  // Its errors name the line.
  const auto error = [](const std::string& text) {
    try {
      RadiusTable::parse(text, "c.config");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("types:\nC 1.8 apolar\natoms:\nANY CA X\n").find("c.config:4: type 'X' is not defined"),
            std::string::npos)
      << error("types:\nC 1.8 apolar\natoms:\nANY CA X\n");
  EXPECT_NE(error("types:\nC 1.8 greasy\n").find("c.config:2: class 'greasy'"), std::string::npos);
  EXPECT_NE(error("types:\nC one apolar\n").find("c.config:2: radius 'one'"), std::string::npos);
  EXPECT_NE(error("types:\nC 1.8 apolar\n").find("no atoms"), std::string::npos);
  EXPECT_NE(error("types:\nC 1.8 apolar\nC 1.7 apolar\n").find("second definition of type"), std::string::npos);
  EXPECT_NE(error("types:\nC 1.8 apolar\natoms:\nANY CA C\nANY CA C\n").find("second entry"),
            std::string::npos);
}

// NACCESS's radii are built in, as FreeSASA's --radii=naccess has them.
TEST(RadiusTable, NaccessBuiltIn) {
  EXPECT_TRUE(RadiusTable::is_builtin("naccess"));
  EXPECT_FALSE(RadiusTable::is_builtin("oons"));
  const RadiusTable naccess = RadiusTable::builtin("naccess");
  EXPECT_DOUBLE_EQ(naccess.radius("ALA", "CB", "C").radius, 1.87);  // C_ALI
  EXPECT_DOUBLE_EQ(naccess.radius("GLY", "O", "O").radius, 1.40);
  EXPECT_EQ(naccess.radius("MET", "SD", "S").polarity, Polarity::apolar);  // NACCESS's S is apolar
}

TEST(RadiusTable, FormatAndLookupOrder) {
  const RadiusTable t = RadiusTable::parse(
      "# comment line\n"
      "\n"
      "default 2.5   # trailing comment\n"
      "Element c 1.5\n"
      "atom any CA 1.1\n"
      "atom ala cb 1.2\n"
      "atom ALA CA 1.3\n",
      "mine");
  EXPECT_EQ(t.name(), "mine");
  EXPECT_DOUBLE_EQ(t.radius("ALA", "CA", "C").radius, 1.3);  // residue beats ANY
  EXPECT_DOUBLE_EQ(t.radius("GLY", "CA", "C").radius, 1.1);  // ANY
  EXPECT_DOUBLE_EQ(t.radius("ALA", "CB", "C").radius, 1.2);  // names are case-insensitive
  const auto by_element = t.radius("GLY", "C", "C");
  EXPECT_EQ(by_element.source, Source::element);
  EXPECT_DOUBLE_EQ(by_element.radius, 1.5);
  const auto by_default = t.radius("GLY", "N", "N");
  EXPECT_EQ(by_default.source, Source::fallback_default);
  EXPECT_DOUBLE_EQ(by_default.radius, 2.5);
}

TEST(RadiusTable, FromFile) {
  const RadiusTable t = RadiusTable::from_file(test_dir / "custom_radii.txt");
  EXPECT_EQ(t.name(), (test_dir / "custom_radii.txt").string());
  EXPECT_DOUBLE_EQ(t.radius("ALA", "CB", "C").radius, 1.23);
  EXPECT_DOUBLE_EQ(t.radius("XYZ", "N", "N").radius, 2.0);
}

TEST(RadiusTable, FromFileErrors) {
  try {
    RadiusTable::from_file(test_dir / "bad_radii.txt");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad_radii.txt:3: radius 'one.five' is not a number"),
              std::string::npos)
        << e.what();
  }
  try {
    RadiusTable::from_file(test_dir / "no_such_table.txt");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_table.txt: file not found"), std::string::npos) << e.what();
  }
}

TEST(RadiusTable, MalformedLinesNameTheLine) {
  EXPECT_EQ(parse_error("default 1.8\nradius C 1.7\n"),
            "table.txt:2: unknown line kind 'radius' (expected 'atom', 'element' or 'default')");
  EXPECT_EQ(parse_error("atom ALA CB\n"), "table.txt:1: 'atom' line needs 3 or 4 values (atom RESIDUE ATOM RADIUS [CLASS]), found 2");
  EXPECT_EQ(parse_error("element C 1.7 1.8\n"), "table.txt:1: class '1.8' is not polar or apolar");
  EXPECT_EQ(parse_error("\n\nelement C -1\n"), "table.txt:3: radius -1 is outside (0, 10] angstrom");
  EXPECT_EQ(parse_error("element C 1.7\nelement c 1.8\n"), "table.txt:2: second radius for element C");
  EXPECT_EQ(parse_error("atom ALA CB 1.8\natom ALA CB 1.9\n"), "table.txt:2: second radius for residue ALA atom CB");
  EXPECT_EQ(parse_error("default 1.8\ndefault 1.9\n"), "table.txt:2: second 'default' line");
  EXPECT_EQ(parse_error("# only a comment\n"),
            "table.txt: no radius entries (expected 'atom', 'element' or 'default' lines)");
}

}  // namespace
}  // namespace molsurf
