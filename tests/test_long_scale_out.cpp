// Long (label `long`): the blocks on assemblies too large for the unit suite. The capsid
// (1f2n, 271 860 atoms) on `mpirun -np 2` against `--blocks 2` in one process, and the
// synthetic assembly of bench/make_assembly.py (8 copies of the capsid, 2.2 M atoms) with
// --blocks: each written surface valid by `molsurf check`, read back through its .pvtp. The
// SES of 3pqr in 3 blocks against one process.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_runner.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;
const std::string kCapsid = kData + "/pdb/1f2n_assembly1.cif.gz";

TEST(LongScaleOut, CapsidOnTwoProcesses) {
#ifndef MOLSURF_MPIRUN
  GTEST_SKIP() << "molsurf built without MPI";
#else
  testing::TempDir mpi, blocks;
  const std::string outputs = " -o c.pvtp --json c.json -q";
  const auto launched = testing::run_molsurf("'" + kCapsid + "'" + outputs, mpi.path(),
                                             MOLSURF_MPIRUN " --oversubscribe --allow-run-as-root -np 2 ");
  ASSERT_EQ(launched.exit_code, 0) << launched.err;
  ASSERT_EQ(testing::run_molsurf("'" + kCapsid + "' --blocks 2" + outputs, blocks.path()).exit_code, 0);
  for (const char* name : {"c.pvtp", "c_0.vtp", "c_1.vtp"})
    EXPECT_EQ(testing::read_text(mpi.path() / name), testing::read_text(blocks.path() / name)) << name;
  const auto check = testing::run_molsurf("check c.pvtp", mpi.path());
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
#endif
}

// The SES in 3 blocks on a membrane protein with lipids and retinal (3pqr, 2 858 atoms):
// the pieces valid by `molsurf check` through their index, the patches' area and volume the
// single process's, the facets' within 2e-3 (each within the cleanup's budgets of the same
// SES before cleanup), the same components.
TEST(LongScaleOut, SesOf3pqrInBlocks) {
  testing::TempDir dir;
  const std::string input = "'" + kData + "/pdb/3pqr.cif' --surface ses";
  ASSERT_EQ(testing::run_molsurf(input + " -o one.vtp --json one.json -q", dir.path()).exit_code, 0);
  const auto blocked = testing::run_molsurf(input + " --blocks 3 -o s.pvtp --json s.json -q", dir.path());
  ASSERT_EQ(blocked.exit_code, 0) << blocked.err;
  const auto check = testing::run_molsurf("check s.pvtp", dir.path());
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  const std::string one = testing::read_text(dir.path() / "one.json"), s = testing::read_text(dir.path() / "s.json");
  for (const char* key : {"area", "volume", "contact_area", "toroidal_area", "reentrant_area"})
    EXPECT_EQ(testing::json_number(s, key), testing::json_number(one, key)) << key;
  for (const char* key : {"facet_area", "facet_volume"})
    EXPECT_NEAR(testing::json_number(s, key), testing::json_number(one, key), 2e-3 * testing::json_number(one, key))
        << key;
  EXPECT_EQ(s.find("did not join"), std::string::npos);
}

TEST(LongScaleOut, SyntheticAssemblyInBlocks) {
  testing::TempDir dir;
  const std::string script = kData + "/../bench/make_assembly.py";
  const std::string make = "cd '" + dir.path().string() + "' && /usr/bin/python3 '" + script + "' '" + kCapsid +
                           "' --copies 8 -o assembly.cif.gz";
  ASSERT_EQ(std::system(make.c_str()), 0);
  const auto run = testing::run_molsurf("assembly.cif.gz --blocks 8 -o a.pvtp --json a.json -q", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string report = testing::read_text(dir.path() / "a.json");
  EXPECT_EQ(testing::json_number(report, "atoms"), 8 * 271860.0);
  // Copies apart: the exact area is eight times one capsid's, to rounding.
  const auto one = testing::run_molsurf("'" + kCapsid + "' --areas-only --json one.json -q", dir.path());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const double area = testing::json_number(testing::read_text(dir.path() / "one.json"), "area");
  EXPECT_NEAR(testing::json_number(report, "area"), 8 * area, 1e-9 * 8 * area);
  const auto check = testing::run_molsurf("check a.pvtp", dir.path());
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

}  // namespace
}  // namespace molsurf
