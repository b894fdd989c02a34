// What a run writes: each lossy format's mesh as read back (mesh_as_written), the check
// of a surface as its file will hold it (check_as_written), and the outputs of a run
// checked up front and replaced together (check_output_paths, OutputFiles).
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/icosphere.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/output_files.hpp"
#include "molsurf/written_check.hpp"

namespace fs = std::filesystem;

namespace molsurf {
namespace {

class OutputFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "molsurf_outputs_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  template <class Action>
  static std::string error_of(Action action) {
    try {
      action();
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  }
  fs::path dir_;
};

// Coordinates that no format with fewer digits than a double keeps: 3 decimals and
// float32 both move them, and two corners 1e-9 apart (not a valid surface, but the
// formats do not care) become one vertex in float32.
Mesh awkward_mesh() {
  Mesh m = make_icosphere({12.3456789012345, -0.000123456789, 1e-7}, 1.23456789, {.frequency = 3, .tag = 4});
  m.vertices[5] = m.vertices[6] + Vec3{1e-9, 0, 0};
  return m;
}

void expect_same(const Mesh& read, const Mesh& predicted, const std::string& what) {
  ASSERT_EQ(read.vertex_count(), predicted.vertex_count()) << what;
  ASSERT_EQ(read.face_count(), predicted.face_count()) << what;
  for (std::size_t v = 0; v < read.vertex_count(); ++v) {
    EXPECT_EQ(read.vertices[v].x, predicted.vertices[v].x) << what << " vertex " << v;
    EXPECT_EQ(read.vertices[v].y, predicted.vertices[v].y) << what << " vertex " << v;
    EXPECT_EQ(read.vertices[v].z, predicted.vertices[v].z) << what << " vertex " << v;
  }
  for (std::size_t f = 0; f < read.face_count(); ++f) EXPECT_EQ(read.faces[f], predicted.faces[f]) << what;
}

// mesh_as_written is what the check of a lossy format relies on: it must be exactly
// what the reader gives back, for every format and variant.
TEST_F(OutputFilesTest, MeshAsWrittenIsExactlyWhatTheReaderGetsBack) {
  const Mesh mesh = awkward_mesh();
  struct Case {
    std::string name;
    MeshWriteOptions options;
  };
  MeshWriteOptions ascii, exact_msms, six_decimals;
  ascii.ascii = true;
  exact_msms.msms_decimals = kMsmsExact;
  six_decimals.msms_decimals = 6;
  for (const Case& c : std::vector<Case>{{"a.stl", {}},
                                         {"b.stl", ascii},
                                         {"c.vert", {}},
                                         {"d.vert", exact_msms},
                                         {"e.vert", six_decimals},
                                         {"f.vtp", {}},
                                         {"g.vtk", {}},
                                         {"h.ply", {}},
                                         {"i.off", {}},
                                         {"j.obj", {}},
                                         {"k.msh", {}}}) {
    write_mesh(dir_ / c.name, mesh, c.options);
    const MeshFormat format = mesh_format_from_path(c.name);
    expect_same(read_mesh(dir_ / c.name), mesh_as_written(mesh, format, c.options), c.name);
  }
  EXPECT_FALSE(mesh_format_is_exact(MeshFormat::stl));
  EXPECT_FALSE(mesh_format_is_exact(MeshFormat::msms));
  EXPECT_TRUE(mesh_format_is_exact(MeshFormat::msms, exact_msms));
  EXPECT_TRUE(mesh_format_is_exact(MeshFormat::ply));
  // The STL rounding merged the two corners 1e-9 apart.
  EXPECT_EQ(mesh_as_written(mesh, MeshFormat::stl).vertex_count(), mesh.vertex_count() - 1);
}

// A tetrahedron 1e-5 high at z = 1000: valid in doubles, flat in float32 and at 3 decimals.
Mesh thin_tetrahedron() {
  Mesh m = fixtures::tetrahedron();
  for (Vec3& v : m.vertices) v.z += 1000;
  m.vertices[3] = {0.3, 0.3, 1000.00001};
  return m;
}

bool is_valid(const MeshCheck& c) { return c.valid(); }

TEST_F(OutputFilesTest, LossyFormatsAreCheckedAsWritten) {
  const Mesh mesh = thin_tetrahedron();
  const MeshCheck check = check_mesh(mesh);
  ASSERT_TRUE(check.valid());
  ASSERT_FALSE(check_mesh(mesh_as_written(mesh, MeshFormat::stl)).valid());
  ASSERT_FALSE(check_mesh(mesh_as_written(mesh, MeshFormat::msms)).valid());

  // STL: refused, naming the file, the reason and the way out.
  const std::string refused = error_of([&] { check_as_written(dir_ / "t.stl", mesh, check, {}, {}, is_valid); });
  EXPECT_NE(refused.find("t.stl: not written: STL stores coordinates as float32"), std::string::npos) << refused;
  EXPECT_NE(refused.find(".ply"), std::string::npos) << refused;

  // MSMS: exact coordinates instead, which then read back as the checked surface.
  const WrittenCheck vert = check_as_written(dir_ / "t.vert", mesh, check, {}, {}, is_valid);
  EXPECT_EQ(vert.options.msms_decimals, kMsmsExact);
  EXPECT_NE(vert.note.find("full precision"), std::string::npos) << vert.note;
  EXPECT_TRUE(vert.check.valid());
  write_mesh(dir_ / "t.vert", mesh, vert.options);
  EXPECT_TRUE(check_mesh(read_mesh(dir_ / "t.vert")).valid());

  // A surface that rounding does not break keeps MSMS's 3 decimals, and the check is
  // of the rounded surface.
  const Mesh sphere = make_icosphere({1, 2, 3}, 2, {.frequency = 4});
  const WrittenCheck plain = check_as_written(dir_ / "s.vert", sphere, check_mesh(sphere), {}, {}, is_valid);
  EXPECT_EQ(plain.options.msms_decimals, 3);
  EXPECT_TRUE(plain.note.empty());
  ASSERT_TRUE(plain.rounded.has_value());
  EXPECT_EQ(plain.rounded->vertices[0].x, std::round(sphere.vertices[0].x * 1000) / 1000);

  // Exact formats: nothing to redo.
  const WrittenCheck ply = check_as_written(dir_ / "t.ply", mesh, check, {}, {}, is_valid);
  EXPECT_FALSE(ply.rounded.has_value());
  EXPECT_TRUE(ply.note.empty());
}

TEST_F(OutputFilesTest, MsmsExactCoordinatesKeepTheColumnsWhereTheyFit) {
  Mesh m = fixtures::tetrahedron();
  m.vertices[1].x = 0.1;
  MeshWriteOptions options;
  options.msms_decimals = kMsmsExact;
  options.msms_header = false;
  write_mesh(dir_ / "t.vert", m, options);
  const std::string vert = slurp(dir_ / "t.vert");
  EXPECT_EQ(vert.substr(0, 30), "        0         0         0 ") << vert;
  EXPECT_NE(vert.find("      0.1         0         0 "), std::string::npos) << vert;
}

TEST_F(OutputFilesTest, OutputPathsAreCheckedBeforeAnyWork) {
  std::ofstream(dir_ / "in.pdb") << "input";
  const auto refusal = [&](std::vector<OutputRequest> outputs) {
    const std::vector<fs::path> inputs{dir_ / "in.pdb"};
    return error_of([&] { check_output_paths(inputs, outputs); });
  };
  EXPECT_EQ(refusal({{dir_ / "out.vtp", "-o", true}, {dir_ / "r.json", "--json"}, {"-", "--per-atom"}}), "");
  EXPECT_NE(refusal({{dir_ / "sub" / ".." / "in.pdb", "--json"}}).find("is an input file"), std::string::npos);
  EXPECT_NE(refusal({{dir_ / "o.vert", "-o", true}, {dir_ / "o.face", "--json"}}).find(".face"), std::string::npos);
  EXPECT_NE(refusal({{dir_ / "o.face", "-o", true}, {dir_ / "o.vert", "--json"}}).find(".vert"), std::string::npos);
  EXPECT_NE(refusal({{"", "-o", true}}).find("-o '': an empty file name"), std::string::npos);
  EXPECT_NE(refusal({{"-", "-o", true}}).find("standard output"), std::string::npos);
  EXPECT_NE(refusal({{"-", "--json"}, {"-", "--per-atom"}}).find("--json and --per-atom"), std::string::npos);
  fs::create_symlink("elsewhere.json", dir_ / "link.json");
  EXPECT_NE(refusal({{dir_ / "link.json", "--json"}}).find("symbolic link"), std::string::npos);
  EXPECT_NE(refusal({{"/dev/null", "--json"}}).find("device"), std::string::npos);
  EXPECT_NE(refusal({{dir_, "--json"}}).find("directory"), std::string::npos);
  EXPECT_NE(refusal({{dir_ / "missing" / "r.json", "--json"}}).find("does not exist"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "elsewhere.json"));
}

TEST_F(OutputFilesTest, OutputsAreReplacedTogether) {
  std::ofstream(dir_ / "old.csv") << "old";
  {
    // A failure before commit leaves every old file and no temporary.
    OutputFiles files;
    files.add_mesh(dir_ / "m.vert", make_icosphere({}, 1, {.frequency = 2}), {});
    files.add_text(dir_ / "old.csv", "new");
  }
  EXPECT_EQ(slurp(dir_ / "old.csv"), "old");
  EXPECT_FALSE(fs::exists(dir_ / "m.vert"));
  EXPECT_FALSE(fs::exists(dir_ / "m.face"));

  OutputFiles files;
  files.add_mesh(dir_ / "m.vert", make_icosphere({}, 1, {.frequency = 2}), {});
  files.add_text(dir_ / "old.csv", "new");
  const std::vector<fs::path> written = files.commit();
  EXPECT_EQ(written, (std::vector<fs::path>{dir_ / "m.vert", dir_ / "m.face", dir_ / "old.csv"}));
  EXPECT_EQ(slurp(dir_ / "old.csv"), "new");
  std::size_t entries = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    ++entries;
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(entries, 3u);
}

// A mesh checked only when it is added (a part that --split-components writes) is checked
// as the file will hold it: a valid one is written, one that the format's rounding
// breaks, or an inside-out one, is refused by name and nothing of the run is written.
TEST_F(OutputFilesTest, CheckedMeshIsRefusedUnlessValidAsWritten) {
  const Mesh sphere = make_icosphere({1, 2, 3}, 1.5, {.frequency = 3, .tag = 0});
  {
    OutputFiles files;
    files.add_checked_mesh(dir_ / "good.vert", sphere, {}, {});
    files.add_text(dir_ / "report.txt", "report");
    EXPECT_EQ(files.commit().size(), 3u);
  }
  Mesh inside_out = sphere;
  for (Triangle& t : inside_out.faces) std::swap(t[1], t[2]);
  const Mesh rounded_away = thin_tetrahedron();  // valid with doubles, flat at 3 decimals
  ASSERT_TRUE(check_mesh(rounded_away).valid());
  for (const auto& [name, mesh] : {std::pair{"turned.ply", inside_out}, std::pair{"rounded.vert", rounded_away}}) {
    OutputFiles files;
    files.add_text(dir_ / "other.txt", "other");
    const std::string message = error_of([&] { files.add_checked_mesh(dir_ / name, mesh, {}, {}); });
    EXPECT_EQ(message.rfind((dir_ / name).string() + ": not written: the surface as this file holds it is not valid (",
                            0),
              0u)
        << name << ": " << message;
  }
  EXPECT_FALSE(fs::exists(dir_ / "other.txt"));
  EXPECT_FALSE(fs::exists(dir_ / "turned.ply"));
  EXPECT_FALSE(fs::exists(dir_ / "rounded.vert"));
}

}  // namespace
}  // namespace molsurf
