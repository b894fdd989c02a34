// The .vtp reader of our own (mesh_vtp.cpp): it reads every encoding VTK's writer
// produces, and answers damaged sizes with one error instead of trusting them. The .vtp
// writer of our own (mesh_vtp_writer.cpp): VTK's reader gets every value back.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// VTK (a test-only dependency) is the reference reader and writer here.
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "common/thread_count_scope.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "mesh_io_samples.hpp"

namespace fs = std::filesystem;
using namespace molsurf;

namespace {

class VtpTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "molsurf_vtp_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  static void put(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }
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

using molsurf::testing::tagged_sphere;
using molsurf::testing::three_atoms;

// Five points; a vertex cell, a quad, a triangle and a strip of 3 triangles, so that cell
// data runs over verts before polys before strips. Tag of cell c: 10 + c.
vtkSmartPointer<vtkPolyData> sample_polydata() {
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double xyz[5][3] = {{0.1, 1.0 / 3.0, -2.0 / 7.0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1e-300}};
  for (const auto& p : xyz) points->InsertNextPoint(p);
  polydata->SetPoints(points);
  vtkNew<vtkCellArray> verts, polys, strips;
  const vtkIdType vertex[] = {4}, quad[] = {0, 1, 2, 3}, triangle[] = {0, 1, 4}, strip[] = {0, 1, 2, 3, 4};
  verts->InsertNextCell(1, vertex);
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(3, triangle);
  strips->InsertNextCell(5, strip);
  polydata->SetVerts(verts);
  polydata->SetPolys(polys);
  polydata->SetStrips(strips);
  vtkNew<vtkIntArray> tags;
  tags->SetName("tag");
  vtkNew<vtkStringArray> names;
  names->SetName("chain");
  for (int c = 0; c < 4; ++c) {
    tags->InsertNextValue(10 + c);
    names->InsertNextValue(c % 2 ? "A" : "chain B");
  }
  polydata->GetCellData()->AddArray(tags);
  polydata->GetCellData()->AddArray(names);
  return polydata;
}

// What sample_polydata() reads as: the quad as 2 triangles, the triangle, the strip as 3
// (every other one reversed); the vertex cell is no face.
void expect_sample(const Mesh& mesh, const std::string& what) {
  ASSERT_EQ(mesh.vertex_count(), 5u) << what;
  EXPECT_EQ(mesh.vertices[0], (Vec3{0.1, 1.0 / 3.0, -2.0 / 7.0})) << what;
  EXPECT_EQ(mesh.vertices[4], (Vec3{0.5, 0.5, 1e-300})) << what;
  const std::vector<Triangle> faces = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {0, 1, 2}, {2, 1, 3}, {2, 3, 4}};
  EXPECT_EQ(mesh.faces, faces) << what;
  EXPECT_EQ(mesh.face_tags, (std::vector<std::int32_t>{11, 11, 12, 13, 13, 13})) << what;
}

struct Dialect {
  int mode;        // vtkXMLWriter::Ascii, Binary or Appended
  bool encode;     // appended data as base64
  bool zlib;
  bool uint64;     // header type
  bool big_endian;
};

TEST_F(VtpTest, ReadsEveryEncodingVtkWrites) {
  for (const int mode : {vtkXMLWriter::Ascii, vtkXMLWriter::Binary, vtkXMLWriter::Appended})
    for (const bool encode : {false, true})
      for (const bool zlib : {false, true})
        for (const bool uint64 : {false, true})
          for (const bool big_endian : {false, true}) {
            if (mode != vtkXMLWriter::Appended && encode) continue;
            vtkNew<vtkXMLPolyDataWriter> writer;
            writer->SetDataMode(mode);
            writer->SetEncodeAppendedData(encode);
            if (zlib) writer->SetCompressorTypeToZLib();
            else writer->SetCompressorTypeToNone();
            if (uint64) writer->SetHeaderTypeToUInt64();
            else writer->SetHeaderTypeToUInt32();
            if (big_endian) writer->SetByteOrderToBigEndian();
            else writer->SetByteOrderToLittleEndian();
            writer->SetBlockSize(64);  // several zlib blocks, the last one partial
            const fs::path file = dir_ / "dialect.vtp";
            writer->SetFileName(file.c_str());
            writer->SetInputData(sample_polydata());
            ASSERT_EQ(writer->Write(), 1);
            const std::string what = "mode " + std::to_string(mode) + (encode ? " base64" : "") +
                                     (zlib ? " zlib" : "") + (uint64 ? " UInt64" : " UInt32") +
                                     (big_endian ? " big-endian" : "");
            Mesh mesh;
            ASSERT_NO_THROW(mesh = read_mesh(file)) << what << ": " << error_of([&] { read_mesh(file); });
            expect_sample(mesh, what);
          }
}

