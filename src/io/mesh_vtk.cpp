// VTK PolyData through VTK itself: XML .vtp (binary, zlib-compressed, appended) and
// legacy .vtk (binary, file version 4.2 so that pre-9.0 readers open it too). Reading .vtp
// goes through VTK after vtp_guard.cpp has checked its sizes; legacy .vtk is read by our
// own reader (mesh_vtk_legacy.cpp), since VTK's trusts every count in the file.
// Stored: double points (exact), area-weighted point normals, cell data "tag" and,
// when atoms are given, "atom_serial", "residue_number", "residue_name", "chain" of
// each face's atom. VTK writes to AtomicFile's temporary, never to the target itself.
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "io/vtp_guard.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

// Collects VTK's error messages from one algorithm instead of letting them go to
// stderr, so they can be put into our exception.
class ErrorCollector : public vtkCommand {
 public:
  static ErrorCollector* New() { return new ErrorCollector; }  // VTK's factory idiom
  void Execute(vtkObject*, unsigned long, void* call_data) override {
    if (call_data != nullptr && messages.empty()) messages = static_cast<const char*>(call_data);
  }
  std::string messages;
};

// VTK objects other than the algorithm (the XML parser, the zlib decompressor) report
// errors to the terminal, through vtkLogger and the output window, unless global warning
// display is off. While one guard lives it is off (our one-line error says what failed);
// the previous setting comes back after. Reads and writes are not concurrent.
class QuietVtkOutput {
 public:
  QuietVtkOutput() : previous_(vtkObject::GetGlobalWarningDisplay()) { vtkObject::GlobalWarningDisplayOff(); }
  ~QuietVtkOutput() { vtkObject::SetGlobalWarningDisplay(previous_); }
  QuietVtkOutput(const QuietVtkOutput&) = delete;
  QuietVtkOutput& operator=(const QuietVtkOutput&) = delete;

 private:
  int previous_;
};

std::string first_line(std::string text) {
  // VTK prefixes "ERROR: In FILE.cxx, line N\nClass (0x...): "; keep what follows.
  if (const std::size_t colon = text.rfind("): "); colon != std::string::npos) text = text.substr(colon + 3);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (const std::size_t newline = text.find('\n'); newline != std::string::npos) text.resize(newline);
  return text;
}

vtkSmartPointer<vtkPolyData> to_polydata(const Mesh& mesh, const MeshWriteOptions& options) {
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertex_count()));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.vertices[v];
    points->SetPoint(static_cast<vtkIdType>(v), p.x, p.y, p.z);
  }
  polydata->SetPoints(points);

  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(mesh.face_count()), static_cast<vtkIdType>(3 * mesh.face_count()));
  for (const Triangle& t : mesh.faces) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  polydata->SetPolys(polys);

  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertex_count()));
  const std::vector<Vec3> vertex_normal = vertex_normals(mesh);
  for (std::size_t v = 0; v < vertex_normal.size(); ++v)
    normals->SetTuple3(static_cast<vtkIdType>(v), vertex_normal[v].x, vertex_normal[v].y, vertex_normal[v].z);
  polydata->GetPointData()->SetNormals(normals);

  if (!mesh.has_tags()) return polydata;
  const auto faces = static_cast<vtkIdType>(mesh.face_count());
  vtkNew<vtkIntArray> tags;
  tags->SetName("tag");
  tags->SetNumberOfTuples(faces);
  for (vtkIdType f = 0; f < faces; ++f) tags->SetValue(f, mesh.face_tags[static_cast<std::size_t>(f)]);
  polydata->GetCellData()->AddArray(tags);
  if (options.atoms.empty()) return polydata;

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
    // check_writable guarantees tag is kNoTag or an atom index.
    const Atom* atom = tag >= 0 ? &options.atoms[static_cast<std::size_t>(tag)] : nullptr;
    serial->SetValue(f, atom ? atom->serial : 0);
    residue_number->SetValue(f, atom ? atom->residue_number : 0);
    residue_name->SetValue(f, atom ? atom->residue_name : "");
    chain->SetValue(f, atom ? atom->chain : "");
  }
  for (vtkAbstractArray* array : std::initializer_list<vtkAbstractArray*>{serial, residue_number, residue_name, chain})
    polydata->GetCellData()->AddArray(array);
  return polydata;
}

template <class Writer>
void write_with(vtkNew<Writer>& writer, AtomicFileSet& files, const path& file, const Mesh& mesh,
                const MeshWriteOptions& options) {
  const vtkSmartPointer<vtkPolyData> polydata = to_polydata(mesh, options);
  AtomicFile& output = files.add(file);
  vtkNew<ErrorCollector> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(polydata);
  writer->SetFileName(output.temp_path().c_str());
  const int written = writer->Write();
  if (written != 1 || writer->GetErrorCode() != 0 || !errors->messages.empty())
    fail(file, "cannot write: " + (errors->messages.empty() ? std::string("VTK writer failed")
                                                            : first_line(errors->messages)));
}

