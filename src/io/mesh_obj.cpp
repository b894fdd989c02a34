// Wavefront OBJ: "v" vertices, "vn" area-weighted vertex normals, "f a//a b//b c//c".
// No per-face data, so tags are not stored. Coordinates are exact (shortest round-trip text).
#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

void write_obj(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions&) {
  const std::vector<Vec3> normals = vertex_normals(mesh);
  std::string text = "# molsurf " MOLSURF_VERSION "\n";
  text.reserve(mesh.vertex_count() * 110 + mesh.face_count() * 40 + 64);
  const auto append_vector = [&text](const char* keyword, const Vec3& p) {
    text += keyword;
    append_point(text, p);
    text += '\n';
  };
  for (const Vec3& p : mesh.vertices) append_vector("v ", p);
  for (const Vec3& n : normals) append_vector("vn ", n);
  for (const Triangle& t : mesh.faces) {
    text += 'f';
    for (Index v : t) {
      const std::string one_based = std::to_string(v + 1);
      text += ' ' + one_based + "//" + one_based;
    }
    text += '\n';
  }
  files.add(file).write(text);
}

namespace {

// "i", "i/t", "i//n" or "i/t/n": the vertex is the first number; negative counts back
// from the latest vertex.
long long obj_vertex_index(std::string_view corner, std::size_t vertex_count, const path& file,
                           std::size_t line) {
  const std::string_view first = corner.substr(0, corner.find('/'));
  const long long index = parse_integer(first, file, line, "face vertex");
  if (index == 0) fail(file, line, "face vertex index 0 (OBJ indices start at 1)");
  if (index < 0) {
    const long long absolute = static_cast<long long>(vertex_count) + index;  // 0-based
    if (absolute < 0)
      fail(file, line, "relative vertex index " + std::to_string(index) + " reaches before the first vertex");
    return absolute;
  }
  return index - 1;
}

}  // namespace

Mesh read_obj(const path& file) {
  LineReader lines(file, read_file_bytes(file));
  Mesh mesh;
  std::string_view line;
  std::vector<long long> polygon;
  while (lines.next(line)) {
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) continue;
    const std::size_t n = lines.line_number();
    if (fields[0] == "v") {
      if (fields.size() < 4) lines.fail_here("vertex needs 3 coordinates");
      mesh.vertices.push_back({parse_double(fields[1], file, n, "x"), parse_double(fields[2], file, n, "y"),
                               parse_double(fields[3], file, n, "z")});
    } else if (fields[0] == "f") {
      polygon.clear();
      for (std::size_t i = 1; i < fields.size(); ++i)
        polygon.push_back(obj_vertex_index(fields[i], mesh.vertices.size(), file, n));
      add_polygon(mesh, polygon, mesh.vertices.size(), file, n, 1);
    }
    // Everything else (vn, vt, g, o, s, usemtl, mtllib, l, p) carries nothing we keep.
  }
  return mesh;
}

}  // namespace molsurf::mesh_io
