// VTK XML PolyData (.vtp) written by molsurf itself, in the layout VTK 9.1's writer gives
// (appended raw data, UInt64 block headers, zlib blocks of 32 KiB), so that VTK, ParaView
// and our own reader (mesh_vtp.cpp) read it alike. VTK compresses the blocks one after
// another; here they are compressed in parallel, at level 1 (at zlib's default level a
// surface's file is only 2 % smaller and takes half as long again to write). Floating-point
// arrays are stored in uncompressed blocks (level 0): their mantissas shrink by 16 % at
// level 1, for two fifths of the compression time (2hhb: 0.07 -> 0.04 s, 4.5 -> 5.2 MB).
// Stored: double points (exact), float32 area-weighted point normals, Int32 connectivity
// and offsets while ids fit (Int64 beyond), cell data "tag" and, when atoms are given,
// "atom_serial", "residue_number", "residue_name", "chain" of each face's atom.
#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "common/parallel_threshold.hpp"
#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

constexpr std::size_t kBlockSize = 32768;  // VTK's default

// One array of the appended section: its XML element up to the offset, its bytes as
// written by VTK (values in native byte order, strings each followed by a NUL), and
// those bytes compressed block by block.
// An array's bytes, left unwritten until a parallel loop fills them (so their pages are
// first touched in parallel).
struct Bytes {
  std::unique_ptr<char[]> data;
  std::size_t size = 0;

  explicit Bytes(std::size_t n = 0) : data(std::make_unique_for_overwrite<char[]>(n)), size(n) {}
};

struct AppendedArray {
  std::string element;  // `<DataArray type=... ` or `<Array type=... `; offset and `/>` follow
  Bytes raw;            // released once compressed
  std::size_t raw_size = 0;
  std::vector<std::vector<unsigned char>> blocks;
  int level = 1;  // of compression; 0 stores
  std::uint64_t offset = 0;  // from the start of the appended data

  std::size_t block_count() const { return (raw.size + kBlockSize - 1) / kBlockSize; }
  std::uint64_t appended_size() const {
    std::uint64_t size = 8 * (3 + blocks.size());
    for (const auto& b : blocks) size += b.size();
    return size;
  }
};

// value(i) for i in [0, n), as T in native byte order, in parallel.
template <class T, class Value>
Bytes bytes_of(std::size_t n, Value&& value) {
  Bytes raw(n * sizeof(T));
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (count >= kParallelMinItems)
  for (std::int64_t i = 0; i < count; ++i) {
    const T v = value(static_cast<std::size_t>(i));
    std::memcpy(raw.data.get() + static_cast<std::size_t>(i) * sizeof(T), &v, sizeof(T));
  }
  return raw;
}

AppendedArray numeric_array(const char* type, const char* name, int components, Bytes raw) {
  AppendedArray a;
  a.element = std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\"";
  if (components > 1) a.element += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  a.element += " format=\"appended\"";
  a.raw = std::move(raw);
  if (std::string_view(type).starts_with("Float")) a.level = 0;
  return a;
}

// value(i) for i in [0, n), each string followed by a NUL.
template <class Value>
AppendedArray string_array(const char* name, std::size_t n, Value&& value) {
  AppendedArray a;
  a.element = std::string("<Array type=\"String\" Name=\"") + name + "\" format=\"appended\"";
  std::vector<std::size_t> start(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) start[i + 1] = start[i] + value(i).size() + 1;
  a.raw = Bytes(start[n]);
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (count >= kParallelMinItems)
  for (std::int64_t i = 0; i < count; ++i) {
    const std::string& v = value(static_cast<std::size_t>(i));
    char* out = a.raw.data.get() + start[i];
    std::memcpy(out, v.data(), v.size());
    out[v.size()] = '\0';
  }
  return a;
}