// Pieces are appended, each indexing its own points.
TEST_F(VtpTest, PiecesAreJoined) {
  const std::string piece =
      "<Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\"><Points>"
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points>"
      "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys></Piece>";
  put(dir_ / "p.vtp", "<VTKFile type=\"PolyData\"><PolyData>" + piece + "<!-- second -->" + piece +
                          "</PolyData></VTKFile>");
  const Mesh mesh = read_mesh(dir_ / "p.vtp");
  EXPECT_EQ(mesh.vertex_count(), 6u);
  EXPECT_EQ(mesh.faces, (std::vector<Triangle>{{0, 1, 2}, {3, 4, 5}}));
}

// The open fuzz finding of issue 12: string cell arrays whose count disagrees with the
// cells made VTK 9.1 read past its buffer. Arrays the mesh does not use are not decoded.
TEST_F(VtpTest, StringArraysAreNotTrusted) {
  const std::string polys =
      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1"
      "</DataArray></Points><Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">"
      "0 2 1 0 1 3 0 3 2 1 2 3</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6 9 12"
      "</DataArray></Polys>";
  const std::string strings = "<CellData><Array type=\"String\" Name=\"tag\" format=\"ascii\">65 0 65 0 65 0 65 0 65 0"
                              "</Array></CellData>";
  put(dir_ / "s.vtp", "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"4\">" +
                          strings + polys + "</Piece></PolyData></VTKFile>");
  const Mesh mesh = read_mesh(dir_ / "s.vtp");
  EXPECT_EQ(mesh.face_count(), 4u);
  EXPECT_FALSE(mesh.has_tags());  // a string "tag" is not ours
  put(dir_ / "s.vtp", "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"3\">" +
                          strings + polys + "</Piece></PolyData></VTKFile>");
  EXPECT_EQ(error_of([&] { read_mesh(dir_ / "s.vtp"); }),
            (dir_ / "s.vtp").string() + ":1: DataArray 'offsets': holds more values than the 3 the Piece's counts need");
}

// Several pieces whose arrays all point at the same appended bytes would let a small file
// describe unbounded data.
TEST_F(VtpTest, OverlappingAppendedArraysAreAnError) {
  write_mesh(dir_ / "o.vtp", [] {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
  }());
  std::string bytes = slurp(dir_ / "o.vtp");
  const std::size_t begin = bytes.find("<Piece"), end = bytes.find("</Piece>") + 8;
  const std::string piece = bytes.substr(begin, end - begin);
  std::string pieces;
  for (int i = 0; i < 50; ++i) pieces += piece;
  bytes.replace(begin, end - begin, pieces);
  put(dir_ / "o.vtp", bytes);
  EXPECT_NE(error_of([&] { read_mesh(dir_ / "o.vtp"); }).find("appended arrays overlap"), std::string::npos);
}

