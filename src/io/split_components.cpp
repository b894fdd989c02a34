#include "molsurf/split_components.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "mesh/component_volume.hpp"
#include "mesh/topology.hpp"

namespace molsurf {

std::vector<SurfaceComponent> split_components(const Mesh& mesh) {
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

  std::vector<SurfaceComponent> out;
  out.reserve(parts.count);
  std::size_t outer_count = 0, cavity_count = 0;
  for (std::size_t c : order) {
    SurfaceComponent part;
    part.kind = is_cavity(c) ? SurfaceComponent::Kind::cavity : SurfaceComponent::Kind::outer;
    part.number = is_cavity(c) ? ++cavity_count : ++outer_count;
    part.area = area[c];
    part.volume = std::abs(volumes.volume[c]);
    part.mesh = mesh;
    std::vector<std::uint8_t> keep(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) keep[f] = parts.face_component[f] == c;
    keep_alive_faces(part.mesh, keep);
    // Vertices in their original relative order (drop_unused_vertices would order them
    // by first use), so a part's rows follow the whole surface's.
    std::vector<std::uint8_t> is_used(mesh.vertices.size(), 0);
    for (const Triangle& t : part.mesh.faces)
      for (Index v : t) is_used[v] = 1;
    std::vector<Index> renumber(mesh.vertices.size(), ~Index{0});
    std::vector<Vec3> used;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      if (is_used[v]) {
        renumber[v] = static_cast<Index>(used.size());
        used.push_back(mesh.vertices[v]);
      }
    part.mesh.vertices = std::move(used);
    for (Triangle& t : part.mesh.faces) {
      for (Index& v : t) v = renumber[v];
      // A cavity alone is a closed surface seen from its inside: turned, it is outward.
      if (part.kind == SurfaceComponent::Kind::cavity) std::swap(t[1], t[2]);
    }
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
