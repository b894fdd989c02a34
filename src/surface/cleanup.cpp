#include "molsurf/cleanup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <memory>
#include <unordered_set>

#include "geometry/predicates.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/topology.hpp"

namespace molsurf {

namespace {

// Faces by the cells of a uniform grid their boxes touch: the exact intersection test
// of moved faces needs every face near them, and faces move as collapses happen.
class FaceGrid {
 public:
  FaceGrid(const Mesh& m, double cell) : m_(m), inverse_cell_(1.0 / cell) {}
  void insert(std::uint32_t f) {
    for_cells(bounding_box(m_, f), [&](std::uint64_t key) { cells_[key].push_back(f); });
  }
  void erase(std::uint32_t f) {
    for_cells(bounding_box(m_, f), [&](std::uint64_t key) { std::erase(cells_[key], f); });
  }
  template <class Visit>
  void near(const BoundingBox& box, Visit&& visit) const {
    for_cells(box, [&](std::uint64_t key) {
      if (auto it = cells_.find(key); it != cells_.end())
        for (std::uint32_t f : it->second) visit(f);
    });
  }

 private:
  template <class F>
  void for_cells(const BoundingBox& b, F&& f) const {
    auto cell = [&](double x) { return static_cast<std::int64_t>(std::floor(x * inverse_cell_)); };
    for (std::int64_t i = cell(b.min.x); i <= cell(b.max.x); ++i)
      for (std::int64_t j = cell(b.min.y); j <= cell(b.max.y); ++j)
        for (std::int64_t k = cell(b.min.z); k <= cell(b.max.z); ++k)
          f((std::uint64_t(i & 0x1fffff) << 42) | (std::uint64_t(j & 0x1fffff) << 21) | std::uint64_t(k & 0x1fffff));
  }
  const Mesh& m_;
  double inverse_cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* p[3] = {&a, &b, &c};
  double smallest = 180;
  for (int i = 0; i < 3; ++i) {
    const Vec3 u = *p[(i + 1) % 3] - *p[i], w = *p[(i + 2) % 3] - *p[i];
    smallest = std::min(smallest, std::atan2(norm(cross(u, w)), dot(u, w)) * 180 / std::numbers::pi);
  }
  return smallest;
}

class Collapser {
 public:
  Collapser(Mesh& m, const CleanupOptions& options) : m_(m), options_(options), alive_(m.faces.size(), 1) {
    faces_of_.resize(m.vertices.size());
    for (std::uint32_t f = 0; f < m.faces.size(); ++f)
      for (Index v : m.faces[f]) faces_of_[v].push_back(f);
    double total = 0;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      total += norm(m.vertices[t[1]] - m.vertices[t[0]]) + norm(m.vertices[t[2]] - m.vertices[t[1]]);
    }
    const double mean_edge = m.faces.empty() ? 1 : total / (2 * m.faces.size());
    grid_ = std::make_unique<FaceGrid>(m, std::max(mean_edge, 1e-9) * 2);
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) grid_->insert(f);
    area_budget_ = options.max_area_change * surface_area(m);
  }

  void run(CleanupStats& stats) {
    for (int pass = 0; pass < options_.passes; ++pass) {
      std::vector<std::pair<double, std::uint32_t>> distorted;
      for (std::uint32_t f = 0; f < m_.faces.size(); ++f)
        if (alive_[f]) {
          const double angle = min_angle(f);
          if (angle < options_.min_angle_deg) distorted.emplace_back(angle, f);
        }
      if (distorted.empty()) break;
      std::sort(distorted.begin(), distorted.end());
      std::size_t done = 0;
      for (const auto& [angle, f] : distorted) {
        if (!alive_[f] || min_angle(f) >= options_.min_angle_deg) continue;
        if (improve_face(f))
          ++done;
        else
          ++stats.refused;
      }
      stats.collapses += done;
      if (done == 0) break;
    }
    stats.flips = flips_;
    stats.collapses -= flips_;  // improve_face counted every change
    if (stats.collapses > 0) compact();  // flips alone remove nothing
  }

 private:
  double min_angle(std::uint32_t f) const {
    const Triangle& t = m_.faces[f];
    return smallest_angle(m_.vertices[t[0]], m_.vertices[t[1]], m_.vertices[t[2]]);
  }

  // Exact relation of two triangles of the mesh (shared indices are what they may share).
  geometry::TrianglePairRelation relation(const Triangle& a, const Triangle& b) const {
    return geometry::classify_triangle_pair(m_, a, b, probe_);
  }

  bool on_seam(Index v) const {
    if (!m_.has_tags()) return false;
    const std::int32_t first = m_.face_tags[faces_of_[v].front()];
    for (std::uint32_t f : faces_of_[v])
      if (m_.face_tags[f] != first) return true;
    return false;
  }

