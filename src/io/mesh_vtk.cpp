// VTK PolyData through VTK itself: XML .vtp (binary, zlib-compressed, appended) and
// legacy .vtk (binary, file version 4.2 so that pre-9.0 readers open it too).
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
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <type_traits>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
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
void write_with(vtkNew<Writer>& writer, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  const vtkSmartPointer<vtkPolyData> polydata = to_polydata(mesh, options);
  AtomicFile output(file);
  vtkNew<ErrorCollector> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(polydata);
  writer->SetFileName(output.temp_path().c_str());
  const int written = writer->Write();
  if (written != 1 || writer->GetErrorCode() != 0 || !errors->messages.empty())
    fail(file, "cannot write: " + (errors->messages.empty() ? std::string("VTK writer failed")
                                                            : first_line(errors->messages)));
  output.commit();
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

// VTK 9.1's legacy reader trusts the per-cell counts of a 4.2-format cell section
// ("POLYGONS n size" then n runs of "k id1 .. idk") and writes past its buffer when a
// damaged file's counts disagree with `size`. Walk those sections first.
void check_legacy_cell_sections(const path& file, const std::string& bytes) {
  // Line 3 says ASCII or BINARY (line 1 is the version, line 2 a free title).
  const std::size_t first_end = bytes.find('\n');
  const std::size_t second_end = first_end == std::string::npos ? first_end : bytes.find('\n', first_end + 1);
  const bool binary = second_end != std::string::npos && bytes.compare(second_end + 1, 6, "BINARY") == 0;
  for (const char* keyword : {"\nVERTICES ", "\nLINES ", "\nPOLYGONS ", "\nTRIANGLE_STRIPS "}) {
    for (std::size_t at = bytes.find(keyword); at != std::string::npos; at = bytes.find(keyword, at + 1)) {
      const std::size_t line_end = bytes.find('\n', at + 1);
      if (line_end == std::string::npos) fail(file, "truncated cell section");
      const std::vector<std::string_view> fields =
          split_fields(std::string_view(bytes).substr(at + 1, line_end - at - 1));
      if (fields.size() != 3) fail(file, "bad cell section header");
      const long long cells = parse_integer(fields[1], file, 0, "cell count");
      const long long size = parse_integer(fields[2], file, 0, "cell list size");
      if (cells < 0 || size < 0) fail(file, "negative cell count");
      if (bytes.compare(line_end + 1, 7, "OFFSETS") == 0) continue;  // 5.1 layout: VTK checks offsets itself
      std::vector<long long> values;
      if (binary) {
        if (static_cast<unsigned long long>(size) > (bytes.size() - line_end - 1) / 4)
          fail(file, "truncated: cell list of " + std::to_string(size) + " values");
        for (long long i = 0; i < size; ++i) {
          std::uint32_t word = 0;
          for (std::size_t b = 0; b < 4; ++b)
            word = (word << 8) | static_cast<unsigned char>(bytes[line_end + 1 + 4 * static_cast<std::size_t>(i) + b]);
          values.push_back(static_cast<std::int32_t>(word));
        }
      } else {
        std::size_t position = line_end + 1;
        for (long long i = 0; i < size; ++i) {
          position = bytes.find_first_not_of(" \t\r\n", position);
          if (position == std::string::npos) fail(file, "truncated: cell list of " + std::to_string(size) + " values");
          const std::size_t end = std::min(bytes.find_first_of(" \t\r\n", position), bytes.size());
          values.push_back(parse_integer(std::string_view(bytes).substr(position, end - position), file, 0, "cell list"));
          position = end;
        }
      }
      long long used = 0;
      for (long long cell = 0; cell < cells; ++cell) {
        if (used >= size || values[static_cast<std::size_t>(used)] < 0 ||
            values[static_cast<std::size_t>(used)] > size - used - 1)
          fail(file, "cell list is inconsistent with its size");
        used += values[static_cast<std::size_t>(used)] + 1;
      }
      if (used != size) fail(file, "cell list is inconsistent with its size");
    }
  }
}

template <class Reader>
Mesh read_with(vtkNew<Reader>& reader, const path& file) {
  const std::string bytes = read_file_bytes(file);  // a missing file gets our usual message
  if constexpr (std::is_same_v<Reader, vtkPolyDataReader>) check_legacy_cell_sections(file, bytes);
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

void write_vtp(const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes, not base64
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // arrays beyond 4 GB stay readable
  write_with(writer, file, mesh, options);
}

void write_vtk(const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetFileTypeToBinary();
  writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
  writer->SetHeader("molsurf " MOLSURF_VERSION);
  write_with(writer, file, mesh, options);
}

Mesh read_vtp(const path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  return read_with(reader, file);
}

Mesh read_vtk(const path& file) {
  vtkNew<vtkPolyDataReader> reader;
  reader->ReadAllScalarsOn();  // not only the active scalars: "tag" is a plain field
  reader->ReadAllFieldsOn();
  return read_with(reader, file);
}

}  // namespace molsurf::mesh_io
