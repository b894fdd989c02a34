// MSMS's triangulated-surface pair, the input of BEM solvers (TABI-PB, PyGBe) and of
// MaSIF-style feature pipelines:
//   NAME.vert  x y z nx ny nz face_number closest_sphere type [atom_name]
//              "%9.3f x6 %7d %7d %2d", the name (when atoms are known) after a blank
//   NAME.face  v1 v2 v3 (1-based) type face_number               "%6d x3 %2d %6d"
// each after MSMS's 3-line header (what the surface is, a column legend, and "count
// #spheres density probe"), which `msms_header = false` leaves out.
//
// MSMS prints coordinates with 3 decimals, so by default this format is lossy (0.0005 A).
// Where 3 decimals would break the surface (faces that become degenerate or cross), the
// caller asks for MeshWriteOptions::msms_decimals = kMsmsExact: each coordinate is then
// the shortest fixed-point text that reads back as the same double, right-aligned in
// the same 9-character column where it fits. Readers of .vert split on whitespace
// (docs/formats.md), so the wider numbers are read correctly.
//
// The solvent-excluded surface (MeshWriteOptions::ses_arrangement given) has MSMS's three
// kinds of patch: each vertex gets its patch type, closest atom and analytic normal from the
// probe position nearest it (patch_types.hpp), each face the type its vertices share (else
// by majority, else toroidal) and its analytical face: the contact patch of an atom, the torus
// of a pair of atoms or a probe position (ses_face_count's numbering, + 1), vertices numbered
// from the faces around them as below.
//
// What MSMS's columns mean for a union of atom spheres (MSMS manual, docs/formats.md):
//  - every triangle lies on an atom's sphere, which MSMS calls a contact face: type 3
//    for every vertex and face (1 and 2 are the SES's toric and spheric reentrant faces,
//    which this surface does not have);
//  - the analytical face of a triangle is its atom's patch: tag + 1 (0 untagged). A
//    vertex inside one patch gets that patch's number; on a seam between two patches
//    (an edge of the analytical surface) minus the seam's number (seams numbered from 1
//    in order of their first vertex); where three or more patches meet (a vertex of the
//    analytical surface), 0;
//  - the closest sphere is the nearest atom by |p-c|-r among the atoms tagging the faces
//    around the vertex (face tag + 1 without atoms, 0 when untagged);
//  - the atom name is that atom as MaSIF's MSMS input names it,
//    CHAIN_RESNUM_INSERTION_RESNAME_ATOM (insertion "x" when blank), or the name an
//    .xyzr file gave it; the column is there only when some atom has a name;
//  - the normal inside one atom's patch is that sphere's outward normal at the vertex,
//    the exact normal of the surface there; on a seam, where the surface has a crease and
//    no normal, it is the area-weighted mean of the normals of the faces around the
//    vertex, the mean normal of the piece of surface the vertex stands for.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"
#include "molsurf/patch_types.hpp"

namespace molsurf::mesh_io {

namespace {

constexpr int kContactType = static_cast<int>(PatchType::contact);  // MSMS: 1 toric reentrant, 2 spheric reentrant, 3 contact

struct PairPaths {
  path vert;
  path face;
};

PairPaths pair_paths(const path& file) {
  path stem = file;
  const std::string extension = file.extension().string();
  if (extension == ".vert" || extension == ".face") stem.replace_extension();
  return {path(stem).concat(".vert"), path(stem).concat(".face")};
}

// 1-based closest sphere per vertex (0: none); see the file comment.
std::vector<long long> closest_spheres(const Mesh& mesh, std::span<const Atom> atoms) {
  std::vector<long long> closest(mesh.vertex_count(), 0);
  if (!mesh.has_tags()) return closest;
  std::vector<double> best(mesh.vertex_count(), std::numeric_limits<double>::infinity());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::int32_t tag = mesh.face_tags[f];
    if (tag < 0) continue;
    for (Index v : mesh.faces[f]) {
      // Without atoms the lowest tag wins, so the choice does not depend on face order.
      const double distance = atoms.empty() ? static_cast<double>(tag)
                                            : norm(mesh.vertices[v] - atoms[tag].centre) - atoms[tag].radius;
      if (distance < best[v] || (distance == best[v] && tag + 1 < closest[v])) {
        best[v] = distance;
        closest[v] = tag + 1;
      }
    }
  }
  return closest;
}

// The distinct atoms (face tags) of the faces around a vertex, as far as the columns need
// them: one (inside that atom's patch), two (on the seam between them) or more.
struct VertexPatches {
  std::int32_t low = kNoTag, high = kNoTag;  // the atom, or the seam's two (low < high)
  std::uint8_t count = 0;                    // distinct atoms, counted up to 3

