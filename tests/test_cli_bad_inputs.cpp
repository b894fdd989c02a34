// The bad-input table (tests/data/bad_inputs/table.json, docs/api.md) through the command
// line: every row's verdict, exit status and whole message. python/tests/test_bad_input_table.py
// runs the same rows through Python and holds it to the same messages, so the two front ends
// cannot drift apart.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace molsurf {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_molsurf;
using testing::TempDir;

const fs::path kTable = fs::path(MOLSURF_DATA_DIR) / ".." / "tests" / "data" / "bad_inputs";

std::string quoted(const std::string& argument) {
  std::string out = "'";
  for (const char c : argument) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// What the command prints for a row: "molsurf: error: WHERE: MESSAGE", a usage error (exit 2)
// followed by CLI11's pointer to --help.
std::string expected_line(const nlohmann::json& row) {
  const std::string where = row["cli_where"];
  std::string line = "molsurf: error: " + (where.empty() ? "" : where + ": ") + row["message"].get<std::string>();
  if (row["cli_exit"] == 2) line += " (run with --help for the options)";
  return line + "\n";
}

TEST(CliBadInputs, EveryRowOfTheTableGetsItsVerdictAndMessage) {
  const nlohmann::json table = nlohmann::json::parse(read_text(kTable / "table.json"));
  ASSERT_GE(table["rows"].size(), 20u);
  for (const nlohmann::json& row : table["rows"]) {
    SCOPED_TRACE(row["input"].get<std::string>());
    TempDir dir;  // a copy of the inputs: the rows' outputs go there
    fs::copy(kTable, dir.path(), fs::copy_options::recursive);
    std::string arguments;
    for (const nlohmann::json& argument : row["cli"]) arguments += quoted(argument) + " ";
    const auto r = run_molsurf(arguments, dir.path());
    if (row["verdict"] == "ok") {
      EXPECT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
      continue;
    }
    ASSERT_EQ(row["verdict"], "error");
    EXPECT_EQ(r.exit_code, row["cli_exit"].get<int>()) << r.err;
    EXPECT_EQ(r.err, expected_line(row));
    // Nothing is written for a refused input.
    EXPECT_FALSE(fs::exists(dir.path() / "o.vtp") || fs::exists(dir.path() / "o.off"));
  }
}

}  // namespace
}  // namespace molsurf
