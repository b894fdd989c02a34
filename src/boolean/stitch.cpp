#include "boolean/stitch.hpp"

#include "boolean/repair_rounding.hpp"

#include <algorithm>

#include "mesh/topology.hpp"
#include <array>
#include <gmpxx.h>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace molsurf::boolean_engine {

namespace {

Vec3 rounded_point(const geometry::ImplicitPoint& p) {
  if (p.is_explicit()) return p.explicit_value();
  // The filter's interval is usually a few ulps wide: its midpoint is as good a rounding
  // as any; only wide intervals pay for the exact rational.
  Vec3 mid{p.coordinate(0).mid(), p.coordinate(1).mid(), p.coordinate(2).mid()};
  // An unbounded interval (the filter's denominator straddles zero: a line nearly parallel
  // to the plane) has width inf <= 4 eps inf and a NaN midpoint: it must take the exact path.
  for (int axis = 0; axis < 3; ++axis) {
    const auto& i = p.coordinate(axis);
    if (!std::isfinite(i.lo) || !std::isfinite(i.hi) ||
        !(i.hi - i.lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(i.lo), std::fabs(i.hi))))
      return p.rounded();
  }
  return mid;
}

using QVec = std::array<mpq_class, 3>;

QVec exact_of(const geometry::ImplicitPoint& p) {
  const geometry::ExactPoint e = p.exact();
  return {e.x, e.y, e.z};
}
QVec minus(const QVec& a, const QVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
mpq_class dot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
QVec cross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Where more than two faces share an edge (the solids touch along it), pairs the faces
// that bound the same material sector, exactly: the faces are sorted by angle around the
// edge, and a face whose material lies counter-clockwise of it (around t = to - from)
// is paired with the next face counter-clockwise. Returns pairs of indices into `faces`.
std::vector<std::pair<std::uint32_t, std::uint32_t>> pair_faces_around_edge(
    const Mesh& m, const std::vector<std::uint32_t>& point_of_vertex, const Arrangement& arr, std::uint32_t from,
    std::uint32_t to, const std::vector<std::uint32_t>& faces) {
  const QVec p0 = exact_of(arr.points[point_of_vertex[from]]);
  const QVec t = minus(exact_of(arr.points[point_of_vertex[to]]), p0);
  const mpq_class tt = dot(t, t);
  struct Sheet {
    std::uint32_t face;
    QVec direction;             // the face's half-plane, perpendicular to t
    bool material_ccw = false;  // the face traverses to -> from
  };
  std::vector<Sheet> sheets;
  for (std::uint32_t f : faces) {
    const Triangle& tri = m.faces[f];
    int k = 0;
    while (tri[k] == from || tri[k] == to) ++k;
    const QVec u = minus(exact_of(arr.points[point_of_vertex[tri[k]]]), p0);
    const mpq_class along = dot(u, t) / tt;
    Sheet s{f, {u[0] - along * t[0], u[1] - along * t[1], u[2] - along * t[2]}};
    // Counter-clockwise order (from, to, wing) gives the normal t x d: material clockwise.
    s.material_ccw = tri[(k + 1) % 3] == to;
    sheets.push_back(std::move(s));
  }
  // Angle of each direction from the first, counter-clockwise around t, compared exactly:
  // first by half (sine >= 0 before sine < 0), then by the sign of the cross product.
  const QVec& ref = sheets[0].direction;
  auto upper_half = [&](const QVec& d) {
    const int sine = sgn(dot(t, cross(ref, d)));
    return sine > 0 || (sine == 0 && sgn(dot(ref, d)) > 0);
  };
  std::sort(sheets.begin() + 1, sheets.end(), [&](const Sheet& a, const Sheet& b) {
    const bool ua = upper_half(a.direction), ub = upper_half(b.direction);
    if (ua != ub) return ua;
    return sgn(dot(t, cross(a.direction, b.direction))) > 0;
  });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const std::size_t n = sheets.size();
  for (std::size_t i = 0; i < n; ++i)
    if (sheets[i].material_ccw && !sheets[(i + 1) % n].material_ccw)
      pairs.emplace_back(sheets[i].face, sheets[(i + 1) % n].face);
  return pairs;
}

using FacePairs = std::unordered_set<std::uint64_t>;  // (lower face, higher face) bound one sector

std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> faces_by_edge(const Mesh& m,
                                                                            const std::vector<std::uint32_t>& faces) {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> faces_of_edge;
  for (std::uint32_t f : faces)
    for (int i = 0; i < 3; ++i) faces_of_edge[undirected_edge_key(m.faces[f][i], m.faces[f][(i + 1) % 3])].push_back(f);
  return faces_of_edge;
}

// Duplicates every vertex of `faces` allowed by `may_split` whose faces form more than one
// fan; `faces` must hold every face around each such vertex. Faces are joined across an edge with
// exactly two faces, and across an edge with more faces by the given pairs.
template <class MaySplit>
std::size_t duplicate_fan_vertices(Mesh& m, const FacePairs& pairs, const std::vector<std::uint32_t>& faces,
                                   MaySplit&& may_split) {
  // Corner slots: 3 per listed face; join slots of the same vertex across connecting edges.
  std::unordered_map<std::uint32_t, std::uint32_t> slot_base;
  for (std::uint32_t k = 0; k < faces.size(); ++k) slot_base.emplace(faces[k], 3 * k);
  DisjointSets fans(3 * faces.size());
  auto slot = [&](std::uint32_t f, std::uint32_t v) {
    const std::uint32_t base = slot_base.at(f);
    for (std::uint32_t i = 0; i < 3; ++i)
      if (m.faces[f][i] == v) return base + i;
    return base;
  };
  auto join = [&](std::uint32_t f, std::uint32_t g, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t v : {a, b}) {
      fans.unite(slot(f, v), slot(g, v));
    }
  };
  for (const auto& [key, around] : faces_by_edge(m, faces)) {
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
    if (around.size() == 2) {
      join(around[0], around[1], a, b);
      continue;
    }
    for (std::uint32_t f : around)
      for (std::uint32_t g : around)
        if (f < g && pairs.count(undirected_edge_key(f, g))) join(f, g, a, b);
  }
  // The first fan (lowest slot) of each vertex keeps it; every other fan gets a copy.
  std::unordered_map<std::uint32_t, std::uint32_t> first_fan_of_vertex;
  std::unordered_map<std::uint32_t, std::uint32_t> copy_of_fan;
  std::size_t copies = 0;
  for (std::uint32_t s = 0; s < 3 * faces.size(); ++s) {
    Triangle& t = m.faces[faces[s / 3]];
    const std::uint32_t v = t[s % 3];
    if (!may_split(v)) continue;
    const std::uint32_t fan = fans.find(s);
    auto [it, first] = first_fan_of_vertex.try_emplace(v, fan);
    if (first || it->second == fan) continue;
    auto [copy, is_new] = copy_of_fan.try_emplace(fan, static_cast<std::uint32_t>(m.vertices.size()));
    if (is_new) {
      m.vertices.push_back(m.vertices[v]);
      ++copies;
    }
    t[s % 3] = copy->second;
  }
  return copies;
}