  void add(std::int32_t tag) {
    if (count == 0) {
      low = tag;
      count = 1;
    } else if (count == 1 && tag != low) {
      high = std::max(low, tag);
      low = std::min(low, tag);
      count = 2;
    } else if (count == 2 && tag != low && tag != high) {
      count = 3;
    }
  }
};

// Per vertex, in one pass over the faces and a few bytes per vertex (no sort: a capsid's
// hundreds of millions of corners stay cheap). `face_patch` gives each face's patch (0-based;
// negative: none).
template <typename FacePatch>
std::vector<VertexPatches> vertex_patches(const Mesh& mesh, FacePatch face_patch) {
  std::vector<VertexPatches> patches(mesh.vertex_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (const std::int32_t patch = face_patch(f); patch >= 0)
      for (Index v : mesh.faces[f]) patches[v].add(patch);
  return patches;
}
std::vector<VertexPatches> vertex_patches(const Mesh& mesh) {
  return vertex_patches(mesh, [&](std::size_t f) { return mesh.tag(f); });
}

// MSMS's analytical face number of each vertex (see the file comment).
std::vector<long long> analytical_numbers(std::span<const VertexPatches> patches) {
  std::vector<long long> number(patches.size(), 0);
  std::map<std::pair<std::int32_t, std::int32_t>, long long> seams;
  for (std::size_t v = 0; v < patches.size(); ++v) {
    const VertexPatches& p = patches[v];
    if (p.count == 1) number[v] = p.low + 1LL;
    if (p.count == 2)
      number[v] = -seams.try_emplace({p.low, p.high}, static_cast<long long>(seams.size()) + 1).first->second;
  }
  return number;
}

// The SES's analytic normals, oriented as the faces are: a cavity written on its own is
// turned inside out, and its normals with it. Each connected component is turned as a whole,
// by the majority of its vertices' agreement with the faces' own normals, so that a vertex on
// a crease (whose analytic normal can be far from its faces') is not turned alone.
std::vector<Vec3> oriented_normals(const Mesh& mesh, std::span<const VertexPatch> patches) {
  const std::vector<Vec3> estimate = vertex_normals(mesh);
  const Components components = connected_components(mesh);
  std::vector<std::uint32_t> component(mesh.vertex_count(), 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (Index v : mesh.faces[f]) component[v] = components.face_component[f];
  std::vector<long long> votes(components.count, 0);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const double side = dot(patches[v].normal, estimate[v]);
    votes[component[v]] += side > 0 ? 1 : side < 0 ? -1 : 0;
  }
  std::vector<Vec3> normals(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    normals[v] = votes.empty() || votes[component[v]] >= 0 ? patches[v].normal : patches[v].normal * -1.0;
  return normals;
}

// Unit normals (see the file comment): the sphere's inside a patch, the area-weighted
// mean of the faces around the vertex elsewhere and without atoms. The sphere's normal is
// oriented as the faces are, so a component written turned inside out stays consistent.
std::vector<Vec3> msms_normals(const Mesh& mesh, std::span<const Atom> atoms,
                               std::span<const VertexPatches> patches) {
  std::vector<Vec3> normals = vertex_normals(mesh);
  if (atoms.empty()) return normals;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (patches[v].count != 1) continue;
    const Vec3 radial = mesh.vertices[v] - atoms[static_cast<std::size_t>(patches[v].low)].centre;
    const double length = norm(radial);
    const double side = dot(radial, normals[v]);
    if (length > 0 && side != 0) normals[v] = radial / (side > 0 ? length : -length);
  }
  return normals;
}

// One whitespace-free token naming an atom, as MaSIF's MSMS input does:
// CHAIN_RESNUM_INSERTION_RESNAME_ATOM, insertion "x" when blank; an atom without a
// residue (from .xyzr) by its own name. Blanks inside a name would split the column: '_'.
std::string atom_token(const Atom& atom) {
  std::string token = atom.residue_name.empty() && atom.chain.empty()
                          ? atom.atom_name
                          : atom.chain + '_' + std::to_string(atom.residue_number) + '_' +
                                (atom.insertion_code == ' ' ? 'x' : atom.insertion_code) + '_' +
                                atom.residue_name + '_' + atom.atom_name;
  for (char& c : token)
    if (static_cast<unsigned char>(c) <= ' ' || c == 0x7f) c = '_';
  return token.empty() ? "?" : token;
}

// The first header line: what the surface is, on one line; for a molecular surface (atoms
// given) also why every row has MSMS's contact type.
std::string header_comment(const char* what, const MeshWriteOptions& options) {
  std::string description = options.surface_description.empty() ? "surface" : options.surface_description;
  for (char& c : description)
    if (c == '\n' || c == '\r') c = ' ';
  const char* faces = options.atoms.empty()               ? ")\n"
                      : options.faces_on_atom_spheres ? ": a union of atom spheres, every face a contact face)\n"
                      : options.ses_arrangement       ? ": types 1 toroidal, 2 reentrant, 3 contact, from the nearest "
                                                        "probe position; normals analytic)\n"
                                                      : ": type 3 on every face; contact, toric and reentrant faces "
                                                        "not told apart)\n";
  return std::string("# MSMS-format ") + what + " of the " + description + " (molsurf " MOLSURF_VERSION + faces;
}

std::size_t sphere_count(const Mesh& mesh, std::span<const Atom> atoms) {
  if (!atoms.empty()) return atoms.size();
  std::int32_t highest = kNoTag;
  for (std::int32_t tag : mesh.face_tags) highest = std::max(highest, tag);
  return static_cast<std::size_t>(highest + 1);
}

// One coordinate as the .vert file holds it: fixed point with `decimals` decimals (or
// the shortest exact text for kMsmsExact), right-aligned in MSMS's 9 columns.
std::string_view vert_coordinate(double value, int decimals, char (&buffer)[400]) {
  const auto result = decimals == kMsmsExact
                          ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                          : std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  // 400 characters hold any double in fixed point: the longest, 5e-324, takes 326.
  return std::string_view(buffer, static_cast<std::size_t>(result.ptr - buffer));
}

void append_vert_coordinate(std::string& out, double value, int decimals) {
  char buffer[400];
  const std::string_view text = vert_coordinate(value, decimals, buffer);
  constexpr std::size_t kWidth = 9;
  if (text.size() < kWidth) out.append(kWidth - text.size(), ' ');
  out += text;
}

template <class... Args>
void append_formatted(std::string& out, const char* format, Args... args) {
  char buffer[160];
  const int length = std::snprintf(buffer, sizeof buffer, format, args...);
  out.append(buffer, static_cast<std::size_t>(std::clamp(length, 0, static_cast<int>(sizeof buffer) - 1)));
}

// MSMS's header of a .vert or .face file: the comment line, the column line and the line
// with the count, the number of spheres, the density and the probe radius.
void append_msms_header(std::string& out, const char* what, const char* count_column, std::size_t count,
                        std::size_t spheres, const MeshWriteOptions& options) {
  out += header_comment(what, options);
  out += count_column;
  out += " #sphere density probe_r\n";
  append_formatted(out, "%7zu %7zu %5.2f %5.2f\n", count, spheres, options.density, options.probe_radius);
}

// Calls on_row(fields, line) for each data row of one file of the pair, after MSMS's
// header when there is one (comment lines, then "count #spheres density probe"), and
// checks the row count against the header's.
template <class OnRow>
void for_each_row(const path& file, std::string text, const char* what, OnRow on_row) {
  LineReader lines(file, std::move(text));
  std::string_view line;
  bool expecting_counts = false;
  long long declared = -1;
  std::size_t count_line = 0;
  std::size_t rows = 0;
  while (lines.next(line)) {
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) continue;
    if (rows == 0 && declared < 0 && fields[0].front() == '#') {
      expecting_counts = true;
      continue;
    }
    if (expecting_counts) {
      expecting_counts = false;
      count_line = lines.line_number();
      declared = parse_integer(fields[0], file, count_line, std::string("number of ") + what);
      if (declared < 0) lines.fail_here("negative count");
      continue;
    }
    if (fields.size() < 3) lines.fail_here(std::string(what) + " line needs at least 3 fields");
    on_row(fields, lines.line_number());
    ++rows;
  }
  if (declared >= 0 && static_cast<std::size_t>(declared) != rows)
    fail(file, count_line, "header declares " + std::to_string(declared) + " " + what + ", file has " +
                               std::to_string(rows));
}

}  // namespace

