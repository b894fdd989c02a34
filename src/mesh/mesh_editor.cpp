#include "mesh/mesh_editor.hpp"

#include <algorithm>
#include <stdexcept>

#include "geometry/predicates.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/topology.hpp"

namespace molsurf {

namespace {

// A crossing, or a contact (two faces touching without crossing): both are defects of a
// surface (mesh_check.hpp), so the repairs count and remove both.
bool crossing(geometry::TrianglePairRelation r) {
  return r == geometry::TrianglePairRelation::intersecting || r == geometry::TrianglePairRelation::contact;
}
// What an edit may not leave: a crossing, a contact, or a face on the same three corners as
// another.
bool acceptable(geometry::TrianglePairRelation r) { return r == geometry::TrianglePairRelation::apart; }

}  // namespace

void EditableMesh::index_all(double cell) {
  faces_of_.add_all(mesh_.faces);
  grid_ = std::make_unique<FaceGrid>(mesh_, cell);
}

std::vector<std::uint32_t> MeshEditor::faces_on_edge(Index a, Index b) const {
  return molsurf::faces_on_edge(mesh(), faces_of(a), a, b);
}

std::vector<Index> MeshEditor::neighbours(Index v) const { return vertex_neighbours(mesh(), faces_of(v), v); }

bool MeshEditor::joined(Index c, Index d) const {
  for (std::uint32_t h : faces_of(c))
    for (Index w : mesh().faces[h])
      if (w == d) return true;
  return false;
}

std::vector<Index> MeshEditor::blocking_vertices(Index a, Index b) const {
  return molsurf::blocking_vertices(mesh(), faces_of(a), faces_of(b), a, b);
}

bool MeshEditor::link_condition(Index u, Index v, std::span<const std::uint32_t> on_edge) const {
  return molsurf::link_condition(mesh(), faces_of(u), faces_of(v), on_edge, u, v);
}

MeshEdit MeshEditor::collapse(Index u, Index v, std::span<const std::uint32_t> on_edge, const Vec3& target) const {
  const Mesh& m = mesh();
  auto on = [&](std::uint32_t g) { return std::find(on_edge.begin(), on_edge.end(), g) != on_edge.end(); };
  MeshEdit e;
  e.kind = MeshEdit::Kind::collapse;
  e.reserve(faces_of(u).size() + faces_of(v).size());
  for (std::uint32_t g : on_edge) e.remove(g);
  for (std::uint32_t g : faces_of(v)) {
    if (on(g)) continue;
    Triangle t = m.faces[g];
    for (Index& w : t)
      if (w == v) w = u;
    e.change(g, t, normal(m.faces[g]));
  }
  if (!(target == m.vertices[u])) {
    for (std::uint32_t g : faces_of(u))
      if (!on(g)) e.change(g, m.faces[g], normal(m.faces[g]));
    e.moved = u;
    e.target = target;
  }
  return e;
}

MeshEdit MeshEditor::merge(Index u, Index v, std::span<const std::uint32_t> on_edge) const {
  const Mesh& m = mesh();
  MeshEdit e;
  e.kind = MeshEdit::Kind::collapse;
  for (std::uint32_t g : faces_of(v)) {
    if (std::find(e.faces.begin(), e.faces.end(), g) != e.faces.end()) continue;  // a repeated corner
    if (std::find(on_edge.begin(), on_edge.end(), g) != on_edge.end()) {
      e.remove(g);
      continue;
    }
    Triangle t = m.faces[g];
    for (Index& w : t)
      if (w == v) w = u;
    e.change(g, t, normal(m.faces[g]));
  }
  return e;
}

MeshEdit MeshEditor::remove_valence_three(Index w) const {
  const Mesh& m = mesh();
  MeshEdit e;
  e.kind = MeshEdit::Kind::collapse;
  const std::span<const std::uint32_t> fan = faces_of(w);
  Triangle first = m.faces[fan[0]];
  while (first[0] != w) first = {first[1], first[2], first[0]};
  const Index p = first[1], q = first[2];
  Index r = kNoVertex;
  for (std::uint32_t g : fan)
    for (Index x : m.faces[g])
      if (x != w && x != p && x != q) r = x;
  if (r == kNoVertex) return e;
  // The fan itself may be a spike whose normals say nothing about the surface around it.
  Vec3 reference;
  for (auto [a, b] : {std::pair{p, q}, std::pair{q, r}, std::pair{r, p}})
    for (std::uint32_t g : faces_on_edge(a, b))
      if (std::find(fan.begin(), fan.end(), g) == fan.end()) {
        const Vec3 n = normal(m.faces[g]);
        if (const double length = norm(n); length > 0) reference += n / length;
      }
  e.remove(fan[1]);
  e.remove(fan[2]);
  e.change(fan[0], Triangle{p, q, r}, reference);
  return e;
}

std::array<Triangle, 2> MeshEditor::flipped(std::uint32_t f, Index c, Index d) const {
  const Triangle& tf = mesh().faces[f];
  int k = 0;
  while (tf[k] != c) ++k;
  // f runs from -> to along the edge (corner order c, from, to), so the face across runs to -> from.
  const Index from = tf[(k + 1) % 3], to = tf[(k + 2) % 3];
  return {Triangle{from, d, c}, Triangle{d, to, c}};
}

MeshEdit MeshEditor::flip(std::uint32_t f, std::uint32_t g, Index c, Index d, const Vec3& reference) const {
  const auto [first, second] = flipped(f, c, d);
  MeshEdit e;
  e.kind = MeshEdit::Kind::flip;
  e.change(f, first, reference);
  e.change(g, second, reference);
  return e;
}

MeshEdit MeshEditor::flip_appending(std::uint32_t f, std::uint32_t g, Index c, Index d) const {
  const auto [first, second] = flipped(f, c, d);
  MeshEdit e;
  e.kind = MeshEdit::Kind::flip;
  e.remove(f);
  e.remove(g);
  e.added = {first, second};
  e.added_like = g;
  return e;
}

MeshEdit MeshEditor::move(Index v, const Vec3& target) const {
  MeshEdit e;
  e.kind = MeshEdit::Kind::move;
  e.reserve(faces_of(v).size());
  for (std::uint32_t g : faces_of(v)) e.change(g, mesh().faces[g], normal(mesh().faces[g]));
  e.moved = v;
  e.target = target;
  return e;
}

bool MeshEditor::crosses_nothing(const MeshEdit& e) {
  Mesh& m = s_.mesh_;
  Vec3 saved;
  if (e.moved != kNoVertex) {
    saved = m.vertices[e.moved];
    m.vertices[e.moved] = e.target;
  }
  bool ok = true;
  for (std::size_t k = 0; ok && k < e.faces.size(); ++k)
    if (!e.removes(k)) ok = crosses_nothing_near(e, e.after[k]);
  for (std::size_t k = 0; ok && k < e.added.size(); ++k) ok = crosses_nothing_near(e, e.added[k]);
  // The new faces among themselves.
  made_.clear();
  for (std::size_t k = 0; ok && k < e.faces.size(); ++k)
    if (!e.removes(k)) made_.push_back(&e.after[k]);
  for (const Triangle& t : e.added) made_.push_back(&t);
  for (std::size_t i = 0; ok && i < made_.size(); ++i)
    for (std::size_t j = i + 1; ok && j < made_.size(); ++j)
      ok = acceptable(geometry::classify_triangle_pair(m, *made_[i], *made_[j]));
  if (e.moved != kNoVertex) m.vertices[e.moved] = saved;
  return ok;
}

// The faces the edit removes or changes have no stored box that is still right (the moved
// vertex is a corner of changed faces only): they are marked seen before the query. Faces
// whose box is apart from the new face's cannot meet it.
bool MeshEditor::crosses_nothing_near(const MeshEdit& e, const Triangle& t) {
  const Mesh& m = mesh();
  const FaceGrid& grid = *s_.grid_;
  if (seen_.size() < m.faces.size()) seen_.resize(m.faces.size(), 0);
  BoundingBox box;
  for (Index w : t) box.extend(m.vertices[w]);
  if (++query_ == 0) {  // wrapped: no stale mark may match
    std::fill(seen_.begin(), seen_.end(), 0);
    query_ = 1;
  }
  for (std::uint32_t g : e.faces) seen_[g] = query_;
  return grid.near(box, [&](std::uint32_t g) {
    if (seen_[g] == query_) return true;
    seen_[g] = query_;
    if (!s_.alive_[g]) return true;
    if (!grid.box(g).overlaps(box)) return true;
    return acceptable(geometry::classify_triangle_pair(m, t, m.faces[g]));
  });
}

std::size_t MeshEditor::crossings_around(std::initializer_list<Index> centres) const {
  const Mesh& m = mesh();
  std::vector<std::uint32_t> faces;
  for (Index c : centres)
    for (std::uint32_t g : faces_of(c))
      for (Index w : m.faces[g]) {
        const auto around_w = faces_of(w);
        faces.insert(faces.end(), around_w.begin(), around_w.end());
      }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::size_t count = 0;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j)
      if (alive(faces[i]) && alive(faces[j]) && folds(m.faces[faces[i]], m.faces[faces[j]])) ++count;
  return count;
}

