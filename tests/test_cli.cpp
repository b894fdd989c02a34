// End-to-end: the molsurf command as a user runs it.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_runner.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/icosphere.hpp"
#include "molsurf/io.hpp"

namespace molsurf {
namespace {

using testing::run_molsurf;
using testing::TempDir;

const std::string kData = MOLSURF_DATA_DIR;

TEST(Cli, HelpExplainsEveryOptionWithItsDefault) {
  TempDir dir;
  const auto r = run_molsurf("--help", dir.path());
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--output", "--model", "--chains", "--keep-water", "--hydrogens", "--no-hetatm",
                             "--radius-set", "--radii", "--probe", "--density", "--frequency",
                             "--inscribed", "--quiet", "--version", "check"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  EXPECT_NE(r.out.find("1.4"), std::string::npos);      // probe default
  EXPECT_NE(r.out.find("protor"), std::string::npos);   // radius set default
  const auto check = run_molsurf("check --help", dir.path());
  EXPECT_EQ(check.exit_code, 0);
  EXPECT_NE(check.out.find("--json"), std::string::npos);
}

TEST(Cli, VersionIsPrinted) {
  TempDir dir;
  const auto r = run_molsurf("--version", dir.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find(MOLSURF_VERSION), std::string::npos);
}

TEST(Cli, SurfaceOfCrambinWithReports) {
  TempDir dir;
  const auto r = run_molsurf("--per-atom atoms.csv --per-residue residues.csv --json report.json '" + kData +
                                 "/pdb/1crn.pdb'",
                             dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("327 kept"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("valid: closed"), std::string::npos) << r.out;
  ASSERT_TRUE(std::filesystem::exists(dir.path() / "1crn.vtp"));  // STEM.vtp where it is run
  const auto check = run_molsurf("check 1crn.vtp", dir.path());
  EXPECT_EQ(check.exit_code, 0) << check.out;
  const std::string atoms = testing::read_text(dir.path() / "atoms.csv");
  EXPECT_EQ(std::count(atoms.begin(), atoms.end(), '\n'), 1 + 327);
  const std::string residues = testing::read_text(dir.path() / "residues.csv");
  EXPECT_EQ(std::count(residues.begin(), residues.end(), '\n'), 1 + 46);
  const std::string json = testing::read_text(dir.path() / "report.json");
  EXPECT_NE(json.find("\"valid\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"cavity\""), std::string::npos) << json;
}

TEST(Cli, ThreadCountDoesNotChangeTheOutput) {
  TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  EXPECT_EQ(run_molsurf("-q --threads 1 -o one.ply " + input, dir.path()).exit_code, 0);
  EXPECT_EQ(run_molsurf("-q --threads 2 -o two.ply " + input, dir.path()).exit_code, 0);
  const std::string one = testing::read_text(dir.path() / "one.ply"), two = testing::read_text(dir.path() / "two.ply");
  EXPECT_GT(one.size(), 1000u);
  EXPECT_TRUE(one == two);
}

TEST(Cli, OuterOnlyAndMsmsOutput) {
  TempDir dir;
  const auto r = run_molsurf("--outer-only -o crambin.vert '" + kData + "/pdb/1crn.pdb'", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 outer, 0 cavities"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "crambin.vert"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "crambin.face"));
}

TEST(Cli, SelectionOptionsReachTheReader) {
  TempDir dir;
  const auto r = run_molsurf("--chains A --no-hetatm --density 0.5 -o a.off '" + kData + "/pdb/2hhb.pdb'", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("other chains"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1069 kept"), std::string::npos) << r.out;
}

TEST(Cli, MissingStructureIsAClearError) {
  TempDir dir;
  const auto r = run_molsurf("no_such_file.pdb", dir.path());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("no_such_file.pdb"), std::string::npos) << r.err;
}

TEST(Cli, UnknownOutputFormatIsRejectedBeforeAnyWork) {
  TempDir dir;
  const auto r = run_molsurf("-o out.xyz '" + kData + "/pdb/1crn.pdb'", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("out.xyz"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.xyz"));
}

TEST(Cli, MalformedStructureNamesFileAndLine) {
  TempDir dir;
  {
    std::ofstream bad(dir.path() / "bad.xyzr");
    bad << "1 2 3 1.5\n4 5 six 1.5\n";
  }
  const auto r = run_molsurf("bad.xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.xyzr:2"), std::string::npos) << r.err;
}

TEST(Cli, CheckSaysValidForEveryFormatWrittenFromAnIcosphere) {
  TempDir dir;
  const Mesh sphere = make_icosphere({1, 2, 3}, 2.5, {.frequency = 4, .tag = 0});
  for (const char* name : {"s.vtp", "s.vtk", "s.ply", "s.off", "s.stl", "s.obj"}) {
    write_mesh(dir.path() / name, sphere);
    const auto r = run_molsurf(std::string("check ") + name, dir.path());
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("VALID"), std::string::npos) << name;
    EXPECT_NE(r.out.find("320"), std::string::npos) << name;  // faces
  }
}

TEST(Cli, CheckNamesTheDefectOfABrokenMesh) {
  TempDir dir;
  Mesh holed = make_icosphere({}, 1, {.frequency = 2});
  holed.faces.pop_back();
  write_mesh(dir.path() / "holed.off", holed);
  auto r = run_molsurf("check holed.off", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("INVALID"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("boundary"), std::string::npos) << r.out;

  Mesh crossing = fixtures::unit_cube();
  crossing.append(fixtures::box({0.3, 0.4, 0.45}, {1.3, 1.4, 1.45}));
  write_mesh(dir.path() / "crossing.ply", crossing);
  r = run_molsurf("check --json crossing.ply", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("\"valid\": false"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\"intersecting_pairs\": 0,"), std::string::npos) << r.out;
}

TEST(Cli, CheckOfAnUnreadableFileIsAnError) {
  TempDir dir;
  {
    std::ofstream bad(dir.path() / "bad.off");
    bad << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
  }
  const auto r = run_molsurf("check bad.off", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.off"), std::string::npos) << r.err;
}

TEST(Cli, BooleanOfTwoMeshFiles) {
  TempDir dir;
  write_mesh(dir.path() / "a.ply", make_icosphere({0, 0, 0}, 1.0, {.frequency = 4}));
  write_mesh(dir.path() / "b.off", make_icosphere({0.7, 0.2, 0.1}, 0.9, {.frequency = 4}));
  auto r = run_molsurf("boolean union a.ply b.off -o u.vtp", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("VALID"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("intersect"), std::string::npos) << r.out;
  const auto check = run_molsurf("check u.vtp", dir.path());
  EXPECT_EQ(check.exit_code, 0) << check.out;
}

TEST(Cli, BooleanOfDisjointSolidsIsAnEmptyIntersection) {
  TempDir dir;
  write_mesh(dir.path() / "a.ply", make_icosphere({0, 0, 0}, 1.0, {.frequency = 2}));
  write_mesh(dir.path() / "b.ply", make_icosphere({5, 0, 0}, 1.0, {.frequency = 2}));
  const auto r = run_molsurf("boolean intersection a.ply b.ply -o i.off", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("zero faces"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "i.off"));
}

TEST(Cli, BooleanRefusesAnInvalidOperand) {
  TempDir dir;
  Mesh holed = make_icosphere({}, 1, {.frequency = 2});
  holed.faces.pop_back();
  write_mesh(dir.path() / "holed.off", holed);
  write_mesh(dir.path() / "b.off", make_icosphere({0.5, 0, 0}, 1.0, {.frequency = 2}));
  const auto r = run_molsurf("boolean union holed.off b.off -o u.off", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("holed.off"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("boundary"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "u.off"));
}

}  // namespace
}  // namespace molsurf
