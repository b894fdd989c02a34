#include "molsurf/cleanup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <omp.h>

#include "common/parallel_exceptions.hpp"
#include "geometry/predicates.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/topology.hpp"
#include "mesh/vertex_face_index.hpp"
#include "mesh/face_grid.hpp"

namespace molsurf {

namespace {

constexpr Index kNoVertex = ~Index{0};
constexpr double kSameTagFlipCos = 0.9;    // faces within 26 degrees of each other
constexpr double kCrossTagFlipCos = 0.94;  // within 20 degrees
constexpr double kClusterFraction = 0.2;   // a cluster's edges: under this part of the sliver's middle edge
constexpr std::size_t kMaxCluster = 8;
constexpr std::size_t kMaxUnblockSteps = 3;  // edits that may clear the way for a collapse
constexpr double kSmallestNewAngle = 1e-3;  // degrees; no change makes a face thinner
constexpr double kSmoothCos = 0.87;        // a vertex moves only if its faces are within 30 degrees of their sum
constexpr double kNeckFraction = 0.5;  // a neck's loop: edges under this part of the sliver's longest
constexpr double kNeckWidth = 0.5;     // it widens to this part of the edges leaving it
constexpr double kCapHeight = 0.02;    // a cap: its apex within this part of its base's length (about 1 degree)
constexpr double kMinOpeningDeg = 1;  // no edit folds two faces on an edge closer than this

// One local change of the mesh, described before it is made so that every check can be
// run on it first. Faces keep their index (and tag); a collapse removes two.
struct Edit {
  enum class Kind { collapse, flip, move } kind = Kind::collapse;
  std::vector<std::uint32_t> removed;  // faces that disappear
  std::vector<std::uint32_t> changed;  // faces that stay, with new corners or a moved corner
  std::vector<Triangle> triangles;     // the corners of each changed face afterwards
  std::vector<Vec3> reference;         // per changed face: a direction its normal must keep
  Index moved = kNoVertex;             // a vertex that moves to `target`
  Vec3 target;
  // Set by Cleaner::evaluate.
  double before = 0, after = 0, area_change = 0, volume_change = 0;
  int rank = 0;  // 0: the seams (where spheres meet) stay where they are; 1: they move a little
};

// What every worker of the cleanup shares: the mesh and what is kept per face and vertex.
// Workers that run at the same time touch only faces and vertices in regions far apart
// (see Sweep), so nothing here is locked.
struct CleanupShared {
  // `area`: the mesh's surface area, which the caller has measured.
  CleanupShared(Mesh& mesh, const CleanupOptions& opts, double area)
      : m(mesh), options(opts), alive(mesh.faces.size(), 1), faces_of(mesh.vertices.size()) {
    // Every vertex with a face gets its list here: edits only regroup the faces of vertices
    // that have some, so the workers never give a vertex its first face.
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) faces_of.add(f, m.faces[f]);
    double total = 0;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      total += norm(m.vertices[t[1]] - m.vertices[t[0]]) + norm(m.vertices[t[2]] - m.vertices[t[1]]);
    }
    const double mean_edge = m.faces.empty() ? 1 : total / (2 * m.faces.size());
    grid = std::make_unique<FaceGrid>(m, std::max(mean_edge, 1e-9) * 2);
    angle.assign(m.faces.size(), std::numeric_limits<double>::quiet_NaN());
    face_area.assign(m.faces.size(), std::numeric_limits<double>::quiet_NaN());
    area_budget = options.max_area_change * area;
    // Edits keep the topology, so a face stays in its component.
    Components components = connected_components(m);
    component_of = std::move(components.face_component);
    component_volume.assign(components.count, 0);
    std::vector<Index> origin(components.count, kNoVertex);
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      Index& o = origin[component_of[f]];
      if (o == kNoVertex) o = t[0];
      component_volume[component_of[f]] += tetrahedron_volume(m.vertices[o], m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    }
    initial_volume = component_volume;
  }

  static double tetrahedron_volume(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot(a - o, cross(b - o, c - o)) / 6;
  }

  Mesh& m;
  const CleanupOptions& options;
  std::vector<std::uint8_t> alive;
  VertexFaceIndex faces_of;
  std::unique_ptr<FaceGrid> grid;
  std::vector<double> angle, face_area;  // per face; NaN: not measured since it changed
  double area_budget = 0, area_drift = 0;
  std::vector<std::uint32_t> component_of;  // per face
  std::vector<double> component_volume, initial_volume;
};

// Where a worker may change the mesh, and its share of the budgets that bound the change
// of the whole (the area, each component's volume): fixed before workers start, so what
// a worker does depends on nothing the others do at the same time.
struct WorkRegion {
  BoundingBox box;               // every corner an edit moves, removes or changes lies in it
  double max_extent = 0;         // no new face's box is longer than this on any axis
  double area_share = 0;         // |the worker's area change| stays within it
  const std::vector<std::uint32_t>* volume_sharers = nullptr;  // per component: workers that may change it
};

// What a worker changed, to be added to the shared sums in a fixed order.
struct WorkResult {
  double area_drift = 0;
  std::vector<std::pair<std::uint32_t, double>> volume_changes;  // per component touched
  std::size_t collapses = 0, flips = 0, moves = 0, done = 0, refused = 0;
  std::vector<std::uint32_t> touched;   // faces changed or restored
  std::vector<std::uint32_t> deferred;  // positions of faces whose edits reached outside the region
};

// One worker of the cleanup: the edits around a distorted face, measured, tested and made
// (paper §2.5). The strategies are in improve_face.
class Cleaner {
 public:
  explicit Cleaner(CleanupShared& shared)
      : s_(shared), m_(shared.m), options_(shared.options), alive_(shared.alive), faces_of_(shared.faces_of),
        grid_(*shared.grid), angle_(shared.angle), area_(shared.face_area), component_of_(shared.component_of),
        initial_volume_(shared.initial_volume), seen_(shared.m.faces.size(), 0) {}

  // Starts a piece of work: edits within `region` (none: anywhere, with the whole budgets).
  void begin(const WorkRegion* region) {
    region_ = region;
    result_ = WorkResult{};
    volume_change_.clear();
    if (region) {
      area_share_ = region->area_share;
    } else {
      area_share_ = s_.area_budget - std::abs(s_.area_drift);
    }
  }

  // The best valid edit around distorted face f, if any (counted in the result). A face
  // whose edits were all refused, some of them only for leaving the region, is left for
  // later, under its `position` in the pass's order.
  void improve(std::uint32_t f, std::uint32_t position) {
    if (!alive_[f] || min_angle(f) >= options_.min_angle_deg) return;
    deferred_ = false;
    if (improve_face(f))
      ++result_.done;
    else if (deferred_)
      result_.deferred.push_back(position);
    else
      ++result_.refused;
  }

  WorkResult finish() {
    result_.area_drift = area_drift_;
    area_drift_ = 0;
    for (const auto& [component, change] : volume_change_) result_.volume_changes.emplace_back(component, change);
    std::sort(result_.volume_changes.begin(), result_.volume_changes.end());
    volume_change_.clear();
    result_.touched = std::move(touched_);
    touched_.clear();
    return std::move(result_);
  }