TEST_F(VtpTest, DamagedZlibHeadersAreErrors) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt32();
  const fs::path file = dir_ / "z.vtp";
  writer->SetFileName(file.c_str());
  writer->SetInputData(sample_polydata());
  ASSERT_EQ(writer->Write(), 1);
  const std::string bytes = slurp(file);
  const std::size_t points = bytes.find("offset=\"", bytes.find("<Points")) + 8;
  const std::size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1 + std::stoul(bytes.substr(points));
  // UInt32 words: block count, block size, last block size, compressed sizes.
  const auto damaged = [&](std::size_t word, std::uint32_t value) {
    std::string copy = bytes;
    for (int b = 0; b < 4; ++b) copy[data + 4 * word + b] = static_cast<char>(value >> (8 * b) & 0xff);
    put(file, copy);
    return error_of([&] { read_mesh(file); });
  };
  const auto expect = [&](std::size_t word, std::uint32_t value, const std::string& wanted) {
    const std::string message = damaged(word, value);
    EXPECT_NE(message.find(wanted), std::string::npos) << message;
  };
  expect(0, 0x80000000u, "DataArray 'Points': damaged header: 2147483648 blocks");
  // One block, so it is the last: its own size (word 2) counts, the block size does not.
  EXPECT_EQ(damaged(1, 0x7fffffffu), "");
  expect(3, 0xfffffff0u, "DataArray 'Points': truncated: block 0 declares");
  expect(0, 0, "DataArray 'Points': damaged header: 0 blocks");
  // A last block of size 0 is a full one (VTK's rule): 32768 bytes, 4096 doubles.
  expect(2, 0, "DataArray 'Points': holds 4096 values; the Piece's counts need 15");
}

TEST_F(VtpTest, UnsupportedFilesSayWhy) {
  const auto message = [&](const std::string& text) {
    put(dir_ / "u.vtp", text);
    return error_of([&] { read_mesh(dir_ / "u.vtp"); });
  };
  const std::string file = (dir_ / "u.vtp").string();
  EXPECT_EQ(message("<VTKFile type=\"PolyData\" compressor=\"vtkLZ4DataCompressor\"><PolyData/></VTKFile>"),
            file + ":1: compressor 'vtkLZ4DataCompressor' is not supported: molsurf reads zlib-compressed and "
                   "uncompressed .vtp files");
  EXPECT_EQ(message("<VTKFile type=\"UnstructuredGrid\"/>"),
            file + ":1: a VTK XML file of type 'UnstructuredGrid', not PolyData");
  EXPECT_EQ(message("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\">\n<PolyData>\n</VTKFile>"),
            file + ":4: </VTKFile> closes <PolyData> of line 3");
  EXPECT_EQ(message("<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"3\"/></PolyData></VTKFile>"),
            file + ":1: Piece of 3 points has no <Points> array");
}

// ---- VTK cell data --------------------------------------------------------------------

template <class Reader>
vtkSmartPointer<vtkPolyData> read_with_vtk(const fs::path& file) {
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

void expect_atom_cell_data(vtkPolyData* polydata, const Mesh& mesh, const std::vector<Atom>& atoms) {
  ASSERT_NE(polydata, nullptr);
  ASSERT_EQ(polydata->GetNumberOfCells(), static_cast<vtkIdType>(mesh.face_count()));
  vtkCellData* cells = polydata->GetCellData();
  auto* tag = vtkIntArray::SafeDownCast(cells->GetAbstractArray("tag"));
  auto* serial = vtkIntArray::SafeDownCast(cells->GetAbstractArray("atom_serial"));
  auto* residue_number = vtkIntArray::SafeDownCast(cells->GetAbstractArray("residue_number"));
  auto* residue_name = vtkStringArray::SafeDownCast(cells->GetAbstractArray("residue_name"));
  auto* chain = vtkStringArray::SafeDownCast(cells->GetAbstractArray("chain"));
  ASSERT_NE(tag, nullptr);
  ASSERT_NE(serial, nullptr);
  ASSERT_NE(residue_number, nullptr);
  ASSERT_NE(residue_name, nullptr);
  ASSERT_NE(chain, nullptr);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto id = static_cast<vtkIdType>(f);
    const Atom& atom = atoms[static_cast<std::size_t>(mesh.face_tags[f])];
    ASSERT_EQ(tag->GetValue(id), mesh.face_tags[f]);
    ASSERT_EQ(serial->GetValue(id), atom.serial);
    ASSERT_EQ(residue_number->GetValue(id), atom.residue_number);
    ASSERT_EQ(residue_name->GetValue(id), atom.residue_name);
    ASSERT_EQ(chain->GetValue(id), atom.chain);
  }
  vtkDataArray* normals = polydata->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  EXPECT_EQ(normals->GetNumberOfTuples(), static_cast<vtkIdType>(mesh.vertex_count()));
  // Area-weighted normals of a sphere point away from its centre; written as float32.
  EXPECT_EQ(normals->GetDataType(), VTK_FLOAT);
  const std::vector<Vec3> expected = vertex_normals(mesh);
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 17) {
    const double* n = normals->GetTuple3(static_cast<vtkIdType>(v));
    EXPECT_EQ(n[0], static_cast<float>(expected[v].x));
    EXPECT_EQ(n[1], static_cast<float>(expected[v].y));
    EXPECT_EQ(n[2], static_cast<float>(expected[v].z));
    EXPECT_GT(dot(Vec3{n[0], n[1], n[2]}, mesh.vertices[v] - Vec3{1.1, -2.3, 0.7}), 0);
  }
}

