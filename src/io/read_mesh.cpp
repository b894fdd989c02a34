// read_mesh: picks the reader from the extension, then checks what every reader
// promises (indices in range, coordinates finite and below 1e16 in magnitude, one tag per
// face or none).
#include <string>

#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf {

namespace {

Mesh read_by_format(const std::filesystem::path& path, MeshFormat format) {
  switch (format) {
    case MeshFormat::vtp: return mesh_io::read_vtp(path);
    case MeshFormat::vtk: return mesh_io::read_vtk(path);
    case MeshFormat::ply: return mesh_io::read_ply(path);
    case MeshFormat::off: return mesh_io::read_off(path);
    case MeshFormat::stl: return mesh_io::read_stl(path);
    case MeshFormat::obj: return mesh_io::read_obj(path);
    case MeshFormat::msms: return mesh_io::read_msms(path);
    case MeshFormat::msh: return mesh_io::read_msh(path);
  }
  fail(path, "unknown mesh format");
}

}  // namespace

Mesh read_mesh(const std::filesystem::path& path) {
  // A surface in pieces: written only by the blocked surface (its pieces and index), read
  // as the one mesh it is; no MeshFormat of its own.
  Mesh mesh = mesh_io::is_pvtp_path(path) ? mesh_io::read_pvtp(path) : read_by_format(path, mesh_format_from_path(path));
  mesh_io::check_vertex_coordinates(mesh, path);
  if (mesh.has_tags() && mesh.face_tags.size() != mesh.face_count())
    fail(path, "internal: " + std::to_string(mesh.face_tags.size()) + " tags for " +
                   std::to_string(mesh.face_count()) + " faces");
  return mesh;
}

}  // namespace molsurf
