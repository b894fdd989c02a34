// mpirun -np 2 molsurf (docs/scale-out.md): two processes, one block each, each writing its
// own piece and sending the first only its seam band and summary, against the same two
// blocks made by one process (the same bytes, pieces, seams, report and tables but the
// report's timings) and against the single-process surface (the facets' area within 1e-4,
// the same components). The exact report, which each block computes for its own atoms and the
// first process joins, against one process's (and against three blocks made by one process,
// through the same path): the same numbers to rounding, shells, cavities, lining atoms and
// counts, and the same per-atom, per-residue and per-chain tables. Only the first process
// reads the structure (a second given no structure at all writes the same bytes), and a
// structure it cannot read stops every process with one message. Skipped when molsurf was
// built without MPI.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

// The report without what depends on the run (times, threads, the output's name).
std::string without_run_details(const std::string& json) {
  static const std::regex details(R"re(\s*"(read|surface|cleanup|check|write|measures|seconds|total|threads|output)": [^,\n]*,?)re");
  return std::regex_replace(json, details, "");
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Exact numbers to rounding: the blocks sum them in another order, and a sphere's area may be
// integrated from another pole (its neighbour list, from a block's power diagram, may hold a
// sphere that covers nothing).
void expect_close(double blocked, double whole, const std::string& what) {
  EXPECT_NEAR(blocked, whole, 1e-10 * std::fabs(whole) + 1e-12) << what;
}

// The true spheres' report of a blocked run against one process's.
void expect_same_exact_report(const std::string& blocked_text, const std::string& whole_text) {
  const nlohmann::json blocked = nlohmann::json::parse(blocked_text), whole = nlohmann::json::parse(whole_text);
  expect_close(blocked["area"], whole["area"], "area");
  expect_close(blocked["volume"], whole["volume"], "volume");
  EXPECT_EQ(blocked["cavities"], whole["cavities"]);
  for (const char* count : {"vertices", "arcs", "buried_atoms", "degenerate_points"})
    EXPECT_EQ(blocked["arrangement"][count], whole["arrangement"][count]) << count;
  const nlohmann::json &a = blocked["shells"], &b = whole["shells"];
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t s = 0; s < b.size(); ++s) {
    const std::string shell = "shell " + std::to_string(s);
    EXPECT_EQ(a[s]["kind"], b[s]["kind"]) << shell;
    EXPECT_EQ(a[s]["atoms"], b[s]["atoms"]) << shell;
    expect_close(a[s]["area"], b[s]["area"], shell + " area");
    expect_close(a[s]["volume"], b[s]["volume"], shell + " volume");
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[s]["centroid"][k], b[s]["centroid"][k], 1e-9) << shell;
  }
  // The mesh's components: as many, outer and cavities.
  ASSERT_EQ(blocked["components"].size(), whole["components"].size());
  for (std::size_t c = 0; c < whole["components"].size(); ++c)
    EXPECT_EQ(blocked["components"][c]["kind"], whole["components"][c]["kind"]) << "component " << c;
}

// A CSV table against another, cell by cell: the same text, or numbers equal to rounding.
void expect_same_table(const std::string& blocked, const std::string& whole, const std::string& name) {
  std::istringstream a(blocked), b(whole);
  std::string line_a, line_b;
  std::size_t line = 0;
  while (std::getline(b, line_b)) {
    ++line;
    ASSERT_TRUE(std::getline(a, line_a)) << name << ": " << line - 1 << " lines only";
    if (line_a == line_b) continue;
    std::istringstream cells_a(line_a), cells_b(line_b);
    std::string x, y;
    while (std::getline(cells_b, y, ',')) {
      ASSERT_TRUE(std::getline(cells_a, x, ',')) << name << " line " << line;
      if (x == y) continue;
      char *end_x = nullptr, *end_y = nullptr;
      const double u = std::strtod(x.c_str(), &end_x), v = std::strtod(y.c_str(), &end_y);
      ASSERT_TRUE(*end_x == 0 && *end_y == 0 && !x.empty() && !y.empty())
          << name << " line " << line << ": " << x << " / " << y;
      expect_close(u, v, name + " line " + std::to_string(line));
    }
  }
  EXPECT_FALSE(std::getline(a, line_a)) << name << ": more lines than " << line;
}

class TwoProcesses : public ::testing::TestWithParam<std::string> {};

