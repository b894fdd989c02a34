#include "boolean/stitch.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace molsurf::boolean_engine {

Keep select_sub_face(BooleanOp op, int operand, Side side) {
  // Regularised operations. A coincident piece keeps a's copy when the result has a
  // surface there, and both copies go when the solids meet face to face (the surface
  // vanishes inside the union, or there is no volume left between them).
  switch (op) {
    case BooleanOp::union_:
      if (side == Side::outside) return Keep::keep;
      if (side == Side::coincident_same && operand == 0) return Keep::keep;
      return Keep::drop;
    case BooleanOp::intersection:
      if (side == Side::inside) return Keep::keep;
      if (side == Side::coincident_same && operand == 0) return Keep::keep;
      return Keep::drop;
    case BooleanOp::difference:
      if (operand == 0) {
        if (side == Side::outside || side == Side::coincident_opposite) return Keep::keep;
        return Keep::drop;
      }
      return side == Side::inside ? Keep::keep_flipped : Keep::drop;
  }
  return Keep::drop;
}

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

Vec3 rounded_point(const geometry::ImplicitPoint& p) {
  if (p.is_explicit()) return p.explicit_value();
  // The filter's interval is usually a few ulps wide: its midpoint is as good a rounding
  // as any; only wide intervals pay for the exact rational.
  Vec3 mid{p.coordinate(0).mid(), p.coordinate(1).mid(), p.coordinate(2).mid()};
  for (int axis = 0; axis < 3; ++axis) {
    const auto& i = p.coordinate(axis);
    if (!(i.hi - i.lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(i.lo), std::fabs(i.hi))))
      return p.rounded();
  }
  return mid;
}

// Duplicates every vertex whose faces form more than one fan. Faces are joined across an
// edge with exactly two faces, or, where both solids pass along an edge (two faces of
// each operand), across the edge within each operand.
std::size_t split_touching_vertices(StitchResult& r) {
  Mesh& m = r.mesh;
  const auto face_count = static_cast<std::uint32_t>(m.faces.size());
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> faces_of_edge;
  for (std::uint32_t f = 0; f < face_count; ++f)
    for (int i = 0; i < 3; ++i) faces_of_edge[edge_key(m.faces[f][i], m.faces[f][(i + 1) % 3])].push_back(f);
  // Corner slots: 3 per face; join slots of the same vertex across connecting edges.
  std::vector<std::uint32_t> parent(3 * face_count);
  std::iota(parent.begin(), parent.end(), 0u);
  auto slot = [&](std::uint32_t f, std::uint32_t v) {
    for (std::uint32_t i = 0; i < 3; ++i)
      if (m.faces[f][i] == v) return 3 * f + i;
    return 3 * f;
  };
  auto join = [&](std::uint32_t f, std::uint32_t g, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t v : {a, b}) {
      const std::uint32_t x = find_root(parent, slot(f, v)), y = find_root(parent, slot(g, v));
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  };
  for (const auto& [key, faces] : faces_of_edge) {
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
    if (faces.size() == 2) {
      join(faces[0], faces[1], a, b);
    } else if (faces.size() == 4) {
      std::vector<std::uint32_t> by_operand[2];
      for (std::uint32_t f : faces) by_operand[r.face_operand[f]].push_back(f);
      if (by_operand[0].size() == 2 && by_operand[1].size() == 2)
        for (const auto& pair : by_operand) join(pair[0], pair[1], a, b);
    }
  }
  // The first fan (lowest slot) of each vertex keeps it; every other fan gets a copy.
  std::unordered_map<std::uint32_t, std::uint32_t> first_fan_of_vertex;
  std::unordered_map<std::uint32_t, std::uint32_t> copy_of_fan;
  std::size_t copies = 0;
  for (std::uint32_t s = 0; s < 3 * face_count; ++s) {
    const std::uint32_t v = m.faces[s / 3][s % 3];
    const std::uint32_t fan = find_root(parent, s);
    auto [it, first] = first_fan_of_vertex.try_emplace(v, fan);
    if (first || it->second == fan) continue;
    auto [copy, is_new] = copy_of_fan.try_emplace(fan, static_cast<std::uint32_t>(m.vertices.size()));
    if (is_new) {
      m.vertices.push_back(m.vertices[v]);
      ++copies;
    }
    m.faces[s / 3][s % 3] = copy->second;
  }
  return copies;
}

}  // namespace

StitchResult stitch_sub_faces(const Operands& ops, const Arrangement& arr, const std::vector<SubFace>& subs,
                              const std::vector<Side>& sides, BooleanOp op) {
  StitchResult r;
  std::vector<std::uint32_t> vertex_of_point(arr.points.size(), ~0u);
  auto vertex = [&](std::uint32_t p) {
    if (vertex_of_point[p] == ~0u) {
      vertex_of_point[p] = static_cast<std::uint32_t>(r.mesh.vertices.size());
      r.mesh.vertices.push_back(rounded_point(arr.points[p]));
    }
    return vertex_of_point[p];
  };
  const bool tagged = ops.mesh(0).has_tags() || ops.mesh(1).has_tags();
  for (std::size_t s = 0; s < subs.size(); ++s) {
    const int operand = ops.operand_of_face(subs[s].face);
    const Keep keep = select_sub_face(op, operand, sides[s]);
    if (keep == Keep::drop) continue;
    Triangle t{vertex(subs[s].points[0]), vertex(subs[s].points[1]), vertex(subs[s].points[2])};
    if (keep == Keep::keep_flipped) std::swap(t[1], t[2]);
    r.mesh.faces.push_back(t);
    const std::uint32_t source = ops.local_face(subs[s].face);
    r.face_operand.push_back(static_cast<std::uint8_t>(operand));
    r.face_source.push_back(source);
    if (tagged) r.mesh.face_tags.push_back(ops.mesh(operand).tag(source));
  }
  r.split_vertices = split_touching_vertices(r);
  return r;
}

}  // namespace molsurf::boolean_engine
