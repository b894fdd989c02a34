// Mesh files: every writer round-trips through its reader, legacy VTK files carry the
// atom data, hand-made files in other tools' dialects read correctly, and malformed input
// gives an error naming the file (and line). VTK's own reader checks our VTK files in
// test_mesh_vtp.cpp and test_mesh_vtk_writer.cpp.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <tuple>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/icosphere.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "mesh_io_samples.hpp"
#include "scratch_directory.hpp"

namespace fs = std::filesystem;
using namespace molsurf;

namespace {

const fs::path kHandMade = fs::path(MOLSURF_DATA_DIR) / ".." / "tests" / "data" / "mesh";

// Coordinates chosen so that any rounding on the way shows: thirds, tiny and huge values.
Mesh tetrahedron() {
  Mesh mesh;
  mesh.vertices = {{0.1, 1.0 / 3.0, -2.0 / 7.0}, {1.0e-17 + 1.0, 0.2, 0.3}, {0.3, 1.7, 1e-300}, {0.5, 0.6, 2.0 / 3.0}};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  mesh.face_tags = {0, 1, 2, 1};
  return mesh;
}

using molsurf::testing::tagged_sphere;
using molsurf::testing::three_atoms;

class MeshIoTest : public ::testing::Test {
 protected:
  static void put(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }
  static std::string slurp(const fs::path& file) { return molsurf::testing::file_bytes(file); }
  // The message of the molsurf::Error that `action` throws ("" when it throws none).
  template <class Action>
  static std::string error_of(Action action) {
    try {
      action();
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  }

  molsurf::testing::ScratchDirectory scratch_{"molsurf_mesh_io"};
  const fs::path dir_ = scratch_.path();
};

// ---- round trips --------------------------------------------------------------------

struct RoundTrip {
  std::string name;      // test name and file name
  bool ascii = false;
  bool msms_header = true;
  double tolerance = 0;  // 0: exact; otherwise max coordinate error
  bool same_vertex_order = true;
  bool stores_tags = false;
};

void PrintTo(const RoundTrip& c, std::ostream* os) { *os << c.name; }

class RoundTripTest : public MeshIoTest, public ::testing::WithParamInterface<RoundTrip> {};

void expect_same_mesh(const Mesh& written, const Mesh& read, const RoundTrip& c) {
  ASSERT_EQ(read.vertex_count(), written.vertex_count());
  ASSERT_EQ(read.face_count(), written.face_count());
  const float_t unused = 0;
  (void)unused;
  for (std::size_t f = 0; f < written.face_count(); ++f) {
    if (c.same_vertex_order) ASSERT_EQ(read.faces[f], written.faces[f]) << "face " << f;
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3& a = written.vertices[written.faces[f][k]];
      const Vec3& b = read.vertices[read.faces[f][k]];
      if (c.tolerance == 0) {
        ASSERT_EQ(a, b) << "face " << f << " corner " << k;
      } else {
        ASSERT_NEAR(a.x, b.x, c.tolerance) << "face " << f;
        ASSERT_NEAR(a.y, b.y, c.tolerance) << "face " << f;
        ASSERT_NEAR(a.z, b.z, c.tolerance) << "face " << f;
      }
    }
  }
  if (c.stores_tags) {
    EXPECT_EQ(read.face_tags, written.face_tags);
  }
}

TEST_P(RoundTripTest, TetrahedronAndSphere) {
  const RoundTrip& c = GetParam();
  MeshWriteOptions options;
  options.ascii = c.ascii;
  options.msms_header = c.msms_header;
  for (const Mesh& mesh : {tetrahedron(), tagged_sphere()}) {
    const fs::path file = dir_ / c.name;
    write_mesh(file, mesh, options);
    const Mesh read = read_mesh(file);
    expect_same_mesh(mesh, read, c);
    if (c.tolerance == 0) {
      EXPECT_EQ(surface_area(read), surface_area(mesh));
    }
  }
}

// STL stores float32: the expected coordinates are the floats nearest the doubles.
constexpr double kFloatTolerance = 1e-6;  // coordinates here are below 4, float ulp ~ 5e-7
constexpr double kMsmsTolerance = 0.0005;

INSTANTIATE_TEST_SUITE_P(
    Formats, RoundTripTest,
    ::testing::Values(RoundTrip{"mesh.vtp", false, true, 0, true, true}, RoundTrip{"mesh.vtk", false, true, 0, true, true},
                      RoundTrip{"binary.ply", false, true, 0, true, true}, RoundTrip{"ascii.ply", true, true, 0, true, true},
                      RoundTrip{"mesh.off", false, true, 0, true, false}, RoundTrip{"mesh.obj", false, true, 0, true, false},
                      RoundTrip{"mesh.msh", false, true, 0, true, true},
                      RoundTrip{"binary.stl", false, true, kFloatTolerance, false, false},
                      RoundTrip{"ascii.stl", true, true, kFloatTolerance, false, false},
                      RoundTrip{"with_header.vert", false, true, kMsmsTolerance, true, false},
                      RoundTrip{"without_header.face", false, false, kMsmsTolerance, true, false}),
    [](const ::testing::TestParamInfo<RoundTrip>& info) {
      std::string name = info.param.name;
      for (char& ch : name)
        if (ch == '.') ch = '_';
      return name;
    });

TEST_F(MeshIoTest, StlVariantsReadBackTheSameFloats) {
  const Mesh mesh = tagged_sphere();
  write_mesh(dir_ / "b.stl", mesh);
  write_mesh(dir_ / "a.stl", mesh, {.ascii = true});
  EXPECT_EQ(slurp(dir_ / "a.stl").rfind("solid", 0), 0u);
  EXPECT_NE(slurp(dir_ / "b.stl").rfind("solid", 0), 0u);  // a binary header must not look ASCII
  const Mesh binary = read_mesh(dir_ / "b.stl");
  const Mesh ascii = read_mesh(dir_ / "a.stl");
  EXPECT_EQ(binary.vertices, ascii.vertices);
  EXPECT_EQ(binary.faces, ascii.faces);
  // Shared vertices are recovered: the icosphere's 10 n^2 + 2.
  EXPECT_EQ(binary.vertex_count(), 162u);
  EXPECT_EQ(static_cast<float>(binary.vertices[binary.faces[5][1]].y),
            static_cast<float>(mesh.vertices[mesh.faces[5][1]].y));
  EXPECT_EQ(binary.vertices[binary.faces[5][1]].y, static_cast<double>(static_cast<float>(mesh.vertices[mesh.faces[5][1]].y)));
}

TEST_F(MeshIoTest, PlyVariantsAreWhatTheyClaim) {
  const Mesh mesh = tetrahedron();
  write_mesh(dir_ / "b.ply", mesh);
  write_mesh(dir_ / "a.ply", mesh, {.ascii = true});
  EXPECT_NE(slurp(dir_ / "b.ply").find("format binary_little_endian 1.0\n"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "a.ply").find("format ascii 1.0\n"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "a.ply").find("property int tag\n"), std::string::npos);
}

TEST_F(MeshIoTest, UntaggedMeshStaysUntaggedWhereTagsAreOptional) {
  Mesh mesh = tetrahedron();
  mesh.face_tags.clear();
  for (const char* name : {"u.ply", "u.vtp", "u.vtk"}) {
    write_mesh(dir_ / name, mesh);
    EXPECT_FALSE(read_mesh(dir_ / name).has_tags()) << name;
  }
}

// Legacy binary field arrays: "NAME 1 COUNT int\n" then COUNT big-endian int32.
std::vector<std::int32_t> legacy_int_array(const std::string& bytes, const std::string& name, std::size_t count) {
  const std::string header = "\n" + name + " 1 " + std::to_string(count) + " int\n";
  const std::size_t at = bytes.find(header);
  if (at == std::string::npos || at + header.size() + 4 * count > bytes.size()) return {};
  std::vector<std::int32_t> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint32_t bits = 0;
    for (std::size_t b = 0; b < 4; ++b)
      bits = (bits << 8) | static_cast<unsigned char>(bytes[at + header.size() + 4 * i + b]);
    values[i] = static_cast<std::int32_t>(bits);
  }
  return values;
}

