// Every output is written or the run fails: a report that cannot reach standard output or
// its file, a mesh that cannot be written, a name too long for its temporary, a signal
// in the middle of a write. And every report parses, whatever the names in it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "rfc4180.hpp"

namespace molsurf {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_molsurf;
using testing::TempDir;

// Three touching spheres: a surface in a fraction of a second.
void write_small_structure(const fs::path& file) { std::ofstream(file) << "0 0 0 1.6\n2 0 0 1.7\n1 1.5 0 1.5\n"; }

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(CliOutputs, AReportThatCannotReachStandardOutputFailsTheRunAndWritesNothing) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  for (const std::string option : {"--json", "--per-atom", "--per-residue", "--per-chain"}) {
    for (const std::string redirection : {"> /dev/full", ">&-"}) {
      for (const std::string mode : {"--areas-only", "-o s.ply"}) {
        // A file written alongside must not be replaced either.
        std::ofstream(dir.path() / "old.csv") << "old\n";
        const std::string other = option == "--per-atom" ? "--per-chain old.csv" : "--per-atom old.csv";
        const auto r = run_molsurf(mode + " " + option + " - " + other + " s.xyzr", dir.path(), "", redirection);
        const std::string what = option + " - " + redirection + " " + mode;
        EXPECT_EQ(r.exit_code, 1) << what << r.err;
        EXPECT_NE(r.err.find("molsurf: error: standard output: cannot write: "), std::string::npos) << what << r.err;
        EXPECT_NE(r.err.find(redirection == ">&-" ? "it is closed" : "No space left on device"), std::string::npos)
            << what << r.err;
        EXPECT_EQ(read_text(dir.path() / "old.csv"), "old\n") << what;
        EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"old.csv", "s.xyzr"})) << what;
      }
    }
  }
}

TEST(CliOutputs, TheTextReportIsAnOutputToo) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  write_small_structure(dir.path() / "t.xyzr");
  for (const std::string redirection : {"> /dev/full", ">&-"}) {
    auto r = run_molsurf("--areas-only s.xyzr", dir.path(), "", redirection);
    EXPECT_EQ(r.exit_code, 1) << redirection << r.err;
    EXPECT_NE(r.err.find("standard output: cannot write"), std::string::npos) << r.err;
    r = run_molsurf("-o s.off s.xyzr", dir.path(), "", redirection);
    EXPECT_EQ(r.exit_code, 1) << redirection << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "s.off")) << "the surface was written although its report was lost";
    ASSERT_EQ(run_molsurf("-q -o s.off s.xyzr", dir.path()).exit_code, 0);
    r = run_molsurf("check s.off", dir.path(), "", redirection);
    EXPECT_EQ(r.exit_code, 1) << "check's verdict was lost: " << r.err;
    EXPECT_NE(r.err.find("standard output: cannot write"), std::string::npos) << r.err;
    fs::remove(dir.path() / "s.off");
  }
  // -q prints nothing, so nothing is lost.
  EXPECT_EQ(run_molsurf("-q --areas-only s.xyzr", dir.path(), "", "> /dev/full").exit_code, 0);
  EXPECT_EQ(run_molsurf("-q --areas-only s.xyzr", dir.path(), "", ">&-").exit_code, 0);
}

// A write the file system refuses (here the file size limit, EFBIG) fails the run in every
// mesh format, leaves the old file and no temporary.
TEST(CliOutputs, AMeshThatCannotBeWrittenIsAnErrorInEveryFormat) {
  TempDir dir;
  for (const std::string extension : {"vtp", "vtk", "ply", "off", "stl", "obj", "vert", "msh"}) {
    std::ofstream(dir.path() / ("old." + extension)) << "old\n";
    const auto r = run_molsurf("-q -o old." + extension + " " + MOLSURF_DATA_DIR "/pdb/1crn.pdb", dir.path(),
                               "trap '' XFSZ; ulimit -f 8; ");
    EXPECT_EQ(r.exit_code, 1) << extension << r.err;
    EXPECT_NE(r.err.find("cannot write: File too large"), std::string::npos) << extension << r.err;
    EXPECT_EQ(read_text(dir.path() / ("old." + extension)), "old\n") << extension;
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"old." + extension}) << extension;
    fs::remove(dir.path() / ("old." + extension));
  }
  std::ofstream(dir.path() / "r.json") << "old\n";
  const auto r = run_molsurf("-q --areas-only --per-atom r.json " MOLSURF_DATA_DIR "/pdb/1crn.pdb", dir.path(),
                             "trap '' XFSZ; ulimit -f 8; ");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(read_text(dir.path() / "r.json"), "old\n");
}