// Keeps the sheets apart where the solids touch. First, faces around each edge shared by
// more than two faces are paired by material sector and vertices are duplicated per fan.
// Where both ends of such an edge are places where the sheets join, no end can be
// duplicated: the edge is then split at its midpoint (each half-face keeps its pairing),
// and the midpoint, which the sheets do not share, is duplicated.
std::size_t split_touching_vertices(StitchResult& r, const std::vector<std::uint32_t>& point_of_vertex,
                                    const Arrangement& arr, const std::vector<std::uint8_t>& touching) {
  Mesh& m = r.mesh;
  // Sheets can only touch at points on both surfaces that are not transversal crossings
  // (`touching`: such points, and the vertices the rounding repair merged them into):
  // look at the faces around them only (in a generic union there are none).
  std::vector<std::uint32_t> near;
  if (std::find(arr.may_touch.begin(), arr.may_touch.end(), 1) == arr.may_touch.end()) return 0;
  for (std::uint32_t f = 0; f < m.faces.size(); ++f)
    for (std::uint32_t v : m.faces[f])
      if (touching[v]) {
        near.push_back(f);
        break;
      }
  FacePairs pairs;
  for (const auto& [key, faces] : faces_by_edge(m, near)) {
    if (faces.size() <= 2) continue;
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
    for (auto [f, g] : pair_faces_around_edge(m, point_of_vertex, arr, a, b, faces)) pairs.insert(undirected_edge_key(f, g));
  }
  const std::size_t original_vertices = point_of_vertex.size();
  auto may_split = [&](std::uint32_t v) {  // on both surfaces, or a midpoint added below
    return v >= original_vertices || touching[v];
  };
  std::size_t copies = duplicate_fan_vertices(m, pairs, near, may_split);
  if (pairs.empty()) return copies;

  std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>> shared;
  for (auto& [key, faces] : faces_by_edge(m, near))
    if (faces.size() > 2) shared.emplace_back(key, std::move(faces));
  std::sort(shared.begin(), shared.end());  // deterministic order of new vertices and faces
  for (const auto& [key, faces] : shared) {
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
    const auto mid = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(0.5 * (m.vertices[a] + m.vertices[b]));
    // Each face's half on a's side and on b's side (which is which depends on how the
    // face runs along the edge); halves pair as their faces did.
    std::unordered_map<std::uint32_t, std::uint32_t> half_at_a, half_at_b;
    for (std::uint32_t f : faces) {
      Triangle& t = m.faces[f];
      int i = 0;  // t[i] -> t[i+1] is the edge
      while (!((t[i] == a || t[i] == b) && (t[(i + 1) % 3] == a || t[(i + 1) % 3] == b))) ++i;
      Triangle half = t;
      const bool starts_at_a = t[i] == a;
      t[(i + 1) % 3] = mid;  // (t[i], mid, w)
      half[i] = mid;         // (mid, t[i+1], w)
      const auto added = static_cast<std::uint32_t>(m.faces.size());
      near.push_back(added);
      half_at_a[f] = starts_at_a ? f : added;
      half_at_b[f] = starts_at_a ? added : f;
      m.faces.push_back(half);
      r.face_operand.push_back(r.face_operand[f]);
      r.face_source.push_back(r.face_source[f]);
      if (!m.face_tags.empty()) m.face_tags.push_back(m.face_tags[f]);
    }
    std::vector<std::uint64_t> halves_paired;
    for (std::uint32_t f : faces)
      for (std::uint32_t g : faces)
        if (f < g && pairs.count(undirected_edge_key(f, g))) {
          halves_paired.push_back(undirected_edge_key(half_at_a[f], half_at_a[g]));
          halves_paired.push_back(undirected_edge_key(half_at_b[f], half_at_b[g]));
        }
    pairs.insert(halves_paired.begin(), halves_paired.end());
  }
  if (!shared.empty()) copies += duplicate_fan_vertices(m, pairs, near, may_split);
  return copies;
}

}  // namespace

