// Legacy VTK PolyData (.vtk) written by molsurf itself, byte for byte what VTK 9.1's
// vtkPolyDataWriter writes for the same data (binary, file version 4.2 so that pre-9.0
// readers open it too); tests/test_mesh_vtk_writer.cpp compares the two. Read by a reader
// of our own (mesh_vtk_legacy.cpp); .vtp has its own writer too (mesh_vtp_writer.cpp).
// Stored: double points (exact), float32 area-weighted point normals, cell data "tag" and,
// when atoms are given, "atom_serial", "residue_number", "residue_name", "chain" of
// each face's atom.
//
// The layout, in VTK's order: four header lines; "POINTS n double" and the coordinates;
// "POLYGONS faces 4*faces" and per face 3, a, b, c as int32 (version 4.2's only id type);
// "CELL_DATA faces" with the arrays as a FIELD; "POINT_DATA n" with the normals as the
// NORMALS attribute. Every number is big-endian, every block of values ends with "\n",
// and the sections after POINTS are left out when they would hold no values. A string is its length in 1, 2, 4 or 8
// big-endian bytes (the top two bits of the first byte say which: 11, 10, 01, 00) and
// its bytes as they are.
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

template <class T>
void store_big_endian(char* out, T value) {
  static_assert(sizeof(T) == 2 || sizeof(T) == 4 || sizeof(T) == 8);
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t,
                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint16_t>>;
  auto bits = std::bit_cast<Bits>(value);
  for (std::size_t i = sizeof(T); i-- > 0;) {
    out[i] = static_cast<char>(bits & 0xffu);
    bits = static_cast<Bits>(bits >> 8);
  }
}

// value(i) for i in [0, n) as big-endian T, then the newline VTK ends every block with.
// One thread: 2hhb's whole file takes 0.010-0.016 s of CPU this way, less than an OpenMP
// region's barrier costs on a busy machine (docs/formats.md).
template <class T, class Value>
std::string big_endian_values(std::size_t n, Value&& value) {
  std::string out(n * sizeof(T) + 1, '\n');
  for (std::size_t i = 0; i < n; ++i) store_big_endian<T>(out.data() + i * sizeof(T), value(i));
  return out;
}

// VTK's binary string: the length in the fewest of 1, 2, 4 or 8 bytes whose spare top bits
// mark the width, then the bytes.
void append_string(std::string& out, const std::string& s) {
  const std::uint64_t length = s.size();
  char prefix[8];
  if (length < (std::uint64_t{1} << 6)) {
    out += static_cast<char>(0xc0u | length);
  } else if (length < (std::uint64_t{1} << 14)) {
    store_big_endian(prefix, static_cast<std::uint16_t>(0x8000u | length));
    out.append(prefix, 2);
  } else if (length < (std::uint64_t{1} << 30)) {
    store_big_endian(prefix, static_cast<std::uint32_t>(0x40000000u | length));
    out.append(prefix, 4);
  } else {
    store_big_endian(prefix, length);
    out.append(prefix, 8);
  }
  out += s;
}

template <class Value>
std::string string_values(std::size_t n, Value&& value) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) append_string(out, value(i));
  out += '\n';
  return out;
}

}  // namespace

void write_vtk(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  const std::size_t vertices = mesh.vertex_count(), faces = mesh.face_count();
  // Version 4.2 stores point ids and counts as 32-bit integers (VTK's writer would cut
  // them short without a word); .vtp has 64-bit ids.
  constexpr std::size_t kMaxInt = std::numeric_limits<std::int32_t>::max();
  if (vertices > kMaxInt || faces > kMaxInt / 4)
    fail(file, "cannot write: " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                   " faces do not fit legacy .vtk's 32-bit ids; write .vtp");

  AtomicFile& output = files.add(file);
  output.write("# vtk DataFile Version 4.2\nmolsurf " MOLSURF_VERSION "\nBINARY\nDATASET POLYDATA\n");
  output.write("POINTS " + std::to_string(vertices) + " double\n");
  output.write(big_endian_values<double>(3 * vertices, [&](std::size_t i) { return mesh.vertices[i / 3][static_cast<int>(i % 3)]; }));
  if (faces > 0) {
    output.write("POLYGONS " + std::to_string(faces) + " " + std::to_string(4 * faces) + "\n");
    output.write(big_endian_values<std::int32_t>(4 * faces, [&](std::size_t i) {
      return i % 4 == 0 ? 3 : static_cast<std::int32_t>(mesh.faces[i / 4][i % 4 - 1]);
    }));
  }

  if (faces > 0 && mesh.has_tags()) {
    const std::string count = std::to_string(faces);
    output.write("CELL_DATA " + count + "\nFIELD FieldData " + (options.atoms.empty() ? "1" : "5") + "\n");
    output.write("tag 1 " + count + " int\n");
    output.write(big_endian_values<std::int32_t>(faces, [&](std::size_t f) { return mesh.face_tags[f]; }));
    if (!options.atoms.empty()) {
      // check_writable guarantees every tag is kNoTag or an atom's.
      const Atom none{};  // for kNoTag: serial and residue number 0, empty names
      const auto atom_of = [&](std::size_t f) -> const Atom& {
        const Atom* atom = tagged_atom(options, mesh.face_tags[f]);
        return atom != nullptr ? *atom : none;
      };
      output.write("atom_serial 1 " + count + " int\n");
      output.write(big_endian_values<std::int32_t>(faces, [&](std::size_t f) { return atom_of(f).serial; }));
      output.write("residue_number 1 " + count + " int\n");
      output.write(big_endian_values<std::int32_t>(
          faces, [&](std::size_t f) { return residue_number_32(atom_of(f).residue_number); }));
      output.write("residue_name 1 " + count + " string\n");
      output.write(string_values(faces, [&](std::size_t f) -> const std::string& { return atom_of(f).residue_name; }));
      output.write("chain 1 " + count + " string\n");
      output.write(string_values(faces, [&](std::size_t f) -> const std::string& { return atom_of(f).chain; }));
    }
  }

  if (vertices > 0) {
    const std::vector<Vec3> normal = vertex_normals(mesh);
    output.write("POINT_DATA " + std::to_string(vertices) + "\nNORMALS Normals float\n");
    output.write(big_endian_values<float>(
        3 * vertices, [&](std::size_t i) { return static_cast<float>(normal[i / 3][static_cast<int>(i % 3)]); }));
  }
}

}  // namespace molsurf::mesh_io
