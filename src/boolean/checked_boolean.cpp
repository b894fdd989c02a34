// The Boolean of two meshes as the front ends run it: operands held to the engine's
// contract, the result checked, and b moved apart where no rounding of the exact result is
// a valid surface (boolean.hpp: checked_boolean, valid_boolean).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "molsurf/boolean.hpp"
#include "molsurf/error.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf {

namespace {

// An operand the outer envelope accepts besides a valid one: open, but otherwise sound
// (2-manifold, oriented, no degenerate face, no self-intersection).
bool open_but_sound(const MeshCheck& c) {
  return c.nonmanifold_edges == 0 && c.nonmanifold_vertices == 0 && c.misoriented_edges == 0 &&
         c.degenerate_faces == 0 && c.duplicate_faces == 0 && c.intersecting_pairs == 0;
}

std::string joined(const std::vector<std::string>& defects) {
  std::string text;
  for (const std::string& defect : defects) text += (text.empty() ? "" : "; ") + defect;
  return text;
}

// Fixed directions, unit length in exact decimals and parallel to no axis or coordinate
// plane, so no mirror plane or lattice of an input is aligned with them.
constexpr std::array<Vec3, 3> kDirections{Vec3{0.48, 0.60, 0.64}, Vec3{-0.64, 0.48, -0.60}, Vec3{0.60, -0.64, 0.48}};
// Steps as powers of two of the coordinates' scale: 2^-36 is about 1.5e-11 at 100 Å,
// 2^17 times the rounding error (2^-53), so sheets that far apart stay apart as written;
// the larger steps are for inputs whose own faces are near that scale.
constexpr std::array<int, 3> kStepExponents{-36, -28, -20};

// The power of two just above every coordinate's magnitude (and above 1 Å).
double coordinate_scale(const Mesh& a, const Mesh& b) {
  double largest = 1;
  for (const Mesh* m : {&a, &b})
    for (const Vec3& v : m->vertices) largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  int exponent = 0;
  std::frexp(largest, &exponent);
  return std::ldexp(1.0, exponent);
}

Vec3 first_defect_place(const Mesh& mesh, const MeshCheck& check) {
  for (const auto* examples : {&check.examples_intersecting, &check.examples_contact, &check.examples_degenerate,
                               &check.examples_nonmanifold_edge, &check.examples_boundary})
    if (!examples->empty() && examples->front() < mesh.faces.size()) {
      const Triangle& t = mesh.faces[examples->front()];
      return (1.0 / 3) * (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]);
    }
  return {};
}

}  // namespace

CheckedBoolean valid_boolean(const Mesh& a, const Mesh& b, BooleanOp op, const MeshCheckOptions& options) {
  CheckedBoolean out;
  out.result = boolean(a, b, op);
  out.check = check_mesh(out.result.mesh, options);
  if (out.check.valid()) return out;

  // The exact result has no valid rounding: its sheets touch, or lie closer than rounding
  // keeps apart. Moving b by far more than rounding and far less than any feature of a
  // molecular or engineering mesh gives a nearby configuration whose result rounds well.
  const Vec3 defect_near = first_defect_place(out.result.mesh, out.check);
  BooleanTimings seconds = out.result.stats.seconds;
  const double scale = coordinate_scale(a, b);
  for (const int exponent : kStepExponents)
    for (const Vec3& direction : kDirections) {
      const Vec3 shift = std::ldexp(scale, exponent) * direction;
      Mesh moved = b;
      for (Vec3& v : moved.vertices) v = v + shift;
      // Moving rounds b's coordinates once more; a face of b that this turns over is no
      // operand (rare: b's own slivers), so that step is skipped.
      if (!check_mesh(moved, options).valid()) continue;
      BooleanResult retry = boolean(a, moved, op);
      seconds += retry.stats.seconds;
      MeshCheck retry_check = check_mesh(retry.mesh, options);
      if (!retry_check.valid()) continue;
      retry.stats.seconds = seconds;
      retry.stats.b_moved_by = shift;
      retry.stats.unmoved_defect_near = defect_near;
      out.result = std::move(retry);
      out.check = std::move(retry_check);
      return out;
    }
  out.result.stats.seconds = seconds;
  out.result.stats.unmoved_defect_near = defect_near;
  return out;
}

std::string boolean_note(const BooleanStats& stats) {
  const Vec3& m = stats.b_moved_by;
  if (m.x == 0 && m.y == 0 && m.z == 0) return {};
  const Vec3& p = stats.unmoved_defect_near;
  char text[400];
  std::snprintf(text, sizeof text,
                "near (%.6g, %.6g, %.6g) A and B touch, or their sheets lie closer than rounding to doubles keeps "
                "apart (no rounding of the exact result is a valid surface there); the result is that of B moved by "
                "(%.3g, %.3g, %.3g) Å",
                p.x, p.y, p.z, m.x, m.y, m.z);
  return text;
}

bool CheckedBoolean::acceptable(const MeshCheck& c) const {
  // From an open operand the envelope is open: its free boundary and the edges where a
  // sheet seen from both sides meets the rest are expected there, nothing else.
  return c.valid() || (open_input && c.misoriented_edges == 0 && c.degenerate_faces == 0 &&
                       c.duplicate_faces == 0 && c.intersecting_pairs == 0);
}

std::string CheckedBoolean::problem(const MeshCheck& c) const {
  if (acceptable(c)) return {};
  std::string why = joined(c.defects());
  if (!open_input) {
    // valid_boolean moved B in every step it has and no result passed.
    const Vec3& p = result.stats.unmoved_defect_near;
    char where[240];
    std::snprintf(where, sizeof where,
                  " (near (%.6g, %.6g, %.6g) A and B touch, or their sheets lie closer than rounding to doubles "
                  "keeps apart, and moving B by up to 2^-20 of the coordinates' scale did not resolve it: move "
                  "one apart, or into the other)",
                  p.x, p.y, p.z);
    why += where;
  }
  return "the result failed its check: " + why;
}

CheckedBoolean checked_boolean(const Mesh& a, const Mesh& b, BooleanOp op, std::string_view name_a,
                               std::string_view name_b, bool outer_envelope) {
  if (outer_envelope && op != BooleanOp::union_)
    throw ParameterError("outer_only", std::string("keeps the outer envelope of a union; it does not apply to ") +
                                           boolean_op_name(op));
  bool open_input = false;
  // The engine's contract: refuse operands it cannot promise a valid result for.
  for (const auto& [mesh, name] : {std::pair{&a, name_a}, std::pair{&b, name_b}}) {
    const MeshCheck c = check_mesh(*mesh);
    if (c.valid() && !c.empty()) continue;
    if (outer_envelope && !c.empty() && open_but_sound(c)) {
      open_input = true;
      continue;
    }
    throw Error(std::string(name) +
                (outer_envelope ? ": not a valid surface (closed or open), so no outer envelope is defined: "
                                : ": not a valid closed surface, so no Boolean is defined: ") +
                (c.empty() ? std::string("no faces") : joined(c.defects())));
  }
  CheckedBoolean out;
  if (outer_envelope) {
    out.result = union_outer_envelope(a, b);
    out.check = check_mesh(out.result.mesh);
  } else {
    out = valid_boolean(a, b, op);
  }
  out.open_input = open_input;
  return out;
}

}  // namespace molsurf
