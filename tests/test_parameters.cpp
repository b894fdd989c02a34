// The library's one home for parameters and input checks (parameters.hpp, input_checks.hpp)
// and the Boolean job (checked_boolean), as a C++ caller meets them: the front ends' table of
// bad inputs (test_cli_bad_inputs.cpp, python/tests/test_bad_input_table.py) goes through the
// command and Python; these are the calls themselves.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "mesh_fixtures.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/input_checks.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf {
namespace {

template <class Call>
std::string message_of(Call call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, ARefusalNamesTheParameterAndTheProblemApart) {
  try {
    check(kProbeParameter, -1);
    FAIL() << "-1 accepted as a probe";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "probe");
    EXPECT_EQ(e.problem(), "-1 is out of range; expected a number in [0, 1e+15]");
    EXPECT_EQ(std::string(e.what()), "probe: -1 is out of range; expected a number in [0, 1e+15]");
  }
  EXPECT_EQ(problem(kDensityParameter, 1e9), "");  // the closed end is in range, the open one not
  EXPECT_EQ(problem(kDensityParameter, 0), "0 is out of range; expected a number in (0, 1e+09]");
  EXPECT_EQ(problem(kThreadsParameter, 1024), "");
  EXPECT_EQ(problem(kThreadsParameter, 1025), "1025 is out of range; expected a whole number in 0..1024");
  EXPECT_EQ(problem(kProbeParameter, -std::numeric_limits<double>::infinity()),
            "-inf is not a finite number; expected one in [0, 1e+15]");
}

TEST(Parameters, NamesComeFromTheTablesBesideTheEnums) {
  for (std::size_t i = 0; i < std::size(kBooleanOpNames); ++i) {
    const BooleanOp op = boolean_op_from_name(kBooleanOpNames[i]);
    EXPECT_EQ(boolean_op_name(op), kBooleanOpNames[i]);
  }
  EXPECT_EQ(surface_kind_name(surface_kind_from_name("ses")), std::string("ses"));
  EXPECT_EQ(surface_method_name(surface_method_from_name("one-pass")), std::string("one-pass"));
  EXPECT_EQ(message_of([] { surface_method_from_name("one_pass"); }),
            "method: 'one_pass' is not one of: one-pass, pairwise");
  EXPECT_EQ(choice_problem("\x01\x02long name that goes on and on and on", kSurfaceKindNames),
            "'??long name that goes on and on ...' is not one of: sas, ses, vdw");
}

TEST(Parameters, TheSurfaceKindSettlesTheProbe) {
  EXPECT_EQ(surface_probe(SurfaceKind::sas, std::nullopt), kDefaultProbe);
  EXPECT_EQ(surface_probe(SurfaceKind::sas, 0.0), 0.0);
  EXPECT_EQ(surface_probe(SurfaceKind::vdw, std::nullopt), 0.0);
  EXPECT_EQ(surface_probe(SurfaceKind::vdw, 0.0), 0.0);
  EXPECT_EQ(surface_probe(SurfaceKind::ses, std::nullopt), kDefaultProbe);
  EXPECT_NE(message_of([] { surface_probe(SurfaceKind::vdw, kDefaultProbe); }).find("probe: the van der Waals"),
            std::string::npos);
  EXPECT_NE(message_of([] { surface_probe(SurfaceKind::ses, 0.0); }).find("probe: the solvent-excluded"),
            std::string::npos);
}

TEST(Parameters, ComputeSurfaceAndComputeAreasRefuseWhatTheFrontEndsRefuse) {
  const std::vector<Atom> atoms{Atom{.centre = {0, 0, 0}, .radius = 1.5}, Atom{.centre = {2, 0, 0}, .radius = 1.5}};
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.method = SurfaceMethod::pairwise;
  EXPECT_EQ(message_of([&] { compute_surface(atoms, options); }),
            "method: 'pairwise' is for the SAS and vdW surfaces; the SES is made one way only");
  options = {};
  options.threads = -1;
  EXPECT_EQ(message_of([&] { compute_surface(atoms, options); }),
            "threads: -1 is out of range; expected a whole number in 0..1024");
  options = {};
  options.max_sphere_faces = 0;
  EXPECT_EQ(message_of([&] { compute_surface(atoms, options); }),
            "max_faces: 0 is out of range; expected a whole number in 1..100000000000");
  SphereOptions spheres;
  spheres.probe = 2e15;
  EXPECT_EQ(message_of([&] { compute_areas(atoms, spheres); }),
            "probe: 2e+15 is out of range; expected a number in [0, 1e+15]");
  EXPECT_EQ(message_of([&] { compute_areas(atoms, {}, 2000); }),
            "threads: 2000 is out of range; expected a whole number in 0..1024");
}