// The file size limit's signal (SIGXFSZ, not ignored) ends the run; its temporary goes too.
TEST(CliOutputs, ASignalInTheMiddleOfAWriteLeavesNoTemporary) {
  TempDir dir;
  const auto r = run_molsurf("-q -o big.obj " MOLSURF_DATA_DIR "/pdb/1crn.pdb", dir.path(), "ulimit -f 8; ");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(entries(dir.path()).empty()) << entries(dir.path()).front();
}

TEST(CliOutputs, LongOutputNamesAreWrittenAndTooLongOnesRefusedBeforeAnyWork) {
  TempDir dir;
  // 251 bytes: legal (NAME_MAX is 255), though ".NAME.tmp-PID-N" would not be.
  const std::string stem(247, 's');
  write_small_structure(dir.path() / (stem + ".xyzr"));
  auto r = run_molsurf("-q " + stem + ".xyzr", dir.path());  // the default output: STEM.vtp
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / (stem + ".vtp")));
  r = run_molsurf("-q -o " + stem + ".off --json " + stem + ".json " + stem + ".xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / (stem + ".off")));
  EXPECT_TRUE(fs::exists(dir.path() / (stem + ".json")));
  EXPECT_EQ(entries(dir.path()).size(), 4u) << "a temporary was left";

  // 256 bytes: no file system takes it; refused before the structure is read.
  const std::string too_long(252, 't');
  r = run_molsurf("-o " + too_long + ".vtp " + stem + ".xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot write: File name too long"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "work was done first: " << r.out;
}

TEST(CliOutputs, JsonNamesThatAreNotUtf8StillParse) {
  TempDir dir;
  const std::string name = "crn\xFF\xFE\x01\x1b[31m.xyzr";
  write_small_structure(dir.path() / name);
  // The name reaches the command through a file: no shell quoting of the raw bytes.
  std::ofstream(dir.path() / "run.sh") << "exec '" MOLSURF_CLI_PATH "' -q --areas-only --json r.json \"$(cat name)\"\n";
  std::ofstream(dir.path() / "name", std::ios::binary) << name;
  ASSERT_EQ(std::system(("cd '" + dir.path().string() + "' && sh run.sh").c_str()), 0);
  const nlohmann::json report = nlohmann::json::parse(read_text(dir.path() / "r.json"));
  EXPECT_EQ(report["input"]["file"].get<std::string>(), "crn\xEF\xBF\xBD\xEF\xBF\xBD\x01\x1b[31m.xyzr");
  EXPECT_GT(report["area"].get<double>(), 0);
}

TEST(CliOutputs, CsvTablesOfMmcifNamesWithCommasQuotesAndLineBreaksReadBack) {
  TempDir dir;
  std::ofstream(dir.path() / "odd.cif") << "data_odd\nloop_\n_atom_site.group_PDB\n_atom_site.type_symbol\n"
                                           "_atom_site.label_atom_id\n_atom_site.label_comp_id\n"
                                           "_atom_site.auth_asym_id\n_atom_site.auth_seq_id\n"
                                           "_atom_site.Cartn_x\n_atom_site.Cartn_y\n_atom_site.Cartn_z\n"
                                           "ATOM C 'C,A' 'R\"S' 'A,B' 1 0 0 0\n"
                                           "ATOM C\n;N\nX\n;\n'R\"S' 'A,B' 1 1.5 0 0\n"
                                           "ATOM C CB GLY '\"' 2 3 0 0\n";
  for (const std::string table : {"--per-atom", "--per-residue", "--per-chain"}) {
    const auto r = run_molsurf("-q --areas-only " + table + " - odd.cif", dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = testing::read_rfc4180(r.out);
    ASSERT_GE(rows.size(), 3u) << r.out;
    for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size()) << table << "\n" << r.out;
    const auto column = [&](const std::string& name) {
      return static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
    };
    EXPECT_EQ(rows[1][column("chain")], "A,B") << table;
    if (table == "--per-atom") {
      ASSERT_EQ(rows.size(), 4u);
      EXPECT_EQ(rows[1][column("atom_name")], "C,A");
      EXPECT_EQ(rows[2][column("atom_name")], "N\nX");
      EXPECT_EQ(rows[1][column("residue_name")], "R\"S");
      EXPECT_EQ(rows[3][column("chain")], "\"");
    }
  }
}

}  // namespace
}  // namespace molsurf
