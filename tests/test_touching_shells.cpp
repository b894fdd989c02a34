// One notion of valid: sheets that touch without crossing (shells touching each other, or a
// surface touching itself) are a defect, as an exact self-intersection test (CGAL's) counts
// them. Surfaces from atoms never hold them: exactly tangent spheres are separate shells
// (inscribed polyhedra lie strictly inside their spheres) or one (area-corrected ones
// overlap); a Boolean of solids that only touch is refused by its check.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "atom_fixtures.hpp"
#include "cli_runner.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

using testing::atom_at;

// Spheres of radius 0.5 spaced 1.0 along x: each touches the next at one point.
std::vector<Atom> tangent_chain(int n) {
  std::vector<Atom> atoms;
  for (int i = 0; i < n; ++i) atoms.push_back(atom_at({1.0 * i, 0, 0}, 0.5));
  return atoms;
}

// A hexagonal close packing of unit spheres (spacing 2) with coordinates rounded to three
// decimals, as a PDB file holds them: pairs along x are exactly tangent, the others a
// rounding of the packing apart or overlapping.
std::vector<Atom> hcp_packing() {
  std::vector<Atom> atoms;
  const auto three_decimals = [](double x) { return std::round(x * 1000) / 1000; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const double x = 2 * (i + 0.5 * ((j + k) % 2)), y = std::sqrt(3.0) * (j + (k % 2) / 3.0),
                     z = 2 * std::sqrt(2.0 / 3.0) * k;
        atoms.push_back(atom_at({three_decimals(x), three_decimals(y), three_decimals(z)}, 1.0));
      }
  return atoms;
}

// A sphere of radius 20 with spheres of radius 0.05 touching it on four sides (contrast 400).
std::vector<Atom> radius_contrast() {
  std::vector<Atom> atoms{atom_at({0, 0, 0}, 20)};
  for (const Vec3 d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, -1}})
    atoms.push_back(atom_at(20.05 * d, 0.05));
  return atoms;
}

struct Family {
  const char* name;
  std::vector<Atom> atoms;
};

// Every family at probe 0, inscribed or area-corrected, at an even frequency (whose
// icospheres have corners on the axes, where the tangent points lie) and by density, with
// --true-points and with the pairwise method: valid, and no contact.
TEST(TouchingShells, TangentSpheresNeverGiveTouchingShells) {
  const Family families[] = {{"chain", tangent_chain(6)}, {"hcp", hcp_packing()}, {"contrast", radius_contrast()}};
  for (const Family& family : families)
    for (const bool inscribed : {true, false})
      for (const int frequency : {0, 2})
        for (const int variant : {0, 1, 2}) {  // plain, --true-points, pairwise
          ComputeSurfaceOptions o;
          o.spheres.probe = 0;
          o.spheres.area_corrected = !inscribed;
          o.spheres.frequency = frequency;
          o.true_points = variant == 1;
          if (variant == 2) o.method = SurfaceMethod::pairwise;
          const std::string what = std::string(family.name) + (inscribed ? " inscribed" : " area-corrected") +
                                   " frequency " + std::to_string(frequency) + " variant " + std::to_string(variant);
          const ComputedSurface s = compute_surface(family.atoms, o);
          const MeshCheck c = check_mesh(s.mesh);
          EXPECT_TRUE(c.valid()) << what;
          EXPECT_EQ(c.contact_pairs, 0u) << what;
          // Inscribed polyhedra of tangent spheres stay apart: the chain is six shells.
          if (inscribed && family.name == std::string("chain")) EXPECT_EQ(c.components, 6u) << what;
          if (!inscribed && family.name == std::string("chain")) EXPECT_EQ(c.components, 1u) << what;
        }
}

// The inscribed scale keeps every corner strictly inside the sphere, at the origin and far
// from it.
TEST(TouchingShells, InscribedCornersLieStrictlyInsideTheSphere) {
  for (const Vec3 centre : {Vec3{0, 0, 0}, Vec3{0.5, -3, 7}, Vec3{1e6, 1e6, -1e6}})
    for (const double radius : {0.5, 1.7, 20.0})
      for (const int frequency : {1, 2, 5, 8}) {
        const Mesh m = make_icosphere(centre, radius, {.frequency = frequency});
        for (const Vec3& v : m.vertices) {
          const long double dx = static_cast<long double>(v.x) - centre.x, dy = static_cast<long double>(v.y) - centre.y,
                            dz = static_cast<long double>(v.z) - centre.z;
          ASSERT_LT(dx * dx + dy * dy + dz * dz, static_cast<long double>(radius) * radius)
              << radius << " at " << centre.x << ", frequency " << frequency;
        }
      }
}

