// gmsh MSH 2.2 ASCII, the version bempp and most BEM/FEM tools read: $Nodes, then
// $Elements of type 2 (3-node triangle) with two tags, physical and elementary. Both are
// the face's closed component, numbered in the report's order (1: the outer surface, then
// the cavities; $PhysicalNames calls them "outer", "cavity-1", ...): gmsh makes one
// discrete surface per elementary tag, and a mesher needs one surface loop per closed
// boundary. With one surface per atom, as the tags once were, gmsh's boundary recovery
// failed around the molecule (an assertion in 2hhb, an empty volume with a cavity in the
// hole's loop in 1crn). Which atom each face belongs to is kept as $ElementData "atom"
// (atom index + 1; 0: untagged), which gmsh shows as a view and meshio reads as cell data.
// Coordinates are shortest round-trip text: exact. Reading keeps triangles, skips points
// and lines, and gives each face the "atom" value - 1 when the file has it, else the
// physical tag - 1.
#include <unordered_map>

#include "molsurf/split_components.hpp"

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

constexpr int kTriangle = 2;

// Element types made of points and lines only: they may sit beside the surface.
bool is_lower_dimensional(long long type) { return type == 15 || type == 1 || type == 8 || type == 26; }

bool next_nonblank(LineReader& lines, std::vector<std::string_view>& fields) {
  std::string_view line;
  while (lines.next(line)) {
    fields = split_fields(line);
    if (!fields.empty()) return true;
  }
  return false;
}

}  // namespace

void write_msh(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions&) {
  const ComponentOrder components = order_components(mesh);
  std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" +
                     std::to_string(components.kind.size()) + "\n";
  for (std::size_t c = 0; c < components.kind.size(); ++c) {
    const bool cavity = components.kind[c] == SurfaceComponent::Kind::cavity;
    std::string name = cavity ? "cavity-" + std::to_string(components.number[c]) : "outer";
    if (!cavity && components.number[c] > 1) name += "-" + std::to_string(components.number[c]);
    text += "2 " + std::to_string(c + 1) + " \"" + name + "\"\n";
  }
  text += "$EndPhysicalNames\n$Nodes\n" + std::to_string(mesh.vertex_count()) + "\n";
  text.reserve(mesh.vertex_count() * 70 + mesh.face_count() * 60 + 256);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    text += std::to_string(v + 1);
    for (double c : {mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z}) {
      text += ' ';
      append_number(text, c);
    }
    text += '\n';
  }
  text += "$EndNodes\n$Elements\n" + std::to_string(mesh.face_count()) + "\n";
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::string entity = std::to_string(components.face_component[f] + 1);
    const Triangle& t = mesh.faces[f];
    text += std::to_string(f + 1) + " 2 2 " + entity + " " + entity + " " + std::to_string(t[0] + 1) + " " +
            std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  }
  text += "$EndElements\n";
  if (mesh.has_tags()) {
    text += "$ElementData\n1\n\"atom\"\n1\n0\n3\n0\n1\n" + std::to_string(mesh.face_count()) + "\n";
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      text += std::to_string(f + 1) + " " + std::to_string(std::max<std::int64_t>(mesh.tag(f), -1) + 1) + "\n";
    text += "$EndElementData\n";
  }
  files.add(file).write(text);
}

