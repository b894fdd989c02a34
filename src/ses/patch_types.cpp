#include "molsurf/patch_types.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "ses/nearest_probe.hpp"

namespace molsurf {

const char* patch_type_name(PatchType type) {
  switch (type) {
    case PatchType::toroidal: return "toroidal";
    case PatchType::reentrant: return "reentrant";
    case PatchType::contact: return "contact";
  }
  return "?";
}

std::size_t ses_face_count(std::size_t atoms, const SphereArrangement& arrangement) {
  return atoms + ses::exposed_pair_count(atoms, arrangement) + arrangement.vertices.size();
}

std::vector<VertexPatch> ses_vertex_patches(std::span<const Vec3> points, std::span<const Atom> atoms, double probe,
                                            const SphereArrangement& arrangement) {
  std::vector<VertexPatch> out(points.size());
  if (atoms.empty() || !(probe > 0)) return out;
  const ses::NearestProbe nearest(atoms, probe, arrangement);
  const auto n = static_cast<std::int64_t>(points.size());
#pragma omp parallel for schedule(dynamic, 512)
  for (std::int64_t k = 0; k < n; ++k) out[static_cast<std::size_t>(k)] = nearest.label(points[static_cast<std::size_t>(k)]);
  return out;
}

std::vector<PatchType> face_patch_types(const Mesh& mesh, std::span<const VertexPatch> vertices) {
  std::vector<PatchType> types(mesh.face_count(), PatchType::contact);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Triangle& t = mesh.faces[f];
    const PatchType a = vertices[t[0]].type, b = vertices[t[1]].type, c = vertices[t[2]].type;
    types[f] = a == b || a == c ? a : b == c ? b : PatchType::toroidal;
  }
  return types;
}

std::vector<std::uint32_t> face_patch_numbers(const Mesh& mesh, std::span<const VertexPatch> vertices) {
  const std::vector<PatchType> types = face_patch_types(mesh, vertices);
  std::vector<std::uint32_t> numbers(mesh.face_count(), 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    // The corners of the face's type: at least one (three different types include toroidal).
    std::array<std::uint32_t, 3> faces{};
    std::size_t n = 0;
    for (Index v : mesh.faces[f])
      if (vertices[v].type == types[f]) faces[n++] = vertices[v].face;
    std::uint32_t number = faces[0];
    for (std::size_t k = 1; k < n; ++k) number = std::min(number, faces[k]);
    if (n == 3 && (faces[1] == faces[2])) number = faces[1];
    if (n >= 2 && (faces[0] == faces[1] || (n == 3 && faces[0] == faces[2]))) number = faces[0];
    numbers[f] = number;
  }
  return numbers;
}

}  // namespace molsurf

