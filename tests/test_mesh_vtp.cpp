// The .vtp reader of our own (mesh_vtp.cpp): it reads every encoding VTK's writer
// produces, and answers damaged sizes with one error instead of trusting them.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <vtk-9.1/vtkCellArray.h>
#include <vtk-9.1/vtkCellData.h>
#include <vtk-9.1/vtkIntArray.h>
#include <vtk-9.1/vtkNew.h>
#include <vtk-9.1/vtkPoints.h>
#include <vtk-9.1/vtkPolyData.h>
#include <vtk-9.1/vtkStringArray.h>
#include <vtk-9.1/vtkXMLPolyDataWriter.h>

#include "molsurf/error.hpp"
#include "molsurf/io.hpp"

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

}  // namespace