TEST_F(MeshIoTest, LegacyVtkCarriesAtomDataPerFace) {
  const Mesh mesh = tagged_sphere();
  const std::vector<Atom> atoms = three_atoms();
  write_mesh(dir_ / "atoms.vtk", mesh, {.atoms = atoms});
  const std::string bytes = slurp(dir_ / "atoms.vtk");
  EXPECT_NE(bytes.find("\nBINARY\n"), std::string::npos);
  const std::size_t faces = mesh.face_count();
  std::vector<std::int32_t> serials, residue_numbers;
  for (std::int32_t tag : mesh.face_tags) {
    serials.push_back(atoms[static_cast<std::size_t>(tag)].serial);
    residue_numbers.push_back(atoms[static_cast<std::size_t>(tag)].residue_number);
  }
  EXPECT_EQ(legacy_int_array(bytes, "tag", faces), mesh.face_tags);
  EXPECT_EQ(legacy_int_array(bytes, "atom_serial", faces), serials);
  EXPECT_EQ(legacy_int_array(bytes, "residue_number", faces), residue_numbers);
  EXPECT_NE(bytes.find("\nresidue_name 1 " + std::to_string(faces) + " string\n"), std::string::npos);
  EXPECT_NE(bytes.find("\nchain 1 " + std::to_string(faces) + " string\n"), std::string::npos);
  EXPECT_NE(bytes.find("\nNORMALS Normals float\n"), std::string::npos);
  EXPECT_EQ(read_mesh(dir_ / "atoms.vtk").face_tags, mesh.face_tags);
}

