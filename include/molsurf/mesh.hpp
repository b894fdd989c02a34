#pragma once
// The indexed triangle mesh every part of molsurf exchanges, and its measures.
//
// Faces are counter-clockwise seen from outside, so (b-a)x(c-a) points outward and a
// closed outward mesh has positive volume. Each face may carry a tag: the index of
// the atom (or of the source face) it came from; -1 means untagged.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf {

using Index = std::uint32_t;
using Triangle = std::array<Index, 3>;
constexpr std::int32_t kNoTag = -1;

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> faces;
  std::vector<std::int32_t> face_tags;  // empty, or one per face

  std::size_t vertex_count() const { return vertices.size(); }
  std::size_t face_count() const { return faces.size(); }
  bool has_tags() const { return !face_tags.empty(); }
  std::int32_t tag(std::size_t face) const { return face_tags.empty() ? kNoTag : face_tags[face]; }

  // Appends `other`, offsetting its indices; tags follow (untagged faces get kNoTag).
  void append(const Mesh& other);
};

struct BoundingBox {
  Vec3 min{1e300, 1e300, 1e300};
  Vec3 max{-1e300, -1e300, -1e300};
  bool empty() const { return min.x > max.x; }
  void extend(const Vec3& p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
  }
  void extend(const BoundingBox& b) {
    if (b.empty()) return;
    extend(b.min);
    extend(b.max);
  }
  // Closed boxes: touching boxes overlap, so culling never drops a contact. All six
  // comparisons are made (`&`): a chain of branches mispredicts on mixed outcomes.
  bool overlaps(const BoundingBox& b) const {
    return (min.x <= b.max.x) & (b.min.x <= max.x) & (min.y <= b.max.y) & (b.min.y <= max.y) & (min.z <= b.max.z) &
           (b.min.z <= max.z);
  }
};

BoundingBox bounding_box(const Mesh& mesh);
BoundingBox bounding_box(const Mesh& mesh, std::size_t face);

double face_area(const Mesh& mesh, std::size_t face);
double surface_area(const Mesh& mesh);
// Signed volume by the divergence theorem: positive for a closed outward mesh.
double signed_volume(const Mesh& mesh);
// Unit normal of a face (zero vector for a degenerate face).
Vec3 face_normal(const Mesh& mesh, std::size_t face);
// Area-weighted vertex normals, unit length.
std::vector<Vec3> vertex_normals(const Mesh& mesh);

// Components of faces connected through shared vertices. `face_component[f]` is in
// [0, count); components are numbered in order of their lowest face index.
struct Components {
  std::size_t count = 0;
  std::vector<std::uint32_t> face_component;
};
Components connected_components(const Mesh& mesh);

// V - E + F over the vertices actually used by faces (edges counted once per vertex pair).
long euler_characteristic(const Mesh& mesh);

// Triangle quality. Aspect ratio is longest edge / (2*sqrt(3)*inradius): 1 for equilateral.
struct Quality {
  double min_angle_deg = 0;   // smallest angle over all faces
  double mean_min_angle_deg = 0;
  double max_aspect_ratio = 0;
  std::size_t below_1deg = 0;  // faces whose smallest angle is below 1 degree
  std::size_t below_5deg = 0;
  std::size_t faces = 0;
};
// The two edges (u, w) leaving the corner of triangle abc opposite its shortest edge: the
// corner of its smallest angle (law of sines).
std::array<Vec3, 2> smallest_angle_edges(const Vec3& a, const Vec3& b, const Vec3& c);
// The smallest angle of triangle abc in degrees, from atan2 of |u x w| and u.w of those
// edges: accurate for tiny and near-straight angles.
double smallest_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c);
double min_angle_deg(const Mesh& mesh, std::size_t face);
double aspect_ratio(const Mesh& mesh, std::size_t face);
Quality mesh_quality(const Mesh& mesh);

}  // namespace molsurf
