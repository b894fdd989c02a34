// mpirun molsurf batch (docs/batch.md): the first process hands the structures out to
// whichever process asks and alone writes the manifest and the summary. Its rows must be
// the one-process batch's (but the seconds), a rerun under MPI must skip what a partial
// manifest lists, and more processes than structures must do. Skipped when molsurf was
// built without MPI.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "rfc4180.hpp"

namespace molsurf {
namespace {

using testing::lines;
using testing::read_text;
using testing::run_molsurf;
using testing::TempDir;

const std::string kData = MOLSURF_DATA_DIR;


// The summary's rows with the seconds column (the sixth) left out.
std::vector<std::vector<std::string>> rows_but_seconds(const std::filesystem::path& csv) {
  std::vector<std::vector<std::string>> rows = testing::read_rfc4180(read_text(csv));
  for (auto& row : rows)
    if (row.size() > 5) row.erase(row.begin() + 5);
  return rows;
}

// Three structures, a broken file and 1crn twice.
void make_list(const std::filesystem::path& dir) {
  std::filesystem::copy_file(kData + "/pdb/1crn.pdb", dir / "1crn.pdb");
  std::filesystem::copy_file(kData + "/pdb/1ubq.pdb", dir / "1ubq.pdb");
  std::filesystem::copy_file(kData + "/pdb/3pqr.cif", dir / "3pqr.cif");
  std::ofstream(dir / "broken.pdb") << "ATOM  garbage\n";
  std::ofstream(dir / "list.txt") << "1crn.pdb\n1ubq.pdb\nbroken.pdb\n3pqr.cif\n1crn.pdb\n";
}

#ifdef MOLSURF_MPIRUN
const std::string kMpirun = MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np ";
#endif

TEST(BatchMpi, TwoProcessesGiveTheOneProcessRowsAndResume) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  TempDir dir;
  make_list(dir.path());
  const auto one = run_molsurf("batch list.txt -o one -q", dir.path());
  EXPECT_EQ(one.exit_code, 1) << one.err;  // the broken file
  const auto two = run_molsurf("batch list.txt -o two -j 1", dir.path(), kMpirun + "2 ");
  EXPECT_EQ(two.exit_code, 1) << two.err;
  EXPECT_NE(two.err.find("5 structures, 0 done before, 5 to run, 1 at a time on each of 2 processes"), std::string::npos)
      << two.err;
  const auto rows = rows_but_seconds(dir.path() / "two" / "summary.csv");
  ASSERT_EQ(rows.size(), 6u) << read_text(dir.path() / "two" / "summary.csv");
  EXPECT_EQ(rows, rows_but_seconds(dir.path() / "one" / "summary.csv"));
  EXPECT_EQ(rows[3][5], "failed");
  EXPECT_NE(rows[3][6].find("broken.pdb:1:"), std::string::npos) << rows[3][6];
  // Each duplicate its own report; the failure's log kept.
  for (const char* name : {"1crn.json", "1crn-2.json", "1ubq.json", "3pqr.json", "logs/broken.log"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "two" / name)) << name;
  EXPECT_EQ(lines(read_text(dir.path() / "two" / "manifest.tsv")).size(), 5u);
  EXPECT_EQ(lines(read_text(dir.path() / "two" / "summary.jsonl")).size(), 5u);

  // A manifest cut short (runs finish in any order under MPI: the lines of 1ubq and of the
  // broken file are kept, and half a line): a rerun under MPI keeps those two rows as they
  // were, their seconds too, and runs the other three.
  std::string partial;
  for (const std::string& line : lines(read_text(dir.path() / "two" / "manifest.tsv")))
    if (line.find("\t1ubq.pdb\t") != std::string::npos || line.find("\tbroken.pdb\t") != std::string::npos)
      partial += line + "\n";
  std::ofstream(dir.path() / "two" / "manifest.tsv", std::ios::trunc) << partial << "0123456789abcdef\tok\t0.1";
  const auto before = testing::read_rfc4180(read_text(dir.path() / "two" / "summary.csv"));
  const auto again = run_molsurf("batch list.txt -o two", dir.path(), kMpirun + "2 ");
  EXPECT_EQ(again.exit_code, 1) << again.err;
  EXPECT_NE(again.err.find("5 structures, 2 done before, 3 to run"), std::string::npos) << again.err;
  const auto after = testing::read_rfc4180(read_text(dir.path() / "two" / "summary.csv"));
  ASSERT_EQ(after.size(), before.size());
  EXPECT_EQ(after[2], before[2]);  // 1ubq
  EXPECT_EQ(after[3], before[3]);  // the broken file
  EXPECT_EQ(rows_but_seconds(dir.path() / "two" / "summary.csv"), rows);
#endif
}

TEST(BatchMpi, MoreProcessesThanStructures) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  TempDir dir;
  std::filesystem::copy_file(kData + "/pdb/1crn.pdb", dir.path() / "1crn.pdb");
  std::ofstream(dir.path() / "list.txt") << "1crn.pdb\n";
  const auto three = run_molsurf("batch list.txt -o out -q", dir.path(), kMpirun + "3 ");
  ASSERT_EQ(three.exit_code, 0) << three.err;
  const auto one = run_molsurf("batch list.txt -o alone -q", dir.path());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(rows_but_seconds(dir.path() / "out" / "summary.csv"), rows_but_seconds(dir.path() / "alone" / "summary.csv"));
  EXPECT_EQ(testing::read_rfc4180(read_text(dir.path() / "out" / "summary.csv")).size(), 2u);
  // A list that cannot be read stops every process with the first one's error.
  const auto missing = run_molsurf("batch missing.txt -o out2", dir.path(), kMpirun + "3 ");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("missing.txt: cannot read the list of structures"), std::string::npos) << missing.err;
#endif
}

}  // namespace
}  // namespace molsurf
