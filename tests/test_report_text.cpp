// Reports always parse: JSON strings hold any bytes (invalid UTF-8, control characters)
// and CSV fields any text (commas, quotes, line breaks), read back by real parsers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/csv_field.hpp"
#include "io/json_writer.hpp"
#include "molsurf/surface_report.hpp"
#include "rfc4180.hpp"

namespace molsurf {
namespace {

std::string through_json(const std::string& bytes) {
  io::JsonWriter j;
  j.begin_object().field(bytes, bytes).end_object();
  const nlohmann::json parsed = nlohmann::json::parse(j.str());  // throws on invalid JSON
  EXPECT_EQ(parsed.size(), 1u);
  EXPECT_EQ(parsed.begin().key(), parsed.begin().value().get<std::string>());
  return parsed.begin().value().get<std::string>();
}

TEST(ReportText, JsonKeepsValidUtf8AndEveryControlCharacter) {
  std::string all_ascii;
  for (int c = 1; c < 128; ++c) all_ascii += static_cast<char>(c);
  for (const std::string& text : {std::string("plain"), std::string("caf\xC3\xA9 \xF0\x9F\x98\x80 \xE2\x82\xAC"),
                                  std::string("a\"b\\c/d"), std::string("\x01\x1f\x7f\b\f\n\r\t"), all_ascii,
                                  std::string("nul\0inside", 10), std::string("\xF4\x8F\xBF\xBF")})
    EXPECT_EQ(through_json(text), text);
}

TEST(ReportText, JsonReplacesEachInvalidUtf8SubpartWithOneReplacementCharacter) {
  const std::string r = "\xEF\xBF\xBD";  // U+FFFD
  const std::pair<std::string, std::string> cases[] = {
      {"a\xFF" "b", "a" + r + "b"},
      {"\xC3", r},                                    // a lead byte at the end
      {"\xC3(", r + "("},                             // a lead byte without its continuation
      {"\xC0\xAF", r + r},                            // overlong: never a lead byte
      {"\xED\xA0\x80", r + r + r},                    // a surrogate
      {"\xF0\x9F\x98x", r + "x"},                     // a 4-byte sequence cut short: one subpart
      {"\xF4\x90\x80\x80", r + r + r + r},            // beyond U+10FFFF
      {"\x80\xBF", r + r},                            // continuation bytes alone
      {"1crn\xFF\xFE.pdb", "1crn" + r + r + ".pdb"}};
  for (const auto& [bytes, expected] : cases) EXPECT_EQ(through_json(bytes), expected) << bytes;
}

Atom named(std::string chain, std::string residue, std::string atom, std::int64_t number) {
  Atom a;
  a.chain = std::move(chain);
  a.residue_name = std::move(residue);
  a.atom_name = std::move(atom);
  a.element = "C";
  a.residue_number = number;
  a.radius = 1.7;
  return a;
}

TEST(ReportText, CsvTablesReadBackFieldForFieldWhateverTheNames) {
  // mmCIF allows all of these in a name (a quoted or semicolon-delimited value).
  const std::vector<Atom> atoms{named("A,B", "AL\"A", "C,A", 1), named("A,B", "AL\"A", "N\nX", 1),
                                named("\"", "GLY", "O\r\nP", 2), named("C", "X Y", "  ", 3)};
  const std::vector<double> area{1.5, 2.25, 3.0, 0.5};
  const auto atom_rows = testing::read_rfc4180(per_atom_csv(atoms, area));
  ASSERT_EQ(atom_rows.size(), atoms.size() + 1);
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const std::vector<std::string>& row = atom_rows[i + 1];
    ASSERT_EQ(row.size(), atom_rows[0].size()) << i;
    EXPECT_EQ(row[2], atoms[i].chain);
    EXPECT_EQ(row[3], atoms[i].residue_name);
    EXPECT_EQ(row[4], std::to_string(atoms[i].residue_number));
    EXPECT_EQ(row[6], atoms[i].atom_name);
    EXPECT_EQ(std::stod(row[9]), area[i]);
  }
  const auto residue_rows = testing::read_rfc4180(per_residue_csv(atoms, area, MaxAreaScale::theoretical));
  ASSERT_EQ(residue_rows.size(), 4u);  // header and three residues
  EXPECT_EQ(residue_rows[1][0], "A,B");
  EXPECT_EQ(residue_rows[1][1], "AL\"A");
  EXPECT_EQ(std::stod(residue_rows[1][5]), 3.75);
  EXPECT_EQ(residue_rows[2][0], "\"");
  for (const auto& row : residue_rows) EXPECT_EQ(row.size(), residue_rows[0].size());
  const auto chain_rows = testing::read_rfc4180(per_chain_csv(atoms, area));
  ASSERT_EQ(chain_rows.size(), 4u);
  EXPECT_EQ(chain_rows[1][0], "A,B");
  EXPECT_EQ(chain_rows[2][0], "\"");

  // --all-models' leading column must not split a quoted line break into two rows.
  const std::string table = per_atom_csv(atoms, area);
  const auto with_model = testing::read_rfc4180(csv_with_model_column(table, 7, true) +
                                                csv_with_model_column(table, 8, false));
  ASSERT_EQ(with_model.size(), 2 * atoms.size() + 1);
  EXPECT_EQ(with_model[0][0], "model");
  for (std::size_t i = 1; i < with_model.size(); ++i) {
    ASSERT_EQ(with_model[i].size(), atom_rows[0].size() + 1) << i;
    EXPECT_EQ(with_model[i][0], i <= atoms.size() ? "7" : "8");
    EXPECT_EQ(with_model[i][7], atoms[(i - 1) % atoms.size()].atom_name);
  }
}

TEST(ReportText, ResidueNumbersKeepTheirFullRange) {
  const std::int64_t big = 3'000'000'000LL, small = -5'000'000'000LL;
  const std::vector<Atom> atoms{named("A", "ALA", "CA", big), named("A", "ALA", "CB", small)};
  const std::vector<double> area{1, 2};
  const auto rows = testing::read_rfc4180(per_residue_csv(atoms, area));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][2], "3000000000");
  EXPECT_EQ(rows[2][2], "-5000000000");
  EXPECT_EQ(testing::read_rfc4180(per_atom_csv(atoms, area))[1][4], "3000000000");
}

TEST(ReportText, CsvFieldQuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(io::csv_field("CA"), "CA");
  EXPECT_EQ(io::csv_field(""), "");
  EXPECT_EQ(io::csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(io::csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(io::csv_field("a\nb"), "\"a\nb\"");
  EXPECT_EQ(io::csv_field("a\rb"), "\"a\rb\"");
}

}  // namespace
}  // namespace molsurf
