// write_mesh: picks the writer from the extension; all files of one mesh are replaced
// together (AtomicFileSet). Also what each format does to coordinates (mesh_as_written).
#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "common/thread_count_scope.hpp"

namespace molsurf {

namespace mesh_io {

void write_into(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  const MeshFormat format = mesh_format_from_path(file);
  check_writable(file, mesh, options);
  const ThreadCountScope thread_count(options.threads);
  switch (format) {
    case MeshFormat::vtp: return write_vtp(files, file, mesh, options);
    case MeshFormat::vtk: return write_vtk(files, file, mesh, options);
    case MeshFormat::ply: return write_ply(files, file, mesh, options);
    case MeshFormat::off: return write_off(files, file, mesh, options);
    case MeshFormat::stl: return write_stl(files, file, mesh, options);
    case MeshFormat::obj: return write_obj(files, file, mesh, options);
    case MeshFormat::msms: return write_msms(files, file, mesh, options);
    case MeshFormat::msh: return write_msh(files, file, mesh, options);
  }
}

}  // namespace mesh_io

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshWriteOptions& options) {
  AtomicFileSet files;
  mesh_io::write_into(files, path, mesh, options);
  files.commit();
}

std::vector<std::filesystem::path> mesh_output_files(const std::filesystem::path& path) {
  if (mesh_format_from_path(path) != MeshFormat::msms) return {path};
  const mesh_io::MsmsPair pair = mesh_io::msms_pair(path);
  return {pair.vert, pair.face};
}

bool mesh_format_is_exact(MeshFormat format, const MeshWriteOptions& options) {
  if (format == MeshFormat::stl) return false;
  if (format == MeshFormat::msms) return options.msms_decimals == kMsmsExact;
  return true;
}

Mesh mesh_as_written(const Mesh& mesh, MeshFormat format, const MeshWriteOptions& options) {
  if (mesh_format_is_exact(format, options)) return mesh;
  return format == MeshFormat::stl ? mesh_io::stl_as_read(mesh) : mesh_io::msms_as_read(mesh, options);
}

}  // namespace molsurf