TEST_F(MeshIoTest, TagThatIsNoAtomIsRefused) {
  Mesh mesh = tetrahedron();
  mesh.face_tags[2] = 7;
  const std::vector<Atom> atoms = three_atoms();
  const std::string message = error_of([&] { write_mesh(dir_ / "x.vtp", mesh, {.atoms = atoms}); });
  EXPECT_NE(message.find("face 2 has tag 7"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_empty(dir_));
}

// ---- MSMS --------------------------------------------------------------------------

TEST_F(MeshIoTest, MsmsPairHasMsmsLayout) {
  const Mesh mesh = tagged_sphere();
  std::vector<Atom> atoms = three_atoms();
  atoms[1].atom_name = "CA";
  atoms[2].insertion_code = 'B';
  MeshWriteOptions options{.atoms = atoms, .probe_radius = 1.5, .density = 3.0};
  options.surface_description = "test surface\nfor x";
  write_mesh(dir_ / "surf.vert", mesh, options);
  ASSERT_TRUE(fs::exists(dir_ / "surf.face"));
  std::istringstream vert(slurp(dir_ / "surf.vert"));
  std::string comment, legend, counts, first;
  std::getline(vert, comment);
  std::getline(vert, legend);
  std::getline(vert, counts);
  std::getline(vert, first);
  // The first line names the surface (on one line, whatever the description holds).
  EXPECT_EQ(comment.rfind("# MSMS-format vertices of the test surface for x (molsurf ", 0), 0u) << comment;
  EXPECT_EQ(legend, "#vertex #sphere density probe_r");
  EXPECT_EQ(counts, "    162       3  3.00  1.50");
  // x y z nx ny nz in %9.3f, then face number, closest sphere, type, then the atom name.
  std::istringstream fields(first);
  double x, y, z, nx, ny, nz;
  int face_number, sphere, type;
  std::string name, rest;
  ASSERT_TRUE(fields >> x >> y >> z >> nx >> ny >> nz >> face_number >> sphere >> type >> name);
  EXPECT_FALSE(fields >> rest);
  EXPECT_EQ(first.substr(0, 6 * 10 + 8 + 8 + 3 - 1).find_first_not_of(" 0123456789.-"), std::string::npos) << first;
  EXPECT_EQ(first[6 * 10 + 8 + 8 + 3 - 1], ' ');
  EXPECT_NEAR(x, mesh.vertices[0].x, kMsmsTolerance);
  EXPECT_NEAR(std::hypot(nx, ny, nz), 1.0, 0.003);
  EXPECT_EQ(type, 3);  // MSMS's contact face: every face lies on an atom's sphere
  // The closest atom (|p - c| - r) among the atoms of the faces around vertex 0.
  double best = 1e300;
  int expected_sphere = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto& t = mesh.faces[f];
    if (t[0] != 0 && t[1] != 0 && t[2] != 0) continue;
    const Atom& atom = atoms[static_cast<std::size_t>(mesh.face_tags[f])];
    const double d = norm(mesh.vertices[0] - atom.centre) - atom.radius;
    if (d < best) best = d, expected_sphere = mesh.face_tags[f] + 1;
  }
  EXPECT_EQ(sphere, expected_sphere);
  // MaSIF's naming: CHAIN_RESNUM_INSERTION_RESNAME_ATOM, insertion "x" when blank.
  const char* expected_names[] = {"A_7_x_ALA_", "B_14_x_GLY_CA", "AB_21_B_HEM_"};
  EXPECT_EQ(name, expected_names[expected_sphere - 1]);

  std::istringstream face(slurp(dir_ / "surf.face"));
  std::getline(face, comment);
  std::getline(face, legend);
  std::getline(face, counts);
  std::getline(face, first);
  EXPECT_EQ(comment.rfind("# MSMS-format faces of the test surface for x (molsurf ", 0), 0u) << comment;
  EXPECT_EQ(legend, "#faces  #sphere density probe_r");
  EXPECT_EQ(counts, "    320       3  3.00  1.50");
  std::istringstream face_fields(first);
  Index a, b, c;
  int analytic;
  ASSERT_TRUE(face_fields >> a >> b >> c >> type >> analytic);
  EXPECT_EQ((Triangle{a - 1, b - 1, c - 1}), mesh.faces[0]);
  EXPECT_EQ(type, 3);
  EXPECT_EQ(analytic, mesh.face_tags[0] + 1);
}

// The .vert rows as whitespace-separated fields, after `header_lines` lines.
std::vector<std::vector<std::string>> msms_rows(const std::string& text, int header_lines) {
  std::istringstream in(text);
  std::string line;
  for (int i = 0; i < header_lines; ++i) std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    rows.emplace_back(std::istream_iterator<std::string>(fields), std::istream_iterator<std::string>());
  }
  return rows;
}

