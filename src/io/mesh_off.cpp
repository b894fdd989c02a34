// Object File Format: "OFF", counts, vertices, polygons. No normals or tags.
// Coordinates are written as shortest round-trip text, so the geometry is exact.
#include <algorithm>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

void write_off(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions&) {
  std::string text = "OFF\n" + std::to_string(mesh.vertex_count()) + " " +
                     std::to_string(mesh.face_count()) + " 0\n";
  text.reserve(text.size() + mesh.vertex_count() * 60 + mesh.face_count() * 24);
  for (const Vec3& p : mesh.vertices) {
    append_point(text, p);
    text += '\n';
  }
  for (const Triangle& t : mesh.faces)
    text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  files.add(file).write(text);
}

namespace {

// The next line holding data: comments ('#' to end of line) and blank lines skipped.
bool next_data_line(LineReader& lines, std::vector<std::string_view>& fields) {
  std::string_view line;
  while (lines.next(line)) {
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    fields = split_fields(line);
    if (!fields.empty()) return true;
  }
  return false;
}

}  // namespace

Mesh read_off(const path& file) {
  LineReader lines(file, read_file_bytes(file));
  std::vector<std::string_view> fields;
  if (!next_data_line(lines, fields) || fields[0] != "OFF")
    fail(file, lines.line_number(), "not an OFF file (first line must be 'OFF')");
  fields.erase(fields.begin());  // counts may follow "OFF" on the same line
  if (fields.empty() && !next_data_line(lines, fields))
    fail(file, lines.line_number(), "missing vertex and face counts");
  if (fields.size() < 2) lines.fail_here("expected vertex, face and edge counts");
  const long long vertex_count = parse_integer(fields[0], file, lines.line_number(), "vertex count");
  const long long face_count = parse_integer(fields[1], file, lines.line_number(), "face count");
  if (vertex_count < 0 || face_count < 0) lines.fail_here("negative count");

  Mesh mesh;
  // Counts come from the file: reserve only what a file of this size could hold.
  mesh.vertices.reserve(static_cast<std::size_t>(std::min<long long>(vertex_count, 1 << 20)));
  for (long long v = 0; v < vertex_count; ++v) {
    if (!next_data_line(lines, fields))
      fail(file, lines.line_number(), "truncated: expected " + std::to_string(vertex_count) +
                                           " vertices, file ends after " + std::to_string(v));
    if (fields.size() < 3) lines.fail_here("vertex needs 3 coordinates");
    const std::size_t n = lines.line_number();
    mesh.vertices.push_back({parse_double(fields[0], file, n, "x"), parse_double(fields[1], file, n, "y"),
                             parse_double(fields[2], file, n, "z")});
  }
  std::vector<long long> polygon;
  for (long long f = 0; f < face_count; ++f) {
    if (!next_data_line(lines, fields))
      fail(file, lines.line_number(), "truncated: expected " + std::to_string(face_count) +
                                           " faces, file ends after " + std::to_string(f));
    const std::size_t n = lines.line_number();
    const long long corners = parse_integer(fields[0], file, n, "polygon size");
    if (corners < 3) lines.fail_here("face with " + std::to_string(corners) + " vertices (need at least 3)");
    if (static_cast<long long>(fields.size()) - 1 < corners)
      lines.fail_here("face lists " + std::to_string(fields.size() - 1) + " of its " +
                      std::to_string(corners) + " vertices");
    polygon.clear();
    // Anything after the indices is a colour, which we do not keep.
    for (long long i = 1; i <= corners; ++i)
      polygon.push_back(parse_integer(fields[static_cast<std::size_t>(i)], file, n, "vertex index"));
    add_polygon(mesh, polygon, mesh.vertices.size(), file, n);
  }
  // Data past the declared counts means the counts are wrong: refuse rather than drop it.
  if (next_data_line(lines, fields))
    lines.fail_here("data after the declared " + std::to_string(vertex_count) + " vertices and " +
                    std::to_string(face_count) + " faces (wrong counts?)");
  return mesh;
}

}  // namespace molsurf::mesh_io
