// The solvent-excluded surface's degenerate families, seeded (label `long`): each seed draws
// one placement of a family where SES constructions classically break, and the surface must
// be valid by molsurf's check (compute_surface never returns anything else), valid by CGAL's
// exact self-intersection test as well (written apart from molsurf), and its volume must
// match the distance reference (ses_reference.hpp), which knows nothing of the construction.
// Families (issue: SES singularities):
//   - a probe larger than the gaps between atoms (clusters, probe 2-3.5 A);
//   - two atoms at spindle-torus distances (the probe's circle smaller than the probe), and
//     at the horn torus between spindle and ring torus; against the closed form as well;
//   - rings whose hole the probe just passes or just fails to pass (relative 1e-3, 1e-9, 0);
//   - cages with a cavity inside (the MSMS failure case);
//   - four atoms whose reentrant patches overlap (tetrahedra of side 4.5-5.5);
//   - exactly symmetric placements (cubes and octahedra with dyadic coordinates).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cgal_check.hpp"
#include "molsurf/compute_surface.hpp"
#include "ses_reference.hpp"

namespace molsurf {
namespace {

using ses_reference::atom_at;

struct Placement {
  std::string name;
  std::vector<Atom> atoms;
  double probe = 1.4;
  bool two_atoms = false;  // also against the closed form (atoms[0] at the origin, atoms[1] on +x)
};

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A random rotation (uniform quaternion), so that the non-symmetric families are not
// aligned with the axes.
std::vector<Atom> rotated(std::vector<Atom> atoms, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  double q[4] = {g(rng), g(rng), g(rng), g(rng)};
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  for (Atom& a : atoms) {
    const Vec3 p = a.centre;
    a.centre = {(1 - 2 * (y * y + z * z)) * p.x + 2 * (x * y - w * z) * p.y + 2 * (x * z + w * y) * p.z,
                2 * (x * y + w * z) * p.x + (1 - 2 * (x * x + z * z)) * p.y + 2 * (y * z - w * x) * p.z,
                2 * (x * z - w * y) * p.x + 2 * (y * z + w * x) * p.y + (1 - 2 * (x * x + y * y)) * p.z};
  }
  return atoms;
}

Placement large_probe(std::mt19937_64& rng) {
  Placement p{"a probe larger than the gaps", {}, uniform(rng, 2.0, 3.5)};
  const int n = std::uniform_int_distribution<int>(6, 10)(rng);
  for (int k = 0; k < n; ++k)
    p.atoms.push_back(atom_at({uniform(rng, 0, 5), uniform(rng, 0, 5), uniform(rng, 0, 5)}, uniform(rng, 1.2, 2.0)));
  return p;
}

// The distance at which two atoms' probe circle has radius rho: the SAS spheres (r + p)
// meet on a circle of radius rho at distance t = sqrt(R1^2 - rho^2) from atom 1's centre.
double distance_for_circle(double r1, double r2, double p, double rho) {
  const double R1 = r1 + p, R2 = r2 + p;
  return std::sqrt(R1 * R1 - rho * rho) + std::sqrt(R2 * R2 - rho * rho);
}

Placement spindle(std::mt19937_64& rng, int seed) {
  const double r1 = uniform(rng, 1.2, 2.0), r2 = uniform(rng, 1.2, 2.0), p = uniform(rng, 1.0, 2.0);
  // Every fourth seed is the horn torus (the probe's circle exactly its radius, in doubles).
  const double rho = seed % 4 == 0 ? p : uniform(rng, 0.05, 0.98) * p;
  const double d = distance_for_circle(r1, r2, p, rho);
  Placement out{seed % 4 == 0 ? "two atoms at the horn torus" : "two atoms at a spindle torus",
                {atom_at({0, 0, 0}, r1), atom_at({d, 0, 0}, r2)},
                p,
                true};
  return out;
}

Placement ring_at_threshold(std::mt19937_64& rng, int seed) {
  const int n = std::uniform_int_distribution<int>(5, 8)(rng);
  const double r = uniform(rng, 1.5, 1.9), p = uniform(rng, 1.0, 2.0);
  // The probe at the ring's centre touches every atom at ring radius r + p.
  constexpr double kOffsets[] = {-1e-3, -1e-9, 0.0, 1e-9, 1e-3};
  const double offset = kOffsets[seed % 5];
  return {"a ring at the threshold of the probe passing (relative offset " + std::to_string(offset) + ")",
          ses_reference::ring(n, (r + p) * (1 + offset), r), p};
}

Placement cage(std::mt19937_64& rng) {
  const int n = std::uniform_int_distribution<int>(40, 60)(rng);
  return {"a cage", rotated(ses_reference::cage(n, uniform(rng, 6.0, 7.0), uniform(rng, 1.8, 2.0)), rng),
          uniform(rng, 1.2, 1.6)};
}

Placement tetrahedron(std::mt19937_64& rng) {
  const double t = uniform(rng, 4.5, 5.5) / (2 * std::sqrt(2.0)), r = uniform(rng, 1.5, 1.7);
  std::vector<Atom> atoms = {atom_at({t, t, t}, r), atom_at({t, -t, -t}, r), atom_at({-t, t, -t}, r),
                             atom_at({-t, -t, t}, r)};
  return {"four atoms whose reentrant patches overlap", rotated(std::move(atoms), rng), uniform(rng, 1.2, 1.6)};
}

Placement symmetric(std::mt19937_64& rng, int seed) {
  // Dyadic coordinates: the placement is exactly symmetric in doubles.
  const double a = std::uniform_int_distribution<int>(16, 28)(rng) / 8.0;
  const double r = std::uniform_int_distribution<int>(12, 16)(rng) / 8.0;
  const double p = std::uniform_int_distribution<int>(8, 16)(rng) / 8.0;
  std::vector<Atom> atoms;
  if (seed % 2 == 0) {
    for (int k = 0; k < 8; ++k) atoms.push_back(atom_at({k & 1 ? a : -a, k & 2 ? a : -a, k & 4 ? a : -a}, r));
    return {"a cube of atoms", atoms, p};
  }
  for (double s : {-a, a}) {
    atoms.push_back(atom_at({s, 0, 0}, r));
    atoms.push_back(atom_at({0, s, 0}, r));
    atoms.push_back(atom_at({0, 0, s}, r));
  }
  return {"an octahedron of atoms", atoms, p};
}

Placement placement(int family, int seed) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(1000 * family + seed));
  switch (family) {
    case 0: return large_probe(rng);
    case 1: return spindle(rng, seed);
    case 2: return ring_at_threshold(rng, seed);
    case 3: return cage(rng);
    case 4: return tetrahedron(rng);
    default: return symmetric(rng, seed);
  }
}

