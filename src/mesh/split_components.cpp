#include "molsurf/split_components.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <string>
#include <utility>

#include "mesh/component_volume.hpp"

namespace molsurf {

ComponentOrder order_components(const Mesh& mesh) {
  const Components parts = connected_components(mesh);
  const ComponentVolumes volumes = component_volumes(mesh, parts);
  // Areas summed as measure_components() sums them, so both sort alike.
  std::vector<double> area(parts.count, 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) area[parts.face_component[f]] += face_area(mesh, f);
  const auto is_cavity = [&](std::size_t c) { return volumes.volume[c] < 0; };
  std::vector<std::size_t> order(parts.count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (is_cavity(a) != is_cavity(b)) return !is_cavity(a);
    return area[a] > area[b];
  });
  ComponentOrder out;
  std::vector<std::uint32_t> position(parts.count);
  std::size_t outer_count = 0, cavity_count = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t c = order[k];
    position[c] = static_cast<std::uint32_t>(k);
    out.kind.push_back(is_cavity(c) ? SurfaceComponent::Kind::cavity : SurfaceComponent::Kind::outer);
    out.number.push_back(is_cavity(c) ? ++cavity_count : ++outer_count);
    out.area.push_back(area[c]);
    out.volume.push_back(volumes.volume[c]);
  }
  out.face_component.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) out.face_component[f] = position[parts.face_component[f]];
  return out;
}

std::vector<SurfaceComponent> split_components(const Mesh& mesh) {
  const ComponentOrder order = order_components(mesh);
  const std::size_t count = order.kind.size();
  // Faces grouped by component (in face order within each), so that each part is built
  // from its own faces: a surface with thousands of cavities costs one pass, not one per part.
  std::vector<std::size_t> first(count + 1, 0);
  for (std::uint32_t c : order.face_component) ++first[c + 1];
  for (std::size_t c = 0; c < count; ++c) first[c + 1] += first[c];
  std::vector<std::size_t> faces_by_component(mesh.faces.size());
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) faces_by_component[next[order.face_component[f]]++] = f;
  }

  std::vector<SurfaceComponent> out;
  out.reserve(count);
  std::vector<Index> renumber(mesh.vertices.size(), ~Index{0});
  std::vector<Index> used;
  for (std::size_t c = 0; c < count; ++c) {
    SurfaceComponent part;
    part.kind = order.kind[c];
    part.number = order.number[c];
    part.area = order.area[c];
    part.volume = std::abs(order.volume[c]);
    const std::span<const std::size_t> faces(faces_by_component.data() + first[c], first[c + 1] - first[c]);
    // Vertices in their original relative order (not by first use), so a part's rows
    // follow the whole surface's.
    used.clear();
    for (std::size_t f : faces)
      for (Index v : mesh.faces[f])
        if (renumber[v] == ~Index{0}) {
          renumber[v] = 0;
          used.push_back(v);
        }
    std::sort(used.begin(), used.end());
    part.mesh.vertices.reserve(used.size());
    for (Index v : used) {
      renumber[v] = static_cast<Index>(part.mesh.vertices.size());
      part.mesh.vertices.push_back(mesh.vertices[v]);
    }
    part.mesh.faces.reserve(faces.size());
    if (mesh.has_tags()) part.mesh.face_tags.reserve(faces.size());
    for (std::size_t f : faces) {
      Triangle t = mesh.faces[f];
      for (Index& v : t) v = renumber[v];
      // A cavity alone is a closed surface seen from its inside: turned, it is outward.
      if (part.kind == SurfaceComponent::Kind::cavity) std::swap(t[1], t[2]);
      part.mesh.faces.push_back(t);
      if (mesh.has_tags()) part.mesh.face_tags.push_back(mesh.face_tags[f]);
    }
    for (Index v : used) renumber[v] = ~Index{0};
    out.push_back(std::move(part));
  }
  return out;
}

std::filesystem::path component_output_path(const std::filesystem::path& path, const SurfaceComponent& component) {
  std::filesystem::path stem = path;
  const std::string extension = path.extension().string();
  stem.replace_extension();
  // (Built by appends: GCC 12 warns falsely about "literal" + std::string here.)
  std::string part = component.kind == SurfaceComponent::Kind::outer ? ".outer" : ".cavity";
  if (component.kind == SurfaceComponent::Kind::cavity || component.number > 1)
    part.append("-").append(std::to_string(component.number));
  return stem.concat(part + extension);
}

}  // namespace molsurf