// Connectivity and offsets (where each triangle ends) in the narrowest type VTK reads.
template <class Id>
void add_polys(const Mesh& mesh, std::vector<AppendedArray>& polys, const char* type) {
  const auto corner = [&](std::size_t i) { return static_cast<Id>(mesh.faces[i / 3][i % 3]); };
  const auto end = [](std::size_t f) { return static_cast<Id>(3 * (f + 1)); };
  polys.push_back(numeric_array(type, "connectivity", 1, bytes_of<Id>(3 * mesh.face_count(), corner)));
  polys.push_back(numeric_array(type, "offsets", 1, bytes_of<Id>(mesh.face_count(), end)));
}

// A zlib stream per block, as VTK's vtkZLibDataCompressor reads it, made by libdeflate:
// at level 1 it takes about half zlib's time for a 5 % larger surface file (2hhb: 0.021 ->
// 0.012 s on two threads, 5.15 -> 5.44 MB). One compressor per level and thread, reused
// block after block.
class BlockCompressor {
 public:
  BlockCompressor() = default;
  BlockCompressor(const BlockCompressor&) = delete;
  BlockCompressor& operator=(const BlockCompressor&) = delete;
  ~BlockCompressor() {
    for (libdeflate_compressor* c : compressors_)
      if (c) libdeflate_free_compressor(c);
  }

  // `in` compressed into `out` (resized to fit); false if it could not be.
  bool compress(const char* in, std::size_t size, int level, std::vector<unsigned char>& out) {
    libdeflate_compressor*& c = compressors_[level == 0 ? 0 : 1];
    if (!c) c = libdeflate_alloc_compressor(level == 0 ? 0 : 1);
    if (!c) return false;
    out.resize(libdeflate_zlib_compress_bound(c, size));
    const std::size_t produced = libdeflate_zlib_compress(c, in, size, out.data(), out.size());
    out.resize(produced);
    return produced > 0;
  }

 private:
  std::array<libdeflate_compressor*, 2> compressors_{};  // levels 0 (stored) and 1
};

void compress_all(const path& file, std::vector<AppendedArray*>& arrays) {
  std::vector<std::pair<AppendedArray*, std::size_t>> tasks;
  for (AppendedArray* a : arrays) {
    a->blocks.resize(a->block_count());
    for (std::size_t b = 0; b < a->blocks.size(); ++b) tasks.emplace_back(a, b);
  }
  const auto count = static_cast<std::int64_t>(tasks.size());
  int failures = 0;
#pragma omp parallel reduction(+ : failures)
  {
    BlockCompressor compressor;
#pragma omp for schedule(dynamic, 4)
    for (std::int64_t t = 0; t < count; ++t) {
      AppendedArray& a = *tasks[t].first;
      const std::size_t b = tasks[t].second, begin = b * kBlockSize, size = std::min(kBlockSize, a.raw.size - begin);
      try {  // nothing may leave the parallel region
        if (!compressor.compress(a.raw.data.get() + begin, size, a.level, a.blocks[b])) ++failures;
      } catch (const std::bad_alloc&) {
        ++failures;
      }
    }
  }
  if (failures > 0) fail(file, "cannot write: the compressor failed (out of memory?)");
  for (AppendedArray* a : arrays) {
    a->raw_size = a->raw.size;
    a->raw = Bytes();
  }
}

void write_u64(std::string& out, std::uint64_t value) {
  char bytes[8];
  std::memcpy(bytes, &value, 8);
  out.append(bytes, 8);
}

}  // namespace