class SesFamilies : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(SesFamilies, ValidByBothChecksAndAsLargeAsTheReference) {
  const auto [family, seed] = GetParam();
  const Placement p = placement(family, seed);
  SCOPED_TRACE(p.name + ", probe " + std::to_string(p.probe));
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.spheres.probe = p.probe;
  options.spheres.density = 2;
  options.exact_areas = false;
  const ComputedSurface s = compute_surface(p.atoms, options);
  EXPECT_TRUE(s.check.valid());
  EXPECT_EQ(s.check.contact_pairs, 0u);
  EXPECT_EQ(testing::cgal_defects(s.mesh), "");
  const double reference = ses_reference::ExcludedSolid(p.atoms, p.probe).grid_volume(0.1);
  const double error = (s.measures.volume - reference) / reference;
  std::printf("%s: %zu faces, volume %.3f vs %.3f (%+.3f %%)\n", p.name.c_str(), s.measures.faces, s.measures.volume,
              reference, 100 * error);
  // The grid's own error is a few hundredths of a percent (docs/ses.md).
  EXPECT_LT(std::abs(error), 0.005);
  if (p.two_atoms) {
    const double d = p.atoms[1].centre.x;
    const ses_reference::AreaVolume exact =
        ses_reference::two_atoms(p.atoms[0].radius, p.atoms[1].radius, d, p.probe);
    EXPECT_LT(std::abs(s.measures.area - exact.area) / exact.area, 0.005) << s.measures.area << " vs " << exact.area;
    EXPECT_LT(std::abs(s.measures.volume - exact.volume) / exact.volume, 0.005)
        << s.measures.volume << " vs " << exact.volume;
  }
}

std::string family_name(const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
  constexpr const char* kNames[] = {"LargeProbe", "Spindle", "Ring", "Cage", "Tetrahedron", "Symmetric"};
  return std::string(kNames[std::get<0>(info.param)]) + "_" + std::to_string(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Seeds, SesFamilies, ::testing::Combine(::testing::Range(0, 6), ::testing::Range(0, 10)),
                         family_name);

}  // namespace
}  // namespace molsurf
