#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/icosphere.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/volume_mesh.hpp"
#include "volume/volume_mesh_size.hpp"

namespace molsurf {
namespace {

// What a gmsh 2.2 file holds, as a reader would see it: nodes, and per element type its
// elements with their physical tag.
struct MshFile {
  std::map<long long, Vec3> nodes;
  struct Element {
    int physical;
    std::vector<long long> nodes;
  };
  std::map<int, std::vector<Element>> by_type;
  std::map<std::pair<int, int>, std::string> names;  // (dim, tag) -> name
};

MshFile parse(const std::string& text) {
  MshFile file;
  std::istringstream in(text);
  std::string section;
  while (in >> section) {
    if (section == "$PhysicalNames") {
      int count;
      in >> count;
      for (int i = 0; i < count; ++i) {
        int dim, tag;
        std::string name;
        in >> dim >> tag >> name;
        file.names[{dim, tag}] = name.substr(1, name.size() - 2);
      }
    } else if (section == "$Nodes") {
      long long count;
      in >> count;
      for (long long i = 0; i < count; ++i) {
        long long n;
        Vec3 p;
        in >> n >> p.x >> p.y >> p.z;
        file.nodes[n] = p;
      }
    } else if (section == "$Elements") {
      long long count;
      in >> count;
      for (long long i = 0; i < count; ++i) {
        long long number;
        int type, tags;
        in >> number >> type >> tags;
        std::vector<int> tag(tags);
        for (int& t : tag) in >> t;
        const int corners = type == 2 ? 3 : type == 4 ? 4 : type == 1 ? 2 : 1;
        MshFile::Element e{tags > 0 ? tag[0] : 0, std::vector<long long>(corners)};
        for (long long& c : e.nodes) in >> c;
        file.by_type[type].push_back(e);
      }
    }
  }
  return file;
}

// Triangles as sets of their corners' coordinates: the same triangle in two meshes,
// whatever the node numbers and the corner order.
using Corners = std::array<std::array<double, 3>, 3>;
Corners corners_of(std::array<Vec3, 3> p) {
  Corners c;
  for (int k = 0; k < 3; ++k) c[k] = {p[k].x, p[k].y, p[k].z};
  std::sort(c.begin(), c.end());
  return c;
}

std::multiset<Corners> triangles_of(const Mesh& mesh) {
  std::multiset<Corners> out;
  for (const Triangle& t : mesh.faces)
    out.insert(corners_of({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]}));
  return out;
}

std::multiset<Corners> triangles_of(const MshFile& file, int physical) {
  std::multiset<Corners> out;
  for (const MshFile::Element& e : file.by_type.at(2))
    if (e.physical == physical)
      out.insert(corners_of({file.nodes.at(e.nodes[0]), file.nodes.at(e.nodes[1]), file.nodes.at(e.nodes[2])}));
  return out;
}

class VolumeMeshTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!volume_mesh_available()) {
      EXPECT_THROW(mesh_volume(make_icosphere({0, 0, 0}, 1, {}), {}), Error);
      GTEST_SKIP() << "built without gmsh (Debian: libgmsh-dev)";
    }
  }
};

