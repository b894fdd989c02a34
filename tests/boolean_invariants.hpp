#pragma once
// What every Boolean result must satisfy, whatever the operands.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "molsurf/boolean.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf::testing {

inline ::testing::AssertionResult valid_surface(const Mesh& m) {
  const MeshCheck c = check_mesh(m);
  if (c.valid()) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure();
  for (const auto& d : c.defects()) failure << d << "\n";
  return failure;
}

// A Boolean's result: valid, or valid but for sheets that touch without crossing, where the
// solids only touch (at a point, along an edge, over a face): the engine keeps such sheets
// apart, and the check then fails the result, so the front ends refuse it (a touching
// contact is a defect). Anything else is a failure.
inline ::testing::AssertionResult valid_or_only_touching(const Mesh& m) {
  MeshCheck c = check_mesh(m);
  c.contact_pairs = 0;  // what the check says apart from the contacts
  if (c.valid()) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure();
  for (const auto& d : c.defects()) failure << d << "\n";
  return failure;
}

// Union, intersection and difference are valid (or only touching, where the solids only
// touch; valid_boolean's result is then valid), and vol(A u B) + vol(A n B) = vol(A) + vol(B), vol(A - B) = vol(A) - vol(A n B),
// to 1e-9 relative.
inline void expect_boolean_invariants(const Mesh& a, const Mesh& b, const std::string& what) {
  double volume[3] = {0, 0, 0};
  const BooleanOp ops[3] = {BooleanOp::union_, BooleanOp::intersection, BooleanOp::difference};
  for (int k = 0; k < 3; ++k) {
    try {
      const BooleanResult r = boolean(a, b, ops[k]);
      EXPECT_TRUE(valid_or_only_touching(r.mesh)) << what << ": " << boolean_op_name(ops[k]);
      volume[k] = signed_volume(r.mesh);
      // What the front ends write: valid, with b moved where no rounding of this is.
      if (!check_mesh(r.mesh).valid()) {
        const CheckedBoolean checked = valid_boolean(a, b, ops[k]);
        EXPECT_TRUE(checked.check.valid()) << what << ": checked " << boolean_op_name(ops[k]);
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": " << boolean_op_name(ops[k]) << " threw: " << e.what();
      return;
    }
  }
  const double va = signed_volume(a), vb = signed_volume(b), scale = std::max({va, vb, 1e-300});
  EXPECT_NEAR(volume[0] + volume[1], va + vb, 1e-9 * scale) << what;
  EXPECT_NEAR(volume[2], va - volume[1], 1e-9 * scale) << what;
}

}  // namespace molsurf::testing
