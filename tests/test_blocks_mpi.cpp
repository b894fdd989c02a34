// mpirun -np 2 molsurf (docs/scale-out.md): two processes, one block each, each writing its
// own piece and sending the first only its seam band and summary, against the same two
// blocks made by one process (the same bytes, pieces, seams and report but its timings) and
// against the single-process surface (the facets' area within 1e-4, the same components,
// the exact areas equal). Skipped when molsurf was built without MPI.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

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

class TwoProcesses : public ::testing::TestWithParam<std::string> {};

TEST_P(TwoProcesses, EqualTwoBlocksAndTheSingleProcessSurface) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir mpi, blocks, single;
  const std::string input = "'" + kData + "/pdb/" + GetParam() + "'";
  const std::string outputs = " -o s.pvtp --json s.json -q";
  const auto launched = testing::run_molsurf(input + outputs, mpi.path(),
                                             MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np 2 ");
  ASSERT_EQ(launched.exit_code, 0) << launched.err;
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 2" + outputs, blocks.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " -o s.vtp --json s.json -q", single.path()).exit_code, 0);
  for (const char* name : {"s.pvtp", "s_0.vtp", "s_1.vtp", "s_seams.vtp"}) {
    const std::string bytes = testing::read_text(mpi.path() / name);
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, testing::read_text(blocks.path() / name)) << name;
  }
  const std::string report = testing::read_text(mpi.path() / "s.json");
  EXPECT_EQ(without_run_details(report), without_run_details(testing::read_text(blocks.path() / "s.json")));
  const std::string whole = testing::read_text(single.path() / "s.json");
  const double area = testing::json_number(whole, "facet_area");
  EXPECT_NEAR(testing::json_number(report, "facet_area"), area, 1e-4 * area);
  EXPECT_EQ(testing::json_number(report, "area"), testing::json_number(whole, "area"));  // exact, from the spheres
  EXPECT_EQ(count_of(report, "\"kind\": \"cavity\""), count_of(whole, "\"kind\": \"cavity\""));
  EXPECT_EQ(count_of(report, "\"kind\": \"outer\""), count_of(whole, "\"kind\": \"outer\""));
#endif
}

INSTANTIATE_TEST_SUITE_P(DataPdb, TwoProcesses, ::testing::Values("1crn.pdb", "2hhb.pdb"));

}  // namespace
}  // namespace molsurf