// MSMS's analytical face number of a vertex: its patch (tag + 1) inside one atom's patch,
// minus the seam's number on a seam between two (seams numbered from 1 in order of their
// first vertex), 0 where three or more meet.
TEST_F(MeshIoTest, MsmsVertexFaceNumberFollowsPatchesAndSeams) {
  Mesh mesh = make_icosphere({0, 0, 0}, 2.0, IcosphereOptions{.frequency = 6, .tag = 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {  // three patches: x < 0, x >= 0 split by y
    Vec3 c{};
    for (Index v : mesh.faces[f]) c += mesh.vertices[v] / 3.0;
    mesh.face_tags[f] = c.x < 0 ? 4 : (c.y < 0 ? 1 : 2);
  }
  write_mesh(dir_ / "p.vert", mesh, {.msms_header = false});
  const auto rows = msms_rows(slurp(dir_ / "p.vert"), 0);
  ASSERT_EQ(rows.size(), mesh.vertex_count());
  std::vector<std::set<std::int32_t>> around(mesh.vertex_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (Index v : mesh.faces[f]) around[v].insert(mesh.face_tags[f]);
  std::map<std::pair<std::int32_t, std::int32_t>, long long> seams;
  std::size_t inside = 0, on_seams = 0, corners = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const long long written = std::stoll(rows[v].at(6));
    const std::vector<std::int32_t> tags(around[v].begin(), around[v].end());
    if (tags.size() == 1) {
      EXPECT_EQ(written, tags[0] + 1) << "vertex " << v;
      ++inside;
    } else if (tags.size() == 2) {
      const auto [it, added] = seams.try_emplace({tags[0], tags[1]}, static_cast<long long>(seams.size()) + 1);
      EXPECT_EQ(written, -it->second) << "vertex " << v;
      ++on_seams;
    } else {
      EXPECT_EQ(written, 0) << "vertex " << v;
      ++corners;
    }
  }
  EXPECT_GT(inside, 0u);
  EXPECT_EQ(seams.size(), 3u);
  EXPECT_GT(on_seams, 0u);
  EXPECT_GT(corners, 0u);
}

// Inside an atom's patch the normal is the atom sphere's (the exact normal of the
// surface there, not the polyhedron's); on a seam, the area-weighted mean of the faces
// around. A surface turned inside out (a cavity written on its own) keeps its normals
// on the side its faces point to.
TEST_F(MeshIoTest, MsmsNormalsAreTheSpheresInsidePatches) {
  std::vector<Atom> atoms = three_atoms();
  atoms[0].centre = {0, 0, 0};
  atoms[1].centre = {0.4, -0.3, 0.2};  // off the mesh's centre: its normals differ from the mesh's
  Mesh mesh = make_icosphere({0, 0, 0}, 2.0, IcosphereOptions{.frequency = 5, .tag = 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    Vec3 c{};
    for (Index v : mesh.faces[f]) c += mesh.vertices[v] / 3.0;
    mesh.face_tags[f] = c.z < 0.3 ? 0 : 1;
  }
  for (const bool turned : {false, true}) {
    Mesh written_mesh = mesh;
    if (turned)
      for (Triangle& t : written_mesh.faces) std::swap(t[1], t[2]);
    write_mesh(dir_ / "n.vert", written_mesh, {.atoms = atoms, .msms_header = false, .msms_atom_names = false});
    const auto rows = msms_rows(slurp(dir_ / "n.vert"), 0);
    ASSERT_EQ(rows.size(), mesh.vertex_count());
    const std::vector<Vec3> mean = vertex_normals(written_mesh);
    std::vector<std::set<std::int32_t>> around(mesh.vertex_count());
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      for (Index v : mesh.faces[f]) around[v].insert(mesh.face_tags[f]);
    std::size_t radial_differs = 0, seam = 0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      ASSERT_EQ(rows[v].size(), 9u);
      const Vec3 n{std::stod(rows[v][3]), std::stod(rows[v][4]), std::stod(rows[v][5])};
      Vec3 expected = mean[v];
      if (around[v].size() == 1) {
        expected = normalized(mesh.vertices[v] - atoms[static_cast<std::size_t>(*around[v].begin())].centre);
        if (turned) expected = expected * -1.0;
        radial_differs += norm(expected - mean[v]) > 0.01;
      } else {
        ++seam;
      }
      EXPECT_LE(norm(n - expected), 0.001) << "vertex " << v << (turned ? " (turned)" : "");
    }
    EXPECT_GT(radial_differs, 20u);  // the test can tell the two rules apart
    EXPECT_GT(seam, 0u);
  }
}

// --no-header's layout: data rows only, every field a number, the same count on every
// row, so a reader that loads the file as one numeric table (PyGBe: numpy.loadtxt) can.
TEST_F(MeshIoTest, MsmsWithoutHeaderIsANumericTable) {
  const Mesh mesh = tagged_sphere();
  const std::vector<Atom> atoms = three_atoms();
  write_mesh(dir_ / "plain.face", mesh, {.atoms = atoms, .msms_header = false, .msms_atom_names = false});
  for (const auto& [file, columns, rows] : {std::tuple{"plain.vert", 9u, mesh.vertex_count()},
                                            std::tuple{"plain.face", 5u, mesh.face_count()}}) {
    const std::string text = slurp(dir_ / file);
    EXPECT_EQ(text.find('#'), std::string::npos);
    const auto table = msms_rows(text, 0);
    ASSERT_EQ(table.size(), rows) << file;
    for (const auto& row : table) {
      ASSERT_EQ(row.size(), columns) << file;
      for (const std::string& field : row) {
        std::size_t used = 0;
        std::stod(field, &used);
        EXPECT_EQ(used, field.size()) << file << ": " << field;
      }
    }
  }
  // Without atoms the closest sphere is the lowest tag + 1 around the vertex.
  write_mesh(dir_ / "t.vert", tetrahedron(), {.msms_header = false});
  const auto tetra = msms_rows(slurp(dir_ / "t.vert"), 0);
  ASSERT_EQ(tetra.size(), 4u);
  EXPECT_EQ(tetra[0][7], "1");
}

// TABI-PB reads MSMS-format files as its source does (src/elements.cpp, read from its
// documented layout): two header lines thrown away, the count from the start of the
// third (std::stoul), then x y z nx ny nz as the first six whitespace tokens of each row
// (faces: the first three, 1-based). Its older Fortran reader also wants four numbers on
// the count line (count, spheres, density, probe) and drops faces under 1e-5 A^2.
TEST_F(MeshIoTest, MsmsReadsAsTabiPbReadsIt) {
  const Mesh mesh = tagged_sphere();
  const std::vector<Atom> atoms = three_atoms();
  write_mesh(dir_ / "tabi.vert", mesh, {.atoms = atoms});
  const auto read_pair = [&](const char* file, std::size_t& declared) {
    std::istringstream in(slurp(dir_ / file));
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    std::getline(in, line);
    declared = std::stoul(line);
    std::istringstream counts(line);
    double spheres = 0, density = 0, probe = 0;
    std::size_t count = 0;
    EXPECT_TRUE(counts >> count >> spheres >> density >> probe) << line;  // the Fortran reader's four
    return msms_rows(in.str().substr(static_cast<std::size_t>(in.tellg())), 0);
  };
  std::size_t vertex_count = 0, face_count = 0;
  const auto vertices = read_pair("tabi.vert", vertex_count);
  const auto faces = read_pair("tabi.face", face_count);
  ASSERT_EQ(vertex_count, mesh.vertex_count());
  ASSERT_EQ(vertices.size(), vertex_count);
  ASSERT_EQ(face_count, mesh.face_count());
  ASSERT_EQ(faces.size(), face_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const Vec3 p{std::stod(vertices[v][0]), std::stod(vertices[v][1]), std::stod(vertices[v][2])};
    const Vec3 n{std::stod(vertices[v][3]), std::stod(vertices[v][4]), std::stod(vertices[v][5])};
    EXPECT_LE(norm(p - mesh.vertices[v]), 1e-3);
    EXPECT_NEAR(norm(n), 1.0, 0.002);
    EXPECT_GT(dot(n, vertex_normals(mesh)[v]), 0.9);  // outward
  }
  Mesh read;
  for (const auto& row : vertices) read.vertices.push_back({std::stod(row[0]), std::stod(row[1]), std::stod(row[2])});
  for (const auto& row : faces) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const unsigned long index = std::stoul(row[static_cast<std::size_t>(k)]);
      ASSERT_GE(index, 1u);
      ASSERT_LE(index, vertex_count);
      t[static_cast<std::size_t>(k)] = static_cast<Index>(index - 1);
    }
    read.faces.push_back(t);
  }
  for (std::size_t f = 0; f < read.face_count(); ++f) EXPECT_GE(face_area(read, f), 1e-5) << "face " << f;
  EXPECT_NEAR(signed_volume(read), signed_volume(mesh), 0.01 * signed_volume(mesh));
}

