// The solvent-excluded surface's mesh against its area and volume from the arrangement's
// patches (ses_measures.hpp), and those against references written apart from both
// (tests/ses_reference.hpp): two atoms' closed form, and for other placements the volume of
// the points whose distance to the probe-accessible region is at least the probe radius,
// counted on a grid. Prints one markdown table; docs/ses.md keeps it.
// Usage: ses_accuracy [GRID_SPACING=0.1] [STRUCTURE.pdb ...]
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "ses_reference.hpp"

using namespace molsurf;
using ses_reference::atom_at;
using ses_reference::ring;

namespace {

struct Case {
  std::string name;
  std::vector<Atom> atoms;
  double probe = 1.4;
  double exact_area = 0, exact_volume = 0;  // 0: the grid reference's volume only
};

}  // namespace

int main(int argc, char** argv) {
  const double grid = argc > 1 ? std::atof(argv[1]) : 0.1;
  std::vector<Case> cases;
  for (const auto& [r1, r2, d] : std::vector<std::array<double, 3>>{{1.7, 1.5, 3.5}, {1.5, 1.5, 5.4}}) {
    const auto exact = ses_reference::two_atoms(r1, r2, d, 1.4);
    cases.push_back({"two atoms r " + std::to_string(r1).substr(0, 3) + "/" + std::to_string(r2).substr(0, 3) +
                         ", d " + std::to_string(d).substr(0, 3) + (d > 5 ? " (spindle)" : ""),
                     {atom_at({0, 0, 0}, r1), atom_at({d, 0, 0}, r2)}, 1.4, exact.area, exact.volume});
  }
  const double s = 5.0 / std::sqrt(3.0);
  cases.push_back({"triangle, probes above and below overlap",
                   {atom_at({s, 0, 0}, 1.7), atom_at({-s / 2, s * std::sqrt(3.0) / 2, 0}, 1.7),
                    atom_at({-s / 2, -s * std::sqrt(3.0) / 2, 0}, 1.7)}});
  cases.push_back({"ring of 6, the probe just fails to pass", ring(6, 3.05, 1.7)});
  const double t = 5 / (2 * std::sqrt(2.0));
  cases.push_back({"tetrahedron, reentrant probes overlap",
                   {atom_at({t, t, t}, 1.6), atom_at({t, -t, -t}, 1.6), atom_at({-t, t, -t}, 1.6),
                    atom_at({-t, -t, t}, 1.6)}});
  cases.push_back({"ring of 5, probe 3.0", ring(5, 2.6, 1.5), 3.0});
  for (int k = 2; k < argc; ++k) {
    const Structure st = read_structure(argv[k]);
    cases.push_back({std::string(argv[k]).substr(std::string(argv[k]).find_last_of('/') + 1), st.atoms});
  }

  std::printf("| case | density | faces | area | patches | error | volume | patches | error | reference volume | "
              "patches vs reference | seconds |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    double ref_volume = c.exact_volume;
    if (ref_volume == 0) ref_volume = ses_reference::ExcludedSolid(c.atoms, c.probe).grid_volume(grid);
    for (const double density : {1.0, 2.0, 4.0}) {
      ComputeSurfaceOptions options;
      options.surface = SurfaceKind::ses;
      options.spheres.probe = c.probe;
      options.spheres.density = density;
      const ComputedSurface ses = compute_surface(c.atoms, options);
      const SesMeasures& m = *ses.ses_patches;
      const std::string reference =
          c.exact_area > 0 ? std::to_string(c.exact_volume).substr(0, 7) + " (closed form; area " +
                                 std::to_string(c.exact_area).substr(0, 7) + ")"
                           : std::to_string(ref_volume).substr(0, 7) + " (grid " + std::to_string(grid).substr(0, 4) + ")";
      std::printf("| %s | %.0f | %zu | %.2f | %.2f | %+.2f %% | %.2f | %.2f | %+.2f %% | %s | %+.3f %% | %.2f |\n",
                  c.name.c_str(), density, ses.measures.faces, ses.measures.area, m.area,
                  (ses.measures.area / m.area - 1) * 100, ses.measures.volume, m.volume,
                  (ses.measures.volume / m.volume - 1) * 100, reference.c_str(), (m.volume / ref_volume - 1) * 100,
                  ses.seconds.total);
      std::fflush(stdout);
    }
  }
}
