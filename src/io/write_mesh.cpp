// write_mesh: picks the writer from the extension; each writer is atomic.
#include "io/mesh_formats.hpp"

namespace molsurf {

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshWriteOptions& options) {
  const MeshFormat format = mesh_format_from_path(path);
  mesh_io::check_writable(path, mesh, options);
  switch (format) {
    case MeshFormat::vtp: return mesh_io::write_vtp(path, mesh, options);
    case MeshFormat::vtk: return mesh_io::write_vtk(path, mesh, options);
    case MeshFormat::ply: return mesh_io::write_ply(path, mesh, options);
    case MeshFormat::off: return mesh_io::write_off(path, mesh, options);
    case MeshFormat::stl: return mesh_io::write_stl(path, mesh, options);
    case MeshFormat::obj: return mesh_io::write_obj(path, mesh, options);
    case MeshFormat::msms: return mesh_io::write_msms(path, mesh, options);
    case MeshFormat::msh: return mesh_io::write_msh(path, mesh, options);
  }
}

}  // namespace molsurf
