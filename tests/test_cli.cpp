// End-to-end: the molsurf command as a user runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "mesh/icosphere.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/io.hpp"
#include "molsurf/volume_mesh.hpp"

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

TEST(Cli, AnEmptyBooleanIsAnErrorThatWritesAndRemovesNothing) {
  // An empty mesh is no closed surface (`molsurf check` fails it), so there is no file; and
  // an older file at the output path must not pass for the result: exit 1, file untouched.
  TempDir dir;
  write_mesh(dir.path() / "a.ply", make_icosphere({0, 0, 0}, 1.0, {.frequency = 2}));
  write_mesh(dir.path() / "b.ply", make_icosphere({5, 0, 0}, 1.0, {.frequency = 2}));
  write_mesh(dir.path() / "inside.ply", make_icosphere({0, 0, 0}, 0.5, {.frequency = 2}));
  const std::string old_result = "an older result\n";
  for (const std::string operation : {"intersection a.ply b.ply", "difference inside.ply a.ply"}) {
    std::ofstream(dir.path() / "r.off") << old_result;
    const auto r = run_molsurf("boolean " + operation + " -o r.off", dir.path());
    EXPECT_EQ(r.exit_code, 1) << operation << r.out << r.err;
    EXPECT_NE(r.err.find("r.off: not written: the " + operation.substr(0, operation.find(' '))), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("is empty (no faces)"), std::string::npos) << r.err;
    EXPECT_EQ(testing::read_text(dir.path() / "r.off"), old_result) << operation;
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 4) << "a temporary was left";
  }
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

// ---- issue 12, item 3: a written surface is always the checked surface ----------------

// Writing and checking must agree for every format, lossy ones (.vert at 3 decimals,
// .stl in float32) included: without cleanup, 1crn at 3 decimals has degenerate and
// crossing faces, so .vert must carry more digits (or nothing may be written).
TEST(Cli, EveryWrittenFormatPassesCheck) {
  TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  for (const char* cleanup : {"--no-cleanup", ""}) {
    for (const char* extension : {"vtp", "vtk", "ply", "off", "stl", "obj", "vert", "msh"}) {
      const std::string name = std::string("s.") + extension;
      const auto r = run_molsurf(std::string("-q ") + cleanup + " -o " + name + " " + input, dir.path());
      const bool written = std::filesystem::exists(dir.path() / name);
      if (r.exit_code == 0) {
        ASSERT_TRUE(written) << name << " " << cleanup;
        const auto check = run_molsurf("check " + name, dir.path());
        EXPECT_EQ(check.exit_code, 0) << name << " " << cleanup << "\n" << check.out << check.err;
      } else {
        EXPECT_FALSE(written) << name << " " << cleanup << ": refused but written";
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
      }
      std::filesystem::remove(dir.path() / name);
      std::filesystem::remove(dir.path() / "s.face");
    }
  }
}

// A tetrahedron 1e-5 high at z = 1000: valid in doubles, flat in float32 and at 3 decimals.
Mesh thin_tetrahedron() {
  Mesh m = fixtures::tetrahedron();
  for (Vec3& v : m.vertices) v.z += 1000;
  m.vertices[3] = {0.3, 0.3, 1000.00001};
  return m;
}

