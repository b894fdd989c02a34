#include "molsurf/surface_measures.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "mesh/component_volume.hpp"
#include "mesh/topology.hpp"

namespace molsurf {

namespace {

// The components with their measures, and their order for reports: the largest outer
// surface first, then by area (order[k] is the k-th component reported).
struct MeasuredComponents {
  Components parts;
  std::vector<ComponentMeasure> measures;
  std::vector<std::size_t> order;
};

MeasuredComponents measured_components(const Mesh& mesh) {
  // Volumes about each component's own vertex, with an exact sign (mesh/component_volume.hpp).
  MeasuredComponents m;
  m.parts = connected_components(mesh);
  const ComponentVolumes volumes = component_volumes(mesh, m.parts);
  m.measures.resize(m.parts.count);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    ComponentMeasure& c = m.measures[m.parts.face_component[f]];
    ++c.faces;
    c.area += face_area(mesh, f);
  }
  for (std::size_t c = 0; c < m.parts.count; ++c) m.measures[c].volume = volumes.volume[c];
  m.order.resize(m.parts.count);
  for (std::size_t c = 0; c < m.parts.count; ++c) m.order[c] = c;
  std::stable_sort(m.order.begin(), m.order.end(), [&](std::size_t x, std::size_t y) {
    const ComponentMeasure &a = m.measures[x], &b = m.measures[y];
    if (a.cavity() != b.cavity()) return !a.cavity();
    return a.area > b.area;
  });
  return m;
}

}  // namespace

std::vector<ComponentMeasure> measure_components(const Mesh& mesh) {
  const MeasuredComponents m = measured_components(mesh);
  std::vector<ComponentMeasure> out;
  out.reserve(m.order.size());
  for (std::size_t c : m.order) out.push_back(m.measures[c]);
  return out;
}

std::vector<std::int64_t> shells_of_components(const Mesh& mesh, const SphereArrangement& arrangement) {
  const MeasuredComponents m = measured_components(mesh);
  const std::size_t atoms = arrangement.area_per_sphere.size();
  // The shells each atom lines (an atom may line the outer surface and a cavity).
  std::vector<std::vector<std::uint32_t>> shells_of_atom(atoms);
  for (const ArrangementPatch& p : arrangement.patches) {
    std::vector<std::uint32_t>& list = shells_of_atom[p.sphere];
    if (std::find(list.begin(), list.end(), p.shell) == list.end()) list.push_back(p.shell);
  }
  // The atoms each component's faces come from.
  std::vector<std::vector<std::uint32_t>> atoms_of(m.parts.count);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::int32_t t = mesh.tag(f);
    if (t >= 0 && static_cast<std::size_t>(t) < atoms) atoms_of[m.parts.face_component[f]].push_back(t);
  }
  // Each component follows the shell whose atoms are most like its own (Jaccard index).
  std::vector<std::int64_t> out;
  out.reserve(m.order.size());
  std::map<std::uint32_t, std::size_t> shared;
  for (std::size_t c : m.order) {
    std::vector<std::uint32_t>& own = atoms_of[c];
    std::sort(own.begin(), own.end());
    own.erase(std::unique(own.begin(), own.end()), own.end());
    shared.clear();
    for (std::uint32_t a : own)
      for (std::uint32_t shell : shells_of_atom[a]) ++shared[shell];
    std::int64_t best = -1;
    double score = 0;
    for (const auto& [shell, common] : shared) {
      const double jaccard =
          double(common) / double(own.size() + arrangement.shells[shell].spheres.size() - common);
      if (jaccard > score) {
        score = jaccard;
        best = shell;
      }
    }
    out.push_back(best);
  }
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
