// The solvent-excluded surface over the real structures of data/pdb up to a few thousand
// atoms, at densities 1, 2 and 4 and probes 1.0, 1.4 and 2.0: valid every time (closed,
// 2-manifold, outward, no self-intersection, no touching faces), and its volume between the
// van der Waals solid's and the accessible solid's. Label `long`; one test per structure and
// probe, so that each stays well within the label's hour on a loaded machine (the whole grid
// took 55 minutes up to 2hhb's last probe with other jobs running).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"

namespace molsurf {
namespace {

class SolventExcludedSurfaceLong : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(SolventExcludedSurfaceLong, ValidAtEveryDensity) {
  const auto [file, probe] = GetParam();
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/" + file);
  ComputeSurfaceOptions vdw_options;
  vdw_options.exact_areas = false;
  vdw_options.surface = SurfaceKind::vdw;
  const double vdw_volume = compute_surface(s.atoms, vdw_options).measures.volume;
  for (const double density : {1.0, 2.0, 4.0}) {
    SCOPED_TRACE(testing::Message() << file << " probe " << probe << " density " << density);
    ComputeSurfaceOptions options;
    options.exact_areas = false;
    options.surface = SurfaceKind::ses;
    options.spheres.probe = probe;
    options.spheres.density = density;
    const ComputedSurface ses = compute_surface(s.atoms, options);
    std::printf("%s probe %.1f density %.0f: %zu faces, %.2f s, %s\n", file, probe, density, ses.measures.faces,
                ses.seconds.total, ses.check.valid() ? "valid" : "INVALID");
    std::fflush(stdout);
    EXPECT_TRUE(ses.check.valid());
    EXPECT_EQ(ses.check.contact_pairs, 0u);
    options.surface = SurfaceKind::sas;
    options.spheres.density = 1;
    const double sas_volume = compute_surface(s.atoms, options).measures.volume;
    EXPECT_GT(ses.measures.volume, vdw_volume);
    EXPECT_LT(ses.measures.volume, sas_volume);
  }
}

std::string name_of(const ::testing::TestParamInfo<std::tuple<const char*, double>>& info) {
  std::string name = std::get<0>(info.param);
  for (char& c : name)
    if (c == '.') c = '_';
  return name + "_p" + std::to_string(static_cast<int>(std::get<1>(info.param) * 10));
}

INSTANTIATE_TEST_SUITE_P(DataPdb, SolventExcludedSurfaceLong,
                         ::testing::Combine(::testing::Values("1crn.pdb", "1ubq.pdb", "1j8k.cif", "3pqr.cif",
                                                              "2hhb.pdb"),
                                            ::testing::Values(1.0, 1.4, 2.0)),
                         name_of);

}  // namespace
}  // namespace molsurf