StitchResult stitch_sub_faces(const Operands& ops, const Arrangement& arr, const std::vector<SubFace>& subs,
                              const std::vector<Side>& sides, BooleanOp op) {
  std::vector<Keep> keep(subs.size());
  for (std::size_t s = 0; s < subs.size(); ++s) keep[s] = select_sub_face(op, ops.operand_of_face(subs[s].face), sides[s]);
  return stitch_sub_faces(ops, arr, subs, keep);
}

StitchResult stitch_sub_faces(const Operands& ops, const Arrangement& arr, const std::vector<SubFace>& subs,
                              const std::vector<Keep>& keeps, bool keep_sheets_apart) {
  StitchResult r;
  std::vector<std::uint32_t> vertex_of_point(arr.points.size(), ~0u);
  std::vector<std::uint32_t> point_of_vertex;
  auto vertex = [&](std::uint32_t p) {
    if (vertex_of_point[p] == ~0u) {
      vertex_of_point[p] = static_cast<std::uint32_t>(r.mesh.vertices.size());
      point_of_vertex.push_back(p);
      r.mesh.vertices.push_back(rounded_point(arr.points[p]));
    }
    return vertex_of_point[p];
  };
  const bool tagged = ops.mesh(0).has_tags() || ops.mesh(1).has_tags();
  for (std::size_t s = 0; s < subs.size(); ++s) {
    const int operand = ops.operand_of_face(subs[s].face);
    const Keep keep = keeps[s];
    if (keep == Keep::drop) continue;
    Triangle t{vertex(subs[s].points[0]), vertex(subs[s].points[1]), vertex(subs[s].points[2])};
    if (keep == Keep::keep_flipped) std::swap(t[1], t[2]);
    r.mesh.faces.push_back(t);
    const std::uint32_t source = ops.local_face(subs[s].face);
    r.face_operand.push_back(static_cast<std::uint8_t>(operand));
    r.face_source.push_back(source);
    if (tagged) r.mesh.face_tags.push_back(ops.mesh(operand).tag(source));
  }
  std::vector<std::uint8_t> rounded(point_of_vertex.size()), frozen;
  for (std::size_t v = 0; v < rounded.size(); ++v) rounded[v] = !arr.points[point_of_vertex[v]].is_explicit();
  if (ops.frozen_count() > 0) {
    frozen.assign(point_of_vertex.size(), 0);
    for (std::size_t v = 0; v < frozen.size(); ++v)
      frozen[v] = point_of_vertex[v] < ops.vertex_count() && ops.frozen(point_of_vertex[v]);
  }
  // The result may feed a later merge (the pairwise surface method): the repair's options
  // for operands tilted by earlier roundings.
  r.repair = repair_rounding(r.mesh, r.face_operand, r.face_source, rounded, frozen,
                             {.nudge_every_fold = true, .collapse_tiny_edges = true, .flat_folds = true});
  if (keep_sheets_apart) {
    // Where the sheets may touch: on the points found so, and on the vertices that the
    // repair merged such a point into.
    std::vector<std::uint8_t> touching(point_of_vertex.size());
    for (std::size_t v = 0; v < touching.size(); ++v) touching[v] = arr.may_touch[point_of_vertex[v]];
    for (auto [removed, kept] : r.repair.collapsed) touching[kept] |= touching[removed];
    r.split_vertices = split_touching_vertices(r, point_of_vertex, arr, touching);
  }
  // Collapses leave vertices no face uses: renumber in order of first use.
  std::vector<Index> renumber(r.mesh.vertices.size(), ~Index{0});
  std::vector<Vec3> used;
  used.reserve(r.mesh.vertices.size());
  r.vertex_point.reserve(r.mesh.vertices.size());
  for (Triangle& t : r.mesh.faces)
    for (Index& v : t) {
      if (renumber[v] == ~Index{0}) {
        renumber[v] = static_cast<Index>(used.size());
        used.push_back(r.mesh.vertices[v]);
        r.vertex_point.push_back(v < point_of_vertex.size() ? point_of_vertex[v] : ~0u);
      }
      v = renumber[v];
    }
  r.mesh.vertices = std::move(used);
  return r;
}

}  // namespace molsurf::boolean_engine