TEST(Cli, BooleanChecksTheResultAsWrittenBeforeWriting) {
  TempDir dir;
  write_mesh(dir.path() / "thin.ply", thin_tetrahedron());
  write_mesh(dir.path() / "cube.ply", fixtures::box({5, 5, 5}, {6, 6, 6}));
  ASSERT_EQ(run_molsurf("check thin.ply", dir.path()).exit_code, 0);

  // STL: float32 flattens the tetrahedron, so nothing is written and the message says why.
  auto r = run_molsurf("boolean union thin.ply cube.ply -o u.stl", dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "u.stl"));
  EXPECT_NE(r.err.find("float32"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;

  // MSMS: more decimals keep it valid, and check agrees.
  r = run_molsurf("boolean union thin.ply cube.ply -o u.vert", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("full precision"), std::string::npos) << r.out;
  const auto check = run_molsurf("check u.vert", dir.path());
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

// ---- item 4: never overwrite what the user did not ask to overwrite ---------------------

TEST(Cli, ReportPathsNeverOverwriteInputsOrOtherOutputs) {
  TempDir dir;
  std::filesystem::copy_file(kData + "/pdb/1crn.pdb", dir.path() / "in.pdb");
  const std::string original = testing::read_text(dir.path() / "in.pdb");
  std::filesystem::create_directory(dir.path() / "sub");
  std::filesystem::create_hard_link(dir.path() / "in.pdb", dir.path() / "sub" / "hard.pdb");
  std::filesystem::create_symlink("target.json", dir.path() / "link.json");
  struct Case {
    std::string arguments, expected;
  };
  for (const Case& c : std::vector<Case>{
           {"--json in.pdb in.pdb", "input"},
           {"--per-atom ./sub/../in.pdb in.pdb", "input"},
           {"--per-residue sub/hard.pdb in.pdb", "input"},
           {"--json out.vtp -o out.vtp in.pdb", "output of -o"},
           {"--json a.csv --per-atom a.csv in.pdb", "output of --json"},
           {"--per-atom o.face -o o.vert in.pdb", ".face"},
           {"--json link.json in.pdb", "symbolic link"},
           {"--json /dev/null in.pdb", "device"},
           {"-o - in.pdb", "standard output"},
           {"--json - --per-atom - in.pdb", "standard output"},
           {"-o '' in.pdb", "empty file name"},
           {"--json '' in.pdb", "empty file name"},
           {"--json no_such_dir/r.json in.pdb", "does not exist"},
       }) {
    const auto r = run_molsurf(c.arguments, dir.path());
    EXPECT_EQ(r.exit_code, 1) << c.arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.arguments << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
    EXPECT_EQ(r.out.find("atoms"), std::string::npos) << c.arguments << ": refused only after work";
  }
  EXPECT_EQ(testing::read_text(dir.path() / "in.pdb"), original);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "target.json"));
  for (const char* absent : {"in.vtp", "out.vtp", "o.vert", "o.face", "a.csv", "STEM.vtp"})
    EXPECT_FALSE(std::filesystem::exists(dir.path() / absent)) << absent;
}

// Three small touching spheres: a surface in a fraction of a second.
void write_small_structure(const std::filesystem::path& file) {
  std::ofstream(file) << "0 0 0 1.6\n2 0 0 1.7\n1 1.5 0 1.5\n";
}