TEST_F(MeshIoTest, MsmsFaceOutOfRange) {
  const std::string message = error_of([] { read_mesh(kHandMade / "msms_bad" / "surface.vert"); });
  EXPECT_EQ(message, (kHandMade / "msms_bad" / "surface.face").string() + ":5: vertex index 4 out of range (1..3)");
}

// ---- other tools' files -------------------------------------------------------------

TEST_F(MeshIoTest, BigEndianPlyQuadsWithTags) {
  const Mesh mesh = read_mesh(kHandMade / "cube_quads_big_endian.ply");
  EXPECT_EQ(mesh.vertex_count(), 8u);
  ASSERT_EQ(mesh.face_count(), 12u);
  EXPECT_EQ(mesh.vertices[6], (Vec3{1, 1, 1}));
  EXPECT_EQ(mesh.faces[0], (Triangle{0, 3, 2}));
  EXPECT_EQ(mesh.faces[1], (Triangle{0, 2, 1}));
  EXPECT_EQ(mesh.face_tags, (std::vector<std::int32_t>{10, 10, 11, 11, 12, 12, 13, 13, 14, 14, 15, 15}));
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST_F(MeshIoTest, AsciiPlyQuadsWithIntCounts) {
  const Mesh mesh = read_mesh(kHandMade / "cube_quads_ascii.ply");
  EXPECT_EQ(mesh.face_count(), 12u);
  EXPECT_FALSE(mesh.has_tags());
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST_F(MeshIoTest, ObjPolygonsSlashFormsAndNegativeIndices) {
  const Mesh mesh = read_mesh(kHandMade / "cube_polygons.obj");
  EXPECT_EQ(mesh.vertex_count(), 8u);
  ASSERT_EQ(mesh.face_count(), 12u);
  EXPECT_EQ(mesh.faces[2], (Triangle{4, 5, 6}));   // "f -4//1 -3//1 -2//1 -1//1"
  EXPECT_EQ(mesh.faces[11], (Triangle{3, 4, 7}));  // "f -5 -8 -4 -1", second fan triangle
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
  EXPECT_DOUBLE_EQ(surface_area(mesh), 6.0);
}

TEST_F(MeshIoTest, StlWithCrlfAndSolidInBinaryHeader) {
  // ASCII with Windows line ends.
  put(dir_ / "crlf.stl",
      "solid t\r\n facet normal 0 0 1\r\n  outer loop\r\n   vertex 0 0 0\r\n   vertex 1 0 0\r\n   vertex 0 1 0\r\n"
      "  endloop\r\n endfacet\r\nendsolid t\r\n");
  EXPECT_EQ(read_mesh(dir_ / "crlf.stl").face_count(), 1u);
  // A binary file whose header starts with "solid", as some exporters write.
  write_mesh(dir_ / "b.stl", tetrahedron());
  std::string bytes = slurp(dir_ / "b.stl");
  bytes.replace(0, 5, "solid");
  put(dir_ / "b.stl", bytes);
  EXPECT_EQ(read_mesh(dir_ / "b.stl").face_count(), 4u);
}

TEST_F(MeshIoTest, MshNodesNeedNotBeNumberedFromOne) {
  put(dir_ / "gaps.msh",
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 5 \"protein\"\n$EndPhysicalNames\n"
      "$Nodes\n3\n10 0 0 0\n20 1 0 0\n30 0 1 0\n$EndNodes\n$Elements\n2\n1 15 2 0 1 10\n2 2 2 5 5 10 20 30\n"
      "$EndElements\n");
  const Mesh mesh = read_mesh(dir_ / "gaps.msh");
  ASSERT_EQ(mesh.face_count(), 1u);
  EXPECT_EQ(mesh.faces[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.face_tags[0], 4);
}

// ---- malformed input ----------------------------------------------------------------

TEST_F(MeshIoTest, TruncatedBinaryStl) {
  const fs::path file = kHandMade / "truncated.stl";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ": truncated: expected 1200 faces, file ends after 37");
}

TEST_F(MeshIoTest, TruncatedBinaryPly) {
  const fs::path file = kHandMade / "truncated_faces.ply";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ": truncated: expected 1200 faces, file ends after 37");
}

TEST_F(MeshIoTest, ShortStlFacet) {
  const fs::path file = kHandMade / "short_facet.stl";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ":2: facet has 2 vertices (STL facets have 3)");
}

TEST_F(MeshIoTest, BadIndexOff) {
  const fs::path file = kHandMade / "bad_index.off";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ":9: vertex index 7 out of range (0..3)");
}

TEST_F(MeshIoTest, BadIndexObj) {
  const fs::path file = kHandMade / "bad_index.obj";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ":4: vertex index 4 out of range (1..3)");
}

TEST_F(MeshIoTest, BadNodeMsh) {
  const fs::path file = kHandMade / "bad_node.msh";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ":12: element refers to undefined node 9");
}

TEST_F(MeshIoTest, NonNumericObj) {
  const fs::path file = kHandMade / "non_numeric.obj";
  EXPECT_EQ(error_of([&] { read_mesh(file); }), file.string() + ":4: y: expected a number, found '1.5x'");
}

