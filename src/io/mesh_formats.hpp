#pragma once
// Internal: one reader/writer pair per mesh format (mesh_FORMAT.cpp), and the small
// text and binary helpers they share (mesh_format.cpp). Every writer goes through
// AtomicFile; every reader reports problems as "FILE:LINE: problem" via molsurf::fail.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/text_fields.hpp"
#include "molsurf/io.hpp"

namespace molsurf {
class AtomicFileSet;
}

namespace molsurf::mesh_io {

using std::filesystem::path;

// Writers add their file(s) to `files` and write the temporaries; the caller commits the
// set, so a mesh and its reports (or MSMS's .vert and .face) are replaced together.

void write_vtp(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_vtk(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_ply(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_off(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_stl(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_obj(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_msms(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
void write_msh(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);
// The writer for `file`'s extension (write_mesh without the commit).
void write_into(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options);

// MSMS's two files for a path naming either of them (or any stem).
struct MsmsPair {
  path vert;
  path face;
};
MsmsPair msms_pair(const path& file);

// What the readers get back from the lossy writers (see mesh_as_written in io.hpp).
Mesh msms_as_read(const Mesh& mesh, const MeshWriteOptions& options);
Mesh stl_as_read(const Mesh& mesh);

Mesh read_vtp(const path& file);
Mesh read_vtk(const path& file);
Mesh read_ply(const path& file);
Mesh read_off(const path& file);
Mesh read_stl(const path& file);
Mesh read_obj(const path& file);
Mesh read_msms(const path& file);
Mesh read_msh(const path& file);
// Whether `file` names a .pvtp index (the extension in any case, as the formats are).
bool is_pvtp_path(const path& file);
// A .pvtp index: its .vtp pieces glued along their seams (mesh_pvtp.cpp).
Mesh read_pvtp(const path& file);

// ---- shared helpers --------------------------------------------------------------

// Throws unless every index is a vertex, tags are absent or one per face, and (when
// atoms are given) every tag is kNoTag or an atom index: writers index with them.
void check_writable(const path& file, const Mesh& mesh, const MeshWriteOptions& options);
// The atom face tag `tag` names under options.atoms (and atom_tags); null for kNoTag or a
// tag no atom has.
const Atom* tagged_atom(const MeshWriteOptions& options, std::int32_t tag);

// The whole file as bytes; throws "FILE: cannot read: REASON".
std::string read_file_bytes(const path& file);

// Shortest text that parses back to exactly the same double (or float).
void append_number(std::string& out, double value);
void append_number(std::string& out, float value);
// "x y z" (shortest round-trip numbers, no newline).
void append_point(std::string& out, const Vec3& p);

using text::split_fields;

// Parsers that name the file and line in their errors; `what` says which field.
double parse_double(std::string_view text, const path& file, std::size_t line, std::string_view what);
long long parse_integer(std::string_view text, const path& file, std::size_t line, std::string_view what);

// Lines of a text file with their 1-based numbers; the trailing '\r' is dropped.
class LineReader {
 public:
  LineReader(const path& file, std::string text) : file_(file), text_(std::move(text)) {
    text::normalize_text(text_);
  }
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_number_; }
  const path& file() const { return file_; }
  [[noreturn]] void fail_here(const std::string& problem) const;

 private:
  path file_;
  std::string text_;
  std::size_t position_ = 0;
  std::size_t line_number_ = 0;
};

// Converts a polygon's vertex list to triangles (triangulate_polygon: concave polygons as
// drawn), checking each index against `vertex_count`; `line` may be 0 for binary formats. Indices are 0-based;
// `first_index` (1 for OBJ, MSMS, gmsh) only makes the error message quote the file's numbering.
void add_polygon(Mesh& mesh, std::span<const long long> polygon, std::size_t vertex_count,
                 const path& file, std::size_t line, int first_index = 0);

// Rejects non-finite coordinates and those of magnitude 1e16 or more, as the structure
// readers do (coordinate_range.hpp); "vertex N of M" counts from 1 in file order.
void check_vertex_coordinates(const Mesh& mesh, const path& file);

}  // namespace molsurf::mesh_io