  double min_angle(std::uint32_t f) const {
    if (std::isnan(angle_[f])) {
      const Triangle& t = m_.faces[f];
      angle_[f] = smallest_angle_deg(m_.vertices[t[0]], m_.vertices[t[1]], m_.vertices[t[2]]);
    }
    return angle_[f];
  }
  // Whether face f's smallest angle is surely not under the angle whose tangent is
  // `tan_angle` (about a millionth over it): the corner smallest_angle_deg measures, on
  // the tangent |u x w| / u.w instead of atan2, which costs several times more. A face it
  // cannot clear (including a degenerate one) has its angle measured.
  bool surely_at_least(std::uint32_t f, double tan_angle) const {
    const Triangle& t = m_.faces[f];
    const Vec3 &a = m_.vertices[t[0]], &b = m_.vertices[t[1]], &c = m_.vertices[t[2]];
    const auto [u, w] = smallest_angle_edges(a, b, c);
    const double sine = norm(cross(u, w)), cosine = dot(u, w);  // both times |u| |w|
    return sine > 0 && (cosine <= 0 || sine >= cosine * tan_angle);
  }

 private:
  // A face's smallest angle and area are kept until its corners change (forget): every
  // option tried around a distorted face measures the same faces before the change.
  double area(std::uint32_t f) const {
    if (std::isnan(area_[f])) area_[f] = face_area(m_, f);
    return area_[f];
  }
  void forget(std::uint32_t f) {
    angle_[f] = area_[f] = std::numeric_limits<double>::quiet_NaN();
    touched_.push_back(f);
  }
  Vec3 normal(const Triangle& t) const {
    const Vec3 &a = m_.vertices[t[0]], &b = m_.vertices[t[1]], &c = m_.vertices[t[2]];
    return cross(b - a, c - a);
  }

  // The tags of the faces around v, sorted and unique (one tag: not on a seam).
  std::vector<std::int32_t> tags_of(Index v) const {
    std::vector<std::int32_t> tags;
    for (std::uint32_t f : faces_of_.of(v)) tags.push_back(m_.tag(f));
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    return tags;
  }

  // The faces on edge ab (a closed 2-manifold has exactly two).
  std::vector<std::uint32_t> faces_on_edge(Index a, Index b) const { return molsurf::faces_on_edge(m_, faces_of_.of(a), a, b); }

  // Cheap checks and measures, on doubles: no face may become degenerate (exact) or turn
  // by more than 60 degrees (a selection: far from the exact question "does it turn
  // over", on normals that rounding cannot reverse, as no new face is that thin), the worst angle among the faces involved must get better (unless the edit is
  // one step of a larger one, judged as a whole), and the area must stay within budget.
  bool evaluate(Edit& e, bool must_improve = true) const {
    if (!within_region(e)) {
      deferred_ = true;
      return false;
    }
    auto pos = [&](Index w) -> const Vec3& { return w == e.moved ? e.target : m_.vertices[w]; };
    double before = 180, area_before = 0;
    for (std::uint32_t f : e.removed) {
      before = std::min(before, min_angle(f));
      area_before += area(f);
    }
    for (std::uint32_t f : e.changed) {
      before = std::min(before, min_angle(f));
      area_before += area(f);
    }
    double after = 180, area_after = 0;
    for (std::size_t k = 0; k < e.triangles.size(); ++k) {
      const Triangle& t = e.triangles[k];
      const Vec3 &a = pos(t[0]), &b = pos(t[1]), &c = pos(t[2]);
      if (geometry::collinear3d(a, b, c)) return false;
      const double angle = smallest_angle_deg(a, b, c);
      // One step of a larger edit may leave a face that thin (in a cluster of vertices
      // far closer than a thousandth of a degree's worth, every single collapse does);
      // the edit as a whole may not.
      if (must_improve && !(angle > kSmallestNewAngle)) return false;
      const Vec3 n = cross(b - a, c - a);
      const Vec3& r = e.reference[k];
      if (!(dot(n, r) > 0.5 * norm(n) * norm(r))) return false;
      after = std::min(after, angle);
      area_after += 0.5 * norm(n);
    }
    if (must_improve && !(after > before)) return false;
    e.before = before;
    e.after = after;
    e.area_change = area_after - area_before;
    if (!(std::abs(area_drift_ + e.area_change) <= area_share_)) return false;
    // Each face's own turn says nothing about a component a few faces across (a small
    // cavity): edit by edit it could be flattened and turned inside out. Its volume keeps
    // its sign and at least half its size. The change is measured about a point of the
    // edit: the old and the new faces span the same boundary, so the origin cancels.
    if (e.triangles.empty()) return true;
    const Vec3 o = pos(e.triangles.front()[0]);
    double volume_change = 0;
    for (const Triangle& t : e.triangles) volume_change += CleanupShared::tetrahedron_volume(o, pos(t[0]), pos(t[1]), pos(t[2]));
    for (const auto* list : {&e.removed, &e.changed})
      for (std::uint32_t f : *list) {
        const Triangle& t = m_.faces[f];
        volume_change -= CleanupShared::tetrahedron_volume(o, m_.vertices[t[0]], m_.vertices[t[1]], m_.vertices[t[2]]);
      }
    e.volume_change = volume_change;
    // The volume at the start of this work plus every change made since, by this worker
    // and by the others that may change the component at the same time, each of which
    // keeps to its share of what may be lost.
    const std::uint32_t component = component_of_[e.changed.empty() ? e.removed.front() : e.changed.front()];
    const double initial = initial_volume_[component];
    if (!(initial != 0)) return false;
    const double sign = initial > 0 ? 1 : -1;
    const double slack = sign * s_.component_volume[component] - 0.5 * std::abs(initial);
    const double sharers = region_ ? (*region_->volume_sharers)[component] : 1;
    const auto it = volume_change_.find(component);
    const double changed = (it == volume_change_.end() ? 0 : it->second) + volume_change;
    return sign * changed >= -slack / sharers;
  }

