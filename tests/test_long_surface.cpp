// Every structure in data/pdb at densities 1, 2, 4 and probes 0 and 1.4 (label `long`):
// the surface must be valid (closed, 2-manifold, outward, no self-intersection).
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {
namespace {

using Case = std::tuple<std::string, double, double>;

class Structures : public ::testing::TestWithParam<Case> {};

TEST_P(Structures, ValidSurface) {
  const auto& [file, density, probe] = GetParam();
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/" + file);
  SurfaceOptions o;
  o.spheres.density = density;
  o.spheres.probe = probe;
  SurfaceResult r = solvent_accessible_surface(s.atoms, o);
  EXPECT_TRUE(check_mesh(r.mesh).valid()) << "before cleanup";
  improve_surface(r.mesh);  // what `molsurf STRUCTURE` writes
  const MeshCheck c = check_mesh(r.mesh);
  EXPECT_TRUE(c.valid()) << ::testing::PrintToString(c.defects());
  EXPECT_GT(c.volume, 0);
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = std::get<0>(info.param) + "_d" + std::to_string(static_cast<int>(std::get<1>(info.param))) +
                     "_p" + (std::get<2>(info.param) > 0 ? "14" : "0");
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, Structures,
                         ::testing::Combine(::testing::Values("1crn.pdb", "1crn.cif.gz", "1ubq.pdb", "1j8k.cif",
                                                              "3pqr.cif", "2hhb.pdb", "2hhb.cif", "4hhb.cif",
                                                              "7cth.cif", "4yvs.cif", "2btv.pdb",
                                                              "1f2n_assembly1.cif.gz"),
                                            ::testing::Values(1.0, 2.0, 4.0), ::testing::Values(0.0, 1.4)),
                         case_name);

}  // namespace
}  // namespace molsurf
