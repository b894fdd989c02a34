// STL: independent triangles with a facet normal, coordinates in float32 by definition,
// so writing is lossy (documented). Binary is the default; ASCII prints each float in
// its shortest round-trip form, so both variants read back to the same floats.
// Reading merges exactly equal coordinates into shared vertices.
#include <array>
#include <bit>
#include <cstring>
#include <unordered_map>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

constexpr std::size_t kHeaderSize = 80;
constexpr std::size_t kCountOffset = 80;
constexpr std::size_t kFirstFacet = 84;
constexpr std::size_t kFacetSize = 50;  // normal, 3 vertices (12 floats) + 2 attribute bytes

void put_u32(std::string& out, std::uint32_t value) {
  for (int byte = 0; byte < 4; ++byte) out += static_cast<char>((value >> (8 * byte)) & 0xffu);
}

void put_f32(std::string& out, float value) { put_u32(out, std::bit_cast<std::uint32_t>(value)); }

std::uint32_t get_u32(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (int byte = 0; byte < 4; ++byte)
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[offset + byte])) << (8 * byte);
  return value;
}

float get_f32(const std::string& bytes, std::size_t offset) {
  return std::bit_cast<float>(get_u32(bytes, offset));
}

std::array<float, 3> as_floats(const Vec3& p) {
  return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
}

// Shared vertices from independent triangles: exactly equal coordinates become one vertex.
class VertexMerger {
 public:
  explicit VertexMerger(Mesh& mesh) : mesh_(mesh) {}
  Index add(const Vec3& p) {
    // +0.0 and -0.0 are the same point.
    const Key key{bits(p.x), bits(p.y), bits(p.z)};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<Index>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (std::uint64_t part : k) h = (h ^ part) * 1099511628211ull + (h >> 29);
      return static_cast<std::size_t>(h);
    }
  };
  static std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value == 0 ? 0.0 : value); }

  Mesh& mesh_;
  std::unordered_map<Key, Index, KeyHash> index_;
};

Mesh read_binary_stl(const path& file, const std::string& bytes) {
  if (bytes.size() < kFirstFacet)
    fail(file, "truncated: binary STL needs an 84-byte header, file has " + std::to_string(bytes.size()) +
                   " bytes");
  const std::uint32_t facet_count = get_u32(bytes, kCountOffset);
  const std::size_t available = (bytes.size() - kFirstFacet) / kFacetSize;
  if (available < facet_count)
    fail(file, "truncated: expected " + std::to_string(facet_count) + " faces, file ends after " +
                   std::to_string(available));
  // Bytes past the declared facets mean a damaged count (a count of 0 before 20 facets
  // would otherwise read as an empty surface): refuse rather than drop them.
  if (const std::size_t extra = bytes.size() - kFirstFacet - facet_count * kFacetSize; extra > 0)
    fail(file, "binary STL declares " + std::to_string(facet_count) + " faces (" +
                   std::to_string(kFirstFacet + facet_count * kFacetSize) + " bytes) but the file has " +
                   std::to_string(extra) + " more bytes" +
                   (extra >= kFacetSize ? " (" + std::to_string(extra / kFacetSize) + " more faces' worth): damaged count?"
                                        : ""));
  Mesh mesh;
  VertexMerger merger(mesh);
  mesh.faces.reserve(facet_count);
  for (std::size_t f = 0; f < facet_count; ++f) {
    const std::size_t facet = kFirstFacet + f * kFacetSize;
    Triangle triangle{};
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const std::size_t at = facet + 12 + corner * 12;  // skip the facet normal
      triangle[corner] = merger.add({get_f32(bytes, at), get_f32(bytes, at + 4), get_f32(bytes, at + 8)});
    }
    mesh.faces.push_back(triangle);
  }
  return mesh;
}

