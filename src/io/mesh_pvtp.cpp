// The .pvtp index of a surface in pieces (molsurf --blocks, mpirun molsurf): its pieces
// read as .vtp and glued along their seams into the one surface they are, so that
// `molsurf check` (and every reader of meshes) sees the whole. The pieces of one surface
// share their seam vertices as equal doubles (the blocks write each seam point once, with
// the same coordinates on both sides: docs/scale-out.md), so the glue merges the
// vertices of each piece's open edges that are equal in all three coordinates, and no
// others: a vertex inside a piece stays its own, and a seam that does not close shows in
// the check as open edges.
#include <array>
#include <cctype>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "io/mesh_formats.hpp"
#include "io/vtk_xml.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

// The vertices on the piece's open edges: a directed edge whose reverse no face of the
// piece has.
std::vector<bool> open_edge_vertices(const Mesh& piece) {
  std::set<std::pair<Index, Index>> edges;
  for (const Triangle& t : piece.faces)
    for (int k = 0; k < 3; ++k) edges.insert({t[k], t[(k + 1) % 3]});
  std::vector<bool> open(piece.vertex_count(), false);
  for (const auto& [a, b] : edges)
    if (!edges.contains({b, a})) open[a] = open[b] = true;
  return open;
}

}  // namespace

Mesh read_pvtp(const path& file) {
  const std::string bytes = read_file_bytes(file);
  const XmlDocument document = parse_vtk_xml(file, bytes);
  const XmlElement& root = document.elements[0];
  if (root.name != "VTKFile" || root.attribute("type") != "PPolyData")
    fail(file, root.line, "not a .pvtp index: the root is not <VTKFile type=\"PPolyData\">");
  const XmlElement* index = nullptr;
  for (const std::size_t c : root.children)
    if (document.elements[c].name == "PPolyData") index = &document.elements[c];
  if (index == nullptr) fail(file, root.line, "<VTKFile> has no <PPolyData> element");

  Mesh glued;
  std::map<std::array<double, 3>, Index> seam_vertex;  // by exact coordinates
  std::size_t pieces = 0;
  for (const std::size_t c : index->children) {
    const XmlElement& element = document.elements[c];
    if (element.name != "Piece") continue;
    const std::string_view source = element.attribute("Source").value_or("");
    if (source.empty()) fail(file, element.line, "<Piece> without a Source file");
    const path piece_path = path(source).is_absolute() ? path(source) : file.parent_path() / path(source);
    Mesh piece;
    try {
      piece = read_vtp(piece_path);
    } catch (const Error& e) {
      fail(file, element.line, std::string("piece ") + e.what());
    }
    ++pieces;
    const std::vector<bool> open = open_edge_vertices(piece);
    std::vector<Index> glued_index(piece.vertex_count());
    for (std::size_t v = 0; v < piece.vertex_count(); ++v) {
      const Vec3& p = piece.vertices[v];
      const auto next = static_cast<Index>(glued.vertices.size());
      if (open[v]) {
        const auto [at, inserted] = seam_vertex.try_emplace({p.x, p.y, p.z}, next);
        if (inserted) glued.vertices.push_back(p);
        glued_index[v] = at->second;
      } else {
        glued.vertices.push_back(p);
        glued_index[v] = next;
      }
    }
    // Tags as Mesh::append keeps them: untagged faces beside tagged ones get kNoTag.
    const bool tagged = glued.has_tags() || piece.has_tags();
    if (tagged) glued.face_tags.resize(glued.faces.size(), kNoTag);
    for (const Triangle& t : piece.faces)
      glued.faces.push_back({glued_index[t[0]], glued_index[t[1]], glued_index[t[2]]});
    if (tagged && piece.has_tags())
      glued.face_tags.insert(glued.face_tags.end(), piece.face_tags.begin(), piece.face_tags.end());
    if (tagged) glued.face_tags.resize(glued.faces.size(), kNoTag);
  }
  if (pieces == 0) fail(file, index->line, "the index lists no <Piece>");
  return glued;
}

bool is_pvtp_path(const path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".pvtp";
}

}  // namespace molsurf::mesh_io
