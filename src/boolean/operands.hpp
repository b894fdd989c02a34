#pragma once
// The two operands seen as one combined mesh: vertices of a then b, faces of a then b,
// and the edge table (each undirected edge once, with its two faces). Indices into this
// combined numbering are what intersection points are keyed by.
//
// The operands may be parts of two larger closed solids (the faces that can meet the
// other solid, see active_part.hpp): then an edge may have one face only. Such an open
// edge borders faces that lie outside the other solid's box; its vertices are "frozen":
// the rest of the solid is joined there, so the result must keep them as they are.
#include <array>
#include <cstdint>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf::boolean_engine {

inline constexpr std::uint32_t kNoFace = ~std::uint32_t{0};

class Operands {
 public:
  // Parts of the closed solids `solid_a` and `solid_b` (open edges allowed). With
  // `allow_open`, the operands may also be open surfaces themselves (the outer envelope,
  // outer_envelope.hpp): an edge with one face is then a free boundary.
  Operands(const Mesh& a, const Mesh& b, const Mesh& solid_a, const Mesh& solid_b, bool allow_open = false);
  // The same, with the solids' bounding boxes already known (each costs a pass over a solid).
  Operands(const Mesh& a, const Mesh& b, const Mesh& solid_a, const Mesh& solid_b,
           const std::array<BoundingBox, 2>& solid_boxes, bool allow_open = false);

  const Mesh& mesh(int operand) const { return operand == 0 ? a_ : b_; }
  // The whole closed solid an operand is part of (for point-in-solid tests) and its box.
  const Mesh& solid(int operand) const { return operand == 0 ? solid_a_ : solid_b_; }
  const BoundingBox& solid_box(int operand) const { return solid_box_[operand]; }
  std::uint32_t vertex_count() const { return vertex_offset_b_ + static_cast<std::uint32_t>(b_.vertices.size()); }
  std::uint32_t face_count() const { return face_offset_b_ + static_cast<std::uint32_t>(b_.faces.size()); }
  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edge_vertices_.size()); }
  std::uint32_t face_offset_b() const { return face_offset_b_; }

  int operand_of_face(std::uint32_t f) const { return f < face_offset_b_ ? 0 : 1; }
  int operand_of_vertex(std::uint32_t v) const { return v < vertex_offset_b_ ? 0 : 1; }
  std::uint32_t local_face(std::uint32_t f) const { return f < face_offset_b_ ? f : f - face_offset_b_; }

  const Vec3& vertex(std::uint32_t v) const {
    return v < vertex_offset_b_ ? a_.vertices[v] : b_.vertices[v - vertex_offset_b_];
  }
  // Combined vertex indices of a combined face, in the face's order.
  const std::array<std::uint32_t, 3>& face(std::uint32_t f) const { return faces_[f]; }
  // face_edges(f)[i] is the edge from corner i to corner i + 1.
  const std::array<std::uint32_t, 3>& face_edges(std::uint32_t f) const { return face_edges_[f]; }
  const std::array<std::uint32_t, 2>& edge_vertices(std::uint32_t e) const { return edge_vertices_[e]; }
  // The two faces of an edge; the second is kNoFace on an open edge.
  const std::array<std::uint32_t, 2>& edge_faces(std::uint32_t e) const { return edge_faces_[e]; }
  // A vertex on an open edge (never moved or merged by the Boolean).
  bool frozen(std::uint32_t v) const { return !frozen_.empty() && frozen_[v]; }
  std::size_t frozen_count() const { return frozen_count_; }

 private:
  void build_edges(bool allow_open);

  const Mesh& a_;
  const Mesh& b_;
  const Mesh& solid_a_;
  const Mesh& solid_b_;
  std::array<BoundingBox, 2> solid_box_;
  std::uint32_t vertex_offset_b_, face_offset_b_;
  std::vector<std::array<std::uint32_t, 3>> faces_, face_edges_;
  std::vector<std::array<std::uint32_t, 2>> edge_vertices_, edge_faces_;  // vertices sorted
  std::vector<std::uint8_t> frozen_;
  std::size_t frozen_count_ = 0;
};

}  // namespace molsurf::boolean_engine