  // Whether the edit leaves no fold: on every edge of its new faces, the two faces open at
  // least kMinOpeningDeg (180: flat), or at least as wide as the sharpest edge of the faces it
  // replaces. Each face's own turn is bounded elsewhere, but a face may turn onto the
  // unchanged face across one of its edges; a knife-edge fold is exactly valid, yet
  // floating-point consumers (a mesher's boundary recovery) take its two faces for
  // overlapping.
  bool keeps_edges_open(const Edit& e) const {
    auto pos = [&](Index w) -> const Vec3& { return w == e.moved ? e.target : m_.vertices[w]; };
    auto normal_at = [&](const Triangle& t, bool moved) {
      const Vec3 &a = moved ? pos(t[0]) : m_.vertices[t[0]], &b = moved ? pos(t[1]) : m_.vertices[t[1]],
                 &c = moved ? pos(t[2]) : m_.vertices[t[2]];
      return cross(b - a, c - a);
    };
    auto in_edit = [&](std::uint32_t g) {
      return std::find(e.removed.begin(), e.removed.end(), g) != e.removed.end() ||
             std::find(e.changed.begin(), e.changed.end(), g) != e.changed.end();
    };
    // The cosine of the angle between the normals, against -cos(opening).
    auto opening_cos = [](const Vec3& n1, const Vec3& n2) {
      const double l = norm(n1) * norm(n2);
      return l > 0 ? dot(n1, n2) / l : 1.0;
    };
    static const double limit = -std::cos(kMinOpeningDeg * std::numbers::pi / 180);
    double after = 1;  // the most negative cosine: the sharpest edge
    for (std::size_t k = 0; k < e.triangles.size(); ++k) {
      const Triangle& t = e.triangles[k];
      const Vec3 n = normal_at(t, true);
      for (int i = 0; i < 3; ++i) {
        const Index a = t[i], b = t[(i + 1) % 3];
        // The face across: another new face running b -> a, else an unchanged one.
        bool found = false;
        for (std::size_t j = 0; j < e.triangles.size() && !found; ++j) {
          const Triangle& u = e.triangles[j];
          for (int m = 0; m < 3 && !found; ++m)
            if (u[m] == b && u[(m + 1) % 3] == a) {
              after = std::min(after, opening_cos(n, normal_at(u, true)));
              found = true;
            }
        }
        for (std::uint32_t g : faces_of_.of(a)) {
          if (found) break;
          if (in_edit(g)) continue;
          const Triangle& u = m_.faces[g];
          for (int m = 0; m < 3 && !found; ++m)
            if (u[m] == b && u[(m + 1) % 3] == a) {
              after = std::min(after, opening_cos(n, normal_at(u, true)));
              found = true;
            }
        }
      }
    }
    if (after >= limit) return true;
    double before = 1;
    for (const auto* list : {&e.removed, &e.changed})
      for (std::uint32_t f : *list) {
        const Triangle& t = m_.faces[f];
        const Vec3 n = normal_at(t, false);
        for (int i = 0; i < 3; ++i)
          for (std::uint32_t g : faces_on_edge(t[i], t[(i + 1) % 3]))
            if (g != f) before = std::min(before, opening_cos(n, normal_at(m_.faces[g], false)));
      }
    return after >= before;
  }

  // Whether the edit stays within the worker's region: every corner it moves, removes or
  // changes, and no new face longer than the region allows. Outside it, another worker may
  // be changing the mesh.
  bool within_region(const Edit& e) const {
    if (!region_) return true;
    const BoundingBox& r = region_->box;
    auto inside = [&](const Vec3& p) {
      return p.x >= r.min.x && p.x <= r.max.x && p.y >= r.min.y && p.y <= r.max.y && p.z >= r.min.z && p.z <= r.max.z;
    };
    for (const auto* list : {&e.removed, &e.changed})
      for (std::uint32_t f : *list)
        for (Index w : m_.faces[f])
          if (!inside(m_.vertices[w])) return false;
    if (e.moved != kNoVertex && !inside(e.target)) return false;
    for (const Triangle& t : e.triangles) {
      BoundingBox box;
      for (Index w : t) box.extend(w == e.moved ? e.target : m_.vertices[w]);
      for (int a = 0; a < 3; ++a)
        if (!(box.max[a] - box.min[a] <= region_->max_extent)) return false;
    }
    return true;
  }

  // The tests of an edit that the cheap measures of evaluate leave: no fold, then (exact) no
  // crossing. Run only on the options tried, best first.
  bool fits(const Edit& e) { return keeps_edges_open(e) && crosses_nothing(e); }

  // Exactly: no face of the edit meets a face around it, or another face of the edit,
  // beyond the corners and edges they share.
  bool crosses_nothing(const Edit& e) {
    Vec3 saved;
    if (e.moved != kNoVertex) {
      saved = m_.vertices[e.moved];
      m_.vertices[e.moved] = e.target;
    }
    // The faces the edit removes or changes hold no stored box that is still right (the
    // moved vertex is a corner of changed faces only): they are marked seen before each
    // query. Faces whose box is apart from the new face's cannot meet it.
    bool ok = true;
    for (std::size_t k = 0; ok && k < e.triangles.size(); ++k) {
      const Triangle& t = e.triangles[k];
      BoundingBox box;
      for (Index w : t) box.extend(m_.vertices[w]);
      if (++query_ == 0) {  // wrapped: no stale mark may match
        std::fill(seen_.begin(), seen_.end(), 0);
        query_ = 1;
      }
      for (const auto* list : {&e.removed, &e.changed})
        for (std::uint32_t g : *list) seen_[g] = query_;
      ok = grid_.near(box, [&](std::uint32_t g) {
        if (seen_[g] == query_) return true;
        seen_[g] = query_;
        if (!alive_[g]) return true;
        const BoundingBox& b = grid_.box(g);
        if (b.max.x < box.min.x || box.max.x < b.min.x || b.max.y < box.min.y || box.max.y < b.min.y ||
            b.max.z < box.min.z || box.max.z < b.min.z)
          return true;
        return acceptable(geometry::classify_triangle_pair(m_, t, m_.faces[g]));
      });
    }
    for (std::size_t i = 0; ok && i < e.triangles.size(); ++i)
      for (std::size_t j = i + 1; ok && j < e.triangles.size(); ++j)
        ok = acceptable(geometry::classify_triangle_pair(m_, e.triangles[i], e.triangles[j]));
    if (e.moved != kNoVertex) m_.vertices[e.moved] = saved;
    return ok;
  }
  static bool acceptable(geometry::TrianglePairRelation r) {
    return r != geometry::TrianglePairRelation::intersecting && r != geometry::TrianglePairRelation::duplicate;
  }

  void commit(const Edit& e) {
    if (journal_) {
      Step step{e, {}, {}};
      for (std::uint32_t f : e.changed) step.old_triangles.push_back(m_.faces[f]);
      if (e.moved != kNoVertex) step.old_position = m_.vertices[e.moved];
      for (const auto* list : {&e.removed, &e.changed})
        for (std::uint32_t f : *list)
          if (!first_angle_.contains(f)) first_angle_.emplace(f, min_angle(f));
      journal_->push_back(std::move(step));
    }
    for (const auto* list : {&e.removed, &e.changed})
      for (std::uint32_t f : *list) {
        grid_.erase(f);
        faces_of_.remove(f, m_.faces[f]);
      }
    for (std::uint32_t f : e.removed) alive_[f] = 0;
    if (e.moved != kNoVertex) m_.vertices[e.moved] = e.target;
    for (std::size_t k = 0; k < e.changed.size(); ++k) {
      const std::uint32_t f = e.changed[k];
      m_.faces[f] = e.triangles[k];
      forget(f);
      grid_.insert(f);
      faces_of_.add(f, m_.faces[f]);
    }
    area_drift_ += e.area_change;
    volume_change_[component_of_[e.changed.empty() ? e.removed.front() : e.changed.front()]] += e.volume_change;
    switch (e.kind) {
      case Edit::Kind::collapse: ++result_.collapses; break;
      case Edit::Kind::flip: ++result_.flips; break;
      case Edit::Kind::move: ++result_.moves; break;
    }
  }