TEST_F(MeshIoTest, NonNumericPly) {
  const fs::path file = kHandMade / "non_numeric.ply";
  EXPECT_EQ(error_of([&] { read_mesh(file); }),
            file.string() + ":11: number property: expected a number, found 'zero'");
}

TEST_F(MeshIoTest, UnknownExtension) {
  const fs::path file = dir_ / "mesh.xyz";
  EXPECT_EQ(error_of([&] { read_mesh(file); }),
            file.string() + ": unknown mesh format '.xyz' (expected .vtp .vtk .ply .off .stl .obj .vert/.face or .msh)");
  EXPECT_NE(error_of([&] { write_mesh(file, tetrahedron()); }).find("unknown mesh format"), std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(MeshIoTest, MissingFile) {
  for (const char* name : {"none.ply", "none.vtp", "none.vtk", "none.stl", "none.vert"}) {
    const fs::path file = dir_ / name;
    const std::string message = error_of([&] { read_mesh(file); });
    EXPECT_EQ(message.rfind(file.parent_path().string(), 0), 0u) << message;
    EXPECT_NE(message.find("cannot read: No such file or directory"), std::string::npos) << message;
  }
}

TEST_F(MeshIoTest, WriteIntoMissingDirectoryNamesTheFile) {
  for (const char* name : {"x.vtp", "x.vtk", "x.ply", "x.stl", "x.vert", "x.msh"}) {
    const fs::path file = dir_ / "missing" / name;
    const std::string message = error_of([&] { write_mesh(file, tetrahedron()); });
    EXPECT_NE(message.find(": cannot write: No such file or directory"), std::string::npos) << message;
    EXPECT_NE(message.find(std::string(name).substr(0, 2)), std::string::npos) << message;
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(MeshIoTest, CorruptVtpIsAnErrorNotACrash) {
  write_mesh(dir_ / "c.vtp", tagged_sphere());
  std::string bytes = slurp(dir_ / "c.vtp");
  put(dir_ / "c.vtp", bytes.substr(0, bytes.size() / 2));
  const std::string message = error_of([&] { read_mesh(dir_ / "c.vtp"); });
  EXPECT_EQ(message.rfind((dir_ / "c.vtp").string() + ":", 0), 0u) << message;
}

// Every prefix of every format must give a clean error or a mesh, never a crash.
TEST_F(MeshIoTest, EveryTruncationIsHandled) {
  const Mesh mesh = tetrahedron();
  for (const char* name : {"t.ply", "t.stl", "t.off", "t.obj", "t.msh"}) {
    for (bool ascii : {false, true}) {
      write_mesh(dir_ / name, mesh, {.ascii = ascii});
      const std::string bytes = slurp(dir_ / name);
      const fs::path cut = dir_ / (std::string("cut_") + name);
      for (std::size_t size = 0; size < bytes.size(); size += 7) {
        put(cut, bytes.substr(0, size));
        try {
          const Mesh read = read_mesh(cut);
          for (const Triangle& t : read.faces)
            for (Index v : t) ASSERT_LT(v, read.vertex_count());
        } catch (const Error& error) {
          ASSERT_EQ(std::string(error.what()).rfind(cut.string(), 0), 0u) << error.what();
        }
      }
    }
  }
}

// Random byte damage (fixed seed) must give a clean error or a valid mesh (every format:
// test_mesh_read_property.cpp).
TEST_F(MeshIoTest, DamagedFilesAreHandled) {
  const Mesh mesh = tetrahedron();
  std::mt19937 random(12345);
  for (const char* name : {"d.ply", "d.stl", "d.off", "d.obj", "d.msh", "d.vtp", "d.vtk"}) {
    for (bool ascii : {false, true}) {
      write_mesh(dir_ / name, mesh, {.ascii = ascii});
      const std::string bytes = slurp(dir_ / name);
      const fs::path damaged = dir_ / (std::string("damaged_") + name);
      for (int trial = 0; trial < 80; ++trial) {
        std::string copy = bytes;
        const int hits = 1 + static_cast<int>(random() % 4);
        for (int h = 0; h < hits; ++h) copy[random() % copy.size()] = static_cast<char>(random() % 256);
        put(damaged, copy);
        try {
          const Mesh read = read_mesh(damaged);
          for (const Triangle& t : read.faces)
            for (Index v : t) ASSERT_LT(v, read.vertex_count()) << name << " trial " << trial;
        } catch (const Error& error) {
          ASSERT_EQ(std::string(error.what()).rfind(damaged.string(), 0), 0u) << error.what();
        }
      }
    }
  }
}

// ---- hostile files (issue 12, item 6): legacy .vtk is read by our own reader --------

TEST_F(MeshIoTest, LegacyVtkNegativePointCountIsAnError) {
  const fs::path file = dir_ / "negative.vtk";
  put(file, "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS -12 float\n0 0 0\n");
  const std::string message = error_of([&] { read_mesh(file); });
  EXPECT_EQ(message.rfind(file.string() + ":5: negative point count", 0), 0u) << message;
}

// Counts in the billions in files of a few hundred bytes: an error at once, with no
// allocation of the declared size (VTK's reader grew memory at 300 MB/s on these).
TEST_F(MeshIoTest, LegacyVtkHeaderBombsAreErrors) {
  const std::string head = "# vtk DataFile Version 4.2\nbomb\n";
  const std::string points = "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  const std::string cases[] = {
      head + "ASCII\nDATASET POLYDATA\nPOINTS 2000000000 float\n0 0 0 1 1 1\n",
      head + "BINARY\nDATASET POLYDATA\nPOINTS 2000000000 double\n" + std::string(48, '\0') + "\n",
      head + "ASCII\nDATASET POLYDATA\n" + points + "POLYGONS 2000000000 2000000000\n3 0 1 2\n",
      head + "ASCII\nDATASET POLYDATA\n" + points + "POLYGONS 1 4\n3 0 1 2\nCELL_DATA 1\nFIELD FieldData 1\n" +
          "tag 1 2000000000 int\n0\n",
      head + "ASCII\nDATASET POLYDATA\n" + points + "POLYGONS 1 4\n3 0 1 2\nCELL_DATA 1\nFIELD FieldData 1\n" +
          "other 2000000000 1 double\n0\n",
      head + "BINARY\nDATASET POLYDATA\n" + points + "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nFIELD f 1\n" +
          "names 1 2000000000 string\n\xc0\xc0\n",
      head + "ASCII\nDATASET UNSTRUCTURED_GRID\n" + points + "CELLS 1 2000000000\n3 0 1 2\n"};
  for (const std::string& text : cases) {
    const fs::path file = dir_ / "bomb.vtk";
    put(file, text);
    const std::string message = error_of([&] { read_mesh(file); });
    EXPECT_EQ(message.rfind(file.string() + ":", 0), 0u) << text << "\n-> " << message;
  }
}

TEST_F(MeshIoTest, LegacyVtkDialects) {
  const std::string head = "# vtk DataFile Version 4.2\nhand made\nASCII\n";
  const std::string points = "POINTS 4 float\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  struct Case {
    std::string text;
    std::size_t faces;
    std::vector<std::int32_t> tags;
  };
  const Case cases[] = {
      // 4.x cells, a SCALARS tag, a vertex cell first (cell data counts it), lookup table
      {head + "DATASET POLYDATA\n" + points + "VERTICES 1 2\n1 3\nPOLYGONS 2 9\n3 0 2 1\n4 0 1 3 2\n" +
           "CELL_DATA 3\nSCALARS tag int 1\nLOOKUP_TABLE default\n9 7 8\nPOINT_DATA 4\nNORMALS n float\n" +
           "0 0 1 0 0 1 0 0 1 0 0 1\n",
       3, {7, 8, 8}},
      // 5.1 layout (OFFSETS, CONNECTIVITY) and a FIELD tag with VTK 9's METADATA block
      {"# vtk DataFile Version 5.1\nx\nASCII\nDATASET POLYDATA\n" + points +
           "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 3 6\nCONNECTIVITY vtktypeint64\n0 2 1 0 1 3\n" +
           "CELL_DATA 2\nFIELD FieldData 1\ntag 1 2 int\n4 5\nMETADATA\nINFORMATION 0\n\n",
       2, {4, 5}},
      // unstructured grid: a triangle, a quad, a line (skipped)
      {head + "DATASET UNSTRUCTURED_GRID\n" + points + "CELLS 3 12\n3 0 2 1\n4 0 1 3 2\n2 0 3\n" +
           "CELL_TYPES 3\n5\n9\n3\n",
       3, {}},
      // a triangle strip
      {head + "DATASET POLYDATA\n" + points + "TRIANGLE_STRIPS 1 5\n4 0 1 2 3\n", 2, {}}};
  for (const Case& c : cases) {
    const fs::path file = dir_ / "dialect.vtk";
    put(file, c.text);
    Mesh mesh;
    ASSERT_NO_THROW(mesh = read_mesh(file)) << c.text;
    EXPECT_EQ(mesh.vertex_count(), 4u) << c.text;
    EXPECT_EQ(mesh.face_count(), c.faces) << c.text;
    EXPECT_EQ(mesh.face_tags, c.tags) << c.text;
  }
  put(dir_ / "tetra.vtk", head + "DATASET UNSTRUCTURED_GRID\n" + points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n");
  EXPECT_NE(error_of([&] { read_mesh(dir_ / "tetra.vtk"); }).find("cell type 10 is not a surface cell"),
            std::string::npos);
}

// The Points array's header says 2^31 blocks: VTK aborted on such headers.
TEST_F(MeshIoTest, VtpDamagedAppendedHeaderIsAnError) {
  write_mesh(dir_ / "h.vtp", tagged_sphere());
  std::string bytes = slurp(dir_ / "h.vtp");
  const std::size_t offset = bytes.find("offset=\"", bytes.find("<Points")) + 8;
  const std::size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1 + std::stoul(bytes.substr(offset));
  bytes.replace(data, 8, std::string("\x00\x00\x00\x80\x00\x00\x00\x00", 8));  // UInt64 block count
  put(dir_ / "h.vtp", bytes);
  const std::string message = error_of([&] { read_mesh(dir_ / "h.vtp"); });
  EXPECT_NE(message.find(": DataArray 'Points': damaged header: 2147483648 blocks"), std::string::npos) << message;
  EXPECT_EQ(message.rfind((dir_ / "h.vtp").string() + ":", 0), 0u) << message;
}

TEST_F(MeshIoTest, VtpHugeCountsAreErrors) {
  write_mesh(dir_ / "n.vtp", tagged_sphere());
  const std::string bytes = slurp(dir_ / "n.vtp");
  for (const char* attribute : {"NumberOfPoints=\"", "NumberOfPolys=\""}) {
    std::string copy = bytes;
    const std::size_t at = copy.find(attribute) + std::string(attribute).size();
    copy.replace(at, copy.find('"', at) - at, "2000000000");
    put(dir_ / "n.vtp", copy);
    const std::string message = error_of([&] { read_mesh(dir_ / "n.vtp"); });
    const bool points = std::string(attribute) == "NumberOfPoints=\"";  // 3 values a point; 1 tag a cell
    EXPECT_NE(message.find("the Piece's counts need " + std::string(points ? "6000000000" : "2000000000")),
              std::string::npos)
        << message;
  }
}

// No VTK code runs when a .vtp is read: nothing reaches stderr, the error is one line.
TEST_F(MeshIoTest, VtkChatterStaysOffTheTerminal) {
  put(dir_ / "x.vtp", "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"1\"");
  ::testing::internal::CaptureStderr();
  const std::string message = error_of([&] { read_mesh(dir_ / "x.vtp"); });
  const std::string chatter = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(chatter, "");
  EXPECT_EQ(message, (dir_ / "x.vtp").string() + ":2: truncated: <Piece tag is not closed");
}

// ---- coordinates: every reader refuses what the structure readers refuse -------------

// |x| >= 1e16 and NaN in every format, checked once for all readers in read_mesh.
TEST_F(MeshIoTest, OutOfRangeCoordinatesAreErrorsInEveryFormat) {
  Mesh mesh = tetrahedron();
  mesh.vertices[1].y = -3e16;
  for (const char* name : {"r.vtp", "r.vtk", "r.ply", "r.off", "r.stl", "r.obj", "r.vert", "r.msh"})
    for (const bool ascii : {false, true}) {
      write_mesh(dir_ / name, mesh, {.ascii = ascii});
      const std::string message = error_of([&] { read_mesh(dir_ / name); });
      EXPECT_EQ(message.rfind((dir_ / name).string() + ": vertex ", 0), 0u) << message;
      EXPECT_NE(message.find(" of 4: y coordinate: -3e+16 is out of range (its magnitude must be below 1e16 angstrom)"),
                std::string::npos)
          << message;
    }
  mesh.vertices[1].y = -9.9e15;  // below the bound: read as written
  write_mesh(dir_ / "ok.off", mesh);
  EXPECT_EQ(read_mesh(dir_ / "ok.off").vertices[1].y, -9.9e15);
}

TEST_F(MeshIoTest, NonFiniteCoordinatesAreErrors) {
  const std::string head = "# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n";
  const std::pair<const char*, std::string> files[] = {
      {"n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n"},
      {"n.vtk", head + "0 0 0 1 0 0 inf 1 0\nPOLYGONS 1 4\n3 0 1 2\n"},
      {"n.vtp", "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\"><Points>"
                "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 -inf 1 0</DataArray>"
                "</Points><Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
                "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys></Piece></PolyData>"
                "</VTKFile>"}};
  for (const auto& [name, text] : files) {
    put(dir_ / name, text);
    const std::string message = error_of([&] { read_mesh(dir_ / name); });
    // Named as a vertex, or by its line where a reader refuses the word itself: either way in
    // the words of coordinate_problem (input_checks.hpp).
    EXPECT_NE(message.find(" is not a finite number"), std::string::npos) << name << ": " << message;
    EXPECT_EQ(message.rfind((dir_ / name).string() + ":", 0), 0u) << message;
  }
}

// ---- data after the declared counts (issue 12, item 7): an error, never dropped -------

TEST_F(MeshIoTest, BinaryStlCountZeroBeforeFacetsIsAnError) {
  write_mesh(dir_ / "z.stl", tetrahedron());
  std::string bytes = slurp(dir_ / "z.stl");
  bytes.replace(80, 4, std::string(4, '\0'));
  put(dir_ / "z.stl", bytes);
  const std::string message = error_of([&] { read_mesh(dir_ / "z.stl"); });
  EXPECT_NE(message.find("binary STL declares 0 faces"), std::string::npos) << message;
  EXPECT_NE(message.find("4 more faces' worth"), std::string::npos) << message;
}

TEST_F(MeshIoTest, DataAfterTheDeclaredCountsIsAnError) {
  write_mesh(dir_ / "a.off", tetrahedron());
  put(dir_ / "a.off", slurp(dir_ / "a.off") + "3 0 1 2\n");
  EXPECT_NE(error_of([&] { read_mesh(dir_ / "a.off"); }).find(":11: data after the declared 4 vertices and 4 faces"),
            std::string::npos)
      << error_of([&] { read_mesh(dir_ / "a.off"); });
  for (const bool ascii : {false, true}) {
    write_mesh(dir_ / "a.ply", tetrahedron(), {.ascii = ascii});
    put(dir_ / "a.ply", slurp(dir_ / "a.ply") + (ascii ? "3 0 1 2 0\n" : std::string(17, '\1')));
    EXPECT_NE(error_of([&] { read_mesh(dir_ / "a.ply"); }).find("data after the declared elements"), std::string::npos);
  }
  write_mesh(dir_ / "a.stl", tetrahedron(), {.ascii = true});
  put(dir_ / "a.stl", slurp(dir_ / "a.stl") + "facet normal 0 0 1\n");
  EXPECT_NE(error_of([&] { read_mesh(dir_ / "a.stl"); }).find("'facet' outside 'solid'"), std::string::npos);
}

TEST_F(MeshIoTest, EmptyFilesAreErrors) {
  put(dir_ / "e.obj", "");
  EXPECT_EQ(error_of([&] { read_mesh(dir_ / "e.obj"); }), (dir_ / "e.obj").string() + ": empty file (0 bytes)");
  put(dir_ / "e.vert", "");
  put(dir_ / "e.face", "");
  EXPECT_EQ(error_of([&] { read_mesh(dir_ / "e.vert"); }), (dir_ / "e.vert").string() + ": empty file (0 bytes)");
}

TEST_F(MeshIoTest, FormatNames) {
  EXPECT_EQ(mesh_format_from_path("a/b.VTP"), MeshFormat::vtp);
  EXPECT_EQ(mesh_format_from_path("x.face"), MeshFormat::msms);
  EXPECT_EQ(mesh_format_from_path("x.vert"), MeshFormat::msms);
  EXPECT_STREQ(mesh_format_name(MeshFormat::msh), "gmsh 2.2 (.msh)");
  EXPECT_THROW(mesh_format_from_path("noextension"), Error);
}

}  // namespace
