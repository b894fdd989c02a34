// Accuracy of molsurf's solvent-accessible surface against the exact union of balls
// (measure_ball_union): total area and volume at several densities, with and without the
// icosphere area correction, and per-residue area agreement. Prints a Markdown table.
//   accuracy_table STRUCTURE [--probe P] [--density-only] [densities...]
// Defaults: probe 1.4, densities 1 2 4. --density-only: every sphere's frequency from the
// density alone (SphereOptions::min_density_radius = 0), the rule before the radius floor.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/surface_report.hpp"
#include "support/ball_union.hpp"
#include "surface/cleanup.hpp"
#include "surface/solvent_accessible_surface.hpp"

using namespace molsurf;

namespace {

using ResidueKey = std::tuple<std::string, int, char>;

std::map<ResidueKey, double> per_residue(const std::vector<Atom>& atoms, const std::vector<double>& area) {
  std::map<ResidueKey, double> out;
  for (std::size_t i = 0; i < atoms.size(); ++i)
    out[{atoms[i].chain, atoms[i].residue_number, atoms[i].insertion_code}] += area[i];
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: accuracy_table STRUCTURE [--probe P] [--density-only] [densities...]\n");
    return 2;
  }
  std::vector<double> densities;
  double probe = 1.4;
  bool density_only = false;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--probe" && i + 1 < argc) probe = std::atof(argv[++i]);
    else if (arg == "--density-only") density_only = true;
    else densities.push_back(std::atof(argv[i]));
  }
  if (densities.empty()) densities = {1, 2, 4};
  const Structure s = read_structure(argv[1]);
  std::vector<Vec3> centres;
  std::vector<double> radii;
  for (const Atom& a : s.atoms) {
    centres.push_back(a.centre);
    radii.push_back(a.radius + probe);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const BallUnionMeasure exact = measure_ball_union(centres, radii, 4000);
  const double exact_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto exact_residues = per_residue(s.atoms, exact.area_per_ball);
  char rule[96];
  std::snprintf(rule, sizeof rule, "frequency from the density at radius >= %g A", SphereOptions{}.min_density_radius);
  std::printf("%s: %zu atoms, probe %.1f, %s; exact union of balls (4000 slices per ball, %.1f s): area %.2f A^2, "
              "volume %.2f A^3\n\n",
              argv[1], s.atoms.size(), probe,
              density_only ? "frequency from the density alone" : rule,
              exact_seconds, exact.area, exact.volume);
  std::printf("| density | area corrected | faces | area (A^2) | area error | volume (A^3) | volume error | "
              "residues > 10 A^2 within 2%% | surface s |\n|---:|:---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (double density : densities)
    for (bool corrected : {false, true}) {
      SphereUnionOptions o;
      o.spheres.density = density;
      o.spheres.probe = probe;
      o.spheres.area_corrected = corrected;
      if (density_only) o.spheres.min_density_radius = 0;
      const auto t1 = std::chrono::steady_clock::now();
      SphereUnion r = solvent_accessible_surface(s.atoms, o);
      improve_surface(r.mesh);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      const double area = surface_area(r.mesh), volume = signed_volume(r.mesh);
      const auto residues = per_residue(s.atoms, area_per_atom(r.mesh, s.atoms.size()));
      std::size_t exposed = 0, within = 0;
      std::string outside;  // the residues off by more than 2 %, for stderr
      for (const auto& [key, reference] : exact_residues) {
        if (reference <= 10) continue;
        ++exposed;
        const auto it = residues.find(key);
        const double ours = it == residues.end() ? 0 : it->second;
        if (std::abs(ours - reference) <= 0.02 * reference) {
          ++within;
        } else {
          char line[160];
          std::snprintf(line, sizeof line, "  chain %s residue %d%c: %.2f A^2 against %.2f (%+.2f%%)\n",
                        std::get<0>(key).c_str(), std::get<1>(key), std::get<2>(key), ours, reference,
                        100 * (ours - reference) / reference);
          outside += line;
        }
      }
      std::fprintf(stderr, "density %.1f, area corrected %s: residues outside 2 %%:\n%s", density,
                   corrected ? "yes" : "no", outside.c_str());
      std::printf("| %.1f | %s | %zu | %.2f | %+.3f%% | %.2f | %+.3f%% | %zu / %zu (%.1f%%) | %.1f |\n", density,
                  corrected ? "yes" : "no", r.mesh.faces.size(), area, 100 * (area - exact.area) / exact.area, volume,
                  100 * (volume - exact.volume) / exact.volume, within, exposed, 100.0 * within / exposed, seconds);
      std::fflush(stdout);
    }
  return 0;
}
