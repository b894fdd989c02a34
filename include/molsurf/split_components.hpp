#pragma once
// One closed surface per file: solvers that take one closed surface per file (PyGBe,
// one surface loop per boundary in a mesher) need the outer surface and each cavity
// apart. Each part is written as a closed, outward surface of its own.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct SurfaceComponent {
  enum class Kind { outer, cavity };
  Kind kind = Kind::outer;
  std::size_t number = 1;  // from 1 within its kind, in the order below
  // Closed and outward on its own: a cavity's faces are turned to point out of the
  // cavity (into the molecule), the reverse of how they sit in the whole surface.
  Mesh mesh;
  double area = 0;
  double volume = 0;  // enclosed by this part alone: positive
};

// The components of `mesh` (faces connected through shared vertices) in the report's
// order, without copying them: outer surfaces first, then cavities (a component of negative
// volume, decided exactly), each kind by decreasing area, ties by lowest face index.
struct ComponentOrder {
  std::vector<std::uint32_t> face_component;   // per face: its component's position in the order
  std::vector<SurfaceComponent::Kind> kind;    // per position
  std::vector<std::size_t> number;             // per position: from 1 within its kind
  std::vector<double> area, volume;            // per position; volume signed (cavities negative)
};
ComponentOrder order_components(const Mesh& mesh);

// The components of `mesh` (faces connected through shared vertices) as separate meshes:
// outer surfaces first, then cavities (a component of negative volume, decided exactly),
// each kind by decreasing area, ties by lowest face index: the order of
// measure_components() and of the report, so cavity K here is cavity K there. Vertices
// keep their relative order and faces their order and tags.
std::vector<SurfaceComponent> split_components(const Mesh& mesh);

// Where split_components' part is written for the output `path`: NAME.outer.EXT for the
// first outer surface, NAME.outer-K.EXT for further ones (K from 2), NAME.cavity-K.EXT for
// the cavities (K from 1). NAME.EXT is `path`; for MSMS the part's path names one file of
// its pair, as `path` does (mesh_output_files() gives both).
std::filesystem::path component_output_path(const std::filesystem::path& path, const SurfaceComponent& component);

}  // namespace molsurf