TEST(Parameters, ChainListsAndMemoryLimits) {
  EXPECT_EQ(chain_list("A,C"), (std::vector<std::string>{"A", "C"}));
  EXPECT_EQ(chain_list(",A,,B,"), (std::vector<std::string>{"A", "B"}));
  EXPECT_TRUE(chain_list("").empty());
  EXPECT_EQ(chain_list("AA"), (std::vector<std::string>{"AA"}));  // mmCIF chains have long names
  EXPECT_EQ(memory_limit_bytes(2.5), 2'500'000'000u);
  EXPECT_EQ(message_of([] { memory_limit_bytes(0); }), "max_memory: 0 is out of range; expected a number in (0, 1e+09]");
  ReadOptions read;
  read.radius_set = "vdw";
  EXPECT_EQ(message_of([&] { validate(read); }), "radius_set: 'vdw' is not one of: bondi, naccess, protor");
}

TEST(InputChecks, ArrayEntriesAreNamedAsNumPyIndexesThem) {
  const std::size_t frames[] = {2, 3, 3};
  std::vector<double> xyz(18, 0.0);
  xyz[3 * 3 + 3 + 2] = 1e17;  // frame 1, atom 1, z
  EXPECT_EQ(message_of([&] { check_coordinate_array("coords", xyz, frames); }),
            "coords[1, 1, 2]: 1e+17 is out of range (its magnitude must be below 1e16 angstrom)");
  EXPECT_EQ(message_of([] { check_radius_array("radii", std::vector<double>{1.0, 0.0, -0.25}); }),
            "radii[2]: -0.25 is negative; a radius is 0 or more (angstrom, without the probe)");
  EXPECT_EQ(message_of([] { check_face_array("faces", std::vector<std::int64_t>{0, 1, 2, 2, 1, 3}, 3); }),
            "faces[1, 2]: vertex index 3 out of range (0..2)");
  EXPECT_EQ(vertex_index_problem(4, 3, 1), "vertex index 4 out of range (1..3)");  // OBJ and MSMS count from 1
  EXPECT_EQ(vertex_index_problem(3, 3, 1), "");
  EXPECT_EQ(radius_problem(0), "");
  EXPECT_EQ(coordinate_problem(-9.9e15), "");
}

TEST(CheckedBoolean, EmptyAndOpenOperandsAreRefusedByName) {
  const Mesh cube = fixtures::box({0, 0, 0}, {1, 1, 1});
  EXPECT_EQ(message_of([&] { checked_boolean(Mesh{}, cube, BooleanOp::union_, "left", "right"); }),
            "left: not a valid closed surface, so no Boolean is defined: no faces");
  Mesh open = cube;
  open.faces.pop_back();
  EXPECT_NE(message_of([&] { checked_boolean(cube, open, BooleanOp::union_, "left", "right"); })
                .find("right: not a valid closed surface, so no Boolean is defined: "),
            std::string::npos);
  // The outer envelope takes an open operand, and is a union's only.
  EXPECT_EQ(checked_boolean(cube, open, BooleanOp::union_, "left", "right", true).open_input, true);
  EXPECT_EQ(message_of([&] { checked_boolean(cube, cube, BooleanOp::difference, "left", "right", true); }),
            "outer_only: keeps the outer envelope of a union; it does not apply to difference");
  const CheckedBoolean r = checked_boolean(cube, fixtures::box({0.5, 0.5, 0.5}, {2, 2, 2}),
                                           BooleanOp::intersection, "left", "right");
  EXPECT_TRUE(r.check.valid());
  EXPECT_EQ(r.problem(r.check), "");
}

}  // namespace
}  // namespace molsurf
