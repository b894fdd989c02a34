// The Boolean with its result checked, and moved apart where no rounding of the exact
// result is a valid surface.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "molsurf/boolean.hpp"

namespace molsurf {

namespace {

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

void sum_seconds_into(BooleanTimings& total, const BooleanTimings& more) {
  total.cull += more.cull;
  total.intersect += more.intersect;
  total.split += more.split;
  total.classify += more.classify;
  total.stitch += more.stitch;
}

}  // namespace

BooleanResult checked_boolean(const Mesh& a, const Mesh& b, BooleanOp op, const MeshCheckOptions& options) {
  BooleanResult result = boolean(a, b, op);
  result.check = check_mesh(result.mesh, options);
  if (result.check.valid()) return result;

  // The exact result has no valid rounding: its sheets touch, or lie closer than rounding
  // keeps apart. Moving b by far more than rounding and far less than any feature of a
  // molecular or engineering mesh gives a nearby configuration whose result rounds well.
  const Vec3 defect_near = first_defect_place(result.mesh, result.check);
  BooleanTimings seconds = result.stats.seconds;
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
      sum_seconds_into(seconds, retry.stats.seconds);
      retry.check = check_mesh(retry.mesh, options);
      if (!retry.check.valid()) continue;
      retry.stats.seconds = seconds;
      retry.stats.b_moved_by = shift;
      retry.stats.unmoved_defect_near = defect_near;
      return retry;
    }
  result.stats.seconds = seconds;
  result.stats.unmoved_defect_near = defect_near;
  return result;
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

}  // namespace molsurf