  // Undoes the last journaled edit.
  void undo_last() {
    const Step& step = journal_->back();
    const Edit& e = step.edit;
    for (std::uint32_t f : e.changed) {
      grid_.erase(f);
      faces_of_.remove(f, m_.faces[f]);
    }
    if (e.moved != kNoVertex) m_.vertices[e.moved] = step.old_position;
    for (std::size_t k = 0; k < e.changed.size(); ++k) m_.faces[e.changed[k]] = step.old_triangles[k];
    for (const auto* list : {&e.removed, &e.changed})
      for (std::uint32_t f : *list) {
        alive_[f] = 1;
        forget(f);
        grid_.insert(f);
        faces_of_.add(f, m_.faces[f]);
      }
    area_drift_ -= e.area_change;
    volume_change_[component_of_[e.changed.empty() ? e.removed.front() : e.changed.front()]] -= e.volume_change;
    switch (e.kind) {
      case Edit::Kind::collapse: --result_.collapses; break;
      case Edit::Kind::flip: --result_.flips; break;
      case Edit::Kind::move: --result_.moves; break;
    }
    journal_->pop_back();
  }

  // A sliver whose short edge belongs to a cluster of vertices much closer to each other
  // than to the rest (typically around a point where three spheres meet) often has no
  // single collapse that keeps the link condition or improves the angles: the cluster
  // merges into one vertex, edge by edge (each step under every validity check), and the
  // whole is kept only if the worst angle among the faces it touched got better.
  bool merge_cluster(std::uint32_t f) {
    const Triangle t = m_.faces[f];
    std::array<double, 3> length;
    for (int i = 0; i < 3; ++i) length[i] = norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]);
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int x, int y) { return length[x] < length[y]; });
    const double tiny = kClusterFraction * length[order[1]];
    if (!(length[order[0]] <= tiny)) return false;
    std::vector<Index> cluster{t[order[0]]};
    for (std::size_t k = 0; k < cluster.size() && cluster.size() <= kMaxCluster; ++k)
      for (Index w : vertex_neighbours(m_, faces_of_.of(cluster[k]), cluster[k]))
        if (std::find(cluster.begin(), cluster.end(), w) == cluster.end() &&
            norm(m_.vertices[w] - m_.vertices[cluster[k]]) <= tiny)
          cluster.push_back(w);
    if (cluster.size() < 2 || cluster.size() > kMaxCluster) return false;
    // Everything merges into the vertex on the most seams (the junction), which stays.
    Index keep = cluster[0];
    std::size_t most = 0;
    for (Index v : cluster)
      if (const std::size_t n = tags_of(v).size(); n > most) {
        most = n;
        keep = v;
      }
    std::vector<Index> rest;
    for (Index v : cluster)
      if (v != keep) rest.push_back(v);
    std::stable_sort(rest.begin(), rest.end(), [&](Index x, Index y) {
      return norm(m_.vertices[x] - m_.vertices[keep]) < norm(m_.vertices[y] - m_.vertices[keep]);
    });

    std::vector<Step> journal;
    journal_ = &journal;
    first_angle_.clear();
    for (bool progress = true; progress && !rest.empty();) {
      progress = false;
      for (auto it = rest.begin(); it != rest.end(); ++it) {
        const std::vector<std::uint32_t> on_edge = faces_on_edge(keep, *it);
        if (on_edge.size() != 2 || !link_condition(m_, faces_of_.of(keep), faces_of_.of(*it), on_edge, keep, *it)) continue;
        Edit e = collapse(keep, *it, on_edge, m_.vertices[keep]);
        if (!evaluate(e, false) || !fits(e)) continue;
        commit(e);
        rest.erase(it);
        progress = true;
        break;
      }
    }
    return keep_if_better(!journal.empty());
  }

  // Ends the compound edit journaled in *journal_: kept when `complete` and the worst
  // angle among the faces it touched got better, else undone step by step.
  bool keep_if_better(bool complete) {
    double before = 180, after = 180;
    for (const auto& [g, angle] : first_angle_) {
      before = std::min(before, angle);
      if (alive_[g]) after = std::min(after, min_angle(g));
    }
    const bool better = complete && after > before;
    if (!better)
      while (!journal_->empty()) undo_last();
    journal_ = nullptr;
    return better;
  }

  // A sliver on a neck. Where two spheres barely overlap, the surface runs through a loop
  // of three edges far shorter than the faces around it (a 3-cycle that is not a face),
  // and the faces on the loop are needles that no collapse may shorten (each would pinch
  // the neck: the link condition fails) and no flip may fix. The loop widens about its
  // centre until its edges are half as long as the edges leaving it, one corner at a time
  // under every validity check, and the whole is kept only if the worst angle among the
  // faces it touched got better.
  bool widen_neck(std::uint32_t f) {
    const Triangle t = m_.faces[f];
    double longest = 0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]));
    const double short_edge = kNeckFraction * longest;
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[(i + 1) % 3];
      if (!(norm(m_.vertices[b] - m_.vertices[a]) <= short_edge)) continue;
      std::vector<Index> opposite;
      for (std::uint32_t g : faces_on_edge(a, b))
        for (Index w : m_.faces[g])
          if (w != a && w != b) opposite.push_back(w);
      const std::vector<Index> around_a = vertex_neighbours(m_, faces_of_.of(a), a);
      const std::vector<Index> around_b = vertex_neighbours(m_, faces_of_.of(b), b);
      for (Index w : around_a) {
        if (std::find(opposite.begin(), opposite.end(), w) != opposite.end() ||
            !std::binary_search(around_b.begin(), around_b.end(), w))
          continue;
        if (norm(m_.vertices[w] - m_.vertices[a]) <= short_edge && norm(m_.vertices[w] - m_.vertices[b]) <= short_edge &&
            widen_loop({a, b, w}))
          return true;
      }
    }
    return false;
  }

  bool widen_loop(const std::array<Index, 3>& loop) {
    Vec3 centre;
    double size = 0, leaving = 0;
    std::size_t leaving_count = 0;
    for (int k = 0; k < 3; ++k) {
      centre += m_.vertices[loop[k]] / 3.0;
      size = std::max(size, norm(m_.vertices[loop[(k + 1) % 3]] - m_.vertices[loop[k]]));
      for (Index w : vertex_neighbours(m_, faces_of_.of(loop[k]), loop[k]))
        if (std::find(loop.begin(), loop.end(), w) == loop.end()) {
          leaving += norm(m_.vertices[w] - m_.vertices[loop[k]]);
          ++leaving_count;
        }
    }
    if (leaving_count == 0 || !(size > 0)) return false;
    const double full = kNeckWidth * leaving / static_cast<double>(leaving_count) / size;
    // Less widening where the full width turns a face too far or meets another.
    for (const double factor : {full, full / 3, full / 10}) {
      if (!(factor > 1)) return false;
      std::vector<Step> journal;
      journal_ = &journal;
      first_angle_.clear();
      bool ok = true;
      for (Index v : loop) {
        Edit e = move(v, centre + factor * (m_.vertices[v] - centre));
        if (!evaluate(e, false) || !fits(e)) {
          ok = false;
          break;
        }
        commit(e);
      }
      if (keep_if_better(ok)) return true;
    }
    return false;
  }

  // A sliver whose short edge ab fails the link condition only because a and b have a
  // common neighbour beyond the edge's two faces (a fold, or a small tetrahedral pocket
  // around a point where spheres meet: the usual case at scale). The obstacle is first
  // taken out of the way, one step at a time: a vertex with three faces, across the edge
  // or in the way, is removed (its three faces become one); else edge aw or bw to a
  // vertex w in the way flips. Then ab collapses. Every step is under every validity
  // check, and the whole is kept only if the worst angle among the faces it touched got
  // better.
  bool unblock_collapse(std::uint32_t f) {
    const Triangle t = m_.faces[f];
    std::array<double, 3> length;
    for (int i = 0; i < 3; ++i) length[i] = norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]);
    const int longest = static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
    for (int i = 0; i < 3; ++i) {
      if (i == longest || !(length[i] <= 0.6 * length[longest])) continue;
      const Index a = t[i], b = t[(i + 1) % 3];
      if (blocking_vertices(a, b).empty()) continue;
      std::vector<Step> journal;
      journal_ = &journal;
      first_angle_.clear();
      bool ok = true;
      for (std::size_t step = 0; ok; ++step) {
        const std::vector<Index> blocking = blocking_vertices(a, b);
        if (blocking.empty()) break;
        ok = false;
        if (step == kMaxUnblockSteps || blocking.size() > kMaxUnblockSteps) break;
        std::vector<Edit> steps;
        for (std::uint32_t g : faces_on_edge(a, b))
          for (Index o : m_.faces[g])
            if (o != a && o != b && faces_of_.of(o).size() == 3) steps.push_back(remove_valence_three(o));
        for (Index w : blocking) {
          if (faces_of_.of(w).size() == 3) steps.push_back(remove_valence_three(w));
          for (Index end : {a, b})
            if (const std::vector<std::uint32_t> on = faces_on_edge(end, w); on.size() == 2)
              steps.push_back(flip(on[0], end, w));
        }
        for (Edit& e : steps)
          if (!e.changed.empty() && evaluate(e, false) && fits(e)) {
            commit(e);
            ok = true;
            break;
          }
      }
      if (ok) {
        ok = false;
        const std::vector<std::uint32_t> on_edge = faces_on_edge(a, b);
        if (on_edge.size() == 2 && link_condition(m_, faces_of_.of(a), faces_of_.of(b), on_edge, a, b)) {
          const Vec3 pa = m_.vertices[a], pb = m_.vertices[b];
          std::vector<Edit> collapses;
          for (auto [u, v, target] : {std::tuple{a, b, pa}, std::tuple{b, a, pb}, std::tuple{a, b, 0.5 * (pa + pb)}}) {
            Edit e = collapse(u, v, on_edge, target);
            if (evaluate(e, false)) collapses.push_back(std::move(e));
          }
          std::stable_sort(collapses.begin(), collapses.end(), [](const Edit& x, const Edit& y) { return x.after > y.after; });
          for (const Edit& e : collapses)
            if (fits(e)) {
              commit(e);
              ok = true;
              break;
            }
        }
      }
      if (keep_if_better(ok)) return true;
    }
    return false;
  }

  std::vector<Index> blocking_vertices(Index a, Index b) const {
    return molsurf::blocking_vertices(m_, faces_of_.of(a), faces_of_.of(b), a, b);
  }

  // Removal of a vertex with three faces: they become the one face on its three neighbours.
  Edit remove_valence_three(Index w) const {
    Edit e;
    e.kind = Edit::Kind::collapse;
    const std::span<const std::uint32_t> fan = faces_of_.of(w);
    Triangle first = m_.faces[fan[0]];
    while (first[0] != w) first = {first[1], first[2], first[0]};
    const Index p = first[1], q = first[2];
    Index r = kNoVertex;
    for (std::uint32_t g : fan)
      for (Index x : m_.faces[g])
        if (x != w && x != p && x != q) r = x;
    if (r == kNoVertex) return e;
    // The new face must agree with the surface around the fan (the fan itself may be a
    // spike whose normals say nothing about it): the faces across its three edges.
    Vec3 reference;
    for (auto [u, v] : {std::pair{p, q}, std::pair{q, r}, std::pair{r, p}})
      for (std::uint32_t g : faces_on_edge(u, v))
        if (std::find(fan.begin(), fan.end(), g) == fan.end()) {
          const Vec3 n = normal(m_.faces[g]);
          if (const double length = norm(n); length > 0) reference += n / length;
        }
    e.removed = {fan[1], fan[2]};
    e.changed = {fan[0]};
    e.triangles = {Triangle{p, q, r}};
    e.reference = {reference};
    return e;
  }

  // Face g becomes t; its present normal is the reference no new normal may turn far from.
  void add_change(Edit& e, std::uint32_t g, const Triangle& t) const {
    e.changed.push_back(g);
    e.triangles.push_back(t);
    e.reference.push_back(normal(m_.faces[g]));
  }

  // Collapse of edge uv: v merges into u, which moves to `target`. The caller has checked
  // that the edge has two faces and the link condition.
  Edit collapse(Index u, Index v, const std::vector<std::uint32_t>& on_edge, const Vec3& target) const {
    Edit e;
    e.kind = Edit::Kind::collapse;
    e.removed = on_edge;
    for (std::uint32_t g : faces_of_.of(v)) {
      if (g == on_edge[0] || g == on_edge[1]) continue;
      Triangle t = m_.faces[g];
      for (Index& w : t)
        if (w == v) w = u;
      add_change(e, g, t);
    }
    if (!(target == m_.vertices[u])) {
      for (std::uint32_t g : faces_of_.of(u))
        if (g != on_edge[0] && g != on_edge[1]) add_change(e, g, m_.faces[g]);
      e.moved = u;
      e.target = target;
    }
    return e;
  }

  // Flip of edge ab of face f: f and the face g across it become the two faces on the
  // other diagonal cd. Empty (no faces) when the edge cannot flip.
  Edit flip(std::uint32_t f, Index a, Index b) const {
    Edit e;
    e.kind = Edit::Kind::flip;
    const std::vector<std::uint32_t> on = faces_on_edge(a, b);
    if (on.size() != 2) return e;
    const std::uint32_t g = on[0] == f ? on[1] : on[0];
    const Triangle tf = m_.faces[f], tg = m_.faces[g];
    Index c = 0, d = 0;
    for (Index w : tf)
      if (w != a && w != b) c = w;
    for (Index w : tg)
      if (w != a && w != b) d = w;
    for (std::uint32_t h : faces_of_.of(c))  // the new edge cd must not exist yet
      for (Index w : m_.faces[h])
        if (w == d) return e;
    // Nearly coplanar faces only; across a seam (different tags) nearer still. A cap on
    // the edge (c within a sliver's height of ab, between a and b) has no meaningful
    // normal of its own: the new faces lie along g's plane and keep to g's normal.
    const bool same_tag = m_.tag(f) == m_.tag(g);
    const double min_cos = same_tag ? kSameTagFlipCos : kCrossTagFlipCos;
    const Vec3 old_f = normal(tf), old_g = normal(tg);
    const Vec3 ab = m_.vertices[b] - m_.vertices[a], ac = m_.vertices[c] - m_.vertices[a];
    const double ab2 = dot(ab, ab), along = dot(ac, ab);
    const bool cap = norm(old_f) < kCapHeight * ab2 && along > 0 && along < ab2;
    if (!cap && !(dot(old_f, old_g) > min_cos * norm(old_f) * norm(old_g))) return e;
    int k = 0;
    while (tf[k] != c) ++k;
    const Index from = tf[(k + 1) % 3], to = tf[(k + 2) % 3];  // f runs from -> to along the edge
    const Vec3 mean = cap ? old_g : old_f / std::max(norm(old_f), 1e-300) + old_g / std::max(norm(old_g), 1e-300);
    e.changed = {f, g};
    e.triangles = {Triangle{from, d, c}, Triangle{d, to, c}};
    e.reference = {mean, mean};
    e.rank = same_tag ? 0 : 1;
    return e;
  }

  // v moves to `target`.
  Edit move(Index v, const Vec3& target) const {
    Edit e;
    e.kind = Edit::Kind::move;
    for (std::uint32_t g : faces_of_.of(v)) add_change(e, g, m_.faces[g]);
    e.moved = v;
    e.target = target;
    return e;
  }

  // Where v may go to improve its faces: toward the centre of its neighbours, within the
  // plane tangent to the surface there; a seam vertex only along its seam.
  void move_candidates(Index v, std::vector<Edit>& out) const {
    const std::vector<std::int32_t> tags = tags_of(v);
    if (tags.size() > 2) return;  // where three spheres meet: stays
    const Vec3 p = m_.vertices[v];
    Vec3 step;
    if (tags.size() == 1) {
      Vec3 n, centre;
      const std::vector<Index> ring = vertex_neighbours(m_, faces_of_.of(v), v);
      for (std::uint32_t g : faces_of_.of(v)) n += normal(m_.faces[g]);
      for (Index w : ring) centre += m_.vertices[w];
      centre = centre / static_cast<double>(ring.size());
      const double nn = dot(n, n);
      if (!(nn > 0)) return;
      // Only where the surface is smooth: a corner or crease (of an untagged mesh) stays.
      for (std::uint32_t g : faces_of_.of(v)) {
        const Vec3 ng = normal(m_.faces[g]);
        if (!(dot(ng, n) > kSmoothCos * norm(ng) * std::sqrt(nn))) return;
      }
      step = centre - p;
      step -= n * (dot(step, n) / nn);
    } else {
      // The two neighbours along the seam: edges whose two faces have different tags.
      std::vector<Index> along;
      for (Index w : vertex_neighbours(m_, faces_of_.of(v), v)) {
        const std::vector<std::uint32_t> on = faces_on_edge(v, w);
        if (on.size() == 2 && m_.tag(on[0]) != m_.tag(on[1])) along.push_back(w);
      }
      if (along.size() != 2) return;
      const Vec3 s = m_.vertices[along[1]] - m_.vertices[along[0]];
      const Vec3 centre = 0.5 * (m_.vertices[along[0]] + m_.vertices[along[1]]);
      const double ss = dot(s, s);
      if (!(ss > 0)) return;
      step = s * (dot(centre - p, s) / ss);
    }
    for (double fraction : {1.0, 0.5, 0.25}) {
      Edit e = move(v, p + fraction * step);
      e.rank = tags.size() == 1 ? 0 : 1;
      if (!(e.target == p) && evaluate(e)) out.push_back(std::move(e));
    }
  }

  // One distorted face: the collapses of its short edges (to either end or the midpoint)
  // and the flips of its edges, best first; then the merge of a cluster of vertices
  // around it; last, a move of one of its corners.
  bool improve_face(std::uint32_t f) {
    const Triangle t = m_.faces[f];
    std::array<double, 3> length;
    for (int i = 0; i < 3; ++i) length[i] = norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]);
    const int longest = static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
    std::vector<Edit> options;
    for (int i = 0; i < 3; ++i) {
      if (i != longest && length[i] <= 0.6 * length[longest]) {
        const Index a = t[i], b = t[(i + 1) % 3];
        const std::vector<std::uint32_t> on_edge = faces_on_edge(a, b);
        if (on_edge.size() != 2 || !link_condition(m_, faces_of_.of(a), faces_of_.of(b), on_edge, a, b)) continue;
        const std::vector<std::int32_t> tags_a = tags_of(a), tags_b = tags_of(b);
        const Vec3 &pa = m_.vertices[a], &pb = m_.vertices[b];
        auto add = [&](Index u, Index v, const Vec3& target, int rank) {
          Edit e = collapse(u, v, on_edge, target);
          e.rank = rank;
          if (evaluate(e)) options.push_back(std::move(e));
        };
        auto within = [](const std::vector<std::int32_t>& x, const std::vector<std::int32_t>& y) {
          return std::includes(y.begin(), y.end(), x.begin(), x.end());
        };
        add(a, b, pa, within(tags_b, tags_a) ? 0 : 1);
        add(b, a, pb, within(tags_a, tags_b) ? 0 : 1);
        add(a, b, 0.5 * (pa + pb), tags_a == tags_b ? 0 : 1);
      }
    }
    for (int i = 0; i < 3; ++i) {
      Edit e = flip(f, t[i], t[(i + 1) % 3]);
      if (!e.changed.empty() && evaluate(e)) options.push_back(std::move(e));
    }
    if (try_best(options)) return true;
    if (merge_cluster(f)) return true;
    if (widen_neck(f)) return true;
    if (unblock_collapse(f)) return true;
    options.clear();
    for (Index v : t) move_candidates(v, options);
    return try_best(options);
  }

  // The best option that passes the exact test: first whatever reaches the target angle,
  // seams kept before seams moved; below it, the best angle.
  bool try_best(std::vector<Edit>& options) {
    const double goal = options_.min_angle_deg;
    std::stable_sort(options.begin(), options.end(), [&](const Edit& x, const Edit& y) {
      const double gx = std::min(x.after, goal), gy = std::min(y.after, goal);
      if (gx != gy) return gx > gy;
      if (x.rank != y.rank) return x.rank < y.rank;
      if (std::abs(x.area_change) != std::abs(y.area_change)) return std::abs(x.area_change) < std::abs(y.area_change);
      return x.after > y.after;
    });
    for (const Edit& e : options)
      if (fits(e)) {
        commit(e);
        return true;
      }
    return false;
  }

 public:
  // Edges far shorter than the surface's typical edge (under min_edge_fraction of the
  // median) are collapsed, shortest first, even where their faces' angles are fine: a
  // mesher's boundary recovery (gmsh's, tetgen's) works in floating point and takes the
  // faces around such an edge for overlapping. A collapse here may not make the worst
  // angle it touches worse than it was or than the angle target; every other rule of an
  // edit holds (link condition, no face turned, budgets, the exact crossing test).
  std::vector<std::pair<double, std::array<Index, 2>>> short_edges(double floor) const {
    std::vector<std::pair<double, std::array<Index, 2>>> out;
    for (std::uint32_t f = 0; f < m_.faces.size(); ++f) {
      if (!alive_[f]) continue;
      const Triangle& t = m_.faces[f];
      for (int i = 0; i < 3; ++i) {
        const Index a = t[i], b = t[(i + 1) % 3];
        if (a > b) continue;  // each edge once, from the face that runs it upward
        const double length = norm(m_.vertices[b] - m_.vertices[a]);
        if (length < floor) out.push_back({length, {a, b}});
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  void shorten_edges(CleanupStats& stats) {
    std::vector<double> lengths;
    lengths.reserve(m_.faces.size() * 3 / 2);
    for (std::uint32_t f = 0; f < m_.faces.size(); ++f) {
      if (!alive_[f]) continue;
      const Triangle& t = m_.faces[f];
      for (int i = 0; i < 3; ++i)
        if (t[i] < t[(i + 1) % 3]) lengths.push_back(norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]));
    }
    if (lengths.empty()) return;
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double floor = options_.min_edge_fraction * lengths[lengths.size() / 2];
    std::vector<std::pair<double, std::array<Index, 2>>> edges = short_edges(floor);
    stats.short_edges_before = edges.size();
    for (int pass = 0; pass < options_.passes && !edges.empty(); ++pass) {
      std::size_t done = 0;
      for (const auto& [length, edge] : edges) {
        const auto [a, b] = edge;
        if (!(norm(m_.vertices[b] - m_.vertices[a]) < floor)) continue;  // an earlier collapse moved it
        const std::vector<std::uint32_t> on_edge = faces_on_edge(a, b);
        if (on_edge.size() != 2 || !link_condition(m_, faces_of_.of(a), faces_of_.of(b), on_edge, a, b)) continue;
        const std::vector<std::int32_t> tags_a = tags_of(a), tags_b = tags_of(b);
        auto within = [](const std::vector<std::int32_t>& x, const std::vector<std::int32_t>& y) {
          return std::includes(y.begin(), y.end(), x.begin(), x.end());
        };
        std::vector<Edit> options;
        auto add = [&](Index u, Index v, const Vec3& target, int rank) {
          Edit e = collapse(u, v, on_edge, target);
          e.rank = rank;
          if (evaluate(e, false) && e.after >= std::min(e.before, options_.min_angle_deg) && e.after > kSmallestNewAngle)
            options.push_back(std::move(e));
        };
        const Vec3 pa = m_.vertices[a], pb = m_.vertices[b];
        add(a, b, pa, within(tags_b, tags_a) ? 0 : 1);
        add(b, a, pb, within(tags_a, tags_b) ? 0 : 1);
        add(a, b, 0.5 * (pa + pb), tags_a == tags_b ? 0 : 1);
        if (try_best(options)) ++done;
      }
      if (done == 0) break;
      edges = short_edges(floor);
    }
    stats.short_edges_after = edges.size();
  }

 private:
  CleanupShared& s_;
  Mesh& m_;
  const CleanupOptions& options_;
  std::vector<std::uint8_t>& alive_;
  VertexFaceIndex& faces_of_;
  FaceGrid& grid_;
  std::vector<double>& angle_;
  std::vector<double>& area_;
  const std::vector<std::uint32_t>& component_of_;
  const std::vector<double>& initial_volume_;
  // Per face: the query of the crossing test that last saw it (each face is tested once).
  std::vector<std::uint32_t> seen_;
  std::uint32_t query_ = 0;
  const WorkRegion* region_ = nullptr;
  mutable bool deferred_ = false;  // an edit around the present face was refused for leaving the region
  WorkResult result_;
  std::vector<std::uint32_t> touched_;  // faces changed or restored
  double area_share_ = 0, area_drift_ = 0;
  std::unordered_map<std::uint32_t, double> volume_change_;  // per component
  // While a compound edit is tried: its steps, and the angle of each face it touched as
  // it was before.
  struct Step {
    Edit edit;
    std::vector<Triangle> old_triangles;
    Vec3 old_position;
  };
  std::vector<Step>* journal_ = nullptr;
  std::unordered_map<std::uint32_t, double> first_angle_;
};