void write_vtp(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  // Point data, cell data, points, then the four cell sections in VTK's order.
  std::vector<AppendedArray> point_data, cell_data, points, verts, lines, strips, polys;
  {
    const std::vector<Vec3> normal = vertex_normals(mesh);
    const auto component = [&](std::size_t i) { return static_cast<float>(normal[i / 3][static_cast<int>(i % 3)]); };
    point_data.push_back(numeric_array("Float32", "Normals", 3, bytes_of<float>(3 * normal.size(), component)));
  }
  if (mesh.has_tags()) {
    const std::size_t faces = mesh.face_count();
    cell_data.push_back(
        numeric_array("Int32", "tag", 1, bytes_of<std::int32_t>(faces, [&](std::size_t f) { return mesh.face_tags[f]; })));
    if (!options.atoms.empty()) {
      // check_writable guarantees every tag is kNoTag or an atom's.
      const Atom none{};  // for kNoTag: serial and residue number 0, empty names
      const auto atom_of = [&](std::size_t f) -> const Atom& {
        const Atom* atom = tagged_atom(options, mesh.face_tags[f]);
        return atom != nullptr ? *atom : none;
      };
      cell_data.push_back(numeric_array("Int32", "atom_serial", 1,
                                        bytes_of<std::int32_t>(faces, [&](std::size_t f) { return atom_of(f).serial; })));
      cell_data.push_back(numeric_array(
          "Int32", "residue_number", 1,
          bytes_of<std::int32_t>(faces, [&](std::size_t f) { return residue_number_32(atom_of(f).residue_number); })));
      cell_data.push_back(
          string_array("residue_name", faces, [&](std::size_t f) -> const std::string& { return atom_of(f).residue_name; }));
      cell_data.push_back(string_array("chain", faces, [&](std::size_t f) -> const std::string& { return atom_of(f).chain; }));
    }
  }
  {
    const auto coordinate = [&](std::size_t i) { return mesh.vertices[i / 3][static_cast<int>(i % 3)]; };
    points.push_back(numeric_array("Float64", "Points", 3, bytes_of<double>(3 * mesh.vertex_count(), coordinate)));
  }
  for (auto* section : {&verts, &lines, &strips}) {
    section->push_back(numeric_array("Int64", "connectivity", 1, Bytes()));
    section->push_back(numeric_array("Int64", "offsets", 1, Bytes()));
  }
  // Point ids are signed in VTK: 32 bits while every id and offset fits.
  if (mesh.vertex_count() < (std::size_t{1} << 31) && 3 * mesh.face_count() < (std::size_t{1} << 31))
    add_polys<std::int32_t>(mesh, polys, "Int32");
  else
    add_polys<std::int64_t>(mesh, polys, "Int64");

  std::vector<AppendedArray*> all;
  for (auto* group : {&point_data, &cell_data, &points, &verts, &lines, &strips, &polys})
    for (AppendedArray& a : *group) all.push_back(&a);
  compress_all(file, all);
  std::uint64_t offset = 0;
  for (AppendedArray* a : all) {
    a->offset = offset;
    offset += a->appended_size();
  }

  std::string xml;
  xml += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"";
  xml += std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  xml += "\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n  <PolyData>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(mesh.vertex_count()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(mesh.face_count()) + "\">\n";
  auto section = [&](const char* open, const char* close, const std::vector<AppendedArray>& arrays) {
    xml += std::string("      ") + open + "\n";
    for (const AppendedArray& a : arrays)
      xml += "        " + a.element + " offset=\"" + std::to_string(a.offset) + "\"/>\n";
    xml += std::string("      ") + close + "\n";
  };
  section("<PointData Normals=\"Normals\">", "</PointData>", point_data);
  section("<CellData>", "</CellData>", cell_data);
  section("<Points>", "</Points>", points);
  section("<Verts>", "</Verts>", verts);
  section("<Lines>", "</Lines>", lines);
  section("<Strips>", "</Strips>", strips);
  section("<Polys>", "</Polys>", polys);
  xml += "    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

  AtomicFile& output = files.add(file);
  output.write(xml);
  for (const AppendedArray* a : all) {
    std::string header;
    write_u64(header, a->blocks.size());
    write_u64(header, kBlockSize);
    write_u64(header, a->raw_size % kBlockSize);
    for (const auto& b : a->blocks) write_u64(header, b.size());
    output.write(header);
    for (const auto& b : a->blocks) output.write({reinterpret_cast<const char*>(b.data()), b.size()});
  }
  output.write("\n  </AppendedData>\n</VTKFile>\n");
}

}  // namespace molsurf::mesh_io