void write_msms(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  const PairPaths paths = pair_paths(file);
  const std::vector<VertexPatches> patches = vertex_patches(mesh);
  const bool ses = options.ses_arrangement && !options.atoms.empty();
  const std::vector<VertexPatch> ses_patches =
      ses ? ses_vertex_patches(mesh.vertices, options.atoms, options.probe_radius, *options.ses_arrangement)
          : std::vector<VertexPatch>{};
  const std::vector<Vec3> normals = ses                             ? oriented_normals(mesh, ses_patches)
                                    : options.faces_on_atom_spheres ? msms_normals(mesh, options.atoms, patches)
                                                                    : vertex_normals(mesh);
  std::vector<long long> closest = closest_spheres(mesh, options.atoms);
  std::vector<int> vertex_type(mesh.vertex_count(), kContactType), face_type(mesh.face_count(), kContactType);
  std::vector<long long> face_number(mesh.face_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) face_number[f] = std::max(mesh.tag(f), kNoTag) + 1LL;
  if (ses) {
    const std::vector<std::uint32_t> numbers = face_patch_numbers(mesh, ses_patches);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) face_number[f] = numbers[f] + 1LL;
  }
  const std::vector<long long> analytical =
      analytical_numbers(ses ? vertex_patches(mesh, [&](std::size_t f) { return static_cast<std::int32_t>(face_number[f] - 1); })
                             : patches);
  if (ses) {
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      closest[v] = ses_patches[v].atom + 1LL;
      vertex_type[v] = static_cast<int>(ses_patches[v].type);
    }
    const std::vector<PatchType> types = face_patch_types(mesh, ses_patches);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) face_type[f] = static_cast<int>(types[f]);
  }
  const std::size_t spheres = sphere_count(mesh, options.atoms);
  // Names only when the atoms have some, as MSMS writes them only when its input names them.
  const bool names = options.msms_atom_names &&
                     std::any_of(options.atoms.begin(), options.atoms.end(),
                                 [](const Atom& atom) { return !atom.atom_name.empty() || !atom.residue_name.empty(); });

  std::string vert;
  vert.reserve(mesh.vertex_count() * (names ? 100 : 82) + 256);
  if (options.msms_header) append_msms_header(vert, "vertices", "#vertex", mesh.vertex_count(), spheres, options);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.vertices[v];
    const Vec3& n = normals[v];
    for (double c : {p.x, p.y, p.z}) {
      append_vert_coordinate(vert, c, options.msms_decimals);
      vert += ' ';
    }
    append_formatted(vert, "%9.3f %9.3f %9.3f %7lld %7lld %2d", n.x, n.y, n.z, analytical[v], closest[v],
                     vertex_type[v]);
    if (names) {
      vert += ' ';
      vert += closest[v] > 0 ? atom_token(options.atoms[static_cast<std::size_t>(closest[v] - 1)]) : "?";
    }
    vert += '\n';
  }

  std::string face;
  face.reserve(mesh.face_count() * 32 + 256);
  if (options.msms_header) append_msms_header(face, "faces", "#faces ", mesh.face_count(), spheres, options);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Triangle& t = mesh.faces[f];
    append_formatted(face, "%6u %6u %6u %2d %6lld\n", t[0] + 1, t[1] + 1, t[2] + 1, face_type[f], face_number[f]);
  }

  // Both go into the caller's set: both are complete before either replaces an old one.
  files.add(paths.vert).write(vert);
  files.add(paths.face).write(face);
}

