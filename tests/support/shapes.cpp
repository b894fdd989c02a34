#include "support/shapes.hpp"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace molsurf {

namespace {

// Vertices keyed by integer lattice coordinates, so that grids of adjacent box sides
// share their border vertices exactly.
class LatticeVertices {
 public:
  LatticeVertices(Mesh& mesh, Vec3 lo, Vec3 step) : mesh_(mesh), lo_(lo), step_(step) {}
  Index at(int i, int j, int k) {
    auto [it, inserted] = index_.try_emplace({i, j, k}, static_cast<Index>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back({lo_.x + i * step_.x, lo_.y + j * step_.y, lo_.z + k * step_.z});
    return it->second;
  }

 private:
  Mesh& mesh_;
  Vec3 lo_, step_;
  std::map<std::array<int, 3>, Index> index_;
};

void add_quad(Mesh& m, Index a, Index b, Index c, Index d) {  // a b c d counter-clockwise
  m.faces.push_back({a, b, c});
  m.faces.push_back({a, c, d});
}

}  // namespace

Mesh make_box(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("make_box: divisions must be at least 1");
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) throw std::invalid_argument("make_box: empty box");
  Mesh m;
  const std::array<int, 3> n{nx, ny, nz};
  const Vec3 step{(hi.x - lo.x) / nx, (hi.y - lo.y) / ny, (hi.z - lo.z) / nz};
  LatticeVertices lattice(m, lo, step);
  // Each side: fixed axis a at 0 or n[a]; grid over the two other axes (u, v) with u x v = +a.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n[u]; ++i)
        for (int j = 0; j < n[v]; ++j) {
          auto vertex = [&](int di, int dj) {
            std::array<int, 3> c{};
            c[a] = side ? n[a] : 0;
            c[u] = i + di;
            c[v] = j + dj;
            return lattice.at(c[0], c[1], c[2]);
          };
          if (side)
            add_quad(m, vertex(0, 0), vertex(1, 0), vertex(1, 1), vertex(0, 1));
          else
            add_quad(m, vertex(0, 0), vertex(0, 1), vertex(1, 1), vertex(1, 0));
        }
    }
  }
  return m;
}

