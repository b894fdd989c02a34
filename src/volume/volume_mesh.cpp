#include "molsurf/volume_mesh.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"
#include "molsurf/split_components.hpp"
#include "volume/tetrahedron_quality.hpp"
#include "volume/volume_mesh_size.hpp"

#ifdef MOLSURF_HAVE_GMSH
#include "volume/gmsh_library.hpp"
#endif

namespace molsurf {

bool volume_mesh_available() {
#ifdef MOLSURF_HAVE_GMSH
  return true;
#else
  return false;
#endif
}

#ifndef MOLSURF_HAVE_GMSH

VolumeMesh mesh_volume(const Mesh&, const VolumeMeshOptions&) {
  throw Error("this molsurf was built without gmsh, which makes the volume mesh: install gmsh's library "
              "(Debian: libgmsh-dev) and build again");
}

#else

namespace {

using volume_detail::GmshArray;
using volume_detail::GmshLibrary;

// One gmsh model for the call: gmsh is initialised here and finalised on every way out.
class GmshSession {
 public:
  explicit GmshSession(const GmshLibrary& gmsh) : gmsh_(gmsh) {
    gmsh.call(gmsh.gmshInitialize, 0, nullptr, 0);
    gmsh.call(gmsh.gmshOptionSetNumber, "General.Terminal", 0.0);
    // One thread: with two, gmsh 4.8's tetrahedra differed from run to run (1crn: 101 542
    // and 101 619) and took twice as long; with one the file is the same on every run.
    gmsh.call(gmsh.gmshOptionSetNumber, "General.NumThreads", 1.0);
    gmsh.call(gmsh.gmshLoggerStart);
    gmsh.call(gmsh.gmshModelAdd, "molsurf");
  }
  ~GmshSession() {
    int ierr = 0;
    gmsh_.gmshLoggerStop(&ierr);
    gmsh_.gmshFinalize(&ierr);
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  const GmshLibrary& gmsh_;
};

// The surface's components as gmsh discrete surfaces 1..C (the report's order), their
// nodes and triangles as they are.
void add_surface(const GmshLibrary& gmsh, const Mesh& surface, const ComponentOrder& order) {
  const std::size_t count = order.kind.size();
  std::vector<std::vector<std::size_t>> node_tags(count), triangle_nodes(count), triangle_tags(count);
  std::vector<std::vector<double>> coordinates(count);
  std::vector<std::uint32_t> component_of_vertex(surface.vertices.size(), ~std::uint32_t{0});
  for (std::size_t f = 0; f < surface.faces.size(); ++f)
    for (Index v : surface.faces[f]) component_of_vertex[v] = order.face_component[f];
  for (std::size_t v = 0; v < surface.vertices.size(); ++v) {
    const std::uint32_t c = component_of_vertex[v];
    if (c == ~std::uint32_t{0}) continue;
    node_tags[c].push_back(v + 1);
    for (double x : {surface.vertices[v].x, surface.vertices[v].y, surface.vertices[v].z}) coordinates[c].push_back(x);
  }
  for (std::size_t f = 0; f < surface.faces.size(); ++f) {
    const std::uint32_t c = order.face_component[f];
    triangle_tags[c].push_back(f + 1);
    for (Index v : surface.faces[f]) triangle_nodes[c].push_back(v + 1);
  }
  for (std::size_t c = 0; c < count; ++c) {
    const int tag = static_cast<int>(c + 1);
    gmsh.call(gmsh.gmshModelAddDiscreteEntity, 2, tag, static_cast<int*>(nullptr), std::size_t{0});
    gmsh.call(gmsh.gmshModelMeshAddNodes, 2, tag, node_tags[c].data(), node_tags[c].size(), coordinates[c].data(),
              coordinates[c].size(), static_cast<double*>(nullptr), std::size_t{0});
    gmsh.call(gmsh.gmshModelMeshAddElementsByType, tag, 2, triangle_tags[c].data(), triangle_tags[c].size(),
              triangle_nodes[c].data(), triangle_nodes[c].size());
  }
}

// The box's six sides as plane surfaces; their tags (gmsh chooses free ones, so any number
// of components fits).
std::vector<int> add_box(const GmshLibrary& gmsh, const BoundingBox& box, double size) {
  std::array<int, 8> point{};
  for (int i = 0; i < 8; ++i)
    point[i] = gmsh.call(gmsh.gmshModelGeoAddPoint, i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                         i & 4 ? box.max.z : box.min.z, size, -1);
  constexpr int edge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  std::array<int, 12> line{};
  for (int k = 0; k < 12; ++k) line[k] = gmsh.call(gmsh.gmshModelGeoAddLine, point[edge[k][0]], point[edge[k][1]], -1);
  // Each side as a loop of the edges above (1-based); a negative entry runs against the edge.
  constexpr int side[6][4] = {{1, 6, -2, -5}, {3, 8, -4, -7}, {1, 10, -3, -9},
                              {2, 12, -4, -11}, {5, 11, -7, -9}, {6, 12, -8, -10}};
  std::vector<int> sides;
  for (int k = 0; k < 6; ++k) {
    std::vector<int> loop;
    for (int e : side[k]) loop.push_back(e > 0 ? line[e - 1] : -line[-e - 1]);
    int curve_loop = gmsh.call(gmsh.gmshModelGeoAddCurveLoop, loop.data(), loop.size(), -1, 0);
    sides.push_back(gmsh.call(gmsh.gmshModelGeoAddPlaneSurface, &curve_loop, std::size_t{1}, -1));
  }
  return sides;
}

int add_surface_loop(const GmshLibrary& gmsh, std::vector<int> surfaces) {
  return gmsh.call(gmsh.gmshModelGeoAddSurfaceLoop, surfaces.data(), surfaces.size(), -1);
}

int add_volume(const GmshLibrary& gmsh, std::vector<int> loops, int tag) {
  return gmsh.call(gmsh.gmshModelGeoAddVolume, loops.data(), loops.size(), tag);
}

void add_physical_group(const GmshLibrary& gmsh, int dim, std::vector<int> entities, int tag, const std::string& name) {
  gmsh.call(gmsh.gmshModelAddPhysicalGroup, dim, entities.data(), entities.size(), tag);
  gmsh.call(gmsh.gmshModelSetPhysicalName, dim, tag, name.c_str());
}

// A physical group of the model, with the entities it holds.
struct Group {
  int dim, physical;
  std::string name;
  std::vector<int> entities;
};

std::vector<Group> physical_groups(const GmshLibrary& gmsh) {
  std::vector<Group> groups;
  for (int dim : {2, 3}) {
    GmshArray<int> tags(gmsh);
    gmsh.call(gmsh.gmshModelGetPhysicalGroups, &tags.data, &tags.size, dim);
    for (std::size_t k = 0; k + 1 < tags.size; k += 2) {
      Group g{tags[k], tags[k + 1], "", {}};
      GmshArray<char> name(gmsh);
      gmsh.call(gmsh.gmshModelGetPhysicalName, g.dim, g.physical, &name.data);
      if (name.data) g.name = name.data;
      GmshArray<int> entities(gmsh);
      gmsh.call(gmsh.gmshModelGetEntitiesForPhysicalGroup, g.dim, g.physical, &entities.data, &entities.size);
      g.entities.assign(entities.data, entities.data + entities.size);
      groups.push_back(std::move(g));
    }
  }
  return groups;
}

// The elements of one type on one entity: their tags and corners.
struct Elements {
  Elements(const GmshLibrary& gmsh, int type, int entity) : tags(gmsh), nodes(gmsh) {
    gmsh.call(gmsh.gmshModelMeshGetElementsByType, type, &tags.data, &tags.size, &nodes.data, &nodes.size, entity,
              std::size_t{0}, std::size_t{1});
  }
  GmshArray<std::size_t> tags, nodes;
};

// gmsh MSH 2.2 ASCII written here rather than by gmsh: gmsh prints coordinates with 16
// significant digits, which does not always read back as the same double, and the
// surface's nodes must stay exactly the surface's (shortest round-trip text).
std::string msh_text(const GmshLibrary& gmsh, const GmshArray<std::size_t>& node_tags,
                     const GmshArray<double>& coordinates, const std::vector<Group>& groups) {
  std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" + std::to_string(groups.size()) + "\n";
  for (const Group& g : groups)
    text += std::to_string(g.dim) + " " + std::to_string(g.physical) + " \"" + g.name + "\"\n";
  text += "$EndPhysicalNames\n$Nodes\n" + std::to_string(node_tags.size) + "\n";
  for (std::size_t k = 0; k < node_tags.size; ++k) {
    text += std::to_string(node_tags[k]);
    for (std::size_t a = 0; a < 3; ++a) {
      text += ' ';
      mesh_io::append_number(text, coordinates[3 * k + a]);
    }
    text += '\n';
  }
  text += "$EndNodes\n";
  std::string elements;
  std::size_t count = 0;
  for (const Group& g : groups)
    for (int entity : g.entities) {
      const int type = g.dim == 2 ? 2 : 4, corners = g.dim == 2 ? 3 : 4;
      const Elements e(gmsh, type, entity);
      const std::string prefix = " " + std::to_string(type) + " 2 " + std::to_string(g.physical) + " " +
                                 std::to_string(entity);
      for (std::size_t k = 0; k < e.tags.size; ++k) {
        elements += std::to_string(++count) + prefix;
        for (int c = 0; c < corners; ++c) elements += " " + std::to_string(e.nodes[corners * k + c]);
        elements += '\n';
      }
    }
  text += "$Elements\n" + std::to_string(count) + "\n" + elements + "$EndElements\n";
  return text;
}

}  // namespace

VolumeMesh mesh_volume(const Mesh& surface, const VolumeMeshOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (surface.faces.empty()) throw Error("volume mesh: the surface is empty");
  if (!(options.box_margin > 0) || !std::isfinite(options.box_margin))
    throw Error("volume mesh: the box margin must be a positive number of angstroms");
  const ComponentOrder order = order_components(surface);
  BoundingBox box;
  for (const Triangle& t : surface.faces)
    for (Index v : t) box.extend(surface.vertices[v]);
  const Vec3 margin{options.box_margin, options.box_margin, options.box_margin};
  box.min = box.min - margin;
  box.max = box.max + margin;
  const double size = options.box_size > 0 ? options.box_size : std::max(1.0, options.box_margin / 3);
  volume_detail::check_volume_mesh_memory(box, size, options.max_memory);

  const GmshLibrary gmsh;
  const GmshSession session(gmsh);
  VolumeMesh result;
  add_surface(gmsh, surface, order);
  gmsh.call(gmsh.gmshModelMeshCreateTopology, 1, 1);
  const std::vector<int> box_sides = add_box(gmsh, box, size);
  const int box_loop = add_surface_loop(gmsh, box_sides);
  std::vector<int> component_loops;
  for (std::size_t c = 0; c < order.kind.size(); ++c)
    component_loops.push_back(add_surface_loop(gmsh, {static_cast<int>(c + 1)}));
  // The solvent: inside the box, outside every outer surface. Cavities are inside the
  // molecule: they bound the solute and their own regions, not the solvent.
  std::vector<int> solvent{box_loop};
  for (std::size_t c = 0; c < order.kind.size(); ++c)
    if (order.kind[c] == SurfaceComponent::Kind::outer) solvent.push_back(component_loops[c]);
  struct Planned {
    std::string name;
    int physical;
    std::vector<int> volumes;
  };
  std::vector<Planned> regions{{"solvent", 1, {add_volume(gmsh, solvent, 1)}}};
  if (options.fill_inside) {
    // The solute: inside the outer surfaces, outside the cavities (a surface with more than
    // one outer component gets one solute volume per outer surface, one physical group).
    Planned solute{"solute", 2, {}};
    int next = 2;
    for (std::size_t c = 0; c < order.kind.size(); ++c) {
      if (order.kind[c] != SurfaceComponent::Kind::outer) continue;
      std::vector<int> loops{component_loops[c]};
      if (order.number[c] == 1)
        for (std::size_t k = 0; k < order.kind.size(); ++k)
          if (order.kind[k] == SurfaceComponent::Kind::cavity) loops.push_back(component_loops[k]);
      solute.volumes.push_back(add_volume(gmsh, loops, next++));
    }
    regions.push_back(std::move(solute));
    for (std::size_t c = 0; c < order.kind.size(); ++c)
      if (order.kind[c] == SurfaceComponent::Kind::cavity)
        regions.push_back({"cavity-" + std::to_string(order.number[c]), 2 + static_cast<int>(order.number[c]),
                           {add_volume(gmsh, {component_loops[c]}, next++)}});
  }
  gmsh.call(gmsh.gmshModelGeoSynchronize);
  for (const Planned& r : regions) add_physical_group(gmsh, 3, r.volumes, r.physical, r.name);
  for (std::size_t c = 0; c < order.kind.size(); ++c) {
    const bool cavity = order.kind[c] == SurfaceComponent::Kind::cavity;
    add_physical_group(gmsh, 2, {static_cast<int>(c + 1)}, static_cast<int>(c + 1),
                       cavity ? "cavity-" + std::to_string(order.number[c])
                              : (order.number[c] == 1 ? std::string("outer") : "outer-" + std::to_string(order.number[c])));
  }
  // The box after the components: fixed numbers would collide with the cavities of a
  // large structure (7cth has more than 200).
  add_physical_group(gmsh, 2, box_sides, static_cast<int>(order.kind.size()) + 1, "box");

  gmsh.call(gmsh.gmshModelMeshGenerate, 3);

  // What came out, region by region.
  GmshArray<std::size_t> node_tags(gmsh);
  GmshArray<double> coordinates(gmsh), parametric(gmsh);
  gmsh.call(gmsh.gmshModelMeshGetNodes, &node_tags.data, &node_tags.size, &coordinates.data, &coordinates.size,
            &parametric.data, &parametric.size, -1, -1, 0, 0);
  std::size_t largest = 0;
  for (std::size_t k = 0; k < node_tags.size; ++k) largest = std::max(largest, node_tags[k]);
  std::vector<Vec3> node(largest + 1);
  for (std::size_t k = 0; k < node_tags.size; ++k)
    node[node_tags[k]] = {coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]};
  VolumeMeshReport& report = result.report;
  report.nodes = node_tags.size;
  report.min_dihedral_deg = 180;
  report.min_radius_ratio = 1;
  std::vector<double> ratios;
  for (const Planned& r : regions) {
    VolumeRegion region{r.name, r.physical, 0, 0};
    for (int entity : r.volumes) {
      const Elements tets(gmsh, 4, entity);
      region.tetrahedra += tets.tags.size;
      for (std::size_t e = 0; e < tets.tags.size; ++e) {
        const std::array<Vec3, 4> p{node[tets.nodes[4 * e]], node[tets.nodes[4 * e + 1]], node[tets.nodes[4 * e + 2]],
                                    node[tets.nodes[4 * e + 3]]};
        const volume_detail::TetrahedronShape shape = volume_detail::tetrahedron_shape(p);
        region.volume += shape.volume;
        report.min_dihedral_deg = std::min(report.min_dihedral_deg, shape.min_dihedral_deg);
        report.min_radius_ratio = std::min(report.min_radius_ratio, shape.radius_ratio);
        ratios.push_back(shape.radius_ratio);
      }
    }
    if (region.tetrahedra == 0) {
      const std::string why = gmsh.last_error();
      throw Error("volume mesh: gmsh made no tetrahedra in the " + r.name + " region" +
                  (why.empty() ? std::string() : " (" + why + ")"));
    }
    report.tetrahedra += region.tetrahedra;
    report.regions.push_back(region);
  }
  if (!ratios.empty()) {
    std::nth_element(ratios.begin(), ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2), ratios.end());
    report.median_radius_ratio = ratios[ratios.size() / 2];
  }
  const Vec3 extent = box.max - box.min;
  report.box_volume = extent.x * extent.y * extent.z;
  result.msh = msh_text(gmsh, node_tags, coordinates, physical_groups(gmsh));
  result.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

#endif

}  // namespace molsurf