  bool improve_face(std::uint32_t f) {
    const Triangle t = m_.faces[f];
    std::array<std::pair<double, int>, 3> edges;
    for (int i = 0; i < 3; ++i) edges[i] = {norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]), i};
    std::sort(edges.begin(), edges.end());
    for (const auto& [length, i] : edges) {
      Index a = t[i], b = t[(i + 1) % 3];
      // Keep the seam vertex: it lies on an intersection curve between two atoms' spheres.
      const bool seam_a = on_seam(a), seam_b = on_seam(b);
      if (seam_a && !seam_b) {
        if (try_collapse(a, b)) return true;
      } else if (seam_b && !seam_a) {
        if (try_collapse(b, a)) return true;
      } else if (try_collapse(a, b) || try_collapse(b, a)) {
        return true;
      }
    }
    // A cap (one corner almost on the opposite edge) has no short edge to lose: flip its
    // longest edge instead.
    const int longest = edges[2].second;
    return try_flip(f, t[longest], t[(longest + 1) % 3]);
  }

  // Flips edge ab of face f with the face across it, within one sphere (same tag).
  bool try_flip(std::uint32_t f, Index a, Index b) {
    std::uint32_t g = ~0u;
    for (std::uint32_t h : faces_of_[a]) {
      if (h == f) continue;
      const Triangle& t = m_.faces[h];
      if (t[0] == b || t[1] == b || t[2] == b) {
        if (g != ~0u) return false;  // more than two faces: leave it
        g = h;
      }
    }
    if (g == ~0u || (m_.has_tags() && m_.face_tags[f] != m_.face_tags[g])) return false;
    const Triangle tf = m_.faces[f], tg = m_.faces[g];
    Index c = 0, d = 0;
    for (Index w : tf)
      if (w != a && w != b) c = w;
    for (Index w : tg)
      if (w != a && w != b) d = w;
    for (std::uint32_t h : faces_of_[c])  // the new edge cd must not exist yet
      for (Index w : m_.faces[h])
        if (w == d) return false;
    int k = 0;
    while (tf[k] != c) ++k;
    const Index from = tf[(k + 1) % 3], to = tf[(k + 2) % 3];  // f runs from -> to along the edge
    const Triangle n1{from, d, c}, n2{d, to, c};
    const Vec3 &pf = m_.vertices[from], &pt = m_.vertices[to], &pc = m_.vertices[c], &pd = m_.vertices[d];
    const Vec3 old1 = cross(pt - pf, pc - pf), old2 = cross(pf - pt, pd - pt);
    const Vec3 new1 = cross(pd - pf, pc - pf), new2 = cross(pt - pd, pc - pd);
    if (geometry::collinear3d(pf, pd, pc) || geometry::collinear3d(pd, pt, pc)) return false;
    // Nearly coplanar pair only, and no face turns over.
    const Vec3 mean = old1 / std::max(norm(old1), 1e-300) + old2 / std::max(norm(old2), 1e-300);
    for (const Vec3& n : {new1, new2})
      if (!(dot(n, mean) > 0.5 * norm(n) * norm(mean))) return false;
    if (!(dot(old1, old2) > 0.9 * norm(old1) * norm(old2))) return false;
    const double before = std::min(min_angle(f), min_angle(g));
    const double after = std::min(smallest_angle(pf, pd, pc), smallest_angle(pd, pt, pc));
    if (after <= before) return false;
    const double area_change = 0.5 * (norm(new1) + norm(new2) - norm(old1) - norm(old2));
    if (std::abs(area_drift_ + area_change) > area_budget_) return false;
    const std::unordered_set<std::uint32_t> skip{f, g};
    for (const Triangle& t : {n1, n2}) {
      BoundingBox box;
      for (Index w : t) box.extend(m_.vertices[w]);
      std::vector<std::uint32_t> candidates;
      grid_->near(box, [&](std::uint32_t h) {
        if (alive_[h] && !skip.count(h)) candidates.push_back(h);
      });
      std::sort(candidates.begin(), candidates.end());
      candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
      for (std::uint32_t h : candidates) {
        const auto r = relation(t, m_.faces[h]);
        if (r == geometry::TrianglePairRelation::intersecting || r == geometry::TrianglePairRelation::duplicate)
          return false;
      }
    }
    const auto r = relation(n1, n2);
    if (r == geometry::TrianglePairRelation::intersecting) return false;
    // Commit: f becomes n1, g becomes n2 (their tags are equal).
    for (std::uint32_t h : {f, g}) {
      grid_->erase(h);
      for (Index w : m_.faces[h]) std::erase(faces_of_[w], h);
    }
    m_.faces[f] = n1;
    m_.faces[g] = n2;
    for (std::uint32_t h : {f, g}) {
      grid_->insert(h);
      for (Index w : m_.faces[h]) faces_of_[w].push_back(h);
    }
    area_drift_ += area_change;
    ++flips_;
    return true;
  }

  // Merges v into u.
  bool try_collapse(Index u, Index v) {
    std::vector<std::uint32_t> on_edge, moving;
    for (std::uint32_t g : faces_of_[v]) {
      const Triangle& t = m_.faces[g];
      if (t[0] == u || t[1] == u || t[2] == u)
        on_edge.push_back(g);
      else
        moving.push_back(g);
    }
    if (on_edge.size() != 2) return false;
    if (!link_condition(m_, faces_of_[u], faces_of_[v], on_edge, u, v)) return false;

    // Quality before: every face that changes or disappears.
    double before = 180, after = 180, area_before = 0, area_after = 0;
    for (std::uint32_t g : on_edge) {
      before = std::min(before, min_angle(g));
      area_before += face_area(m_, g);
    }
    const Vec3& pu = m_.vertices[u];
    std::vector<Triangle> moved(moving.size());
    for (std::size_t k = 0; k < moving.size(); ++k) {
      const std::uint32_t g = moving[k];
      Triangle t = m_.faces[g];
      before = std::min(before, min_angle(g));
      area_before += face_area(m_, g);
      // The face keeps its orientation: u must stay strictly on the same side of the plane
      // through the other two corners and v's old normal, decided exactly as "the new
      // triangle is not degenerate and its normal does not turn by more than 90 degrees".
      int k_v = 0;
      while (t[k_v] != v) ++k_v;
      const Vec3& p1 = m_.vertices[t[(k_v + 1) % 3]];
      const Vec3& p2 = m_.vertices[t[(k_v + 2) % 3]];
      const Vec3 old_normal = cross(p1 - m_.vertices[v], p2 - m_.vertices[v]);
      const Vec3 new_normal = cross(p1 - pu, p2 - pu);
      if (geometry::collinear3d(pu, p1, p2)) return false;
      if (!(dot(old_normal, new_normal) > 0.5 * norm(old_normal) * norm(new_normal))) return false;
      t[k_v] = u;
      moved[k] = t;
      after = std::min(after, smallest_angle(pu, p1, p2));
      area_after += 0.5 * norm(new_normal);
    }
    if (after <= before) return false;
    const double area_change = area_after - area_before;
    if (std::abs(area_drift_ + area_change) > area_budget_) return false;

    // Exactly: no moved face may meet another face beyond shared corners.
    std::unordered_set<std::uint32_t> skip(on_edge.begin(), on_edge.end());
    skip.insert(moving.begin(), moving.end());
    for (const Triangle& t : moved) {
      BoundingBox box;
      for (Index w : t) box.extend(m_.vertices[w]);
      std::vector<std::uint32_t> candidates;
      grid_->near(box, [&](std::uint32_t g) {
        if (alive_[g] && !skip.count(g)) candidates.push_back(g);
      });
      std::sort(candidates.begin(), candidates.end());
      candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
      for (std::uint32_t g : candidates) {
        const auto r = relation(t, m_.faces[g]);
        if (r == geometry::TrianglePairRelation::intersecting || r == geometry::TrianglePairRelation::duplicate)
          return false;
      }
    }
    // Moved faces against each other.
    for (std::size_t i = 0; i < moved.size(); ++i)
      for (std::size_t j = i + 1; j < moved.size(); ++j) {
        const auto r = relation(moved[i], moved[j]);
        if (r == geometry::TrianglePairRelation::intersecting || r == geometry::TrianglePairRelation::duplicate)
          return false;
      }

    // Commit.
    for (std::uint32_t g : on_edge) {
      grid_->erase(g);
      alive_[g] = 0;
      for (Index w : m_.faces[g]) std::erase(faces_of_[w], g);
    }
    for (std::size_t k = 0; k < moving.size(); ++k) {
      const std::uint32_t g = moving[k];
      grid_->erase(g);
      m_.faces[g] = moved[k];
      grid_->insert(g);
      faces_of_[u].push_back(g);
    }
    faces_of_[v].clear();
    area_drift_ += area_change;
    return true;
  }

  void compact() {
    std::size_t out = 0;
    for (std::size_t f = 0; f < m_.faces.size(); ++f) {
      if (!alive_[f]) continue;
      m_.faces[out] = m_.faces[f];
      if (m_.has_tags()) m_.face_tags[out] = m_.face_tags[f];
      ++out;
    }
    m_.faces.resize(out);
    if (m_.has_tags()) m_.face_tags.resize(out);
    std::vector<Index> renumber(m_.vertices.size(), ~Index{0});
    std::vector<Vec3> used;
    for (Triangle& t : m_.faces)
      for (Index& v : t) {
        if (renumber[v] == ~Index{0}) {
          renumber[v] = static_cast<Index>(used.size());
          used.push_back(m_.vertices[v]);
        }
        v = renumber[v];
      }
    m_.vertices = std::move(used);
  }

  Mesh& m_;
  const CleanupOptions& options_;
  std::vector<std::uint8_t> alive_;
  std::vector<std::vector<std::uint32_t>> faces_of_;
  std::unique_ptr<FaceGrid> grid_;
  mutable Mesh probe_;
  double area_budget_ = 0, area_drift_ = 0;
  std::size_t flips_ = 0;
};

}  // namespace

CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options) {
  CleanupStats stats;
  stats.before = mesh_quality(mesh);
  stats.area_before = surface_area(mesh);
  if (!mesh.faces.empty()) Collapser(mesh, options).run(stats);
  stats.after = mesh_quality(mesh);
  stats.area_after = surface_area(mesh);
  return stats;
}

}  // namespace molsurf
