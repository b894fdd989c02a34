#pragma once
// A shell's measures as sums over its patches (Stokes' theorem on each sphere, the
// divergence theorem over the shell), and the shells finished from those sums: centroid,
// the sign that tells a cavity from an outer surface, the report's order. Shared by the
// whole arrangement (sphere_arrangement.cpp) and the arrangement joined from blocks
// (joined_parts.cpp), whose shells are sums of the blocks' own.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

// Sums about `origin`, the centre of the shell's first sphere (the divergence theorem's
// origin is free; a near one keeps the sum's cancellation small). Plain numbers: they
// travel between processes as their bytes.
struct ShellMoments {
  Vec3 origin;
  double area = 0;
  double volume = 0;      // signed, about origin
  Vec3 vector_area;       // integral of the outward normal
  Vec3 moment;            // the centroid's numerator about origin: sum of (c - origin) A + r VA
  double volume_error = 0;   // a bound on the volume's rounding
  double squared_radii = 0;  // sum of r^2 over the patches: the bound's growth per angstrom the origin moves

  // One patch of sphere (centre, radius): its area and vector area.
  void add_patch(const Vec3& centre, double radius, double patch_area, const Vec3& patch_vector_area);
  // Another shell's sums (about its own origin), moved to this one's.
  void add(const ShellMoments& other);
};

// What finish_shells needs of a sphere: to settle a shell too small for its volume's sign.
struct Ball {
  Vec3 centre;
  double radius = 0;
};

struct FinishedShells {
  std::vector<ArrangementShell> shells;  // the largest outer shell first, then by area
  std::vector<std::uint32_t> rank;       // per shell as given: its index in `shells`
};

// The shells from their sums and their spheres (each shell's, in any order, repeats
// allowed), given in the order of their first patch (the order ties keep).
FinishedShells finish_shells(std::span<const ShellMoments> moments, std::vector<std::vector<std::uint32_t>> spheres,
                             const std::function<Ball(std::uint32_t)>& ball_of);

}  // namespace molsurf::arrangement