// The passes of the cleanup. Each pass takes the distorted faces, worst first, and gives
// each the best valid edit. The edits run in parallel with a result that does not depend
// on the thread count: the faces are sorted into the cells of a coarse grid, coloured like
// a 3-d chessboard by the parity of their coordinates (eight colours). Two cells of one
// colour are at least a cell's side apart, which is more than an edit's region on each
// side (`margin`) and how far beyond it a worker reads (`reach`). The colours run one
// after another; within a colour, the cells run in parallel, each worker in its cell's
// region, its faces in the pass's order. A face whose edits would leave the region waits
// for a serial sweep after the eighth colour. The budgets (area, each component's volume)
// are shared out at the start of each colour among the cells that may use them, and the
// cells' changes are added up in cell order.
class Sweep {
 public:
  explicit Sweep(CleanupShared& shared) : s_(shared) {
    const int threads = std::max(1, omp_get_max_threads());
    for (int t = 0; t < threads; ++t) workers_.push_back(std::make_unique<Cleaner>(shared));
    volume_sharers_.assign(shared.initial_volume.size(), 0);
    sharer_stamp_.assign(shared.initial_volume.size(), kNoCell);
  }

  void run(CleanupStats& stats) {
    const Mesh& m = s_.m;
    Cleaner& serial = *workers_.front();
    // A margin of a millionth, far above the rounding of atan2 and of the tangent.
    const double tan_goal = std::tan(s_.options.min_angle_deg * std::numbers::pi / 180) * (1 + 1e-6);
    // The first pass measures every face; a later one only the faces the one before
    // listed or changed: no other face's corners moved, so its angle holds.
    std::vector<std::pair<double, std::uint32_t>> distorted;
    for (int pass = 0; pass < s_.options.passes; ++pass) {
      if (pass == 0) {
        // In parallel, atan2 only where the tangent leaves it in doubt; in face order.
        std::vector<double> angle(m.faces.size());
        const auto nf = static_cast<std::int64_t>(m.faces.size());
#pragma omp parallel for schedule(static)
        for (std::int64_t f = 0; f < nf; ++f) {
          const auto face = static_cast<std::uint32_t>(f);
          angle[f] = s_.alive[f] && !serial.surely_at_least(face, tan_goal) ? serial.min_angle(face) : 180;
        }
        for (std::uint32_t f = 0; f < m.faces.size(); ++f)
          if (s_.alive[f] && angle[f] < s_.options.min_angle_deg) distorted.emplace_back(angle[f], f);
      } else {
        for (const auto& listed : distorted) touched_.push_back(listed.second);
        std::sort(touched_.begin(), touched_.end());
        touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
        distorted.clear();
        for (std::uint32_t f : touched_)
          if (s_.alive[f])
            if (const double angle = serial.min_angle(f); angle < s_.options.min_angle_deg) distorted.emplace_back(angle, f);
      }
      touched_.clear();
      if (distorted.empty()) break;
      std::sort(distorted.begin(), distorted.end());
      if (sweep(distorted, stats) == 0) break;
    }
    if (s_.options.min_edge_fraction > 0) {
      serial.begin(nullptr);
      serial.shorten_edges(stats);
      WorkResult r = serial.finish();
      add(r, stats);
    }
  }