TEST_P(TwoProcesses, EqualTwoBlocksAndTheSingleProcessSurface) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir mpi, blocks, three, single;
  const std::string input = "'" + kData + "/pdb/" + GetParam() + "'";
  const std::string reports = " --json s.json --per-atom a.csv --per-residue r.csv --per-chain c.csv -q";
  const std::string outputs = " -o s.pvtp" + reports;
  const auto launched = testing::run_molsurf(input + outputs, mpi.path(),
                                             MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np 2 ");
  ASSERT_EQ(launched.exit_code, 0) << launched.err;
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 2" + outputs, blocks.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 3" + outputs, three.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " -o s.vtp" + reports, single.path()).exit_code, 0);
  for (const char* name : {"s.pvtp", "s_0.vtp", "s_1.vtp", "s_seams.vtp", "a.csv", "r.csv", "c.csv"}) {
    const std::string bytes = testing::read_text(mpi.path() / name);
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, testing::read_text(blocks.path() / name)) << name;
  }
  const std::string report = testing::read_text(mpi.path() / "s.json");
  EXPECT_EQ(without_run_details(report), without_run_details(testing::read_text(blocks.path() / "s.json")));
  const std::string whole = testing::read_text(single.path() / "s.json");
  const double area = testing::json_number(whole, "facet_area");
  EXPECT_NEAR(testing::json_number(report, "facet_area"), area, 1e-4 * area);
  EXPECT_EQ(count_of(report, "\"kind\": \"cavity\""), count_of(whole, "\"kind\": \"cavity\""));
  EXPECT_EQ(count_of(report, "\"kind\": \"outer\""), count_of(whole, "\"kind\": \"outer\""));
  for (const testing::TempDir* run : {&mpi, &three}) {
    SCOPED_TRACE(run == &mpi ? "mpirun -np 2" : "--blocks 3");
    expect_same_exact_report(testing::read_text(run->path() / "s.json"), whole);
    for (const char* name : {"a.csv", "r.csv", "c.csv"})
      expect_same_table(testing::read_text(run->path() / name), testing::read_text(single.path() / name), name);
  }
#endif
}

INSTANTIATE_TEST_SUITE_P(DataPdb, TwoProcesses, ::testing::Values("1crn.pdb", "2hhb.pdb"));

// The SES on two processes: each draws its block's piece from the block's atoms and halo,
// cleaned with its seam band frozen, and the first joins them and cleans the band. The same
// bytes as two blocks in one process (pieces, index, tables; the report but for its times),
// with no seams' piece; against one process, the patches' numbers and per-atom, per-residue
// and per-chain tables the same, the facets' area and volume within 1e-3.
TEST(TwoProcesses, TheSesIsTheTwoBlocksSes) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir mpi, blocks, single;
  const std::string input = "'" + kData + "/pdb/1crn.pdb' --surface ses";
  const std::string reports = " --json s.json --per-atom a.csv --per-residue r.csv --per-chain c.csv -q";
  const auto launched = testing::run_molsurf(input + " -o s.pvtp" + reports, mpi.path(),
                                             MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np 2 ");
  ASSERT_EQ(launched.exit_code, 0) << launched.err;
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 2 -o s.pvtp" + reports, blocks.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " -o s.vtp" + reports, single.path()).exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(mpi.path() / "s_seams.vtp"));
  for (const char* name : {"s.pvtp", "s_0.vtp", "s_1.vtp", "a.csv", "r.csv", "c.csv"}) {
    const std::string bytes = testing::read_text(mpi.path() / name);
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, testing::read_text(blocks.path() / name)) << name;
  }
  for (const char* name : {"a.csv", "r.csv", "c.csv"})
    EXPECT_EQ(testing::read_text(mpi.path() / name), testing::read_text(single.path() / name)) << name;
  const std::string report = testing::read_text(mpi.path() / "s.json");
  EXPECT_EQ(without_run_details(report), without_run_details(testing::read_text(blocks.path() / "s.json")));
  const std::string whole = testing::read_text(single.path() / "s.json");
  for (const char* key : {"area", "volume", "contact_area", "toroidal_area", "reentrant_area"})
    EXPECT_EQ(testing::json_number(report, key), testing::json_number(whole, key)) << key;
  for (const char* key : {"facet_area", "facet_volume"})
    EXPECT_NEAR(testing::json_number(report, key), testing::json_number(whole, key),
                1e-3 * testing::json_number(whole, key))
        << key;
