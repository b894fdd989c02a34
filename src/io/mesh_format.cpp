// Format detection from file names, and the helpers every mesh format shares.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/message_text.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "io/coordinate_range.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"
#include "molsurf/input_checks.hpp"

namespace molsurf {

MeshFormat mesh_format_from_path(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".vtp") return MeshFormat::vtp;
  if (extension == ".vtk") return MeshFormat::vtk;
  if (extension == ".ply") return MeshFormat::ply;
  if (extension == ".off") return MeshFormat::off;
  if (extension == ".stl") return MeshFormat::stl;
  if (extension == ".obj") return MeshFormat::obj;
  if (extension == ".vert" || extension == ".face") return MeshFormat::msms;
  if (extension == ".msh") return MeshFormat::msh;
  fail(path, "unknown mesh format '" + extension +
                 "' (expected .vtp .vtk .ply .off .stl .obj .vert/.face or .msh)");
}

const char* mesh_format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::vtp: return "VTK XML PolyData (.vtp)";
    case MeshFormat::vtk: return "legacy VTK (.vtk)";
    case MeshFormat::ply: return "PLY (.ply)";
    case MeshFormat::off: return "OFF (.off)";
    case MeshFormat::stl: return "STL (.stl)";
    case MeshFormat::obj: return "Wavefront OBJ (.obj)";
    case MeshFormat::msms: return "MSMS (.vert/.face)";
    case MeshFormat::msh: return "gmsh 2.2 (.msh)";
  }
  return "unknown";
}

}  // namespace molsurf

namespace molsurf::mesh_io {

void check_writable(const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  const std::size_t vertex_count = mesh.vertex_count();
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (Index v : mesh.faces[f])
      if (v >= vertex_count)
        fail(file, "cannot write: face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                       " of a mesh with " + std::to_string(vertex_count) + " vertices");
  if (mesh.has_tags() && mesh.face_tags.size() != mesh.face_count())
    fail(file, "cannot write: " + std::to_string(mesh.face_tags.size()) + " face tags for " +
                   std::to_string(mesh.face_count()) + " faces");
  if (options.atoms.empty()) return;
  if (!options.atom_tags.empty()) {
    const MeshFormat format = mesh_format_from_path(file);
    if (format != MeshFormat::vtp && format != MeshFormat::vtk)
      fail(file, "cannot write: atoms tagged by their index in a larger structure go to .vtp and .vtk only");
    if (options.atom_tags.size() != options.atoms.size())
      fail(file, "cannot write: " + std::to_string(options.atom_tags.size()) + " atom tags for " +
                     std::to_string(options.atoms.size()) + " atoms");
  }
  for (std::size_t f = 0; f < mesh.face_tags.size(); ++f) {
    const std::int32_t tag = mesh.face_tags[f];
    if (tag != kNoTag && tagged_atom(options, tag) == nullptr)
      fail(file, "cannot write: face " + std::to_string(f) + " has tag " + std::to_string(tag) +
                     ", not an index into the " + std::to_string(options.atoms.size()) + " atoms");
  }
}

const Atom* tagged_atom(const MeshWriteOptions& options, std::int32_t tag) {
  if (tag < 0) return nullptr;
  const auto t = static_cast<std::uint32_t>(tag);
  if (options.atom_tags.empty()) return t < options.atoms.size() ? &options.atoms[t] : nullptr;
  const auto it = std::lower_bound(options.atom_tags.begin(), options.atom_tags.end(), t);
  if (it == options.atom_tags.end() || *it != t) return nullptr;
  return &options.atoms[static_cast<std::size_t>(it - options.atom_tags.begin())];
}

std::string read_file_bytes(const path& file) {
  // A device or pipe has no size to bound (/dev/zero never ends), and opening a pipe
  // would wait for a writer: refused before the open.
  std::error_code status_error;
  const auto type = std::filesystem::status(file, status_error).type();
  if (!status_error && type != std::filesystem::file_type::regular && type != std::filesystem::file_type::directory &&
      type != std::filesystem::file_type::not_found)
    fail(file, "cannot read: it is a device, pipe or socket, not a regular file; give a file");
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, std::string("cannot read: ") + (errno ? std::strerror(errno) : "cannot open"));
  std::error_code error;
  if (std::filesystem::is_directory(file, error)) fail(file, "cannot read: Is a directory");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) fail(file, "cannot read: read error");
  // No format reads a zero-byte file as a mesh: an empty .obj or .vert/.face would
  // otherwise pass for an empty surface.
  if (content.view().empty()) fail(file, "empty file (0 bytes)");
  return std::move(content).str();
}