bool MeshEditor::folds(const Triangle& a, const Triangle& b) const {
  return crossing(geometry::classify_triangle_pair(mesh(), a, b)) ||
         (count_flat_folds_ && geometry::folded_flat(mesh(), a, b));
}

bool MeshEditor::touches_frozen(std::initializer_list<Index> vertices) {
  for (Index v : vertices)
    if (frozen(v)) {
      ++refused_frozen_;
      return true;
    }
  return false;
}

bool MeshEditor::spares_frozen(const MeshEdit& e) const {
  if (s_.frozen_.empty()) return true;
  if (e.moved != kNoVertex && frozen(e.moved)) return false;
  // x stays in the mesh if a new face has it, or a face the edit leaves alone.
  auto stays = [&](Index x) {
    for (std::size_t k = 0; k < e.faces.size(); ++k)
      if (!e.removes(k) && std::find(e.after[k].begin(), e.after[k].end(), x) != e.after[k].end()) return true;
    for (const Triangle& t : e.added)
      if (std::find(t.begin(), t.end(), x) != t.end()) return true;
    for (std::uint32_t g : faces_of(x))
      if (alive(g) && std::find(e.faces.begin(), e.faces.end(), g) == e.faces.end()) return true;
    return false;
  };
  for (std::uint32_t f : e.faces)
    for (Index x : mesh().faces[f])
      if (frozen(x) && !stays(x)) return false;
  return true;
}