TEST(Cli, DashWritesAReportToStandardOutputAndTheTextReportToStandardError) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  const auto r = run_molsurf("--json - -o s.ply s.xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u) << r.out;  // nothing but the JSON
  EXPECT_NE(r.out.find("\"valid\": true"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("written: s.ply, (standard output)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "-"));
}

TEST(Cli, SaysWhatWasWrittenAndReplacesTheMsmsPairTogether) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  const auto r = run_molsurf("--per-atom atoms.csv -o pair.vert s.xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("written: pair.vert, pair.face, atoms.csv"), std::string::npos) << r.out;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

// ---- item 5: bounded resources ---------------------------------------------------------

TEST(Cli, HugeSphereCountsAreRefusedUpFrontAndTheLimitCanBeRaised) {
  TempDir dir;
  const std::string crambin = "'" + kData + "/pdb/1crn.pdb'";
  for (const char* options : {"--density 1e6", "--probe 3e4", "--max-faces 1000"}) {
    const auto r = run_molsurf(std::string(options) + " " + crambin, dir.path());
    EXPECT_EQ(r.exit_code, 1) << options << r.err;
    EXPECT_NE(r.err.find("faces"), std::string::npos) << options << r.err;
    EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto limited = run_molsurf("--max-faces 1000 " + crambin, dir.path());
  EXPECT_NE(limited.err.find("--max-faces"), std::string::npos) << limited.err;
  // A 1000 A radius (50 M faces at density 2) and one huge enough to overflow an int.
  std::ofstream(dir.path() / "big.xyzr") << "0 0 0 1000\n";
  std::ofstream(dir.path() / "huge.xyzr") << "0 0 0 1e15\n";
  for (const char* file : {"big.xyzr", "huge.xyzr"}) {
    const auto r = run_molsurf(file, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(std::string(file) + ": one sphere would have"), std::string::npos) << r.err;
  }
  auto r = run_molsurf("--max-faces 1000 --density 1 '" + kData + "/pdb/1crn.pdb'", dir.path());
  EXPECT_NE(r.err.find("faces before the union"), std::string::npos) << r.err;
  write_small_structure(dir.path() / "s.xyzr");
  r = run_molsurf("-q --max-faces 100000 -o s.off s.xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(Cli, ASurfaceTooLargeForTheMemoryLimitIsRefusedBeforeAnythingIsWritten) {
  TempDir dir;
  const std::string crambin = "'" + kData + "/pdb/1crn.pdb'";
  auto r = run_molsurf("-q --max-memory 0.001 -o c.vtp " + crambin, dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("1crn.pdb: the surface would have about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "c.vtp"));
  for (const char* bad : {"0", "-1", "nan", "1e12"}) {
    r = run_molsurf(std::string("--max-memory ") + bad + " " + crambin, dir.path());
    EXPECT_EQ(r.exit_code, 2) << bad << r.err;
  }
  r = run_molsurf("-q --max-memory 1 -o c.vtp " + crambin, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A job large against the memory limit runs with the allocator's small-footprint settings
// (src/cli/allocation.cpp); nothing in the surface may depend on them (no array is read
// before it is written, whatever memory the allocator hands out).
TEST(Cli, TheAllocatorsSettingsForLargeJobsChangeNoByte) {
  TempDir dir;
  const std::string crambin = "'" + kData + "/pdb/1crn.pdb'";
  // 1crn's spheres are estimated at about 12 MB: over 1/32 of 0.2 GB, far under 0.2 GB.
  auto r = run_molsurf("-q --max-memory 0.2 -o small.off " + crambin, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_molsurf("-q -o fast.off " + crambin, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto bytes = [&](const char* name) {
    std::ifstream in(dir.path() / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_GT(bytes("fast.off").size(), 100000u);
  EXPECT_TRUE(bytes("small.off") == bytes("fast.off"));
}

TEST(Cli, VolumeMeshIsWrittenWithTheSurfaceOrRefusedBeforeAnyWork) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  auto r = run_molsurf("--volume-mesh v.vtk -o s.vtp s.xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("must end in .msh"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.vtp"));
  r = run_molsurf("--volume-mesh s.xyzr -o s.vtp s.xyzr", dir.path());
  EXPECT_NE(r.exit_code, 0) << r.err;  // never over the input
  r = run_molsurf("--volume-mesh v.msh --box-margin 5 -o s.vtp s.xyzr", dir.path());
  if (!volume_mesh_available()) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("without gmsh"), std::string::npos) << r.err;
    return;
  }
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("volume mesh"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("solvent"), std::string::npos) << r.out;
  std::ifstream in(dir.path() / "v.msh");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"solvent\""), std::string::npos);
  EXPECT_NE(text.find("\"box\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "s.vtp"));
}

TEST(Cli, ThreadCountIsBounded) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  for (const char* threads : {"100000", "-1", "1025", "nan"}) {
    const auto r = run_molsurf(std::string("--threads ") + threads + " s.xyzr", dir.path());
    EXPECT_EQ(r.exit_code, 2) << threads << r.err;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto r = run_molsurf("--threads 1024 -o s.off s.xyzr", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("more than the"), std::string::npos) << r.err;  // a note, not a crash
}

// Issue 34: --threads 1024 is in range, but under a virtual-memory limit libgomp could not
// start the team and ended the process with its own message. The count is capped at what
// the process can start, with a note, and the run completes.
TEST(Cli, MoreThreadsThanTheProcessCanStartAreCappedWithANote) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  const auto r = run_molsurf("--threads 1024 -o s.off s.xyzr", dir.path(), "ulimit -v 4000000; ");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("molsurf: note: --threads: 1024 threads asked for, but this process can start only"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("libgomp"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "s.off"));
}

TEST(Cli, RunningOutOfMemoryIsAClearError) {
  TempDir dir;
  // 50 spheres of 560 000 faces each, within every limit, but not within 400 MB.
  {
    std::ofstream many(dir.path() / "many.xyzr");
    for (int i = 0; i < 50; ++i) many << 40 * i << " 0 0 15\n";
  }
  const auto r = run_molsurf("--threads 1 --density 100 -o many.vtp many.xyzr", dir.path(), "ulimit -v 400000; ");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "many.vtp"));
}

TEST(Cli, OutOfRangeCoordinatesAreInputErrorsWithFileAndLine) {
  TempDir dir;
  std::ofstream(dir.path() / "far.xyzr") << "0 0 0 1.5\n1e16 0 0 1.5\n";
  std::ofstream(dir.path() / "far.pqr") << "ATOM      1  CA  ALA A   1       1.0     2.0     3.0  0.00 1.80\n"
                                           "ATOM      2  CB  ALA A   1      -2e17    2.0     3.0  0.00 1.80\n";
  // PDB: x in columns 31-38; " 1.0e+16" fills them.
  std::ofstream(dir.path() / "far.pdb")
      << "ATOM      1  CA  ALA A   1       1.000   2.000   3.000  1.00  0.00           C\n"
      << "ATOM      2  CB  ALA A   1    " << " 1.0e+16" << "   2.000   3.000  1.00  0.00           C\n";
  for (const char* file : {"far.xyzr", "far.pqr", "far.pdb"}) {
    const auto r = run_molsurf(file, dir.path());
    EXPECT_EQ(r.exit_code, 1) << file;
    EXPECT_NE(r.err.find(std::string(file) + ":2:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("out of range"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("bug"), std::string::npos) << r.err;
  }
}

// ---- item 8: one line each, naming the file, the line and the problem ------------------

TEST(Cli, BadOptionValuesGetOneLineMessages) {
  TempDir dir;
  write_small_structure(dir.path() / "s.xyzr");
  for (const char* options : {"--probe nan", "--probe inf", "--density nan", "--density -inf", "--density 0",
                              "--probe 1e400", "--probe -1", "--frequency 1e400", "--max-faces 0"}) {
    const auto r = run_molsurf(std::string(options) + " s.xyzr", dir.path());
    EXPECT_EQ(r.exit_code, 2) << options;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_LT(r.err.size(), 200u) << r.err;  // no 309-digit numbers
    EXPECT_EQ(r.err.find("179769"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.vtp")) << options;
  }
}

TEST(Cli, InputProblemsGetOneLineMessages) {
  TempDir dir;
  const std::filesystem::path d = dir.path();
  // Issue 31: an atom of radius 0 (pdb2pqr's hydroxyl hydrogens) is dropped with a note, even
  // with --probe 0; only a file with nothing but such atoms is refused.
  std::ofstream(d / "one_zero.pqr") << "REMARK test\nATOM      1  CA  ALA A   1       1.0     2.0     3.0  0.00 1.80\n"
                                       "ATOM      2  CB  ALA A   1       2.0     2.0     3.0  0.00 0.00\n";
  {
    const auto r = run_molsurf("--probe 0 --hydrogens -o one_zero.vtp one_zero.pqr", d);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("1 atom of radius 0 (it adds nothing to the surface)"), std::string::npos) << r.out;
  }
  std::ofstream(d / "zero.pqr") << "REMARK test\nATOM      1  CA  ALA A   1       1.0     2.0     3.0  0.00 0.00\n"
                                   "ATOM      2  CB  ALA A   1       2.0     2.0     3.0  0.00 0.00\n";
  {
    // mmCIF whose _atom_site table has no Cartn_* columns.
    std::string cif = testing::read_text(kData + "/pdb/3pqr.cif");
    for (const char* axis : {"x ", "y ", "z "}) {
      const std::string from = std::string("_atom_site.Cartn_") + axis, to = std::string("_atom_site.Fract_") + axis;
      cif.replace(cif.find(from), from.size(), to);
    }
    std::ofstream(d / "nocartn.cif") << cif;
    const std::string gz = testing::read_text(kData + "/pdb/1crn.cif.gz");
    std::ofstream(d / "cut.cif.gz", std::ios::binary) << gz.substr(0, gz.size() / 2);
    std::ofstream(d / "radii.txt", std::ios::binary) << "default 1.8\n\x01\x02\xff\xfe\x1b[31mred 1\n";
  }
  std::filesystem::create_symlink("loop2", d / "loop1");
  std::filesystem::create_symlink("loop1", d / "loop2");
  struct Case {
    std::string arguments, expected;
  };
  const std::string crambin = "'" + kData + "/pdb/1crn.pdb'";
  for (const Case& c : std::vector<Case>{
           {"--probe 0 zero.pqr", "zero.pqr: no atoms left after filtering (2 atom records in model 1; dropped: 2 of radius 0"},
           {"nocartn.cif", "nocartn.cif: the _atom_site table has no _atom_site.Cartn_x column"},
           {"cut.cif.gz", "cut.cif.gz: truncated gzip file"},
           {"loop1", "symbolic link loop"},
           {"--radii radii.txt " + crambin, "radii.txt:2: unknown line kind '\\x01\\x02\\xff\\xfe\\x1b[31mred'"},
       }) {
    const auto r = run_molsurf(c.arguments, d);
    EXPECT_NE(r.exit_code, 0) << c.arguments;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.arguments << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
    for (unsigned char ch : r.err) EXPECT_TRUE(ch == '\n' || (ch >= 0x20 && ch < 0x7f)) << c.arguments;
  }
}

// --split-components: one file per closed surface, named after -o, in the report's order,
// each passing `molsurf check` on its own; the parts' names are checked like every output.
TEST(Cli, SplitComponentsWritesEachClosedSurfaceApart) {
  TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  const auto r = run_molsurf("--split-components -o crambin.ply " + input, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 outer, 1 cavity"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("written: crambin.outer.ply, crambin.cavity-1.ply\n"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "crambin.ply"));
  std::size_t faces = 0;
  for (const char* part : {"crambin.outer.ply", "crambin.cavity-1.ply"}) {
    const auto check = run_molsurf("check " + std::string(part), dir.path());
    EXPECT_EQ(check.exit_code, 0) << part << "\n" << check.out << check.err;
    EXPECT_NE(check.out.find("components               1\n"), std::string::npos) << part << "\n" << check.out;
    EXPECT_NE(check.out.find("outward                  yes\n"), std::string::npos) << part << "\n" << check.out;
    faces += read_mesh(dir.path() / part).face_count();
  }
  const auto whole = run_molsurf("-q -o whole.ply " + input, dir.path());
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(faces, read_mesh(dir.path() / "whole.ply").face_count());
  // MSMS parts come in pairs; a part's name that another output takes is refused, and
  // nothing is written.
  const auto msms = run_molsurf("-q --split-components -o c.vert " + input, dir.path());
  ASSERT_EQ(msms.exit_code, 0) << msms.err;
  for (const char* file : {"c.outer.vert", "c.outer.face", "c.cavity-1.vert", "c.cavity-1.face"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / file)) << file;
  std::filesystem::copy_file(dir.path() / "c.outer.vert", dir.path() / "y.outer.vert");
  const auto refused = run_molsurf("-q --split-components -o y.vert --json y.outer.vert " + input, dir.path());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("y.outer.vert"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "y.cavity-1.vert"));
}

// --ascii writes PLY and STL as text, read back as the binary files are.
TEST(Cli, AsciiPlyAndStl) {
  TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  for (const char* extension : {"ply", "stl"}) {
    const std::string binary = std::string("b.") + extension, text = std::string("t.") + extension;
    ASSERT_EQ(run_molsurf("-q -o " + binary + " " + input, dir.path()).exit_code, 0);
    ASSERT_EQ(run_molsurf("-q --ascii -o " + text + " " + input, dir.path()).exit_code, 0);
    const std::string start = testing::read_text(dir.path() / text).substr(0, 40);
    EXPECT_TRUE(start.rfind("ply\nformat ascii 1.0\n", 0) == 0 || start.rfind("solid ", 0) == 0) << start;
    EXPECT_NE(testing::read_text(dir.path() / binary).substr(0, 40), start);
    const Mesh a = read_mesh(dir.path() / binary), b = read_mesh(dir.path() / text);
    EXPECT_EQ(a.vertices, b.vertices) << extension;
    EXPECT_EQ(a.faces, b.faces) << extension;
  }
  // Options that do not apply to the output's format are refused before any work.
  for (const char* options : {"--ascii -o x.vtp", "--no-header -o x.ply"}) {
    const auto r = run_molsurf(std::string("-q ") + options + " " + input, dir.path());
    EXPECT_EQ(r.exit_code, 1) << options;
    EXPECT_NE(r.err.find(std::string(options).substr(0, std::string(options).find(' ')) + ": -o x."), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.vtp"));
  }
}

// --no-header: MSMS rows only, numbers only (no header, no atom names); the default has
// MSMS's three header lines and the closest atom's name.
TEST(Cli, MsmsHeaderAndNamesOrNeither) {
  TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  ASSERT_EQ(run_molsurf("-q -o named.vert " + input, dir.path()).exit_code, 0);
  ASSERT_EQ(run_molsurf("-q --no-header -o bare.vert " + input, dir.path()).exit_code, 0);
  const std::string named = testing::read_text(dir.path() / "named.vert");
  const std::string bare = testing::read_text(dir.path() / "bare.vert");
  EXPECT_EQ(named.rfind("# MSMS-format vertices of the solvent accessible surface for 1crn.pdb (", 0), 0u)
      << named.substr(0, 200);
  EXPECT_NE(named.find(" A_1_x_THR_"), std::string::npos);
  EXPECT_EQ(bare.find_first_not_of("0123456789.- \n"), std::string::npos);
  EXPECT_EQ(std::count(named.begin(), named.end(), '\n'), std::count(bare.begin(), bare.end(), '\n') + 3);
  EXPECT_EQ(read_mesh(dir.path() / "named.vert").vertices, read_mesh(dir.path() / "bare.vert").vertices);
  ASSERT_EQ(run_molsurf("-q --probe 0 -o vdw.vert " + input, dir.path()).exit_code, 0);
  EXPECT_EQ(testing::read_text(dir.path() / "vdw.face").rfind("# MSMS-format faces of the van der Waals surface", 0), 0u);
}

}  // namespace
}  // namespace molsurf
