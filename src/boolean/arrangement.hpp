#pragma once
// The intersection points and constraint segments of all intersecting face pairs,
// gathered per edge and per face: the input of the split step. Point ids below the
// combined vertex count are the input vertices (coincident vertices of a and b share the
// id of a's vertex); intersection points follow in a deterministic order.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "boolean/intersect.hpp"
#include "boolean/sparse_lists.hpp"
#include "geometry/implicit_point.hpp"

namespace molsurf::boolean_engine {

struct Arrangement {
  std::vector<geometry::ImplicitPoint> points;
  std::vector<std::uint32_t> vertex_point;      // combined vertex -> point id
  std::vector<std::uint8_t> on_both_surfaces;   // per point: found on a face of each operand
  // Per point: on both surfaces and not a transversal edge-face crossing (an input vertex
  // on the other surface, or two edges crossing). Only there can the solids touch without
  // crossing: around a transversal crossing the result is always one sheet.
  std::vector<std::uint8_t> may_touch;
  SparseLists<std::uint32_t> edge_points;  // per combined edge: points strictly inside it
  SparseLists<std::uint32_t> face_points;  // per combined face: points strictly inside it
  SparseLists<std::pair<std::uint32_t, std::uint32_t>> face_segments;  // constraints
  // For constraints from non-coplanar pairs: (segment, the other operand's face whose
  // plane holds it), sorted. Segments of one face on one such plane are collinear.
  SparseLists<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>> segment_planes;
  // The constraints of each face that come from transversal crossings (a subset).
  SparseLists<std::pair<std::uint32_t, std::uint32_t>> transversal_segments;
  struct Partner {
    std::uint32_t face;
    bool same_orientation;
  };
  SparseLists<Partner> coplanar_partners;  // per face: coplanar faces of the other operand
  std::size_t intersection_point_count = 0;

  // A face needs re-triangulation when any point or segment lies on it or its edges.
  bool face_is_cut(const Operands& ops, std::uint32_t f) const;
};

Arrangement build_arrangement(const Operands& operands, std::span<const PairIntersection> pairs);

}  // namespace molsurf::boolean_engine