bool MeshEditor::keeps_frozen_edges(const MeshEdit& e) const {
  if (s_.frozen_.empty()) return true;
  auto edges_exist = [&](const Triangle& t) {
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      if (frozen(a) && frozen(b) && faces_on_edge(a, b).empty()) return false;
    }
    return true;
  };
  for (std::size_t k = 0; k < e.faces.size(); ++k)
    if (!e.removes(k) && !edges_exist(e.after[k])) return false;
  for (const Triangle& t : e.added)
    if (!edges_exist(t)) return false;
  return true;
}

void MeshEditor::commit(const MeshEdit& e) {
  if (!spares_frozen(e)) throw std::invalid_argument("MeshEditor::commit: the edit moves or removes a frozen vertex");
  if (s_.grid_ && !e.added.empty())
    throw std::invalid_argument("MeshEditor::commit: faces kept by place cannot be appended");
  Mesh& m = s_.mesh_;
  if (journaling_) {
    Step step{e, {}, {}, static_cast<std::uint32_t>(m.faces.size())};
    step.before.reserve(e.faces.size());
    for (std::uint32_t f : e.faces) step.before.push_back(m.faces[f]);
    if (e.moved != kNoVertex) step.old_position = m.vertices[e.moved];
    journal_.push_back(std::move(step));
  }
  for (std::uint32_t f : e.faces) {
    if (s_.grid_) s_.grid_->erase(f);
    s_.faces_of_.remove(f, m.faces[f]);
  }
  for (std::size_t k = 0; k < e.faces.size(); ++k)
    if (e.removes(k)) s_.alive_[e.faces[k]] = 0;
  if (e.moved != kNoVertex) m.vertices[e.moved] = e.target;
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    const std::uint32_t f = e.faces[k];
    m.faces[f] = e.after[k];
    if (s_.grid_) s_.grid_->insert(f);
    s_.faces_of_.add(f, m.faces[f]);
  }
  for (const Triangle& t : e.added) {
    const auto f = static_cast<std::uint32_t>(m.faces.size());
    m.faces.push_back(t);
    if (m.has_tags()) m.face_tags.push_back(m.face_tags[e.added_like]);
    s_.alive_.push_back(1);
    s_.added_like_.push_back(e.added_like);
    s_.faces_of_.add(f, t);
  }
}

void MeshEditor::reposition(Index v, const Vec3& p) {
  if (s_.grid_) throw std::invalid_argument("MeshEditor::reposition: the faces are kept by place");
  if (frozen(v)) throw std::invalid_argument("MeshEditor::reposition: a frozen vertex");
  s_.mesh_.vertices[v] = p;
}

// Lists the faces back in the edit's order: a face removed or changed comes after the faces
// the edit did not touch, so the order around a vertex after an undo need not be the one
// before. The editors' results depend on that order (it decides which face an edge's
// first is), which is why an edit's builder fixes it.
MeshEdit MeshEditor::undo_last() {
  if (!journaling_ || journal_.empty()) throw std::logic_error("MeshEditor::undo_last: nothing journaled");
  Step step = std::move(journal_.back());
  journal_.pop_back();
  const MeshEdit& e = step.edit;
  Mesh& m = s_.mesh_;
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    const std::uint32_t f = e.faces[k];
    if (s_.grid_) s_.grid_->erase(f);
    s_.faces_of_.remove(f, m.faces[f]);
  }
  for (std::uint32_t f = step.first_added; f < step.first_added + e.added.size(); ++f) {
    s_.faces_of_.remove(f, m.faces[f]);
    s_.alive_[f] = 0;  // stays in the mesh, dead, so later faces keep their index
  }
  if (e.moved != kNoVertex) m.vertices[e.moved] = step.old_position;
  for (std::size_t k = 0; k < e.faces.size(); ++k) m.faces[e.faces[k]] = step.before[k];
  for (std::uint32_t f : e.faces) {
    s_.alive_[f] = 1;
    if (s_.grid_) s_.grid_->insert(f);
    s_.faces_of_.add(f, m.faces[f]);
  }
  return std::move(step.edit);
}

}  // namespace molsurf
