#pragma once
// One block's share of the arrangement (the spheres it owns, arranged among the block and
// its halo) summarised for the join across blocks (joined_parts.hpp): each owned sphere's
// area, the block's patches joined into shell parts through the keys among its own spheres,
// and the keys on those parts that name a sphere of another block, by which the join links
// them to other blocks' parts exactly (as the mesh's seams are glued by their keys). A
// sphere's exposed part reads only the balls that overlap it, so a halo that holds every
// ball overlapping an owned sphere gives the whole arrangement's numbers for it.
#include <cstdint>
#include <span>
#include <vector>

#include "arrangement/shell_moments.hpp"
#include "arrangement/sphere_arranger.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

struct SphereArea {
  std::uint32_t sphere = 0;  // in the whole structure's numbering
  double area = 0;
};

// The patches of a block that its own spheres' keys join: part of one shell (or all of it).
struct ShellPart {
  ShellMoments moments;             // about the centre of its first (lowest) sphere
  std::uint32_t first_sphere = 0;
  std::vector<SphereArea> patches;  // per sphere, increasing: the area of its patches here
};

// A key on a shell part's boundary (or an alias of one) naming another block's sphere.
struct OpenKey {
  Key key;                // in the whole structure's numbering
  std::uint32_t part = 0;  // index into ArrangementPart::shells
};

struct ArrangementPart {
  std::vector<SphereArea> sphere_area;  // the owned spheres with an exposed area, increasing
  std::vector<ShellPart> shells;        // in the order of their first patch
  std::vector<OpenKey> open_keys;       // sorted by key
  std::vector<Key> open_vertices;       // arc ends naming another block's sphere: sorted, once each
  // Of the owned spheres (duplicate: not counted, the copies' holders may lie elsewhere);
  // vertices: the arc ends whose three spheres are all owned.
  ArrangementStats stats;
};

// The part of the spheres `owned` marks, arranged among all the spheres given (the block
// and its halo, in increasing whole-structure index `global_index`, the order the whole
// arrangement decides ties by). `held`: the whole structure's decision (sphere_containers).
// Spheres without `owned` only bound the owned ones. threads: 0 keeps OpenMP's default.
ArrangementPart arrange_part(std::span<const Vec3> centres, std::span<const double> radii,
                             std::span<const std::uint8_t> held, std::span<const std::uint8_t> owned,
                             std::span<const std::uint32_t> global_index, int threads = 0);

}  // namespace molsurf::arrangement