Mesh read_msh(const path& file) {
  LineReader lines(file, read_file_bytes(file));
  std::vector<std::string_view> fields;
  Mesh mesh;
  std::unordered_map<long long, Index> node_index;  // gmsh node numbers need not be 1..N
  std::unordered_map<long long, std::size_t> face_of_element;  // triangles only
  std::vector<std::pair<long long, long long>> atom_of_element;  // $ElementData "atom"
  bool have_format = false, have_nodes = false, have_elements = false;
  const auto expect_end = [&](std::string_view end) {
    if (!next_nonblank(lines, fields) || fields[0] != end)
      fail(file, lines.line_number(), "expected '" + std::string(end) + "'");
  };
  const auto read_count = [&](const char* what) {
    if (!next_nonblank(lines, fields)) fail(file, lines.line_number(), std::string("missing ") + what + " count");
    const long long count = parse_integer(fields[0], file, lines.line_number(), std::string(what) + " count");
    if (count < 0) lines.fail_here("negative count");
    return count;
  };
  while (next_nonblank(lines, fields)) {
    const std::size_t n = lines.line_number();
    if (fields[0] == "$MeshFormat") {
      if (!next_nonblank(lines, fields) || fields.size() < 3) fail(file, lines.line_number(), "bad $MeshFormat line");
      if (fields[0].substr(0, 2) != "2.") lines.fail_here("MSH version " + std::string(fields[0].substr(0, 10)) +
                                                          " (only 2.x ASCII is read)");
      if (fields[1] != "0") lines.fail_here("binary MSH is not supported (only ASCII)");
      expect_end("$EndMeshFormat");
      have_format = true;
    } else if (fields[0] == "$Nodes") {
      const long long count = read_count("node");
      for (long long i = 0; i < count; ++i) {
        if (!next_nonblank(lines, fields) || fields[0].front() == '$')
          fail(file, lines.line_number(), "truncated: expected " + std::to_string(count) + " nodes, found " +
                                               std::to_string(i));
        if (fields.size() < 4) lines.fail_here("node needs a number and 3 coordinates");
        const std::size_t line = lines.line_number();
        const long long number = parse_integer(fields[0], file, line, "node number");
        if (!node_index.try_emplace(number, static_cast<Index>(mesh.vertices.size())).second)
          lines.fail_here("node " + std::to_string(number) + " defined twice");
        mesh.vertices.push_back({parse_double(fields[1], file, line, "x"), parse_double(fields[2], file, line, "y"),
                                 parse_double(fields[3], file, line, "z")});
      }
      expect_end("$EndNodes");
      have_nodes = true;
    } else if (fields[0] == "$Elements") {
      if (!have_nodes) lines.fail_here("$Elements before $Nodes");
      const long long count = read_count("element");
      for (long long i = 0; i < count; ++i) {
        if (!next_nonblank(lines, fields) || fields[0].front() == '$')
          fail(file, lines.line_number(), "truncated: expected " + std::to_string(count) + " elements, found " +
                                               std::to_string(i));
        const std::size_t line = lines.line_number();
        if (fields.size() < 3) lines.fail_here("element needs a number, a type and a tag count");
        const long long type = parse_integer(fields[1], file, line, "element type");
        const long long tag_count = parse_integer(fields[2], file, line, "tag count");
        if (tag_count < 0 || tag_count > 64) lines.fail_here("bad tag count");
        if (type != kTriangle) {
          if (is_lower_dimensional(type)) continue;
          lines.fail_here("element type " + std::to_string(type) + " is not a triangle (type 2)");
        }
        const std::size_t first_node = 3 + static_cast<std::size_t>(tag_count);
        if (fields.size() < first_node + 3) lines.fail_here("triangle needs 3 nodes after its tags");
        std::int32_t tag = 0;
        if (tag_count > 0) {
          const long long physical = parse_integer(fields[3], file, line, "physical tag");
          if (physical < INT32_MIN + 1LL || physical > INT32_MAX) lines.fail_here("physical tag out of range");
          tag = static_cast<std::int32_t>(physical - 1);
        }
        Triangle triangle{};
        for (std::size_t k = 0; k < 3; ++k) {
          const long long node = parse_integer(fields[first_node + k], file, line, "node");
          const auto found = node_index.find(node);
          if (found == node_index.end()) lines.fail_here("element refers to undefined node " + std::to_string(node));
          triangle[k] = found->second;
        }
        const long long number = parse_integer(fields[0], file, line, "element number");
        if (!face_of_element.try_emplace(number, mesh.faces.size()).second)
          lines.fail_here("element " + std::to_string(number) + " defined twice");
        mesh.faces.push_back(triangle);
        mesh.face_tags.push_back(tag);
      }
      expect_end("$EndElements");
      have_elements = true;
    } else if (fields[0] == "$ElementData") {
      // String tags (the first is the view's name), real tags (a time), integer tags (time
      // step, components per value, value count), then one "element value..." row per value.
      const long long strings = read_count("string tag");
      std::string name;
      for (long long i = 0; i < strings; ++i) {
        std::string_view line;
        if (!lines.next(line)) fail(file, lines.line_number(), "truncated $ElementData");
        if (i == 0) {
          name = std::string(line);
          std::erase(name, '"');
          std::erase_if(name, [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
        }
      }
      const long long reals = read_count("real tag");
      for (long long i = 0; i < reals; ++i)
        if (!next_nonblank(lines, fields)) fail(file, lines.line_number(), "truncated $ElementData");
      const long long integers = read_count("integer tag");
      long long components = 1, values = 0;
      for (long long i = 0; i < integers; ++i) {
        if (!next_nonblank(lines, fields)) fail(file, lines.line_number(), "truncated $ElementData");
        const long long value = parse_integer(fields[0], file, lines.line_number(), "integer tag");
        if (i == 1) components = value;
        if (i == 2) values = value;
      }
      if (values < 0 || components < 1) lines.fail_here("bad $ElementData counts");
      for (long long i = 0; i < values; ++i) {
        if (!next_nonblank(lines, fields) || fields[0].front() == '$')
          fail(file, lines.line_number(), "truncated: expected " + std::to_string(values) + " element values, found " +
                                               std::to_string(i));
        if (name != "atom" || components != 1) continue;
        if (fields.size() < 2) lines.fail_here("element value needs an element number and a value");
        const std::size_t line = lines.line_number();
        const long long atom = parse_integer(fields[1], file, line, "atom");
        if (atom < 0 || atom > INT32_MAX) lines.fail_here("atom number out of range");
        atom_of_element.emplace_back(parse_integer(fields[0], file, line, "element number"), atom);
      }
      expect_end("$EndElementData");
    } else if (fields[0].front() == '$') {
      // Sections we do not use ($PhysicalNames, $NodeData, ...): skip to their end.
      const std::string end = "$End" + std::string(fields[0].substr(1));
      while (next_nonblank(lines, fields) && fields[0] != end) {
      }
    } else {
      fail(file, n, "unexpected '" + std::string(fields[0].substr(0, 30)) + "' outside a section");
    }
  }
  if (!have_format) fail(file, "not a gmsh file: no $MeshFormat section");
  if (!have_elements) fail(file, "no $Elements section");
  for (const auto& [element, atom] : atom_of_element) {
    const auto found = face_of_element.find(element);
    if (found == face_of_element.end())
      fail(file, "$ElementData \"atom\" names element " + std::to_string(element) + ", which is not a triangle");
    mesh.face_tags[found->second] = static_cast<std::int32_t>(atom - 1);
  }
  return mesh;
}

}  // namespace molsurf::mesh_io