Mesh make_uv_sphere(const Vec3& centre, double radius, int slices, int stacks) {
  if (slices < 3 || stacks < 2) throw std::invalid_argument("make_uv_sphere: at least 3 slices and 2 stacks");
  Mesh m;
  const double pi = std::numbers::pi;
  m.vertices.push_back(centre + Vec3{0, 0, radius});  // north pole
  for (int s = 1; s < stacks; ++s) {
    const double theta = pi * s / stacks;
    for (int k = 0; k < slices; ++k) {
      const double phi = 2 * pi * k / slices;
      m.vertices.push_back(centre + radius * Vec3{std::sin(theta) * std::cos(phi),
                                                  std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  }
  const auto south = static_cast<Index>(m.vertices.size());
  m.vertices.push_back(centre + Vec3{0, 0, -radius});
  auto ring = [&](int s, int k) { return static_cast<Index>(1 + (s - 1) * slices + (k % slices)); };
  for (int k = 0; k < slices; ++k) m.faces.push_back({0, ring(1, k), ring(1, k + 1)});
  for (int s = 1; s + 1 < stacks; ++s)
    for (int k = 0; k < slices; ++k) add_quad(m, ring(s, k), ring(s + 1, k), ring(s + 1, k + 1), ring(s, k + 1));
  for (int k = 0; k < slices; ++k) m.faces.push_back({south, ring(stacks - 1, k + 1), ring(stacks - 1, k)});
  return m;
}

namespace {

// An orthonormal frame (e1, e2, axis) with e1 x e2 = axis.
std::array<Vec3, 3> frame_around(const Vec3& axis_in) {
  const Vec3 w = normalized(axis_in);
  const Vec3 helper = std::abs(w.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 e1 = normalized(cross(helper, w));
  return {e1, cross(w, e1), w};
}

}  // namespace

Mesh make_capped_cylinder(const Vec3& base, const Vec3& axis, double radius, double length, int segments,
                          int rings) {
  if (segments < 3 || rings < 1) throw std::invalid_argument("make_capped_cylinder: at least 3 segments, 1 ring");
  if (!(radius > 0 && length > 0)) throw std::invalid_argument("make_capped_cylinder: empty cylinder");
  const auto [e1, e2, w] = frame_around(axis);
  Mesh m;
  for (int r = 0; r <= rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const double phi = 2 * std::numbers::pi * k / segments;
      m.vertices.push_back(base + w * (length * r / rings) + radius * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
  auto at = [&](int r, int k) { return static_cast<Index>(r * segments + (k % segments)); };
  for (int r = 0; r < rings; ++r)
    for (int k = 0; k < segments; ++k) add_quad(m, at(r, k), at(r, k + 1), at(r + 1, k + 1), at(r + 1, k));
  const auto bottom = static_cast<Index>(m.vertices.size());
  m.vertices.push_back(base);
  const auto top = static_cast<Index>(m.vertices.size());
  m.vertices.push_back(base + w * length);
  for (int k = 0; k < segments; ++k) {
    m.faces.push_back({bottom, at(0, k + 1), at(0, k)});
    m.faces.push_back({top, at(rings, k), at(rings, k + 1)});
  }
  return m;
}

Mesh make_channel(double outer, double inner, double length, int rings, int divisions) {
  if (!(inner > 0 && inner < outer && length > 0) || rings < 1 || divisions < 1)
    throw std::invalid_argument("make_channel: need 0 < inner < outer, length > 0");
  // Two square loops (outer, inner) of 4 * divisions points each, at rings + 1 heights.
  const int per_loop = 4 * divisions;
  auto loop_point = [&](double side, int i) {
    const int edge = i / divisions, step = i % divisions;
    const double h = side / 2, t = -h + side * step / divisions;
    switch (edge) {
      case 0: return Vec3{t, -h, 0};
      case 1: return Vec3{h, t, 0};
      case 2: return Vec3{-t, h, 0};
      default: return Vec3{-h, -t, 0};
    }
  };
  Mesh m;
  for (int r = 0; r <= rings; ++r)
    for (double side : {outer, inner})
      for (int i = 0; i < per_loop; ++i) m.vertices.push_back(loop_point(side, i) + Vec3{0, 0, length * r / rings});
  auto outer_at = [&](int r, int i) { return static_cast<Index>(r * 2 * per_loop + (i % per_loop)); };
  auto inner_at = [&](int r, int i) { return static_cast<Index>(r * 2 * per_loop + per_loop + (i % per_loop)); };
  for (int r = 0; r < rings; ++r)
    for (int i = 0; i < per_loop; ++i) {
      add_quad(m, outer_at(r, i), outer_at(r, i + 1), outer_at(r + 1, i + 1), outer_at(r + 1, i));  // faces out
      add_quad(m, inner_at(r, i), inner_at(r + 1, i), inner_at(r + 1, i + 1), inner_at(r, i + 1));  // faces the duct
    }
  for (int i = 0; i < per_loop; ++i) {  // end rings join outer and inner loops
    add_quad(m, outer_at(0, i), inner_at(0, i), inner_at(0, i + 1), outer_at(0, i + 1));
    add_quad(m, outer_at(rings, i), outer_at(rings, i + 1), inner_at(rings, i + 1), inner_at(rings, i));
  }
  return m;
}

Vec3 RigidTransform::apply(const Vec3& p) const {
  // Rodrigues' rotation formula.
  const Vec3 k = normalized(axis);
  const double c = std::cos(angle), s = std::sin(angle);
  return p * c + cross(k, p) * s + k * (dot(k, p) * (1 - c)) + translation;
}

Mesh transformed(const Mesh& mesh, const RigidTransform& transform) {
  Mesh out = mesh;
  for (Vec3& v : out.vertices) v = transform.apply(v);
  return out;
}

}  // namespace molsurf
