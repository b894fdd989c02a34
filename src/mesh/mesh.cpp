#include "molsurf/mesh.hpp"

#include "mesh/topology.hpp"
#include "common/block_reduce.hpp"
#include "common/parallel_threshold.hpp"

#include <parallel/algorithm>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>
#include <vector>

namespace molsurf {

void Mesh::append(const Mesh& other) {
  const auto offset = static_cast<Index>(vertices.size());
  const bool tagged = has_tags() || other.has_tags();
  if (tagged && face_tags.size() != faces.size()) face_tags.resize(faces.size(), kNoTag);
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  faces.reserve(faces.size() + other.faces.size());
  for (const Triangle& t : other.faces) faces.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  if (tagged) {
    if (other.has_tags())
      face_tags.insert(face_tags.end(), other.face_tags.begin(), other.face_tags.end());
    else
      face_tags.resize(faces.size(), kNoTag);
  }
}

BoundingBox bounding_box(const Mesh& mesh) {
  // In parallel (a pass over every corner, several times per run): a box is the same
  // whatever order its points are taken in.
  BoundingBox box;
  const auto nf = static_cast<std::int64_t>(mesh.faces.size());
#pragma omp parallel if (nf >= kParallelMinItems)
  {
    BoundingBox part;
#pragma omp for schedule(static) nowait
    for (std::int64_t f = 0; f < nf; ++f)
      for (Index v : mesh.faces[f]) part.extend(mesh.vertices[v]);
#pragma omp critical(molsurf_bounding_box)
    box.extend(part);
  }
  return box;
}

BoundingBox bounding_box(const Mesh& mesh, std::size_t face) {
  BoundingBox box;
  for (Index v : mesh.faces[face]) box.extend(mesh.vertices[v]);
  return box;
}

namespace {

Vec3 area_vector(const Mesh& mesh, std::size_t face) {  // twice the area, along the normal
  const Triangle& t = mesh.faces[face];
  const Vec3& a = mesh.vertices[t[0]];
  return cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
}

}  // namespace

double face_area(const Mesh& mesh, std::size_t face) { return 0.5 * norm(area_vector(mesh, face)); }

double surface_area(const Mesh& mesh) {
  return block_reduce(
      static_cast<std::int64_t>(mesh.faces.size()), 0.0,
      [&](double& sum, std::int64_t f) { sum += face_area(mesh, static_cast<std::size_t>(f)); },
      [](double& total, double block) { total += block; });
}

double signed_volume(const Mesh& mesh) {
  if (mesh.faces.empty()) return 0;
  // Relative to the box centre: the volume does not depend on the origin for a closed
  // mesh, and small relative coordinates lose far less to cancellation.
  const BoundingBox box = bounding_box(mesh);
  const Vec3 origin = 0.5 * (box.min + box.max);
  const double six_volume = block_reduce(
      static_cast<std::int64_t>(mesh.faces.size()), 0.0,
      [&](double& sum, std::int64_t f) {
        const Triangle& t = mesh.faces[static_cast<std::size_t>(f)];
        const Vec3 a = mesh.vertices[t[0]] - origin;
        const Vec3 b = mesh.vertices[t[1]] - origin;
        const Vec3 c = mesh.vertices[t[2]] - origin;
        sum += dot(a, cross(b, c));
      },
      [](double& total, double block) { total += block; });
  return six_volume / 6.0;
}

Vec3 face_normal(const Mesh& mesh, std::size_t face) {
  const Vec3 n = area_vector(mesh, face);
  const double length = norm(n);
  return length > 0 ? n / length : Vec3{};
}

std::vector<Vec3> vertex_normals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Vec3 n = area_vector(mesh, f);
    for (Index v : mesh.faces[f]) normals[v] += n;
  }
  for (Vec3& n : normals) {
    const double length = norm(n);
    if (length > 0) n = n / length;
  }
  return normals;
}

namespace {


}  // namespace

