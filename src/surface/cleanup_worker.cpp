#include "surface/cleanup_worker.hpp"

#include <algorithm>
#include <array>
#include <numbers>

#include "common/parallel_threshold.hpp"
#include "surface/cleanup_rules.hpp"

namespace molsurf::surface_cleanup {

CleanupShared::CleanupShared(Mesh& mesh, const CleanupOptions& opts, double area,
                             std::span<const std::uint8_t> frozen)
    : m(mesh), options(opts), editable(mesh, frozen) {
  // The lengths in parallel, their sum in face order: the same mean for any thread count.
  std::vector<double> lengths(m.faces.size());
  const auto nf = static_cast<std::int64_t>(m.faces.size());
#pragma omp parallel for schedule(static) if (nf >= kParallelMinItems)
  for (std::int64_t f = 0; f < nf; ++f) {
    const Triangle& t = m.faces[f];
    lengths[f] = norm(m.vertices[t[1]] - m.vertices[t[0]]) + norm(m.vertices[t[2]] - m.vertices[t[1]]);
  }
  double total = 0;
  for (const double length : lengths) total += length;
  const double mean_edge = m.faces.empty() ? 1 : total / (2 * m.faces.size());
  // Every vertex with a face gets its list here: edits only regroup the faces of vertices
  // that have some, so the workers never give a vertex its first face.
  editable.index_all(std::max(mean_edge, 1e-9) * 2);
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

Cleaner::Cleaner(CleanupShared& shared)
    : s_(shared), m_(shared.m), options_(shared.options), editor_(shared.editable), angle_(shared.angle),
      area_(shared.face_area), component_of_(shared.component_of), initial_volume_(shared.initial_volume) {}

void Cleaner::begin(const WorkRegion* region) {
  region_ = region;
  result_ = WorkResult{};
  volume_change_.clear();
  area_share_ = region ? region->area_share : s_.area_budget - std::abs(s_.area_drift);
}

void Cleaner::improve(std::uint32_t f, std::uint32_t position) {
  if (!editor_.alive(f) || min_angle(f) >= options_.min_angle_deg) return;
  deferred_ = false;
  if (improve_face(f))
    ++result_.done;
  else if (deferred_)
    result_.deferred.push_back(position);
  else
    ++result_.refused;
}

WorkResult Cleaner::finish() {
  result_.area_drift = area_drift_;
  area_drift_ = 0;
  for (const auto& [component, change] : volume_change_) result_.volume_changes.emplace_back(component, change);
  std::sort(result_.volume_changes.begin(), result_.volume_changes.end());
  volume_change_.clear();
  result_.touched = std::move(touched_);
  touched_.clear();
  return std::move(result_);
}

// The component of the edit's faces (a face that stays, else one that goes): an edit keeps
// to one component, whose volume it changes.
std::uint32_t Cleaner::component(const MeshEdit& e) const {
  for (std::size_t k = 0; k < e.faces.size(); ++k)
    if (!e.removes(k)) return component_of_[e.faces[k]];
  return component_of_[e.faces.front()];
}

// Cheap checks and measures, on doubles: no face may become degenerate (exact) or turn by
// more than 60 degrees (the editor's no-turnover test, a selection: far from the exact
// question "does it turn over", on normals that rounding cannot reverse, as no new face
// is that thin), the worst angle among the faces involved must get better (unless the
// edit is one step of a larger one, judged as a whole), and the area must stay within
// budget.
bool Cleaner::evaluate(Option& o, bool must_improve) const {
  const MeshEdit& e = o.edit;
  if (!within_region(e)) {
    deferred_ = true;
    return false;
  }
  auto pos = [&](Index w) -> const Vec3& { return e.position(m_, w); };
  double before = 180, area_before = 0;
  for (std::uint32_t f : e.faces) {
    before = std::min(before, min_angle(f));
    area_before += area(f);
  }
  double after = 180, area_after = 0;
  bool any_new = false;
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    any_new = true;
    const Triangle& t = e.after[k];
    const Vec3 &a = pos(t[0]), &b = pos(t[1]), &c = pos(t[2]);
    if (!MeshEditor::keeps_facing(a, b, c, e.reference[k], kMaxTurnCos)) return false;
    const double angle = smallest_angle_deg(a, b, c);
    // One step of a larger edit may leave a face that thin (in a cluster of vertices
    // far closer than a thousandth of a degree's worth, every single collapse does);
    // the edit as a whole may not.
    if (must_improve && !(angle > kSmallestNewAngle)) return false;
    after = std::min(after, angle);
    area_after += 0.5 * norm(cross(b - a, c - a));
  }
  if (must_improve && !(after > before)) return false;
  o.before = before;
  o.after = after;
  o.area_change = area_after - area_before;
  if (!(std::abs(area_drift_ + o.area_change) <= area_share_)) return false;
  // Each face's own turn says nothing about a component a few faces across (a small
  // cavity): edit by edit it could be flattened and turned inside out. Its volume keeps
  // its sign and at least half its size. The change is measured about a point of the
  // edit: the old and the new faces span the same boundary, so the origin cancels.
  if (!any_new) return true;
  double volume_change = 0;
  const Vec3* origin = nullptr;
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    const Triangle& t = e.after[k];
    if (!origin) origin = &pos(t[0]);
    volume_change += CleanupShared::tetrahedron_volume(*origin, pos(t[0]), pos(t[1]), pos(t[2]));
  }
  for (std::uint32_t f : e.faces) {
    const Triangle& t = m_.faces[f];
    volume_change -= CleanupShared::tetrahedron_volume(*origin, m_.vertices[t[0]], m_.vertices[t[1]], m_.vertices[t[2]]);
  }
  o.volume_change = volume_change;
  // The volume at the start of this work plus every change made since, by this worker
  // and by the others that may change the component at the same time, each of which
  // keeps to its share of what may be lost.
  const std::uint32_t c = component(e);
  const double initial = initial_volume_[c];
  if (!(initial != 0)) return false;
  const double sign = initial > 0 ? 1 : -1;
  const double slack = sign * s_.component_volume[c] - 0.5 * std::abs(initial);
  const double sharers = region_ ? (*region_->volume_sharers)[c] : 1;
  const auto it = volume_change_.find(c);
  const double changed = (it == volume_change_.end() ? 0 : it->second) + volume_change;
  if (!(sign * changed >= -slack / sharers)) return false;
  if (!(options_.max_volume_change > 0)) return true;
  // And, when asked, within the component's volume budget either way: what it has drifted
  // so far, shared like the slack.
  const double budget = options_.max_volume_change * std::abs(initial);
  const double drift = sign * (s_.component_volume[c] - initial);
  return sign * changed >= -(budget + drift) / sharers && sign * changed <= (budget - drift) / sharers;
}