 private:
  static constexpr std::uint64_t kNoCell = ~std::uint64_t{0};

  // One pass's edits; returns how many faces got one.
  std::size_t sweep(const std::vector<std::pair<double, std::uint32_t>>& distorted, CleanupStats& stats) {
    const Mesh& m = s_.m;
    // The longest face (on any axis of its box) bounds how far a worker reads beyond the
    // faces it changes; an edit may make no face longer than twice that.
    double longest = 0;
    const auto nf = static_cast<std::int64_t>(m.faces.size());
#pragma omp parallel for schedule(static) reduction(max : longest)
    for (std::int64_t f = 0; f < nf; ++f) {
      if (!s_.alive[f]) continue;
      const BoundingBox b = bounding_box(m, static_cast<std::size_t>(f));
      longest = std::max({longest, b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
    }
    const double max_extent = 2 * longest;
    // An edit changes faces around the distorted face's corners; its region reaches this far
    // beyond the cell. Beyond the region a worker reads up to three rings of faces (the
    // faces around the neighbours of an edit's corners) and the faces in the index's cells
    // its queries touch, and the index's blocks of cells.
    const double margin = max_extent;
    const double cell = s_.grid->cell_size();
    const double reach = std::max(4 * max_extent + cell, s_.grid->shard_side() + 2 * cell);
    const double side = 1.25 * (2 * margin + reach);
    const BoundingBox all = bounding_box(m);
    std::int64_t n[3];
    for (int a = 0; a < 3; ++a)
      n[a] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::ceil((all.max[a] - all.min[a]) / side)), 1, 1 << 20);
    auto coordinate = [&](double x, int a) {
      const double i = std::floor((x - all.min[a]) / side);
      return !(i > 0) ? std::int64_t{0} : i >= static_cast<double>(n[a]) ? n[a] - 1 : static_cast<std::int64_t>(i);
    };
    // The faces by colour, then cell, then their order in the pass.
    struct Entry {
      std::uint64_t key;  // colour, then cell
      std::uint32_t position;
      std::array<std::int64_t, 3> cell;
    };
    std::vector<Entry> entries(distorted.size());
    for (std::size_t q = 0; q < distorted.size(); ++q) {
      const Triangle& t = m.faces[distorted[q].second];
      const Vec3 centre = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
      std::array<std::int64_t, 3> c{};
      for (int a = 0; a < 3; ++a) c[a] = coordinate(centre[a], a);
      const std::uint64_t colour = static_cast<std::uint64_t>((c[0] & 1) | (c[1] & 1) << 1 | (c[2] & 1) << 2);
      const auto id = static_cast<std::uint64_t>((c[0] * n[1] + c[1]) * n[2] + c[2]);
      entries[q] = {colour << 60 | id, static_cast<std::uint32_t>(q), c};
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });

