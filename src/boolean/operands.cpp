#include "boolean/operands.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace molsurf::boolean_engine {

Operands::Operands(const Mesh& a, const Mesh& b)
    : a_(a),
      b_(b),
      vertex_offset_b_(static_cast<std::uint32_t>(a.vertices.size())),
      face_offset_b_(static_cast<std::uint32_t>(a.faces.size())) {
  faces_.reserve(a.faces.size() + b.faces.size());
  for (const Triangle& t : a.faces) faces_.push_back({t[0], t[1], t[2]});
  for (const Triangle& t : b.faces)
    faces_.push_back({t[0] + vertex_offset_b_, t[1] + vertex_offset_b_, t[2] + vertex_offset_b_});

  // Sort (lower vertex, higher vertex, face, corner) records: equal vertex pairs are one edge.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint8_t>> half_edges;
  half_edges.reserve(3 * faces_.size());
  for (std::uint32_t f = 0; f < faces_.size(); ++f)
    for (std::uint8_t i = 0; i < 3; ++i) {
      const auto [lo, hi] = std::minmax(faces_[f][i], faces_[f][(i + 1) % 3]);
      half_edges.emplace_back(lo, hi, f, i);
    }
  std::sort(half_edges.begin(), half_edges.end());
  face_edges_.resize(faces_.size());
  for (std::size_t k = 0; k < half_edges.size();) {
    std::size_t end = k;
    while (end < half_edges.size() && std::get<0>(half_edges[end]) == std::get<0>(half_edges[k]) &&
           std::get<1>(half_edges[end]) == std::get<1>(half_edges[k]))
      ++end;
    if (end - k != 2)
      throw std::invalid_argument("boolean: an operand is not a closed 2-manifold (an edge has " +
                                  std::to_string(end - k) + " faces)");
    const auto e = static_cast<std::uint32_t>(edge_vertices_.size());
    edge_vertices_.push_back({std::get<0>(half_edges[k]), std::get<1>(half_edges[k])});
    edge_faces_.push_back({std::get<2>(half_edges[k]), std::get<2>(half_edges[k + 1])});
    for (std::size_t j = k; j < end; ++j) face_edges_[std::get<2>(half_edges[j])][std::get<3>(half_edges[j])] = e;
    k = end;
  }
}

}  // namespace molsurf::boolean_engine