// Whether the edit leaves no fold: on every edge of its new faces, the two faces open at
// least kMinOpeningDeg (180: flat), or at least as wide as the sharpest edge of the faces it
// replaces. Each face's own turn is bounded elsewhere, but a face may turn onto the
// unchanged face across one of its edges; a knife-edge fold is exactly valid, yet
// floating-point consumers (a mesher's boundary recovery) take its two faces for
// overlapping.
bool Cleaner::keeps_edges_open(const MeshEdit& e) const {
  auto pos = [&](Index w) -> const Vec3& { return e.position(m_, w); };
  auto normal_at = [&](const Triangle& t, bool moved) {
    const Vec3 &a = moved ? pos(t[0]) : m_.vertices[t[0]], &b = moved ? pos(t[1]) : m_.vertices[t[1]],
               &c = moved ? pos(t[2]) : m_.vertices[t[2]];
    return cross(b - a, c - a);
  };
  auto in_edit = [&](std::uint32_t g) { return std::find(e.faces.begin(), e.faces.end(), g) != e.faces.end(); };
  // The cosine of the angle between the normals, against -cos(opening).
  auto opening_cos = [](const Vec3& n1, const Vec3& n2) {
    const double l = norm(n1) * norm(n2);
    return l > 0 ? dot(n1, n2) / l : 1.0;
  };
  static const double limit = -std::cos(kMinOpeningDeg * std::numbers::pi / 180);
  double after = 1;  // the most negative cosine: the sharpest edge
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    const Triangle& t = e.after[k];
    const Vec3 n = normal_at(t, true);
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[(i + 1) % 3];
      // The face across: another new face running b -> a, else an unchanged one.
      bool found = false;
      for (std::size_t j = 0; j < e.faces.size() && !found; ++j) {
        if (e.removes(j)) continue;
        const Triangle& u = e.after[j];
        for (int m = 0; m < 3 && !found; ++m)
          if (u[m] == b && u[(m + 1) % 3] == a) {
            after = std::min(after, opening_cos(n, normal_at(u, true)));
            found = true;
          }
      }
      for (std::uint32_t g : editor_.faces_of(a)) {
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
  for (std::uint32_t f : e.faces) {
    const Triangle& t = m_.faces[f];
    const Vec3 n = normal_at(t, false);
    for (int i = 0; i < 3; ++i)
      for (std::uint32_t g : editor_.faces_on_edge(t[i], t[(i + 1) % 3]))
        if (g != f) before = std::min(before, opening_cos(n, normal_at(m_.faces[g], false)));
  }
  return after >= before;
}

// Whether the edit stays within the worker's region: every corner it moves, removes or
// changes, and no new face longer than the region allows. Outside it, another worker may
// be changing the mesh.
bool Cleaner::within_region(const MeshEdit& e) const {
  if (!region_) return true;
  const BoundingBox& r = region_->box;
  auto inside = [&](const Vec3& p) {
    return p.x >= r.min.x && p.x <= r.max.x && p.y >= r.min.y && p.y <= r.max.y && p.z >= r.min.z && p.z <= r.max.z;
  };
  for (std::uint32_t f : e.faces)
    for (Index w : m_.faces[f])
      if (!inside(m_.vertices[w])) return false;
  if (e.moved != kNoVertex && !inside(e.target)) return false;
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    BoundingBox box;
    for (Index w : e.after[k]) box.extend(e.position(m_, w));
    for (int a = 0; a < 3; ++a)
      if (!(box.max[a] - box.min[a] <= region_->max_extent)) return false;
  }
  return true;
}

