// The Stern layer from the same run (ComputeSurfaceOptions::stern_probe, --stern): the SAS of
// the same atoms at its own probe, equal to a separate SAS run at that probe, and written and
// reported as every surface is.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf {
namespace {

using testing::read_text;
using testing::run_molsurf;
using testing::TempDir;

const std::string kCrambin = std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb";

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(SternLayer, IsTheAccessibleSurfaceAtItsProbeMadeInTheSameRun) {
  const std::vector<Atom> atoms = read_structure(kCrambin).atoms;
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.stern_probe = kDefaultSternProbe;
  const ComputedSurface ses = compute_surface(atoms, options);
  ASSERT_TRUE(ses.stern);
  const ComputedSurface& stern = *ses.stern;
  EXPECT_TRUE(stern.check.valid());
  EXPECT_TRUE(check_mesh(stern.mesh).valid());

  ComputeSurfaceOptions sas_options;
  sas_options.spheres.probe = kDefaultSternProbe;
  const ComputedSurface sas = compute_surface(atoms, sas_options);
  EXPECT_LT(relative(stern.exact.area, sas.exact.area), 1e-12);
  EXPECT_LT(relative(stern.exact.volume, sas.exact.volume), 1e-12);
  EXPECT_LT(relative(stern.measures.area, sas.measures.area), 1e-12);
  EXPECT_EQ(stern.mesh.face_count(), sas.mesh.face_count());
  // It encloses the SES: the probe's layer lies outside the molecular surface.
  EXPECT_GT(stern.measures.volume, ses.measures.volume);
  EXPECT_FALSE(ses.ses_arrangement == nullptr);
  EXPECT_FALSE(sas.stern);  // none unless asked for
}

TEST(SternLayer, RefusesABadProbe) {
  const std::vector<Atom> atoms = read_structure(kCrambin).atoms;
  ComputeSurfaceOptions options;
  options.stern_probe = -1;
  EXPECT_THROW(compute_surface(atoms, options), ParameterError);
  options.stern_probe = std::nan("");
  EXPECT_THROW(compute_surface(atoms, options), ParameterError);
}

TEST(SternLayer, CommandWritesItCheckedAndReportsItsAreaAsASeparateRunDoes) {
  TempDir dir;
  auto r = run_molsurf("-q --surface ses -o ses.vert --no-header --stern stern.vert --json ses.json '" + kCrambin + "'",
                       dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"ses.vert", "ses.face", "stern.vert", "stern.face"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / file)) << file;
  r = run_molsurf("check stern.vert", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // --no-header applies to the Stern pair too: numbers only, as PyGBe reads them.
  EXPECT_NE(read_text(dir.path() / "stern.vert").front(), '#');

  r = run_molsurf("-q --probe 2 -o sas.vtp --json sas.json '" + kCrambin + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json ses = nlohmann::json::parse(read_text(dir.path() / "ses.json"));
  const nlohmann::json sas = nlohmann::json::parse(read_text(dir.path() / "sas.json"));
  ASSERT_TRUE(ses.contains("stern"));
  EXPECT_EQ(ses["stern"]["probe"].get<double>(), 2.0);
  EXPECT_TRUE(ses["stern"]["valid"].get<bool>());
  EXPECT_LT(relative(ses["stern"]["area"].get<double>(), sas["area"].get<double>()), 1e-12);
  EXPECT_LT(relative(ses["stern"]["volume"].get<double>(), sas["volume"].get<double>()), 1e-12);
  EXPECT_GT(ses["stern"]["faces"].get<double>(), 0);

  r = run_molsurf("--surface ses --stern-probe 2.5 -o ses.vtp '" + kCrambin + "'", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--stern-probe: give --stern FILE"), std::string::npos) << r.err;
  r = run_molsurf("--stern stern.xyz -o ses.vtp '" + kCrambin + "'", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--stern"), std::string::npos) << r.err;
  r = run_molsurf("--areas-only --stern stern.vtp '" + kCrambin + "'", dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("drop --stern"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace molsurf