TEST_F(VtpTest, VtpCarriesAtomDataPerFace) {
  const Mesh mesh = tagged_sphere();
  const std::vector<Atom> atoms = three_atoms();
  write_mesh(dir_ / "atoms.vtp", mesh, {.atoms = atoms});
  EXPECT_NE(slurp(dir_ / "atoms.vtp").find("vtkZLibDataCompressor"), std::string::npos);
  expect_atom_cell_data(read_with_vtk<vtkXMLPolyDataReader>(dir_ / "atoms.vtp"), mesh, atoms);
}

// Arrays of many zlib blocks (32 KiB each), compressed in parallel: VTK's own reader and
// ours get the same points (exactly), triangles and tags, for any thread count.
TEST_F(VtpTest, VtpOfManyBlocksReadsBackExactlyInVtkAndOurs) {
  Mesh mesh = make_icosphere({1.1, -2.3, 0.7}, 1.7, IcosphereOptions{.frequency = 40, .tag = 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) mesh.face_tags[f] = static_cast<std::int32_t>(f % 7);
  ASSERT_GT(3 * 4 * mesh.face_count(), 8 * 32768u) << "connectivity should span several blocks";
  std::string first;
  for (const int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    write_mesh(dir_ / "big.vtp", mesh);
    const std::string bytes = slurp(dir_ / "big.vtp");
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << "the file depends on the thread count";
  }
  const vtkSmartPointer<vtkPolyData> vtk = read_with_vtk<vtkXMLPolyDataReader>(dir_ / "big.vtp");
  ASSERT_EQ(vtk->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.vertex_count()));
  ASSERT_EQ(vtk->GetNumberOfCells(), static_cast<vtkIdType>(mesh.face_count()));
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 97) {
    const double* p = vtk->GetPoint(static_cast<vtkIdType>(v));
    EXPECT_EQ(Vec3(p[0], p[1], p[2]), mesh.vertices[v]);
  }
  auto* tag = vtkIntArray::SafeDownCast(vtk->GetCellData()->GetAbstractArray("tag"));
  ASSERT_NE(tag, nullptr);
  for (std::size_t f = 0; f < mesh.face_count(); f += 89) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtk->GetCellPoints(static_cast<vtkIdType>(f), n, ids);
    ASSERT_EQ(n, 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(ids[k], static_cast<vtkIdType>(mesh.faces[f][k]));
    EXPECT_EQ(tag->GetValue(static_cast<vtkIdType>(f)), mesh.face_tags[f]);
  }
  const Mesh ours = read_mesh(dir_ / "big.vtp");
  EXPECT_EQ(ours.vertices, mesh.vertices);
  EXPECT_EQ(ours.faces, mesh.faces);
  EXPECT_EQ(ours.face_tags, mesh.face_tags);
}

}  // namespace
