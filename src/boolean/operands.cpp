#include "boolean/operands.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace molsurf::boolean_engine {

Operands::Operands(const Mesh& a, const Mesh& b, const Mesh& solid_a, const Mesh& solid_b, bool allow_open)
    : Operands(a, b, solid_a, solid_b, {bounding_box(solid_a), bounding_box(solid_b)}, allow_open) {}

Operands::Operands(const Mesh& a, const Mesh& b, const Mesh& solid_a, const Mesh& solid_b,
                   const std::array<BoundingBox, 2>& solid_boxes, bool allow_open)
    : a_(a),
      b_(b),
      solid_a_(solid_a),
      solid_b_(solid_b),
      solid_box_(solid_boxes),
      vertex_offset_b_(static_cast<std::uint32_t>(a.vertices.size())),
      face_offset_b_(static_cast<std::uint32_t>(a.faces.size())) {
  faces_.reserve(a.faces.size() + b.faces.size());
  for (const Triangle& t : a.faces) faces_.push_back({t[0], t[1], t[2]});
  for (const Triangle& t : b.faces)
    faces_.push_back({t[0] + vertex_offset_b_, t[1] + vertex_offset_b_, t[2] + vertex_offset_b_});
  build_edges(allow_open || &a != &solid_a || &b != &solid_b);
}

// Edges in order of (lower vertex, higher vertex), found in linear time: half-edges are
// bucketed by their lower vertex (a counting sort), and a bucket holds only the few edges
// around one vertex.
void Operands::build_edges(bool allow_open) {
  const std::uint32_t vertices = vertex_count();
  const auto half_edge_count = static_cast<std::uint32_t>(3 * faces_.size());
  auto ends = [&](std::uint32_t h) {
    const auto& t = faces_[h / 3];
    return std::minmax(t[h % 3], t[(h % 3 + 1) % 3]);
  };
  std::vector<std::uint32_t> start(vertices + 1, 0), higher_end(half_edge_count);
  for (std::uint32_t h = 0; h < half_edge_count; ++h) {
    const auto [lo, hi] = ends(h);
    ++start[lo + 1];
    higher_end[h] = hi;
  }
  for (std::uint32_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> by_lower(half_edge_count);
  {
    std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
    for (std::uint32_t h = 0; h < half_edge_count; ++h) by_lower[cursor[ends(h).first]++] = h;
  }
  face_edges_.resize(faces_.size());
  edge_vertices_.reserve(half_edge_count / 2 + 1);
  edge_faces_.reserve(half_edge_count / 2 + 1);
  for (std::uint32_t v = 0; v < vertices; ++v) {
    const auto first = by_lower.begin() + start[v], last = by_lower.begin() + start[v + 1];
    // Half-edge ids grow with the face, so (higher vertex, id) is the order of the old sort.
    std::sort(first, last, [&](std::uint32_t x, std::uint32_t y) {
      return higher_end[x] != higher_end[y] ? higher_end[x] < higher_end[y] : x < y;
    });
    for (auto k = first; k != last;) {
      const std::uint32_t higher = higher_end[*k];
      auto end = k;
      while (end != last && higher_end[*end] == higher) ++end;
      const auto count = end - k;
      if (count > 2 || (count == 1 && !allow_open))
        throw std::invalid_argument("boolean: an operand is not a closed 2-manifold (an edge has " +
                                    std::to_string(count) + " faces)");
      const auto e = static_cast<std::uint32_t>(edge_vertices_.size());
      edge_vertices_.push_back({v, higher});
      edge_faces_.push_back({*k / 3, count == 2 ? *(k + 1) / 3 : kNoFace});
      for (auto j = k; j != end; ++j) face_edges_[*j / 3][*j % 3] = e;
      if (count == 1) {
        if (frozen_.empty()) frozen_.assign(vertices, 0);
        frozen_count_ += !frozen_[v] + !frozen_[higher];
        frozen_[v] = frozen_[higher] = 1;
      }
      k = end;
    }
  }
}

}  // namespace molsurf::boolean_engine
