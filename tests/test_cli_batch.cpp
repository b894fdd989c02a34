// molsurf batch: every structure of a folder or list, failures recorded, reruns resumed.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace molsurf {
namespace {

using testing::json_number;
using testing::lines;
using testing::read_text;
using testing::run_molsurf;
using testing::TempDir;

const std::string kData = MOLSURF_DATA_DIR;


// A folder with two structures, one in a subfolder, a broken one, and a file that is no
// structure; the same name twice.
std::filesystem::path make_inputs(const std::filesystem::path& dir) {
  const auto in = dir / "in";
  std::filesystem::create_directories(in / "sub");
  std::filesystem::copy_file(kData + "/pdb/1crn.pdb", in / "1crn.pdb");
  std::filesystem::copy_file(kData + "/pdb/1ubq.pdb", in / "sub" / "1ubq.pdb");
  std::filesystem::copy_file(kData + "/pdb/1crn.pdb", in / "sub" / "1crn.pdb");
  std::ofstream(in / "broken.pdb") << "ATOM  garbage\n";
  std::ofstream(in / "notes.txt") << "not a structure\n";
  return in;
}

TEST(CliBatch, RunsEveryStructureRecordsFailuresAndResumes) {
  TempDir dir;
  make_inputs(dir.path());
  const auto r = run_molsurf("batch in -o out -j 2", dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;  // one failed
  const std::vector<std::string> csv = lines(read_text(dir.path() / "out" / "summary.csv"));
  ASSERT_EQ(csv.size(), 5u) << read_text(dir.path() / "out" / "summary.csv");
  EXPECT_EQ(csv[0], "file,atoms,area,volume,cavities,seconds,status,message");
  // Name order, subfolders included; the text file left out.
  EXPECT_EQ(csv[1].rfind("in/1crn.pdb,327,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[2].rfind("in/broken.pdb,,,,,", 0), 0u) << csv[2];
  EXPECT_NE(csv[2].find(",failed,in/broken.pdb:1:"), std::string::npos) << csv[2];
  EXPECT_EQ(csv[3].rfind("in/sub/1crn.pdb,327,", 0), 0u) << csv[3];
  EXPECT_EQ(csv[4].rfind("in/sub/1ubq.pdb,", 0), 0u) << csv[4];
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "logs" / "broken.log"));
  // The same name twice: 1crn and 1crn-2, each with the numbers of a run on its own.
  const auto alone = run_molsurf("-q --areas-only --json alone.json '" + kData + "/pdb/1crn.pdb'", dir.path());
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const double area = json_number(read_text(dir.path() / "alone.json"), "area");
  for (const char* name : {"1crn.json", "1crn-2.json"})
    EXPECT_EQ(json_number(read_text(dir.path() / "out" / name), "area"), area) << name;
  const std::string jsonl = read_text(dir.path() / "out" / "summary.jsonl");
  EXPECT_EQ(std::count(jsonl.begin(), jsonl.end(), '\n'), 4);
  EXPECT_NE(jsonl.find("\"status\": \"failed\""), std::string::npos);

  // A rerun skips everything; a changed file is run again; --retry-failed reruns the failure.
  const auto again = run_molsurf("batch in -o out", dir.path());
  EXPECT_NE(again.err.find("4 done before, 0 to run"), std::string::npos) << again.err;
  std::filesystem::copy_file(kData + "/pdb/1ubq.pdb", dir.path() / "in" / "1crn.pdb",
                             std::filesystem::copy_options::overwrite_existing);
  const auto changed = run_molsurf("batch in -o out", dir.path());
  EXPECT_NE(changed.err.find("3 done before, 1 to run"), std::string::npos) << changed.err;
  EXPECT_EQ(lines(read_text(dir.path() / "out" / "summary.csv"))[1].rfind("in/1crn.pdb,602,", 0), 0u);
  const auto retry = run_molsurf("batch in -o out --retry-failed", dir.path());
  EXPECT_NE(retry.err.find("3 done before, 1 to run"), std::string::npos) << retry.err;
  // Other options make other results: everything runs again.
  const auto probe = run_molsurf("batch in -o out -- --probe 1.2", dir.path());
  EXPECT_NE(probe.err.find("0 done before, 4 to run"), std::string::npos) << probe.err;
}

TEST(CliBatch, ListsMeshesAndTimeouts) {
  TempDir dir;
  make_inputs(dir.path());
  std::ofstream(dir.path() / "list.txt") << "# two structures\nin/1crn.pdb\n\n  in/sub/1ubq.pdb  # ubiquitin\n";
  const auto r = run_molsurf("batch list.txt -o out --mesh off -q", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* mesh : {"out/1crn.off", "out/1ubq.off"}) {
    const auto check = run_molsurf(std::string("check ") + mesh, dir.path());
    EXPECT_EQ(check.exit_code, 0) << mesh;
  }
  EXPECT_EQ(lines(read_text(dir.path() / "out" / "summary.csv")).size(), 3u);
  // A line that names no structure file: refused before any work.
  std::ofstream(dir.path() / "bad_list.txt") << "in/1crn.pdb\nin/notes.txt\n";
  const auto bad = run_molsurf("batch bad_list.txt -o out_bad", dir.path());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("bad_list.txt:2:"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out_bad" / "summary.csv"));
  // A job past its time is stopped and counted failed; the others finish.
  const auto slow = run_molsurf("batch list.txt -o out_slow --timeout 0.001 -q", dir.path());
  EXPECT_EQ(slow.exit_code, 1);
  EXPECT_NE(read_text(dir.path() / "out_slow" / "summary.csv").find("stopped after the --timeout"), std::string::npos);
}

// The batch lists its output folder once and removes, as each job starts, the temporaries
// of that job's files that dead processes left; its jobs list no folder (a sweep's folder of
// 200 000 reports takes 40 ms to list, per job). Other files' temporaries stay.
TEST(CliBatch, RemovesTheStaleTemporariesOfItsJobsOnly) {
  TempDir dir;
  make_inputs(dir.path());
  const pid_t dead = ::fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  const std::string gone = std::to_string(dead);
  std::filesystem::create_directories(dir.path() / "out");
  std::ofstream(dir.path() / "list.txt") << "in/1crn.pdb\n";
  const std::vector<std::string> stale{".1crn.json.tmp-" + gone + "-0", ".1crn.vert.tmp-" + gone + "-0",
                                       ".1crn.face.tmp-" + gone + "-3"};
  const std::vector<std::string> kept{".1ubq.json.tmp-" + gone + "-0", ".summary.txt.tmp-" + gone + "-0"};
  for (const std::string& name : stale) std::ofstream(dir.path() / "out" / name) << "stale";
  for (const std::string& name : kept) std::ofstream(dir.path() / "out" / name) << "kept";
  const auto r = run_molsurf("batch list.txt -o out --mesh vert -q", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& name : stale) EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / name)) << name;
  for (const std::string& name : kept) EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / name)) << name;
  for (const char* name : {"1crn.json", "1crn.vert", "1crn.face"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / name)) << name;
}

// The help says how to run a sweep over MPI.
TEST(CliBatch, HelpNamesMpirun) {
  TempDir dir;
  const auto help = run_molsurf("batch --help", dir.path());
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("mpirun -np N molsurf batch"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace molsurf