void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_point(std::string& out, const Vec3& p) {
  append_number(out, p.x);
  out += ' ';
  append_number(out, p.y);
  out += ' ';
  append_number(out, p.z);
}

void append_number(std::string& out, float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

namespace {

std::string quoted(std::string_view text) { return detail::quoted_text(text, 40); }

}  // namespace

double parse_double(std::string_view text, const path& file, std::size_t line, std::string_view what) {
  // from_chars rejects a leading '+', which some writers emit.
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec == std::errc::result_out_of_range)
    fail(file, line, std::string(what) + ": number out of range " + quoted(text));
  if (result.ec != std::errc() || result.ptr != text.data() + text.size())
    fail(file, line, std::string(what) + ": expected a number, found " + quoted(text));
  if (!std::isfinite(value)) fail(file, line, std::string(what) + ": " + coordinate_problem(value));
  return value;
}

long long parse_integer(std::string_view text, const path& file, std::size_t line, std::string_view what) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec == std::errc::result_out_of_range)
    fail(file, line, std::string(what) + ": integer out of range " + quoted(text));
  if (result.ec != std::errc() || result.ptr != text.data() + text.size())
    fail(file, line, std::string(what) + ": " + integer_text_problem(text));
  return value;
}

bool LineReader::next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', position_);
  if (end == std::string::npos) end = text_.size();
  line = std::string_view(text_).substr(position_, end - position_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  position_ = end + 1;
  ++line_number_;
  return true;
}

void LineReader::fail_here(const std::string& problem) const { fail(file_, line_number_, problem); }

void add_polygon(Mesh& mesh, std::span<const long long> polygon, std::size_t vertex_count,
                 const path& file, std::size_t line, int first_index) {
  if (polygon.size() < 3)
    fail(file, line, "face with " + std::to_string(polygon.size()) + " vertices (need at least 3)");
  for (long long v : polygon)
    if (std::string problem = vertex_index_problem(v + first_index, vertex_count, first_index); !problem.empty())
      fail(file, line, problem);
  if (polygon.size() == 3) {
    mesh.faces.push_back({static_cast<Index>(polygon[0]), static_cast<Index>(polygon[1]), static_cast<Index>(polygon[2])});
    return;
  }
  // Every reader has its vertices when it meets a face that uses them (the indices were
  // just checked against the vertices read), so the polygon is triangulated as drawn.
  std::vector<Index> corners(polygon.begin(), polygon.end());
  if (vertex_count > mesh.vertices.size())
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) mesh.faces.push_back({corners[0], corners[i], corners[i + 1]});
  else
    for (const Triangle& t : triangulate_polygon(mesh.vertices, corners)) mesh.faces.push_back(t);
}

void check_vertex_coordinates(const Mesh& mesh, const path& file) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.vertices[v];
    const double xyz[] = {p.x, p.y, p.z};
    for (int axis = 0; axis < 3; ++axis)
      detail::check_coordinate_range(file, 0, xyz[axis], "vertex " + std::to_string(v + 1) + " of " +
                                                             std::to_string(mesh.vertex_count()) + ": " +
                                                             kAxes[axis] + " coordinate");
  }
}


}  // namespace molsurf::mesh_io
