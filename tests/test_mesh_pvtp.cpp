// The .pvtp reader (src/io/mesh_pvtp.cpp): an index's .vtp pieces glued where their open
// edges' vertices are equal doubles, and no elsewhere; `molsurf check` on a blocked surface's
// index, and on one with a piece missing, a face removed or the index broken.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli_runner.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

void write_index(const std::filesystem::path& index, const std::vector<std::string>& pieces) {
  std::ofstream out(index);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PPolyData\" version=\"1.0\">\n  <PPolyData GhostLevel=\"0\">\n";
  for (const std::string& p : pieces) out << "    <Piece Source=\"" << p << "\"/>\n";
  out << "  </PPolyData>\n</VTKFile>\n";
}

Mesh faces_of(const Mesh& whole, std::initializer_list<std::size_t> faces) {
  Mesh piece;
  piece.vertices = whole.vertices;
  for (std::size_t f : faces) piece.faces.push_back(whole.faces[f]);
  return piece;
}

TEST(MeshPvtp, GluesOpenEdgesOnly) {
  testing::TempDir dir;
  // A tetrahedron in two pieces of two faces each: glued, the closed tetrahedron.
  const Mesh tetrahedron = fixtures::tetrahedron();
  write_mesh(dir.path() / "t_0.vtp", faces_of(tetrahedron, {0, 1}));
  write_mesh(dir.path() / "t_1.vtp", faces_of(tetrahedron, {2, 3}));
  write_index(dir.path() / "t.pvtp", {"t_0.vtp", "t_1.vtp"});
  const Mesh glued = read_mesh(dir.path() / "t.pvtp");
  EXPECT_EQ(glued.faces.size(), 4u);
  EXPECT_EQ(glued.vertices.size(), 4u);
  EXPECT_EQ(check_mesh(glued).verdict(), MeshCheck::Verdict::valid);
  // Two closed tetrahedra with one corner at the same point: no open edge, nothing merged,
  // and the check sees them touch.
  write_mesh(dir.path() / "c_0.vtp", tetrahedron);
  write_mesh(dir.path() / "c_1.vtp", fixtures::tetrahedron({-1, 0, 0}));
  write_index(dir.path() / "c.pvtp", {"c_0.vtp", "c_1.vtp"});
  const Mesh corners = read_mesh(dir.path() / "c.pvtp");
  EXPECT_EQ(corners.vertices.size(), 8u);
  EXPECT_NE(check_mesh(corners).verdict(), MeshCheck::Verdict::valid);
}

TEST(MeshPvtp, BrokenIndexesAreOneError) {
  testing::TempDir dir;
  write_mesh(dir.path() / "t_0.vtp", fixtures::tetrahedron());
  write_index(dir.path() / "none.pvtp", {});
  write_index(dir.path() / "missing.pvtp", {"t_0.vtp", "t_9.vtp"});
  std::ofstream(dir.path() / "cut.pvtp") << "<VTKFile type=\"PPolyData\"><PPolyData><Piece Source=\"t_0.vtp\"/>";
  std::ofstream(dir.path() / "other.pvtp") << "<VTKFile type=\"PolyData\"><PolyData/></VTKFile>";
  const std::pair<const char*, const char*> cases[] = {{"none.pvtp", "lists no <Piece>"},
                                                       {"missing.pvtp", "piece "},
                                                       {"cut.pvtp", "not closed"},
                                                       {"other.pvtp", "not a .pvtp index"}};
  for (const auto& [name, problem] : cases) {
    try {
      read_mesh(dir.path() / name);
      ADD_FAILURE() << name << " was read";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

// molsurf --blocks 3 -o s.pvtp: checked valid through the index, with the counts and area of
// its own report and --merge's area (the streamed seams are cleaned apart from the rest, so
// the two surfaces differ within 1e-4); a piece missing or a face gone is reported.
TEST(MeshPvtp, CheckOfABlockedSurface) {
  testing::TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 3 -o s.pvtp --json s.json -q", dir.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 3 --merge -o merged.vtp -q", dir.path()).exit_code, 0);
  const auto valid = testing::run_molsurf("check s.pvtp --json", dir.path());
  EXPECT_EQ(valid.exit_code, 0) << valid.out << valid.err;
  const Mesh glued = read_mesh(dir.path() / "s.pvtp");
  std::ifstream report_file(dir.path() / "s.json");
  const std::string report((std::istreambuf_iterator<char>(report_file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(static_cast<double>(glued.faces.size()), testing::json_number(report, "faces"));
  const double area = testing::json_number(valid.out, "area");
  EXPECT_NEAR(area, testing::json_number(report, "facet_area"), 1e-9 * area);
  const double merged_area = testing::json_number(testing::run_molsurf("check merged.vtp --json", dir.path()).out, "area");
  EXPECT_NEAR(area, merged_area, 1e-4 * merged_area);

  // One face of a piece removed: open edges.
  Mesh piece = read_mesh(dir.path() / "s_1.vtp");
  piece.faces.erase(piece.faces.begin() + static_cast<std::ptrdiff_t>(piece.faces.size() / 2));
  piece.face_tags.erase(piece.face_tags.begin() + static_cast<std::ptrdiff_t>(piece.face_tags.size() / 2));
  write_mesh(dir.path() / "s_1.vtp", piece);
  const auto open = testing::run_molsurf("check s.pvtp --json", dir.path());
  EXPECT_EQ(open.exit_code, 1);
  EXPECT_EQ(testing::json_number(open.out, "boundary_edges"), 3);

  // A piece deleted: one error naming it.
  std::filesystem::remove(dir.path() / "s_2.vtp");
  const auto missing = testing::run_molsurf("check s.pvtp", dir.path());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("s.pvtp:"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("piece s_2.vtp: cannot read"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.out, "");
}

}  // namespace
}  // namespace molsurf
