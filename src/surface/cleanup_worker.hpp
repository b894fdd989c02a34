#pragma once
// The cleanup's workers (paper §2.5): what they share, where each may change the mesh, and
// the worker itself, which proposes edits around a distorted face (the strategies, in
// cleanup_strategies.cpp), measures them against the cleanup's rules and makes the best
// that passes (cleanup_worker.cpp). Collapses, flips, moves, the link condition, the
// no-turnover and crossing tests and the journal are the editing layer's
// (src/mesh/mesh_editor.hpp). The sweep that runs the workers is in cleanup.cpp.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/mesh_editor.hpp"
#include "molsurf/cleanup.hpp"

namespace molsurf::surface_cleanup {

// What every worker of the cleanup shares: the mesh being edited and what is kept per face
// and component. Workers that run at the same time touch only faces and vertices in regions
// far apart (see Sweep), so nothing here is locked.
struct CleanupShared {
  // `area`: the mesh's surface area, which the caller has measured.
  // `frozen` (empty: none): per vertex, whether no edit may move or merge it away.
  CleanupShared(Mesh& mesh, const CleanupOptions& opts, double area, std::span<const std::uint8_t> frozen = {});

  static double tetrahedron_volume(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot(a - o, cross(b - o, c - o)) / 6;
  }

  Mesh& m;
  const CleanupOptions& options;
  EditableMesh editable;
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

// An edit the worker may make, with its measures (set by Cleaner::evaluate).
struct Option {
  MeshEdit edit;
  double before = 0, after = 0;  // the worst angle among the faces involved
  double area_change = 0, volume_change = 0;
  int rank = 0;  // 0: the seams (where spheres meet) stay where they are; 1: they move a little
};

// An edge under the short-edge floor: its length and its ends, lower index first.
using ShortEdge = std::pair<double, std::array<Index, 2>>;

// One worker of the cleanup: the edits around a distorted face, measured, tested and made.
class Cleaner {
 public:
  explicit Cleaner(CleanupShared& shared);

  // Starts a piece of work: edits within `region` (none: anywhere, with the whole budgets).
  void begin(const WorkRegion* region);
  // The best valid edit around distorted face f, if any (counted in the result). A face
  // whose edits were all refused, some of them only for leaving the region, is left for
  // later, under its `position` in the pass's order.
  void improve(std::uint32_t f, std::uint32_t position);
  WorkResult finish();
  // The length under which an edge is collapsed whatever its faces' angles: the larger of
  // min_edge_fraction of the median edge and min_edge_length (0: no alive edge).
  double short_edge_floor() const;
  // The alive edges shorter than `floor`, shortest first (ties by their ends).
  std::vector<ShortEdge> short_edges(double floor) const;
  // Edge a-b collapsed if it is still shorter than `floor` and a collapse passes the rules
  // (counted in the result; one that would leave the region is left for later under
  // `position`, as in improve).
  void shorten(Index a, Index b, double floor, std::uint32_t position);
  // The component of the faces around vertex v (which has some).
  std::uint32_t vertex_component(Index v) const { return component_of_[editor_.faces_of(v).front()]; }

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
  // The strategies, tried in this order on a distorted face until one makes an edit
  // (cleanup_strategies.cpp).
  bool collapse_or_flip(std::uint32_t f);
  bool merge_cluster(std::uint32_t f);
  bool widen_neck(std::uint32_t f);
  bool unblock_collapse(std::uint32_t f);
  bool move_corner(std::uint32_t f);
  bool improve_face(std::uint32_t f);

  // The pieces the strategies propose.
  bool widen_loop(const std::array<Index, 3>& loop);
  bool clear_collapse(Index a, Index b);
  bool collapse_cleared(Index a, Index b);
  Option flip(std::uint32_t f, Index a, Index b) const;
  void move_candidates(Index v, std::vector<Option>& out) const;
  template <class Keep>
  void collapse_options(Index a, Index b, const std::vector<std::uint32_t>& on_edge, std::vector<Option>& out,
                        Keep&& keep) const;
  std::vector<std::int32_t> tags_of(Index v) const;

  // The cleanup's rules (cleanup_worker.cpp).
  bool evaluate(Option& o, bool must_improve = true) const;
  bool keeps_edges_open(const MeshEdit& e) const;
  bool within_region(const MeshEdit& e) const;
  bool fits(const Option& o) {
    return editor_.spares_frozen(o.edit) && editor_.keeps_frozen_edges(o.edit) && keeps_edges_open(o.edit) && editor_.crosses_nothing(o.edit);
  }
  bool try_best(std::vector<Option>& options);
  std::uint32_t component(const MeshEdit& e) const;

  // Making edits, and compound edits judged as a whole.
  void commit(const Option& o);
  void undo_last();
  void open_compound();
  bool keep_if_better(bool complete);

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

  CleanupShared& s_;
  const Mesh& m_;
  const CleanupOptions& options_;
  MeshEditor editor_;
  std::vector<double>& angle_;
  std::vector<double>& area_;
  const std::vector<std::uint32_t>& component_of_;
  const std::vector<double>& initial_volume_;
  const WorkRegion* region_ = nullptr;
  mutable bool deferred_ = false;  // an edit around the present face was refused for leaving the region
  WorkResult result_;
  std::vector<std::uint32_t> touched_;  // faces changed or restored
  double area_share_ = 0, area_drift_ = 0;
  std::unordered_map<std::uint32_t, double> volume_change_;  // per component
  // While a compound edit is tried: the measures of its steps, which the editor's journal
  // holds, and the angle of each face it touched as it was before.
  struct Applied {
    MeshEdit::Kind kind;
    std::uint32_t component;
    double area_change, volume_change;
  };
  std::vector<Applied> applied_;
  std::unordered_map<std::uint32_t, double> first_angle_;
};

}  // namespace molsurf::surface_cleanup