TEST(TouchingShells, CheckReportsTouchingSheetsAsADefect) {
  const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
  for (const Vec3 offset : {Vec3{1, 0, 0}, Vec3{1, 0.5, 0.25}, Vec3{1, 1, 0}, Vec3{1, 1, 1}}) {
    Mesh both = a;
    const Mesh b = make_box(offset, offset + Vec3{1, 1, 1});
    const auto base = static_cast<Index>(both.vertices.size());
    both.vertices.insert(both.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (Triangle t : b.faces) both.faces.push_back({t[0] + base, t[1] + base, t[2] + base});
    const MeshCheck c = check_mesh(both);
    EXPECT_GT(c.contact_pairs, 0u) << offset.x << offset.y << offset.z;
    EXPECT_FALSE(c.valid());
    bool named = false;
    for (const std::string& d : c.defects()) named |= d.find("touching face pair") != std::string::npos;
    EXPECT_TRUE(named);
  }
}

// Solids that meet along an edge or at a corner: the exact union holds the sheets apart but
// touching, so no rounding of it passes the check. valid_boolean (and the command) then
// move B by a step far below any feature and far above rounding, and say so, naming the
// place; the result is valid. Over a whole face they join into one solid, with nothing
// touching and nothing moved.
TEST(TouchingShells, BooleanOfTouchingSolidsMovesBApart) {
  const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
  for (const Vec3 offset : {Vec3{1, 1, 0}, Vec3{1, 1, 1}}) {
    const Mesh b = make_box(offset, offset + Vec3{1, 1, 1});
    const MeshCheck exact = check_mesh(boolean(a, b, BooleanOp::union_).mesh);
    EXPECT_FALSE(exact.valid()) << offset.x << offset.y << offset.z;
    EXPECT_GT(exact.contact_pairs, 0u);
    const CheckedBoolean moved = valid_boolean(a, b, BooleanOp::union_);
    EXPECT_TRUE(moved.check.valid()) << offset.x << offset.y << offset.z;
    const double shift = norm(moved.result.stats.b_moved_by);
    EXPECT_GT(shift, 0);
    EXPECT_LE(shift, std::ldexp(4.0, -36) * 1.0001);  // the first step: scale 4, the power of two above 2
    EXPECT_NEAR(moved.check.volume, 2.0, 1e-9);
    EXPECT_NE(boolean_note(moved.result.stats).find("touch"), std::string::npos);
    // The difference keeps A whole: nothing touches, nothing moves.
    const CheckedBoolean difference = valid_boolean(a, b, BooleanOp::difference);
    EXPECT_TRUE(difference.check.valid());
    EXPECT_EQ(norm(difference.result.stats.b_moved_by), 0.0);
  }
  const CheckedBoolean joined = valid_boolean(a, make_box({1, 0, 0}, {2, 1, 1}), BooleanOp::union_);
  EXPECT_TRUE(joined.check.valid());
  EXPECT_EQ(norm(joined.result.stats.b_moved_by), 0.0);
  EXPECT_TRUE(boolean_note(joined.result.stats).empty());
  testing::TempDir dir;
  write_mesh(dir.path() / "a.off", a);
  write_mesh(dir.path() / "b.off", make_box({1, 1, 0}, {2, 2, 1}));
  const auto r = testing::run_molsurf("boolean union a.off b.off -o u.off", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("note: near ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the result is that of B moved by"), std::string::npos) << r.out;
  EXPECT_TRUE(check_mesh(read_mesh(dir.path() / "u.off")).valid());
  // Overlapping by a little instead: one valid solid, nothing moved.
  write_mesh(dir.path() / "c.off", make_box({0.5, 0.5, 0}, {2, 2, 1}));
  const auto overlap = testing::run_molsurf("boolean union a.off c.off -o u.off", dir.path());
  EXPECT_EQ(overlap.exit_code, 0) << overlap.err;
  EXPECT_EQ(overlap.out.find("moved by"), std::string::npos) << overlap.out;
}

// A sphere too small to triangulate is refused plainly: under 1e-6 A anywhere, and under
// 2^-30 of its coordinates far from the origin; near the origin a 1e-5 A sphere is fine.
TEST(TouchingShells, TinySpheresFarFromTheOriginAreAPlainError) {
  ComputeSurfaceOptions o;
  o.spheres.probe = 0;
  const auto message = [&](const std::vector<Atom>& atoms) {
    try {
      compute_surface(atoms, o);
    } catch (const SurfaceCheckFailed& failed) {
      return std::string("a failed check: ") + failed.what();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  for (const double radius : {1e-14, 1e-310}) {
    EXPECT_NE(message({atom_at({1e4, 2, 3}, radius), atom_at({0, 0, 0}, 1)}).find("too small"), std::string::npos)
        << radius;
    EXPECT_NE(message({atom_at({0, 0, 0}, radius)}).find("too small to triangulate"), std::string::npos) << radius;
  }
  for (const double x : {1e5, 1e9})
    EXPECT_NE(message({atom_at({x, 2, 3}, 1e-5), atom_at({0, 0, 0}, 1)}).find("too small for its position"),
              std::string::npos)
        << x;
  const std::vector<Atom> origin{atom_at({0, 0, 0}, 1e-5)};
  EXPECT_TRUE(check_mesh(compute_surface(origin, o).mesh).valid());
}

}  // namespace
}  // namespace molsurf