TEST_F(VolumeMeshTest, OneSphereInABox) {
  const Mesh sphere = make_icosphere({1.5, -2, 0.25}, 3, {.frequency = 4});
  VolumeMeshOptions options;
  options.box_margin = 4;
  const VolumeMesh v = mesh_volume(sphere, options);
  ASSERT_EQ(v.report.regions.size(), 1u);
  EXPECT_EQ(v.report.regions[0].name, "solvent");
  EXPECT_GT(v.report.tetrahedra, 500u);
  // The tetrahedra fill the box minus the polyhedron, up to the rounding of their sum.
  const double expected = v.report.box_volume - signed_volume(sphere);
  EXPECT_NEAR(v.report.regions[0].volume, expected, 1e-9 * v.report.box_volume);
  // The box: the polyhedron's bounding box (circumradius 3, less the inscribed shrink) and the margin of 4.
  Vec3 lo = sphere.vertices[0], hi = lo;
  for (const Vec3& p : sphere.vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  EXPECT_NEAR(v.report.box_volume, (hi.x - lo.x + 8) * (hi.y - lo.y + 8) * (hi.z - lo.z + 8), 1e-9 * v.report.box_volume);
  EXPECT_NEAR(v.report.box_volume, std::pow(6 + 8, 3), 1e-4);
  const MshFile file = parse(v.msh);
  EXPECT_EQ(file.by_type.at(4).size(), v.report.tetrahedra);
  // The surface is the boundary as it is: the same triangles, nothing remeshed.
  EXPECT_EQ(triangles_of(file, 1), triangles_of(sphere));
  EXPECT_EQ(file.names.at({2, 1}), "outer");
  EXPECT_EQ(file.names.at({2, 2}), "box");  // after the components
  EXPECT_EQ(file.names.at({3, 1}), "solvent");
  EXPECT_EQ(mesh_volume(sphere, options).msh, v.msh);  // the same file on every run
  EXPECT_GT(v.report.min_dihedral_deg, 0);
  EXPECT_GT(v.report.median_radius_ratio, 0.3);
  EXPECT_LE(v.report.median_radius_ratio, 1.0);
}

// A shell: an outer sphere and, inside it, a cavity (a smaller sphere turned inward), as
// compute_surface gives a molecule with a cavity.
TEST_F(VolumeMeshTest, TheInsideWithACavityAsItsOwnRegion) {
  Mesh shell = make_icosphere({0, 0, 0}, 4, {.frequency = 4});
  Mesh cavity = make_icosphere({0.5, 0, 0}, 1.5, {.frequency = 3});
  const double cavity_volume = signed_volume(cavity);
  const auto offset = static_cast<Index>(shell.vertices.size());
  for (const Vec3& p : cavity.vertices) shell.vertices.push_back(p);
  for (Triangle t : cavity.faces) shell.faces.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  VolumeMeshOptions options;
  options.box_margin = 3;
  options.fill_inside = true;
  const VolumeMesh v = mesh_volume(shell, options);
  ASSERT_EQ(v.report.regions.size(), 3u);
  EXPECT_EQ(v.report.regions[0].name, "solvent");
  EXPECT_EQ(v.report.regions[1].name, "solute");
  EXPECT_EQ(v.report.regions[2].name, "cavity-1");
  const double outer_volume = signed_volume(make_icosphere({0, 0, 0}, 4, {.frequency = 4}));
  EXPECT_NEAR(v.report.regions[0].volume, v.report.box_volume - outer_volume, 1e-9 * v.report.box_volume);
  EXPECT_NEAR(v.report.regions[1].volume, outer_volume - cavity_volume, 1e-9 * outer_volume);
  EXPECT_NEAR(v.report.regions[2].volume, cavity_volume, 1e-9 * outer_volume);
  const MshFile file = parse(v.msh);
  EXPECT_EQ(file.names.at({3, 2}), "solute");
  EXPECT_EQ(file.names.at({3, 3}), "cavity-1");
  EXPECT_EQ(file.names.at({2, 2}), "cavity-1");
  EXPECT_EQ(triangles_of(file, 2), triangles_of(cavity));
  std::map<int, std::size_t> tets_by_region;
  for (const MshFile::Element& e : file.by_type.at(4)) ++tets_by_region[e.physical];
  for (const VolumeRegion& r : v.report.regions) EXPECT_EQ(tets_by_region[r.physical], r.tetrahedra) << r.name;
}

TEST_F(VolumeMeshTest, AroundAMolecularSurface) {
  std::vector<Atom> atoms(3);
  atoms[0].centre = {0, 0, 0};
  atoms[1].centre = {1.6, 0.3, 0};
  atoms[2].centre = {0.7, 1.4, 0.5};
  for (Atom& a : atoms) a.radius = 1.7;
  const ComputedSurface s = compute_surface(atoms);
  const VolumeMesh v = mesh_volume(s.mesh, {});
  EXPECT_NEAR(v.report.regions[0].volume, v.report.box_volume - s.measures.volume, 1e-9 * v.report.box_volume);
  EXPECT_EQ(triangles_of(parse(v.msh), 1), triangles_of(s.mesh));
}

TEST_F(VolumeMeshTest, BadOptionsAreErrors) {
  const Mesh sphere = make_icosphere({0, 0, 0}, 1, {.frequency = 2});
  VolumeMeshOptions options;
  options.box_margin = 0;
  EXPECT_THROW(mesh_volume(sphere, options), Error);
  EXPECT_THROW(mesh_volume(Mesh{}, {}), Error);
}

// Issue 34: --volume-size 0.05 or 1e-3 ran gmsh without end. The tetrahedra are bounded
// from below before gmsh starts (the box's volume over a regular tetrahedron's) and
// refused when their memory is above the limit.
TEST_F(VolumeMeshTest, ATetrahedronSizeTooSmallForTheMemoryIsRefusedBeforeMeshing) {
  const Mesh sphere = make_icosphere({0, 0, 0}, 10, {.frequency = 4});
  for (const double size : {0.05, 1e-3, 1e-300}) {
    VolumeMeshOptions options;
    options.box_size = size;
    try {
      mesh_volume(sphere, options);
      ADD_FAILURE() << "size " << size << " was meshed";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("volume mesh: the box (", 0), 0u) << message;
      EXPECT_NE(message.find("with tetrahedra of size"), std::string::npos) << message;
      EXPECT_NE(message.find("raise --volume-size, lower --box-margin, or raise the limit with --max-memory"),
                std::string::npos)
          << message;
    }
  }
  // The bound is the box's volume over a regular tetrahedron's: 64 000 / (8 / (6 sqrt 2)).
  EXPECT_NEAR(volume_detail::tetrahedra_lower_bound({{-20, -20, -20}, {20, 20, 20}}, 2), 64000 * 6 * std::sqrt(2.0) / 8,
              1e-6);
  // A limit below what the default size needs refuses it too; the default limit meshes it.
  VolumeMeshOptions tight;
  tight.max_memory = 1000;
  EXPECT_THROW(mesh_volume(sphere, tight), Error);
  EXPECT_GT(mesh_volume(sphere, {}).report.tetrahedra, 0u);
}

}  // namespace
}  // namespace molsurf
