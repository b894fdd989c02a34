#include "molsurf/surface_measures.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "mesh/component_volume.hpp"
#include "mesh/topology.hpp"

namespace molsurf {

std::vector<ComponentMeasure> measure_components(const Mesh& mesh) {
  // Volumes about each component's own vertex, with an exact sign (mesh/component_volume.hpp).
  const Components parts = connected_components(mesh);
  const ComponentVolumes volumes = component_volumes(mesh, parts);
  std::vector<ComponentMeasure> out(parts.count);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    ComponentMeasure& c = out[parts.face_component[f]];
    ++c.faces;
    c.area += face_area(mesh, f);
  }
  for (std::size_t c = 0; c < parts.count; ++c) out[c].volume = volumes.volume[c];
  std::stable_sort(out.begin(), out.end(), [](const ComponentMeasure& a, const ComponentMeasure& b) {
    if (a.cavity() != b.cavity()) return !a.cavity();
    return a.area > b.area;
  });
  return out;
}

Mesh outer_surface_only(const Mesh& mesh) {
  const Components parts = connected_components(mesh);
  const std::vector<int> sign = component_volumes(mesh, parts).sign;
  Mesh out = mesh;
  std::vector<std::uint8_t> outer(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) outer[f] = sign[parts.face_component[f]] > 0;
  keep_alive_faces(out, outer);
  drop_unused_vertices(out);
  return out;
}

std::vector<double> area_per_atom(const Mesh& mesh, std::size_t atom_count) {
  std::vector<double> area(atom_count, 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::int32_t t = mesh.tag(f);
    if (t >= 0 && static_cast<std::size_t>(t) < atom_count) area[t] += face_area(mesh, f);
  }
  return area;
}

std::vector<ResidueArea> area_per_residue(std::span<const Atom> atoms, std::span<const double> atom_area) {
  if (atom_area.size() != atoms.size())
    throw std::invalid_argument("area_per_residue: " + std::to_string(atom_area.size()) + " areas for " +
                                std::to_string(atoms.size()) + " atoms");
  using Key = std::tuple<std::string, int, char, std::string>;
  std::map<Key, std::size_t> index;
  std::vector<ResidueArea> rows;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const auto [it, inserted] =
        index.try_emplace(Key{a.chain, a.residue_number, a.insertion_code, a.residue_name}, rows.size());
    if (inserted) rows.push_back({a.chain, a.residue_name, a.residue_number, a.insertion_code, 0, 0.0});
    ResidueArea& row = rows[it->second];
    row.area += atom_area[i];
    ++row.atoms;
  }
  return rows;
}

}  // namespace molsurf
