#include "molsurf/surface_measures.hpp"

#include <algorithm>
#include <limits>
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

double enclosed_volume(std::span<const ComponentMeasure> components) {
  double volume = 0;
  for (const ComponentMeasure& c : components) volume += c.volume;
  return volume;
}

std::vector<ComponentMeasure> measure_components(const Mesh& mesh) {
  const MeasuredComponents m = measured_components(mesh);
  std::vector<ComponentMeasure> out;
  out.reserve(m.order.size());
  for (std::size_t c : m.order) out.push_back(m.measures[c]);
  return out;
}

namespace {

// Each component (in m.order) matched to the shell whose atoms are most like its own.
std::vector<std::int64_t> match_shells(const Mesh& mesh, const MeasuredComponents& m,
                                       const SphereArrangement& arrangement) {
  const std::size_t atoms = arrangement.area_per_sphere.size();
  // The atoms each component's faces come from, once each.
  std::vector<std::vector<std::uint32_t>> atoms_of(m.parts.count);
  std::vector<std::uint32_t> seen_in(atoms, std::numeric_limits<std::uint32_t>::max());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::int32_t t = mesh.tag(f);
    const std::uint32_t c = m.parts.face_component[f];
    if (t < 0 || static_cast<std::size_t>(t) >= atoms || seen_in[t] == c) continue;
    seen_in[t] = c;
    atoms_of[c].push_back(t);
  }
  std::vector<std::vector<std::uint32_t>> in_order;
  in_order.reserve(m.order.size());
  for (std::size_t c : m.order) in_order.push_back(std::move(atoms_of[c]));
  return shells_of_atom_sets(in_order, arrangement);
}

}  // namespace

std::vector<std::int64_t> shells_of_atom_sets(std::span<std::vector<std::uint32_t>> atoms_of,
                                              const SphereArrangement& arrangement) {
  const std::size_t atoms = arrangement.area_per_sphere.size();
  // The shells each atom lines (an atom may line the outer surface and a cavity): CSR.
  std::vector<std::uint32_t> first(atoms + 1, 0);
  for (const ArrangementPatch& p : arrangement.patches) ++first[p.sphere + 1];
  for (std::size_t a = 0; a < atoms; ++a) first[a + 1] += first[a];
  std::vector<std::uint32_t> shells(arrangement.patches.size());
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (const ArrangementPatch& p : arrangement.patches) shells[fill[p.sphere]++] = p.shell;
  }
  // Each component follows the shell whose atoms are most like its own (Jaccard index).
  std::vector<std::int64_t> out;
  out.reserve(atoms_of.size());
  std::vector<std::uint32_t> shared(arrangement.shells.size(), 0);
  std::vector<std::uint32_t> touched;
  for (std::vector<std::uint32_t>& own : atoms_of) {
    std::sort(own.begin(), own.end());
    own.erase(std::unique(own.begin(), own.end()), own.end());
    own.erase(std::remove_if(own.begin(), own.end(), [&](std::uint32_t a) { return a >= atoms; }), own.end());
    touched.clear();
    for (std::uint32_t a : own)
      for (std::uint32_t k = first[a]; k < first[a + 1]; ++k) {
        const std::uint32_t shell = shells[k];
        if (k > first[a] && std::find(&shells[first[a]], &shells[k], shell) != &shells[k]) continue;
        if (shared[shell]++ == 0) touched.push_back(shell);
      }
    std::sort(touched.begin(), touched.end());
    std::int64_t best = -1;
    double score = 0;
    for (std::uint32_t shell : touched) {
      const double common = shared[shell];
      const double jaccard = common / (double(own.size() + arrangement.shells[shell].spheres.size()) - common);
      if (jaccard > score) {
        score = jaccard;
        best = shell;
      }
      shared[shell] = 0;
    }
    out.push_back(best);
  }
  return out;
}

std::vector<std::int64_t> shells_of_components(const Mesh& mesh, const SphereArrangement& arrangement) {
  return match_shells(mesh, measured_components(mesh), arrangement);
}

MeshComponentsAndShells measure_components_and_shells(const Mesh& mesh, const SphereArrangement& arrangement) {
  const MeasuredComponents m = measured_components(mesh);
  MeshComponentsAndShells out;
  out.components.reserve(m.order.size());
  for (std::size_t c : m.order) out.components.push_back(m.measures[c]);
  out.shells = match_shells(mesh, m, arrangement);
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
  using Key = std::tuple<std::string, std::int64_t, char, std::string>;
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

std::vector<ChainArea> area_per_chain(std::span<const Atom> atoms, std::span<const double> atom_area) {
  std::vector<ChainArea> rows;
  std::map<std::string, std::size_t> index;
  for (const ResidueArea& r : area_per_residue(atoms, atom_area)) {
    const auto [it, inserted] = index.try_emplace(r.chain, rows.size());
    if (inserted) rows.push_back({r.chain, 0, 0, 0.0});
    ChainArea& c = rows[it->second];
    c.atoms += r.atoms;
    ++c.residues;
    c.area += r.area;
  }
  return rows;
}

}  // namespace molsurf
