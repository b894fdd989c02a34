// The legacy .vtk writer of our own (mesh_vtk.cpp) against VTK 9.1's vtkPolyDataWriter, the
// writer it replaces: for the same mesh the two files are the same bytes, and VTK's reader
// and ours read every value back.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

// VTK (a test-only dependency) is the reference writer and reader here.
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>

#include "mesh/icosphere.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "scratch_directory.hpp"

namespace fs = std::filesystem;
using namespace molsurf;

namespace {

using molsurf::testing::file_bytes;

class VtkWriterTest : public ::testing::Test {
 protected:
  molsurf::testing::ScratchDirectory scratch_{"molsurf_vtk_writer"};
  const fs::path dir_ = scratch_.path();
};

// The PolyData molsurf handed to VTK's writer before it had its own: double points, 32-bit
// polygons, float normals, the cell arrays in this order.
vtkSmartPointer<vtkPolyData> reference_polydata(const Mesh& mesh, const std::vector<Atom>& atoms) {
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertex_count()));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    points->SetPoint(static_cast<vtkIdType>(v), mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z);
  polydata->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->Use32BitStorage();
  for (const Triangle& t : mesh.faces) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  polydata->SetPolys(polys);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertex_count()));
  const std::vector<Vec3> normal = vertex_normals(mesh);
  for (std::size_t v = 0; v < normal.size(); ++v)
    normals->SetTuple3(static_cast<vtkIdType>(v), normal[v].x, normal[v].y, normal[v].z);
  polydata->GetPointData()->SetNormals(normals);
  if (!mesh.has_tags()) return polydata;

  const auto faces = static_cast<vtkIdType>(mesh.face_count());
  vtkNew<vtkIntArray> tags;
  tags->SetName("tag");
  tags->SetNumberOfTuples(faces);
  for (vtkIdType f = 0; f < faces; ++f) tags->SetValue(f, mesh.face_tags[static_cast<std::size_t>(f)]);
  polydata->GetCellData()->AddArray(tags);
  if (atoms.empty()) return polydata;
  vtkNew<vtkIntArray> serial, residue_number;
  vtkNew<vtkStringArray> residue_name, chain;
  serial->SetName("atom_serial");
  residue_number->SetName("residue_number");
  residue_name->SetName("residue_name");
  chain->SetName("chain");
  for (vtkAbstractArray* array : std::initializer_list<vtkAbstractArray*>{serial, residue_number, residue_name, chain})
    array->SetNumberOfTuples(faces);
  for (vtkIdType f = 0; f < faces; ++f) {
    const std::int32_t tag = mesh.face_tags[static_cast<std::size_t>(f)];
    const Atom* atom = tag >= 0 ? &atoms[static_cast<std::size_t>(tag)] : nullptr;
    serial->SetValue(f, atom ? atom->serial : 0);
    residue_number->SetValue(f, atom ? residue_number_32(atom->residue_number) : 0);
    residue_name->SetValue(f, atom ? atom->residue_name : "");
    chain->SetValue(f, atom ? atom->chain : "");
  }
  for (vtkAbstractArray* array : std::initializer_list<vtkAbstractArray*>{serial, residue_number, residue_name, chain})
    polydata->GetCellData()->AddArray(array);
  return polydata;
}

// What VTK 9.1's writer makes of the mesh, with the settings molsurf used it with.
std::string vtk_writer_bytes(const fs::path& file, const Mesh& mesh, const std::vector<Atom>& atoms) {
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetFileTypeToBinary();
  writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
  writer->SetHeader("molsurf " MOLSURF_VERSION);
  writer->SetInputData(reference_polydata(mesh, atoms));
  writer->SetFileName(file.c_str());
  EXPECT_EQ(writer->Write(), 1);
  return file_bytes(file);
}

// "" when equal; otherwise where they first differ, with a few bytes of each.
std::string difference(const std::string& ours, const std::string& vtk) {
  if (ours == vtk) return "";
  const std::size_t at = static_cast<std::size_t>(
      std::mismatch(ours.begin(), ours.begin() + static_cast<std::ptrdiff_t>(std::min(ours.size(), vtk.size())),
                    vtk.begin())
          .first -
      ours.begin());
  const std::size_t from = at < 24 ? 0 : at - 24;
  return "sizes " + std::to_string(ours.size()) + " and " + std::to_string(vtk.size()) + ", first difference at byte " +
         std::to_string(at) + ": ours \"" + ours.substr(from, 48) + "\", VTK's \"" + vtk.substr(from, 48) + "\"";
}

