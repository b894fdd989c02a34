#pragma once
// Small topology tools shared by the engine and the surface improvement.
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <numeric>
#include <span>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

// One key per undirected edge (the two vertex indices, lower first).
inline std::uint64_t undirected_edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

// Union-find with path halving; the root of a set is its smallest element, so numbering
// by roots is deterministic.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

// The vertices joined to x by the faces around it (sorted, unique).
inline std::vector<Index> vertex_neighbours(const Mesh& m, std::span<const std::uint32_t> faces_around, Index x) {
  std::vector<Index> n;
  for (std::uint32_t f : faces_around)
    for (Index w : m.faces[f])
      if (w != x) n.push_back(w);
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

// The faces on edge ab among `faces_of_a` (the faces around a), in their order; a face
// once per such edge it has (a face with a repeated corner, listed twice around a, can
// have two).
inline std::vector<std::uint32_t> faces_on_edge(const Mesh& m, std::span<const std::uint32_t> faces_of_a, Index a,
                                                Index b) {
  std::vector<std::uint32_t> on;
  for (std::size_t k = 0; k < faces_of_a.size(); ++k) {
    const std::uint32_t g = faces_of_a[k];
    if (std::find(faces_of_a.begin(), faces_of_a.begin() + static_cast<std::ptrdiff_t>(k), g) !=
        faces_of_a.begin() + static_cast<std::ptrdiff_t>(k))
      continue;  // listed again for a repeated corner
    const Triangle& t = m.faces[g];
    for (int i = 0; i < 3; ++i)
      if ((t[i] == a && t[(i + 1) % 3] == b) || (t[i] == b && t[(i + 1) % 3] == a)) on.push_back(g);
  }
  return on;
}

// The common neighbours of a and b beyond the faces on edge ab (sorted): what makes the
// edge's collapse fail the link condition. Empty unless the edge has two faces (no
// collapse is possible then anyway).
inline std::vector<Index> blocking_vertices(const Mesh& m, std::span<const std::uint32_t> faces_of_a,
                                            std::span<const std::uint32_t> faces_of_b, Index a, Index b) {
  const std::vector<std::uint32_t> on_edge = faces_on_edge(m, faces_of_a, a, b);
  if (on_edge.size() != 2) return {};
  std::vector<Index> opposite;
  for (std::uint32_t g : on_edge)
    for (Index w : m.faces[g])
      if (w != a && w != b) opposite.push_back(w);
  const std::vector<Index> around_a = vertex_neighbours(m, faces_of_a, a);
  const std::vector<Index> around_b = vertex_neighbours(m, faces_of_b, b);
  std::vector<Index> blocking;
  for (Index w : around_a)
    if (w != b && std::binary_search(around_b.begin(), around_b.end(), w) &&
        std::find(opposite.begin(), opposite.end(), w) == opposite.end())
      blocking.push_back(w);
  return blocking;
}

// The link condition for collapsing edge uv: the vertices joined to both u and v are
// exactly the opposite corners of the faces on the edge, so the collapse keeps a
// 2-manifold.
inline bool link_condition(const Mesh& m, std::span<const std::uint32_t> faces_of_u,
                           std::span<const std::uint32_t> faces_of_v, std::span<const std::uint32_t> on_edge, Index u,
                           Index v) {
  std::vector<Index> opposite;
  for (std::uint32_t g : on_edge)
    for (Index w : m.faces[g])
      if (w != u && w != v) opposite.push_back(w);
  std::sort(opposite.begin(), opposite.end());
  const std::vector<Index> nu = vertex_neighbours(m, faces_of_u, u), nv = vertex_neighbours(m, faces_of_v, v);
  std::vector<Index> common;
  std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(common));
  return common == opposite;
}

// Keeps the faces f with alive[f], in order, with their tags and the given per-face
// arrays (each as long as the face list).
template <class... PerFace>
void keep_alive_faces(Mesh& m, const std::vector<std::uint8_t>& alive, PerFace&... per_face) {
  const bool tagged = m.has_tags();
  std::size_t out = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!alive[f]) continue;
    m.faces[out] = m.faces[f];
    if (tagged) m.face_tags[out] = m.face_tags[f];
    ((per_face[out] = per_face[f]), ...);
    ++out;
  }
  m.faces.resize(out);
  if (tagged) m.face_tags.resize(out);
  (per_face.resize(out), ...);
}

// The faces f with keep(f), in order, with their tags, on vertices of their own in order of
// first use. Sized exactly: the blocks keep such meshes side by side.
template <class Keep>
Mesh faces_where(const Mesh& m, Keep&& keep) {
  Mesh out;
  std::size_t count = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) count += keep(f) ? 1 : 0;
  const bool tagged = m.has_tags();
  out.faces.reserve(count);
  if (tagged) out.face_tags.reserve(count);
  std::vector<Index> vertex_of(m.vertices.size(), ~Index{0});
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!keep(f)) continue;
    Triangle t = m.faces[f];
    for (Index& v : t) {
      if (vertex_of[v] == ~Index{0}) {
        vertex_of[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(m.vertices[v]);
      }
      v = vertex_of[v];
    }
    out.faces.push_back(t);
    if (tagged) out.face_tags.push_back(m.face_tags[f]);
  }
  out.vertices.shrink_to_fit();
  return out;
}

// Renumbers the vertices in order of first use by the faces; unused ones go.
inline void drop_unused_vertices(Mesh& m) {
  std::vector<Index> renumber(m.vertices.size(), ~Index{0});
  std::vector<Vec3> used;
  used.reserve(m.vertices.size());
  for (Triangle& t : m.faces)
    for (Index& v : t) {
      if (renumber[v] == ~Index{0}) {
        renumber[v] = static_cast<Index>(used.size());
        used.push_back(m.vertices[v]);
      }
      v = renumber[v];
    }
  m.vertices = std::move(used);
}

}  // namespace molsurf