    std::size_t done = 0;
    std::vector<std::uint32_t> deferred;
    for (std::size_t begin = 0; begin < entries.size();) {
      // One colour: its cells [cell_start[k], cell_start[k + 1]).
      const std::uint64_t colour = entries[begin].key >> 60;
      std::vector<std::size_t> cell_start;
      std::size_t end = begin;
      for (; end < entries.size() && entries[end].key >> 60 == colour; ++end)
        if (end == begin || entries[end].key != entries[end - 1].key) cell_start.push_back(end);
      cell_start.push_back(end);
      const std::size_t cells = cell_start.size() - 1;
      for (std::size_t k = 0; k < cells; ++k)
        for (std::size_t q = cell_start[k]; q < cell_start[k + 1]; ++q) {
          const std::uint32_t component = s_.component_of[distorted[entries[q].position].second];
          if (sharer_stamp_[component] != k) {
            sharer_stamp_[component] = k;
            ++volume_sharers_[component];
          }
        }
      std::vector<WorkRegion> regions(cells);
      const double area_share = (s_.area_budget - std::abs(s_.area_drift)) / static_cast<double>(cells);
      for (std::size_t k = 0; k < cells; ++k) {
        const std::array<std::int64_t, 3>& c = entries[cell_start[k]].cell;
        WorkRegion& r = regions[k];
        for (int a = 0; a < 3; ++a) {
          const double infinity = std::numeric_limits<double>::infinity();
          r.box.min[a] = c[a] == 0 ? -infinity : all.min[a] + static_cast<double>(c[a]) * side - margin;
          r.box.max[a] = c[a] == n[a] - 1 ? infinity : all.min[a] + static_cast<double>(c[a] + 1) * side + margin;
        }
        r.max_extent = max_extent;
        r.area_share = area_share;
        r.volume_sharers = &volume_sharers_;
      }
      std::vector<WorkResult> results(cells);
      ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 1)
      for (std::int64_t k = 0; k < static_cast<std::int64_t>(cells); ++k)
        errors.run(k, [&] {
          Cleaner& worker = *workers_[static_cast<std::size_t>(omp_get_thread_num())];
          worker.begin(&regions[k]);
          for (std::size_t q = cell_start[k]; q < cell_start[k + 1]; ++q)
            worker.improve(distorted[entries[q].position].second, entries[q].position);
          results[k] = worker.finish();
        });
      errors.rethrow();
      for (WorkResult& r : results) {
        done += r.done;
        deferred.insert(deferred.end(), r.deferred.begin(), r.deferred.end());
        add(r, stats);
      }
      for (std::size_t q = begin; q < end; ++q) {
        const std::uint32_t component = s_.component_of[distorted[entries[q].position].second];
        volume_sharers_[component] = 0;
        sharer_stamp_[component] = kNoCell;
      }
      begin = end;
    }
    // The faces left for the serial sweep, in the pass's order, with the whole budgets.
    std::sort(deferred.begin(), deferred.end());
    Cleaner& serial = *workers_.front();
    serial.begin(nullptr);
    for (std::uint32_t q : deferred) serial.improve(distorted[q].second, q);
    WorkResult r = serial.finish();
    done += r.done;
    add(r, stats);
    return done;
  }

  void add(WorkResult& r, CleanupStats& stats) {
    s_.area_drift += r.area_drift;
    for (const auto& [component, change] : r.volume_changes) s_.component_volume[component] += change;
    stats.collapses += r.collapses;
    stats.flips += r.flips;
    stats.moves += r.moves;
    stats.refused += r.refused;
    touched_.insert(touched_.end(), r.touched.begin(), r.touched.end());
  }

  CleanupShared& s_;
  std::vector<std::unique_ptr<Cleaner>> workers_;  // one per thread
  std::vector<std::uint32_t> touched_;             // faces changed during the present pass
  std::vector<std::uint32_t> volume_sharers_;      // per component: cells of the present colour that may change it
  std::vector<std::uint64_t> sharer_stamp_;        // per component: the last cell counted
};

}  // namespace

CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options) {
  CleanupStats stats;
  stats.before = mesh_quality(mesh);
  stats.area_before = surface_area(mesh);
  if (!mesh.faces.empty()) {
    CleanupShared shared(mesh, options, stats.area_before);
    Sweep(shared).run(stats);
    if (stats.collapses > 0) {
      keep_alive_faces(mesh, shared.alive);
      drop_unused_vertices(mesh);
    }
  }
  stats.after = mesh_quality(mesh);
  stats.area_after = surface_area(mesh);
  return stats;
}

}  // namespace molsurf