// Every value of the file as VTK's reader and ours get it.
void expect_read_back(const fs::path& file, const Mesh& mesh, const std::vector<Atom>& atoms) {
  vtkNew<vtkPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), 0);
  vtkPolyData* vtk = reader->GetOutput();
  ASSERT_NE(vtk, nullptr);
  ASSERT_EQ(vtk->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.vertex_count()));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const double* p = vtk->GetPoint(static_cast<vtkIdType>(v));
    ASSERT_EQ(Vec3(p[0], p[1], p[2]), mesh.vertices[v]) << "point " << v;
  }
  ASSERT_EQ(vtk->GetNumberOfPolys(), static_cast<vtkIdType>(mesh.face_count()));
  ASSERT_EQ(vtk->GetNumberOfCells(), static_cast<vtkIdType>(mesh.face_count()));
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtk->GetCellPoints(static_cast<vtkIdType>(f), n, ids);
    ASSERT_EQ(n, 3) << "face " << f;
    for (int k = 0; k < 3; ++k) ASSERT_EQ(ids[k], static_cast<vtkIdType>(mesh.faces[f][k])) << "face " << f;
  }
  if (mesh.vertex_count() > 0) {
    auto* normals = vtkFloatArray::SafeDownCast(vtk->GetPointData()->GetNormals());
    ASSERT_NE(normals, nullptr);
    ASSERT_EQ(normals->GetNumberOfTuples(), static_cast<vtkIdType>(mesh.vertex_count()));
    const std::vector<Vec3> expected = vertex_normals(mesh);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(normals->GetValue(static_cast<vtkIdType>(3 * v + k)), static_cast<float>(expected[v][k]))
            << "normal " << v;
  }

  vtkCellData* cells = vtk->GetCellData();
  ASSERT_EQ(cells->GetNumberOfArrays(), !mesh.has_tags() ? 0 : atoms.empty() ? 1 : 5);
  if (mesh.has_tags()) {
    auto* tag = vtkIntArray::SafeDownCast(cells->GetAbstractArray("tag"));
    ASSERT_NE(tag, nullptr);
    ASSERT_EQ(tag->GetNumberOfTuples(), static_cast<vtkIdType>(mesh.face_count()));
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      ASSERT_EQ(tag->GetValue(static_cast<vtkIdType>(f)), mesh.face_tags[f]) << "face " << f;
  }
  if (mesh.has_tags() && !atoms.empty()) {
    auto* serial = vtkIntArray::SafeDownCast(cells->GetAbstractArray("atom_serial"));
    auto* residue_number = vtkIntArray::SafeDownCast(cells->GetAbstractArray("residue_number"));
    auto* residue_name = vtkStringArray::SafeDownCast(cells->GetAbstractArray("residue_name"));
    auto* chain = vtkStringArray::SafeDownCast(cells->GetAbstractArray("chain"));
    ASSERT_NE(serial, nullptr);
    ASSERT_NE(residue_number, nullptr);
    ASSERT_NE(residue_name, nullptr);
    ASSERT_NE(chain, nullptr);
    for (vtkAbstractArray* array : std::initializer_list<vtkAbstractArray*>{serial, residue_number, residue_name, chain})
      ASSERT_EQ(array->GetNumberOfTuples(), static_cast<vtkIdType>(mesh.face_count())) << array->GetName();
    const Atom none{};
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const auto id = static_cast<vtkIdType>(f);
      const std::int32_t t = mesh.face_tags[f];
      const Atom& atom = t >= 0 ? atoms[static_cast<std::size_t>(t)] : none;
      ASSERT_EQ(serial->GetValue(id), atom.serial) << "face " << f;
      ASSERT_EQ(residue_number->GetValue(id), residue_number_32(atom.residue_number)) << "face " << f;
      ASSERT_EQ(residue_name->GetValue(id), atom.residue_name) << "face " << f;
      ASSERT_EQ(chain->GetValue(id), atom.chain) << "face " << f;
    }
  }

  const Mesh ours = read_mesh(file);
  EXPECT_EQ(ours.vertices, mesh.vertices);
  EXPECT_EQ(ours.faces, mesh.faces);
  EXPECT_EQ(ours.face_tags, mesh.face_tags);
}

// Ours and VTK's bytes for the mesh, then every value read back from ours.
void expect_as_vtk_writes_it(const fs::path& dir, const Mesh& mesh, const std::vector<Atom>& atoms = {}) {
  const fs::path ours = dir / "ours.vtk";
  write_mesh(ours, mesh, {.atoms = atoms});
  const std::string expected = vtk_writer_bytes(dir / "vtk.vtk", mesh, atoms);
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(difference(file_bytes(ours), expected), "");
  expect_read_back(ours, mesh, atoms);
}