Mesh read_ascii_stl(const path& file, std::string bytes) {
  LineReader lines(file, std::move(bytes));
  Mesh mesh;
  VertexMerger merger(mesh);
  std::string_view line;
  std::vector<Index> corners;
  std::size_t facet_line = 0;
  bool in_facet = false, in_solid = false;
  while (lines.next(line)) {
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.empty()) continue;
    const std::size_t n = lines.line_number();
    if (fields[0] == "facet") {
      if (!in_solid) lines.fail_here("'facet' outside 'solid' ... 'endsolid'");
      if (in_facet) lines.fail_here("'facet' before 'endfacet'");
      in_facet = true;
      facet_line = n;
      corners.clear();
    } else if (fields[0] == "vertex") {
      if (!in_facet) lines.fail_here("'vertex' outside a facet");
      if (fields.size() < 4) lines.fail_here("vertex needs 3 coordinates");
      // STL coordinates are float32 whatever their text says, as in a binary file.
      const auto coordinate = [&](std::size_t i, const char* what) {
        return static_cast<double>(static_cast<float>(parse_double(fields[i], file, n, what)));
      };
      corners.push_back(merger.add({coordinate(1, "x"), coordinate(2, "y"), coordinate(3, "z")}));
    } else if (fields[0] == "endfacet") {
      if (!in_facet) lines.fail_here("'endfacet' without 'facet'");
      if (corners.size() != 3)
        fail(file, facet_line, "facet has " + std::to_string(corners.size()) + " vertices (STL facets have 3)");
      mesh.faces.push_back({corners[0], corners[1], corners[2]});
      in_facet = false;
    } else if (fields[0] == "endsolid") {
      if (in_facet) lines.fail_here("'endsolid' inside a facet");
      if (!in_solid) lines.fail_here("'endsolid' without 'solid'");
      in_solid = false;
    } else if (fields[0] == "solid") {
      // Several solids may follow one another; their facets make one mesh.
      if (in_solid) lines.fail_here("'solid' before 'endsolid'");
      in_solid = true;
    } else if (!in_solid) {
      lines.fail_here("data after 'endsolid'");
    } else if (fields[0] != "outer" && fields[0] != "endloop") {
      lines.fail_here("unexpected '" + std::string(fields[0].substr(0, 20)) + "' in ASCII STL");
    }
  }
  if (in_solid)
    fail(file, lines.line_number(), in_facet ? "truncated: file ends inside a facet" : "truncated: missing 'endsolid'");
  return mesh;
}

}  // namespace

void write_stl(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  std::string out;
  if (options.ascii) {
    out = "solid molsurf\n";
    out.reserve(mesh.face_count() * 250 + 64);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const auto normal = as_floats(face_normal(mesh, f));
      out += "facet normal ";
      for (int i = 0; i < 3; ++i) {
        append_number(out, normal[i]);
        out += i < 2 ? ' ' : '\n';
      }
      out += " outer loop\n";
      for (Index v : mesh.faces[f]) {
        const auto p = as_floats(mesh.vertices[v]);
        out += "  vertex ";
        for (int i = 0; i < 3; ++i) {
          append_number(out, p[i]);
          out += i < 2 ? ' ' : '\n';
        }
      }
      out += " endloop\nendfacet\n";
    }
    out += "endsolid molsurf\n";
  } else {
    if (mesh.face_count() > UINT32_MAX) fail(file, "cannot write: too many faces for binary STL");
    // The header must not start with "solid": readers take that for ASCII.
    std::string header = "molsurf " MOLSURF_VERSION " binary STL";
    header.resize(kHeaderSize, ' ');
    out = header;
    out.reserve(kFirstFacet + mesh.face_count() * kFacetSize);
    put_u32(out, static_cast<std::uint32_t>(mesh.face_count()));
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      for (float c : as_floats(face_normal(mesh, f))) put_f32(out, c);
      for (Index v : mesh.faces[f])
        for (float c : as_floats(mesh.vertices[v])) put_f32(out, c);
      out += std::string(2, '\0');  // attribute byte count: unused
    }
  }
  files.add(file).write(out);
}

namespace {

// A double rounded to float32 and back. Not inlined on purpose: GCC 12.2 at -O2/-O3
// vectorizes (double)(float) of two neighbouring coordinates and drops the rounding
// (x and y came back unrounded, z rounded); a call per value keeps it scalar.
[[gnu::noinline]] double float32_value(double value) { return static_cast<double>(static_cast<float>(value)); }

}  // namespace

Mesh stl_as_read(const Mesh& mesh) {
  // What read_stl does with the facets write_stl writes: float32 corners, merged where
  // equal, numbered in order of first use.
  Mesh read;
  VertexMerger merger(read);
  read.faces.reserve(mesh.face_count());
  for (const Triangle& t : mesh.faces) {
    Triangle corners{};
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[t[k]];
      corners[k] = merger.add({float32_value(p.x), float32_value(p.y), float32_value(p.z)});
    }
    read.faces.push_back(corners);
  }
  read.face_tags = mesh.face_tags;
  return read;
}

Mesh read_stl(const path& file) {
  std::string bytes = read_file_bytes(file);
  // Binary files may also begin with "solid", so the size decides first: a binary file
  // is exactly 84 + 50 * count bytes.
  if (bytes.size() >= kFirstFacet &&
      bytes.size() == kFirstFacet + kFacetSize * static_cast<std::size_t>(get_u32(bytes, kCountOffset)))
    return read_binary_stl(file, bytes);
  const std::size_t start = bytes.find_first_not_of(" \t\r\n");
  if (start != std::string::npos && bytes.compare(start, 5, "solid") == 0 &&
      (bytes.find("facet", start) != std::string::npos || bytes.find("endsolid", start) != std::string::npos))
    return read_ascii_stl(file, std::move(bytes));
  return read_binary_stl(file, bytes);
}

}  // namespace molsurf::mesh_io
