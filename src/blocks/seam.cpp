#include "blocks/seam.hpp"

#include <algorithm>
#include <map>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace molsurf::blocks {

namespace {

struct CoordinateKey {
  std::array<std::uint64_t, 3> bits;
  bool operator==(const CoordinateKey&) const = default;
};

struct CoordinateHash {
  std::size_t operator()(const CoordinateKey& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t b : k.bits) h = (h ^ b) * 0xff51afd7ed558ccdull, h ^= h >> 33;
    return static_cast<std::size_t>(h);
  }
};

CoordinateKey key_of(const Vec3& p) {
  // + 0.0 makes -0 and +0 one key: equal doubles, one point.
  return {std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
          std::bit_cast<std::uint64_t>(p.z + 0.0)};
}

struct DefinitionHash {
  std::size_t operator()(const surface_detail::PointDefinition& d) const { return static_cast<std::size_t>(d.hash()); }
};

// As the join's window (one_pass/join.cpp): a written coordinate lies within about 2 ulps
// of the exact one, so points equal by exact value lie within this reach of each other.
double rounding_reach(double c) {
  return 8 * std::numeric_limits<double>::epsilon() * std::fabs(c) + 8 * std::numeric_limits<double>::denorm_min();
}

bool windows_overlap(const Vec3& a, const Vec3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    const double x = a[axis], y = b[axis];
    if (x + rounding_reach(x) < y - rounding_reach(y) || y + rounding_reach(y) < x - rounding_reach(x)) return false;
  }
  return true;
}

// A seam vertex of one piece, with its point.
struct SeamEntry {
  std::uint32_t piece, vertex;
  const SeamPoint* point;
};

std::uint32_t root_of(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
  a = root_of(parent, a);
  b = root_of(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

}  // namespace

std::vector<std::array<Index, 2>> seam_edges(const Mesh& mesh) {
  std::vector<std::array<Index, 2>> edges;
  edges.reserve(3 * mesh.faces.size());
  for (const Triangle& t : mesh.faces)
    for (int k = 0; k < 3; ++k) edges.push_back({t[k], t[(k + 1) % 3]});
  std::sort(edges.begin(), edges.end());
  std::vector<std::array<Index, 2>> open;
  for (const auto& e : edges)
    if (!std::binary_search(edges.begin(), edges.end(), std::array<Index, 2>{e[1], e[0]})) open.push_back(e);
  return open;
}

std::vector<std::uint8_t> seam_vertices(const Mesh& mesh) {
  std::vector<std::uint8_t> on_seam(mesh.vertices.size(), 0);
  for (const auto& e : seam_edges(mesh)) on_seam[e[0]] = on_seam[e[1]] = 1;
  return on_seam;
}

std::vector<SeamPoint> seam_points(const Mesh& mesh, std::span<const surface_detail::one_pass::VertexOrigin> origins,
                                   std::span<const std::uint32_t> global_index) {
  if (origins.size() != mesh.vertices.size()) throw std::invalid_argument("seam_points: one origin per vertex");
  const std::vector<std::uint8_t> on_seam = seam_vertices(mesh);
  std::vector<SeamPoint> points;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!on_seam[v]) continue;
    SeamPoint p;
    p.position = mesh.vertices[v];
    p.definition = origins[v].definition;
    // The definition's atoms, renumbered: explicit (atom, vertex), line-plane (atom, v0,
    // v1, atom, face), three planes ((atom, face) x 3). The renumbering keeps the order,
    // so a three-plane definition stays sorted.
    auto& id = p.definition.id;
    using Kind = surface_detail::PointDefinition::Kind;
    switch (p.definition.kind) {
      case Kind::explicit_point: id[0] = global_index[id[0]]; break;
      case Kind::line_plane:
        id[0] = global_index[id[0]];
        id[3] = global_index[id[3]];
        break;
      case Kind::three_planes:
        id[0] = global_index[id[0]];
        id[2] = global_index[id[2]];
        id[4] = global_index[id[4]];
        break;
    }
    p.atom = global_index[origins[v].atom];
    p.position_in_atom = origins[v].position;
    points.push_back(p);
  }
  return points;
}