MsmsPair msms_pair(const path& file) {
  const PairPaths paths = pair_paths(file);
  return {paths.vert, paths.face};
}

Mesh msms_as_read(const Mesh& mesh, const MeshWriteOptions& options) {
  Mesh rounded = mesh;
  for (Vec3& p : rounded.vertices)
    for (double* c : {&p.x, &p.y, &p.z}) {
      char buffer[400];
      const std::string_view text = vert_coordinate(*c, options.msms_decimals, buffer);
      std::from_chars(text.data(), text.data() + text.size(), *c);  // as the reader parses it
    }
  return rounded;
}

Mesh read_msms(const path& file) {
  const PairPaths paths = pair_paths(file);
  std::string vert_text = read_file_bytes(paths.vert);
  std::string face_text = read_file_bytes(paths.face);
  Mesh mesh;
  for_each_row(paths.vert, std::move(vert_text), "vertices",
               [&](const std::vector<std::string_view>& f, std::size_t n) {
                 mesh.vertices.push_back({parse_double(f[0], paths.vert, n, "x"),
                                          parse_double(f[1], paths.vert, n, "y"),
                                          parse_double(f[2], paths.vert, n, "z")});
               });
  for_each_row(paths.face, std::move(face_text), "faces", [&](const std::vector<std::string_view>& f, std::size_t n) {
    long long corners[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const long long one_based = parse_integer(f[k], paths.face, n, "vertex index");
      corners[k] = one_based > 0 ? one_based - 1 : -1;  // add_polygon rejects it, quoting 0
    }
    add_polygon(mesh, corners, mesh.vertices.size(), paths.face, n, 1);
  });
  return mesh;
}

}  // namespace molsurf::mesh_io