// The best option that passes the exact test: first whatever reaches the target angle,
// seams kept before seams moved; below it, the best angle.
bool Cleaner::try_best(std::vector<Option>& options) {
  const double goal = options_.min_angle_deg;
  std::stable_sort(options.begin(), options.end(), [&](const Option& x, const Option& y) {
    const double gx = std::min(x.after, goal), gy = std::min(y.after, goal);
    if (gx != gy) return gx > gy;
    if (x.rank != y.rank) return x.rank < y.rank;
    if (std::abs(x.area_change) != std::abs(y.area_change)) return std::abs(x.area_change) < std::abs(y.area_change);
    return x.after > y.after;
  });
  for (const Option& o : options)
    if (fits(o)) {
      commit(o);
      return true;
    }
  return false;
}

void Cleaner::commit(const Option& o) {
  const MeshEdit& e = o.edit;
  const std::uint32_t c = component(e);
  if (editor_.journaling()) {
    for (std::uint32_t f : e.faces)
      if (!first_angle_.contains(f)) first_angle_.emplace(f, min_angle(f));
    applied_.push_back({e.kind, c, o.area_change, o.volume_change});
  }
  editor_.commit(e);
  for (std::size_t k = 0; k < e.faces.size(); ++k)
    if (!e.removes(k)) forget(e.faces[k]);
  area_drift_ += o.area_change;
  volume_change_[c] += o.volume_change;
  switch (e.kind) {
    case MeshEdit::Kind::collapse: ++result_.collapses; break;
    case MeshEdit::Kind::flip: ++result_.flips; break;
    case MeshEdit::Kind::move: ++result_.moves; break;
  }
}

void Cleaner::undo_last() {
  const MeshEdit e = editor_.undo_last();
  for (std::uint32_t f : e.faces) forget(f);
  const Applied a = applied_.back();
  applied_.pop_back();
  area_drift_ -= a.area_change;
  volume_change_[a.component] -= a.volume_change;
  switch (a.kind) {
    case MeshEdit::Kind::collapse: --result_.collapses; break;
    case MeshEdit::Kind::flip: --result_.flips; break;
    case MeshEdit::Kind::move: --result_.moves; break;
  }
}

// A compound edit: steps made one by one, each under every rule but the improvement, and
// kept or undone as a whole by keep_if_better.
void Cleaner::open_compound() {
  editor_.open_journal();
  applied_.clear();
  first_angle_.clear();
}

// Ends the compound edit: kept when `complete` and the worst angle among the faces it
// touched got better, else undone step by step.
bool Cleaner::keep_if_better(bool complete) {
  double before = 180, after = 180;
  for (const auto& [g, angle] : first_angle_) {
    before = std::min(before, angle);
    if (editor_.alive(g)) after = std::min(after, min_angle(g));
  }
  const bool better = complete && after > before;
  if (!better)
    while (!editor_.journal_empty()) undo_last();
  editor_.close_journal();
  applied_.clear();
  return better;
}

}  // namespace molsurf::surface_cleanup