#endif
}

// Only the first process reads the structure; the second receives its share. Launched as
// two programs (mpirun's MPMD form), the second is given a file that is no structure at all:
// had it read its file it would fail, and with its share it writes the same bytes as two
// blocks in one process.
TEST(TwoProcesses, OnlyTheFirstReadsTheStructure) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir mpi, blocks;
  {
    std::ofstream garbage(mpi.path() / "garbage.pdb");
    garbage << "this is no structure\n";
  }
  const std::string input = "'" + kData + "/pdb/2hhb.pdb'";
  const std::string outputs = " -o s.pvtp --json s.json --per-atom a.csv -q";
  const auto launched = testing::run_molsurf(
      "garbage.pdb" + outputs, mpi.path(),
      "timeout 600 " MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np 1 '" MOLSURF_CLI_PATH "' " + input +
          outputs + " : -np 1 ");
  ASSERT_EQ(launched.exit_code, 0) << launched.err;
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 2" + outputs, blocks.path()).exit_code, 0);
  for (const char* name : {"s.pvtp", "s_0.vtp", "s_1.vtp", "s_seams.vtp", "a.csv"}) {
    const std::string bytes = testing::read_text(mpi.path() / name);
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, testing::read_text(blocks.path() / name)) << name;
  }
  EXPECT_EQ(without_run_details(testing::read_text(mpi.path() / "s.json")),
            without_run_details(testing::read_text(blocks.path() / "s.json")));
#endif
}

#ifdef MOLSURF_MPIRUN
// `structure` (in `dir`) on two processes, which must both stop, none waiting, with
// `message` said once (by the first process: the other stops without a word), writing none
// of s.pvtp, its pieces and s.json; returns what they printed.
std::string stopped_on_two_processes(const testing::TempDir& dir, const std::string& structure,
                                     const std::string& message) {
  const auto launched = testing::run_molsurf(structure + " -o s.pvtp --json s.json", dir.path(),
                                             "timeout 120 " MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np 2 ");
  EXPECT_NE(launched.exit_code, 0);
  EXPECT_NE(launched.exit_code, 124) << "a process waited (timeout)";
  EXPECT_EQ(count_of(launched.err, message), 1u) << launched.err;
  for (const char* name : {"s.pvtp", "s_0.vtp", "s_1.vtp", "s.json"})
    EXPECT_FALSE(std::filesystem::exists(dir.path() / name)) << name;
  return launched.err;
}
#endif

// A structure the first process cannot read: every process stops (none waits for a share
// that will not come), the message is said once, and nothing is written.
TEST(TwoProcesses, AReadErrorReachesEveryProcess) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir dir;
  {
    std::ofstream broken(dir.path() / "broken.pdb");
    broken << "ATOM      1  N   THR A   1      17.047  14.099   3.625  1.00 13.79           N\n"
              "ATOM      2  CA  THR A   1       1e400  12.784   4.338  1.00 10.80           C\n";
  }
  const std::string err = stopped_on_two_processes(
      dir, "broken.pdb", "broken.pdb:2: ATOM record: x coordinate '1e400' (columns 31-38) is not a number");
  EXPECT_EQ(count_of(err, "molsurf: error:"), 1u) << err;
#endif
}

// More processes than atoms: the blocks default to the process count, and a block needs an
// atom, so every process stops, with the message a single process gives for --blocks 2 said
// once.
TEST(TwoProcesses, MoreProcessesThanAtomsStopEveryProcess) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir dir;
  {
    std::ofstream one(dir.path() / "one.pdb");
    one << "ATOM      1  CA  ALA A   1       0.000   0.000   0.000  1.00  0.00           C\n";
  }
  const std::string message = "2 blocks for 1 atom; at most one block per atom";
  stopped_on_two_processes(dir, "one.pdb", message);
  const auto alone = testing::run_molsurf("one.pdb --blocks 2 -o s.pvtp", dir.path());
  EXPECT_EQ(alone.exit_code, 1);
  EXPECT_EQ(count_of(alone.err, message), 1u) << alone.err;
  for (const char* name : {"s.pvtp", "s_0.vtp", "s_1.vtp"})
    EXPECT_FALSE(std::filesystem::exists(dir.path() / name)) << name;
#endif
}

}  // namespace
}  // namespace molsurf
