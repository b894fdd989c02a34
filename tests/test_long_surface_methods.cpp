// The one-pass and the pairwise union on every structure in data/pdb at densities 1, 2
// and 4 and probes 0 and 1.4, the capsid (272k atoms) at the default density and probe
// only: label `long`, the capsid alone takes tens of minutes with the pairwise method.
// Filter with --gtest_filter, e.g. -*Capsid* to leave it out.
#include <gtest/gtest.h>

#include <string>

#include "molsurf/atoms.hpp"
#include "surface_methods.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

class AllStructures : public ::testing::TestWithParam<std::tuple<std::string, double, double>> {};

TEST_P(AllStructures, MethodsAgree) {
  const auto& [name, probe, density] = GetParam();
  const Structure s = read_structure(kData + "/pdb/" + name);
  SphereOptions o;
  o.probe = probe;
  o.density = density;
  EXPECT_TRUE(testing::methods_agree(s.atoms, o));
}

INSTANTIATE_TEST_SUITE_P(DataPdb, AllStructures,
                         ::testing::Combine(::testing::Values("1crn.pdb", "1ubq.pdb", "2hhb.pdb", "4hhb.cif",
                                                              "3pqr.cif", "1j8k.cif", "4yvs.cif", "7cth.cif",
                                                              "2btv.pdb"),
                                            ::testing::Values(0.0, 1.4), ::testing::Values(1.0, 2.0, 4.0)));
INSTANTIATE_TEST_SUITE_P(Capsid, AllStructures,
                         ::testing::Combine(::testing::Values("1f2n_assembly1.cif.gz"), ::testing::Values(1.4),
                                            ::testing::Values(2.0)));

}  // namespace
}  // namespace molsurf