Mesh tetrahedron() {
  Mesh mesh;
  // Thirds, tiny and huge values: any rounding on the way would show.
  mesh.vertices = {{0.1, 1.0 / 3.0, -2.0 / 7.0}, {1.0e-17 + 1.0, 0.2, 0.3}, {0.3, 1.7, 1e-300}, {0.5, 0.6, 2.0 / 3.0}};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  mesh.face_tags = {0, 1, 2, 1};
  return mesh;
}

std::vector<Atom> atoms_named(const std::vector<std::string>& residue_names, const std::vector<std::string>& chains) {
  std::vector<Atom> atoms(residue_names.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    atoms[i].centre = {0.1 * static_cast<double>(i), 0, 0};
    atoms[i].radius = 1.5;
    atoms[i].serial = static_cast<int>(1000 * i) - 1;
    atoms[i].residue_number = static_cast<std::int64_t>(i) * 7 - 3;
    atoms[i].residue_name = residue_names[i];
    atoms[i].chain = chains[i % chains.size()];
  }
  return atoms;
}

const Structure& crambin() {
  static const Structure structure = read_structure(fs::path(MOLSURF_DATA_DIR) / "pdb" / "1crn.pdb");
  return structure;
}

TEST_F(VtkWriterTest, TetrahedronWithTags) { expect_as_vtk_writes_it(dir_, tetrahedron()); }

TEST_F(VtkWriterTest, TetrahedronWithoutTagsHasNoCellData) {
  Mesh mesh = tetrahedron();
  mesh.face_tags.clear();
  expect_as_vtk_writes_it(dir_, mesh);
  EXPECT_EQ(file_bytes(dir_ / "ours.vtk").find("CELL_DATA"), std::string::npos);
}

TEST_F(VtkWriterTest, TetrahedronWithAtomsAndAnUntaggedFace) {
  Mesh mesh = tetrahedron();
  mesh.face_tags[2] = kNoTag;  // serial and residue number 0, empty names
  expect_as_vtk_writes_it(dir_, mesh, atoms_named({"ALA", "GLY", "HEM"}, {"A", "B"}));
}

// Residue names and chains of every length class of VTK's string encoding (1-, 2- and
// 4-byte lengths: below 64, below 16384, beyond), empty, non-ASCII (UTF-8 and a stray
// Latin-1 byte), and with the characters the text lines around them are made of.
TEST_F(VtkWriterTest, StringsOfEveryLengthAndByte) {
  const std::vector<std::string> names = {"",
                                          "\xc3\x84" "BC",
                                          "caf\xe9",
                                          "with space",
                                          "new\nline",
                                          std::string(63, 'x'),
                                          std::string(64, 'y'),
                                          std::string(16383, 'z'),
                                          std::string(16384, 'w'),
                                          std::string(70000, 'v')};
  const std::vector<std::string> chains = {"A", "", "\xce\xb1\xce\xb2", "LONGCHAIN", std::string(200, 'Q')};
  Mesh mesh = make_icosphere({1.1, -2.3, 0.7}, 1.7, IcosphereOptions{.frequency = 3, .tag = 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    mesh.face_tags[f] = f % 11 == 10 ? kNoTag : static_cast<std::int32_t>(f % 11);
  std::vector<Atom> atoms = atoms_named(names, chains);
  atoms.back().residue_number = std::int64_t{1} << 40;  // clamped to INT32_MAX, as VTK's Int32 array holds it
  expect_as_vtk_writes_it(dir_, mesh, atoms);
}

// A real surface: 1crn with its atoms, so every array and string is there.
TEST_F(VtkWriterTest, CrambinSurfaceWithAtoms) {
  const ComputedSurface surface = compute_surface(crambin().atoms);
  ASSERT_GT(surface.mesh.face_count(), 20000u);
  expect_as_vtk_writes_it(dir_, surface.mesh, crambin().atoms);
}

// Points without triangles, and nothing at all: the sections VTK leaves out.
TEST_F(VtkWriterTest, MeshesWithoutFacesOrPoints) {
  Mesh points_only = tetrahedron();
  points_only.faces.clear();
  points_only.face_tags.clear();
  expect_as_vtk_writes_it(dir_, points_only);
  expect_as_vtk_writes_it(dir_, Mesh{});
}

}  // namespace