Mesh glue_pieces(std::span<const Mesh> pieces, std::span<const std::vector<SeamPoint>> seams,
                 const SamePoint& same_point, std::vector<std::uint8_t>* glued_seam) {
  if (seams.size() != pieces.size()) throw std::invalid_argument("glue_pieces: one seam per piece");
  // Every piece's seam vertices with their points.
  std::vector<SeamEntry> entries;
  std::vector<std::vector<std::uint8_t>> on_seam(pieces.size());
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    std::unordered_map<CoordinateKey, const SeamPoint*, CoordinateHash> by_position;
    for (const SeamPoint& p : seams[k]) by_position.emplace(key_of(p.position), &p);
    // A piece's seam vertices are where its seam points are: a whole piece's open edges,
    // or of a seam band (streamed_piece.hpp) the edges on the seam but not those along
    // the band's far side, where the band meets the faces already written.
    on_seam[k].assign(pieces[k].vertices.size(), 0);
    std::size_t found = 0;
    for (std::uint32_t v = 0; v < pieces[k].vertices.size(); ++v) {
      const auto it = by_position.find(key_of(pieces[k].vertices[v]));
      if (it == by_position.end()) continue;
      on_seam[k][v] = 1;
      ++found;
      entries.push_back({k, v, it->second});
    }
    if (found != seams[k].size()) throw std::logic_error("glue_pieces: a seam point that is no vertex of its piece");
  }
  // Classes of equal points: one definition, then equal exact values.
  std::vector<std::uint32_t> parent(entries.size());
  std::iota(parent.begin(), parent.end(), 0u);
  {
    std::unordered_map<surface_detail::PointDefinition, std::uint32_t, DefinitionHash> first;
    for (std::uint32_t e = 0; e < entries.size(); ++e) {
      const auto [it, inserted] = first.try_emplace(entries[e].point->definition, e);
      if (!inserted) unite(parent, it->second, e);
    }
  }
  std::vector<std::pair<double, std::uint32_t>> order(entries.size());
  for (std::uint32_t e = 0; e < entries.size(); ++e) {
    const double x = entries[e].point->position.x;
    order[e] = {x - rounding_reach(x), e};
  }
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const SeamEntry& a = entries[order[i].second];
    const double end = a.point->position.x + rounding_reach(a.point->position.x);
    for (std::size_t j = i + 1; j < order.size() && order[j].first <= end; ++j) {
      const SeamEntry& b = entries[order[j].second];
      if (a.piece == b.piece || root_of(parent, order[i].second) == root_of(parent, order[j].second) ||
          !windows_overlap(a.point->position, b.point->position) ||
          !same_point(a.point->definition, b.point->definition))
        continue;
      unite(parent, order[i].second, order[j].second);
    }
  }
  // Each class's coordinates: its first point in atom order, as the whole join takes them.
  std::vector<std::uint32_t> first_of(entries.size());
  std::iota(first_of.begin(), first_of.end(), 0u);
  for (std::uint32_t e = 0; e < entries.size(); ++e) {
    const std::uint32_t r = root_of(parent, e);
    const SeamPoint &x = *entries[e].point, &y = *entries[first_of[r]].point;
    if (std::tie(x.atom, x.position_in_atom) < std::tie(y.atom, y.position_in_atom)) first_of[r] = e;
  }

  Mesh glued;
  bool tagged = !pieces.empty();
  for (const Mesh& piece : pieces) tagged = tagged && piece.face_tags.size() == piece.faces.size();
  std::vector<Index> class_vertex(entries.size(), ~Index{0});
  for (std::uint32_t k = 0, e = 0; k < pieces.size(); ++k) {
    const Mesh& piece = pieces[k];
    std::vector<Index> vertex_of(piece.vertices.size());
    for (std::uint32_t v = 0; v < piece.vertices.size(); ++v) {
      const auto next = static_cast<Index>(glued.vertices.size());
      if (on_seam[k][v]) {
        const std::uint32_t r = root_of(parent, e++);
        if (class_vertex[r] == ~Index{0}) {
          class_vertex[r] = next;
          glued.vertices.push_back(entries[first_of[r]].point->position);
          if (glued_seam) glued_seam->resize(glued.vertices.size(), 0), glued_seam->back() = 1;
        }
        vertex_of[v] = class_vertex[r];
      } else {
        vertex_of[v] = next;
        glued.vertices.push_back(piece.vertices[v]);
      }
      if (glued_seam) glued_seam->resize(glued.vertices.size(), 0);
    }
    for (std::size_t f = 0; f < piece.faces.size(); ++f) {
      const Triangle& t = piece.faces[f];
      glued.faces.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
      if (tagged) glued.face_tags.push_back(piece.face_tags[f]);
    }
  }
  return glued;
}

Mesh glue_by_position(std::span<const Mesh> pieces, std::vector<std::uint8_t>* on_seam) {
  Mesh glued;
  bool tagged = true;
  for (const Mesh& piece : pieces) tagged = tagged && piece.face_tags.size() == piece.faces.size();
  std::map<std::array<double, 3>, Index> seam_vertex;
  std::vector<std::uint8_t> glued_here;
  for (const Mesh& piece : pieces) {
    const std::vector<std::uint8_t> seam = seam_vertices(piece);
    std::vector<Index> vertex_of(piece.vertices.size());
    for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
      const Vec3& p = piece.vertices[v];
      const auto next = static_cast<Index>(glued.vertices.size());
      if (seam[v]) {
        const auto [it, inserted] = seam_vertex.try_emplace({p.x, p.y, p.z}, next);
        vertex_of[v] = it->second;
        if (!inserted) {
          glued_here[it->second] = 1;
          continue;
        }
      } else {
        vertex_of[v] = next;
      }
      glued.vertices.push_back(p);
      glued_here.push_back(0);
    }
    for (std::size_t f = 0; f < piece.faces.size(); ++f) {
      const Triangle& t = piece.faces[f];
      glued.faces.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
      if (tagged) glued.face_tags.push_back(piece.face_tags[f]);
    }
  }
  if (on_seam) *on_seam = std::move(glued_here);
  return glued;
}

std::vector<std::uint8_t> frozen_beyond(const Mesh& mesh, std::span<const std::uint8_t> near, int rings) {
  std::vector<std::uint8_t> reached(near.begin(), near.end());
  reached.resize(mesh.vertices.size(), 0);
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<std::uint8_t> next = reached;
    for (const Triangle& t : mesh.faces)
      if (reached[t[0]] || reached[t[1]] || reached[t[2]]) next[t[0]] = next[t[1]] = next[t[2]] = 1;
    reached = std::move(next);
  }
  for (auto& r : reached) r = r ? 0 : 1;
  return reached;
}

}  // namespace molsurf::blocks
