// Legacy VTK PolyData written through VTK itself (binary, file version 4.2 so that pre-9.0
// readers open it too; .vtp has a writer of our own, mesh_vtp_writer.cpp). Read by a
// reader of our own (mesh_vtk_legacy.cpp), since VTK's trusts every size in the file.
// Stored: double points (exact), area-weighted point normals, cell data "tag" and,
// when atoms are given, "atom_serial", "residue_number", "residue_name", "chain" of
// each face's atom. VTK writes to AtomicFile's temporary, never to the target itself.
#include <cerrno>
#include <cstring>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>


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
  // 32-bit ids while they fit (point ids are signed): a third less to compress and write.
  if (mesh.vertex_count() < (std::size_t{1} << 31) && 3 * mesh.face_count() < (std::size_t{1} << 31))
    polys->Use32BitStorage();
  polys->AllocateExact(static_cast<vtkIdType>(mesh.face_count()), static_cast<vtkIdType>(3 * mesh.face_count()));
  for (const Triangle& t : mesh.faces) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  polydata->SetPolys(polys);

  // Unit normals need no more than float32: half the bytes of the largest array after the
  // points.
  vtkNew<vtkFloatArray> normals;
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
    residue_number->SetValue(f, atom ? residue_number_32(atom->residue_number) : 0);
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
  errno = 0;
  const int written = writer->Write();
  const int error_number = errno;
  if (written != 1 || writer->GetErrorCode() != 0 || !errors->messages.empty())
    // The system's reason when there is one: VTK's own message names the temporary.
    fail(file, "cannot write: " + (error_number != 0         ? std::string(std::strerror(error_number))
                                   : errors->messages.empty() ? std::string("VTK writer failed")
                                                              : first_line(errors->messages)));
}

}  // namespace

void write_vtk(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetFileTypeToBinary();
  writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
  writer->SetHeader("molsurf " MOLSURF_VERSION);
  write_with(writer, files, file, mesh, options);
}

}  // namespace molsurf::mesh_io
