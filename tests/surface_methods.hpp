#pragma once
// Two independent exact algorithms for one surface: the one-pass union and the
// hierarchical pairwise union must both give a valid surface with the same area and
// volume (the triangulations differ: the pairwise one keeps cuts made between merges).
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>

#include "boolean_invariants.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::testing {

inline ::testing::AssertionResult methods_agree(std::span<const Atom> atoms, const SphereOptions& spheres,
                                                int threads = 2) {
  SphereUnionOptions o;
  o.spheres = spheres;
  o.threads = threads;
  o.method = SurfaceMethod::one_pass;
  const SphereUnion one = solvent_accessible_surface(atoms, o);
  if (one.one_pass.open_edges > 0)
    return ::testing::AssertionFailure() << "one-pass: " << one.one_pass.open_edges << " open edges";
  if (auto v = valid_surface(one.mesh); !v) return ::testing::AssertionFailure() << "one-pass: " << v.message();
  o.method = SurfaceMethod::pairwise;
  const SphereUnion two = solvent_accessible_surface(atoms, o);
  if (auto v = valid_surface(two.mesh); !v) return ::testing::AssertionFailure() << "pairwise: " << v.message();
  const double a1 = surface_area(one.mesh), a2 = surface_area(two.mesh);
  const double v1 = signed_volume(one.mesh), v2 = signed_volume(two.mesh);
  const double scale_a = std::max(std::fabs(a2), 1e-300), scale_v = std::max(std::fabs(v2), 1e-300);
  if (std::fabs(a1 - a2) > 1e-9 * scale_a || std::fabs(v1 - v2) > 1e-9 * scale_v)
    return ::testing::AssertionFailure() << "one-pass area " << a1 << " volume " << v1 << ", pairwise area " << a2
                                         << " volume " << v2;
  return ::testing::AssertionSuccess() << one.mesh.face_count() << " and " << two.mesh.face_count() << " faces";
}

}  // namespace molsurf::testing
