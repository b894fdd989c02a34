#pragma once
// The union engine: exact, robust Boolean operations on closed triangulated surfaces
// (Shostko, Löhner & Sandberg 1999, §2.2-2.4), for any meshes, not only spheres.
//
// Operands must be closed, consistently oriented (outward), 2-manifold and free of
// self-intersections (`check_mesh(m).valid()`); the result meets the same contract, so it
// can be fed back in. Every decision is exact (see docs/boolean.md for the rules on
// coplanar faces, touching solids and coincident vertices).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf {

enum class BooleanOp { union_, intersection, difference };
inline constexpr std::string_view kBooleanOpNames[] = {"union", "intersection", "difference"};  // in the enum's order

struct BooleanTimings {  // seconds per step of the paper
  double cull = 0, intersect = 0, split = 0, classify = 0, stitch = 0;
  double total() const { return cull + intersect + split + classify + stitch; }
  BooleanTimings& operator+=(const BooleanTimings& o) {
    cull += o.cull;
    intersect += o.intersect;
    split += o.split;
    classify += o.classify;
    stitch += o.stitch;
    return *this;
  }
};

struct BooleanStats {
  std::size_t faces_a = 0, faces_b = 0;
  std::size_t active_faces = 0;        // faces that overlap the other operand's box
  std::size_t whole_reruns = 0;        // 1: a rounding repair needed the whole operands
  std::size_t candidate_pairs = 0;     // face pairs whose boxes overlap
  std::size_t intersecting_pairs = 0;  // pairs that share at least one point
  std::size_t coplanar_pairs = 0;
  std::size_t intersection_points = 0;
  std::size_t split_faces = 0;         // faces re-triangulated
  std::size_t ray_casts = 0;           // patches classified by a ray (others by seeds, crossings)
  std::size_t exact_ray_casts = 0;     // of those, rays from an exact rational point
  std::size_t split_vertices = 0;      // vertices duplicated where solids only touch
  std::size_t output_faces = 0;
  // Outer envelope only (union_outer_envelope): components of pieces joined across edges,
  // those kept (not enclosed), and kept pieces seen from both sides (open sheets).
  std::size_t envelope_components = 0, envelope_components_kept = 0, two_sided_faces = 0;
  BooleanTimings seconds;
  // valid_boolean (and checked_boolean) only: how far b was moved because no rounding of the
  // exact result to doubles is a valid surface (zero: not moved), and where the unmoved
  // result failed.
  Vec3 b_moved_by{};
  Vec3 unmoved_defect_near{};
};

struct BooleanResult {
  Mesh mesh;                               // tags: the source face's tag
  std::vector<std::uint8_t> face_operand;  // 0: from a, 1: from b
  std::vector<std::uint32_t> face_source;  // index of the source face in its operand
  BooleanStats stats;
};

// The exact Boolean, rounded to doubles and repaired where rounding broke it (not checked).
BooleanResult boolean(const Mesh& a, const Mesh& b, BooleanOp op);

// The outer envelope of a and b (paper §2.4, visibility): the pieces of both surfaces
// seen from outside, found by a flood fill from the extreme piece. For two closed solids
// it is the union without its cavities (stats.seconds.classify times the flood fill).
// Either operand may be open (2-manifold with a free boundary, no self-intersection):
// then the result is open, and pieces seen from both sides (an open sheet outside the
// other surface) are kept once, as given; where such a sheet meets a closed part, an
// edge has three faces. Faces keep their operand's orientation wherever outside is the
// side their normal points to, and are flipped where only their back is seen.
BooleanResult union_outer_envelope(const Mesh& a, const Mesh& b);

const char* boolean_op_name(BooleanOp op);

// The Boolean as a front end runs it (`molsurf boolean`, Python's boolean()), every rule in
// one place:
//  - each operand must meet the engine's contract: a valid closed surface, not empty (an empty
//    mesh is no closed surface, as `molsurf check` says); with `outer_envelope` (the union's
//    outer envelope, §2.4) an open surface that is otherwise sound will do. Otherwise throws
//    molsurf::Error "NAME: not a valid closed surface, so no Boolean is defined: DEFECTS",
//    NAME being `name_a` or `name_b` (file names on the command line, a and b in Python);
//  - the operation (union_outer_envelope with `outer_envelope`, which only a union has);
//  - the result checked (`check`); problem() says what is wrong with it. An empty result
//    has no problem: it is the value of, e.g., the intersection of disjoint solids.
struct CheckedBoolean {
  BooleanResult result;
  MeshCheck check;          // of result.mesh
  bool open_input = false;  // an operand was open (outer envelope only), so the result may be open
  // Whether `c` (the result's check, or that of the result as a lossy file holds it) passes:
  // a valid surface, or the open envelope an open operand gives.
  bool acceptable(const MeshCheck& c) const;
  // Empty when acceptable(c), else "the result failed its check: DEFECTS", with where the
  // operands touch without overlapping when they do.
  std::string problem(const MeshCheck& c) const;
};
CheckedBoolean checked_boolean(const Mesh& a, const Mesh& b, BooleanOp op, std::string_view name_a,
                               std::string_view name_b, bool outer_envelope = false);

// boolean(), then check_mesh of the result (operands are not checked: the caller's
// contract). Where the exact result holds sheets that touch, or that lie closer than
// rounding to doubles can keep apart (a solid minus its mirror image: faces nearly
// perpendicular to the mirror plane meet their images at dihedral angles of 1e-15, leaving
// wedges 1e-15 Å thick), no rounding of it is a valid surface. Then b is moved by the first
// step of a fixed sequence (2^-36, 2^-28, 2^-20 of the coordinates' scale, along fixed
// directions) whose result passes its check, and result.stats.b_moved_by says by how much.
// The result is valid (check.valid()), empty, or still invalid after every step.
// checked_boolean runs this for every operation but the outer envelope.
CheckedBoolean valid_boolean(const Mesh& a, const Mesh& b, BooleanOp op, const MeshCheckOptions& options = {});

// What a user should know of how the result was made: that b was moved, by how much and
// why (empty when it was not).
std::string boolean_note(const BooleanStats& stats);

}  // namespace molsurf