Components connected_components(const Mesh& mesh) {
  DisjointSets sets(mesh.vertices.size());
  for (const Triangle& t : mesh.faces) {
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
  }
  Components result;
  result.face_component.resize(mesh.faces.size());
  constexpr std::uint32_t kUnnumbered = ~0u;
  std::vector<std::uint32_t> number_of_root(mesh.vertices.size(), kUnnumbered);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::uint32_t& number = number_of_root[sets.find(mesh.faces[f][0])];
    if (number == kUnnumbered) number = static_cast<std::uint32_t>(result.count++);
    result.face_component[f] = number;
  }
  return result;
}

long euler_characteristic(const Mesh& mesh) {
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(3 * mesh.faces.size());
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.faces)
    for (int i = 0; i < 3; ++i) {
      used[t[i]] = 1;
      edges.emplace_back(std::minmax(t[i], t[(i + 1) % 3]));
    }
  __gnu_parallel::sort(edges.begin(), edges.end());
  const auto edge_count = std::unique(edges.begin(), edges.end()) - edges.begin();
  const auto vertex_count = std::count(used.begin(), used.end(), 1);
  return static_cast<long>(vertex_count) - static_cast<long>(edge_count) +
         static_cast<long>(mesh.faces.size());
}

std::array<Vec3, 2> smallest_angle_edges(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, bc = c - b, ca = a - c;
  const double lab = dot(ab, ab), lbc = dot(bc, bc), lca = dot(ca, ca);
  if (lab <= lbc && lab <= lca) return {a - c, b - c};
  if (lbc <= lca) return {b - a, c - a};
  return {c - b, a - b};
}

double smallest_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto [u, w] = smallest_angle_edges(a, b, c);
  return std::min(180.0, std::atan2(norm(cross(u, w)), dot(u, w)) * 180.0 / std::numbers::pi);
}

double min_angle_deg(const Mesh& mesh, std::size_t face) {
  const Triangle& t = mesh.faces[face];
  return smallest_angle_deg(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

double aspect_ratio(const Mesh& mesh, std::size_t face) {
  const Triangle& t = mesh.faces[face];
  const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
  const double ab = norm(b - a), bc = norm(c - b), ca = norm(a - c);
  const double twice_area = norm(cross(b - a, c - a));
  if (twice_area == 0) return std::numeric_limits<double>::infinity();
  const double inradius = twice_area / (ab + bc + ca);
  return std::max({ab, bc, ca}) / (2 * std::sqrt(3.0) * inradius);
}

Quality mesh_quality(const Mesh& mesh) {
  Quality q;
  q.faces = mesh.faces.size();
  if (q.faces == 0) return q;
  struct Part {
    double min_angle = 180, sum = 0, max_aspect = 0;
    std::size_t below_1 = 0, below_5 = 0;
  };
  const Part all = block_reduce(
      static_cast<std::int64_t>(q.faces), Part{},
      [&](Part& p, std::int64_t f) {
        const double angle = min_angle_deg(mesh, static_cast<std::size_t>(f));
        p.min_angle = std::min(p.min_angle, angle);
        p.sum += angle;
        p.below_1 += angle < 1;
        p.below_5 += angle < 5;
        p.max_aspect = std::max(p.max_aspect, aspect_ratio(mesh, static_cast<std::size_t>(f)));
      },
      [](Part& total, const Part& p) {
        total.min_angle = std::min(total.min_angle, p.min_angle);
        total.sum += p.sum;
        total.below_1 += p.below_1;
        total.below_5 += p.below_5;
        total.max_aspect = std::max(total.max_aspect, p.max_aspect);
      });
  q.min_angle_deg = all.min_angle;
  q.below_1deg = all.below_1;
  q.below_5deg = all.below_5;
  q.max_aspect_ratio = all.max_aspect;
  q.mean_min_angle_deg = all.sum / static_cast<double>(q.faces);
  return q;
}

}  // namespace molsurf