// Cell data arrays are indexed over verts, lines, polys, strips in that order.
Mesh from_polydata(const path& file, vtkPolyData* polydata) {
  Mesh mesh;
  const vtkIdType point_count = polydata->GetNumberOfPoints();
  mesh.vertices.reserve(static_cast<std::size_t>(point_count));
  for (vtkIdType i = 0; i < point_count; ++i) {
    double p[3];
    polydata->GetPoint(i, p);
    mesh.vertices.push_back({p[0], p[1], p[2]});
  }
  vtkDataArray* tag_array = polydata->GetCellData()->GetArray("tag");
  if (tag_array != nullptr && tag_array->GetNumberOfComponents() != 1) tag_array = nullptr;
  const vtkIdType first_poly = polydata->GetNumberOfVerts() + polydata->GetNumberOfLines();
  const vtkIdType first_strip = first_poly + polydata->GetNumberOfPolys();
  if (tag_array != nullptr && tag_array->GetNumberOfTuples() < first_strip + polydata->GetNumberOfStrips())
    fail(file, "cell data 'tag' has fewer values than there are cells");

  const auto tag_of = [&](vtkIdType cell) -> std::int32_t {
    const double value = tag_array->GetComponent(cell, 0);
    if (!(value >= INT32_MIN && value <= INT32_MAX) || value != std::floor(value))
      fail(file, "cell " + std::to_string(cell) + ": tag is not a 32-bit integer");
    return static_cast<std::int32_t>(value);
  };
  const auto add_cell = [&](const std::vector<long long>& polygon, vtkIdType cell) {
    add_polygon(mesh, polygon, mesh.vertices.size(), file, 0);
    if (tag_array != nullptr) mesh.face_tags.resize(mesh.faces.size(), tag_of(cell));
  };

  std::vector<long long> polygon;
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = polydata->GetPolys();
  for (vtkIdType cell = 0; cell < polys->GetNumberOfCells(); ++cell) {
    polys->GetCellAtId(cell, size, ids);
    polygon.assign(ids, ids + size);
    add_cell(polygon, first_poly + cell);
  }
  // A strip's triangle k is (k, k+1, k+2), every other one reversed to keep orientation.
  vtkCellArray* strips = polydata->GetStrips();
  for (vtkIdType cell = 0; cell < strips->GetNumberOfCells(); ++cell) {
    strips->GetCellAtId(cell, size, ids);
    if (size < 3) fail(file, "triangle strip " + std::to_string(cell) + " has fewer than 3 points");
    for (vtkIdType k = 0; k + 2 < size; ++k) {
      if (k % 2 == 0) polygon = {ids[k], ids[k + 1], ids[k + 2]};
      else polygon = {ids[k + 1], ids[k], ids[k + 2]};
      add_cell(polygon, first_strip + cell);
    }
  }
  return mesh;
}

template <class Reader>
Mesh read_with(vtkNew<Reader>& reader, const path& file) {
  const std::string bytes = read_file_bytes(file);  // a missing file gets our usual message
  check_vtp_sizes(file, bytes);                       // before VTK allocates what they declare
  const QuietVtkOutput quiet;
  vtkNew<ErrorCollector> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(file.c_str());
  int updated = 0;
  try {
    updated = reader->UpdatePiece(0, 1, 0);
  } catch (const std::exception& error) {
    // A damaged size field makes VTK attempt an impossible allocation.
    fail(file, std::string("cannot read: corrupt data (") + error.what() + ")");
  }
  if (updated != 1 || reader->GetErrorCode() != 0 || !errors->messages.empty())
    fail(file, "cannot read: " + (errors->messages.empty() ? std::string("VTK reader failed")
                                                           : first_line(errors->messages)));
  vtkPolyData* output = reader->GetOutput();
  if (output == nullptr) fail(file, "cannot read: VTK reader produced no PolyData");
  return from_polydata(file, output);
}

}  // namespace

void write_vtp(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes, not base64
  writer->SetCompressorTypeToZLib();
  // Level 1 rather than zlib's default: on 2hhb the file is 2 % larger and the write
  // stage drops from 0.28 to 0.20 s.
  writer->SetCompressionLevel(1);
  writer->SetHeaderTypeToUInt64();  // arrays beyond 4 GB stay readable
  write_with(writer, files, file, mesh, options);
}

void write_vtk(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetFileTypeToBinary();
  writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
  writer->SetHeader("molsurf " MOLSURF_VERSION);
  write_with(writer, files, file, mesh, options);
}

Mesh read_vtp(const path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  return read_with(reader, file);
}

}  // namespace molsurf::mesh_io
