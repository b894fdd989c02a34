// Time of each stage of compute_surface on one structure: the median of several runs in
// one process, and the process's peak memory. One tab-separated line per structure, for
// bench/surface_stage_table.sh (which runs one process per thread count, so that each
// peak is that setting's own).
//
// It also writes the structure's atoms as a PDB whose occupancy column holds each atom's
// radius, so that FreeSASA (`--radius-from-occupancy`) uses the same spheres.
//
// Usage: surface_stage_times STRUCTURE [--threads N] [--repeat N] [--probe P] [--density D] [--header]
//        surface_stage_times STRUCTURE --write-radius-pdb FILE
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"

namespace {

using namespace molsurf;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024;  // ru_maxrss is in KiB on Linux
}

// PDB ATOM records (fixed columns) with the radius in the occupancy field. Every atom is
// an ATOM record (no --hetatm needed); serial numbers and chain IDs are only cosmetic
// here and are cut to fit their columns. Radii are printed with 3 decimals: the built-in
// sets have 2, so FreeSASA gets molsurf's radii exactly (a warning says otherwise).
int write_radius_pdb(const std::vector<Atom>& atoms, const char* path) {
  std::FILE* out = std::fopen(path, "w");
  if (!out) {
    std::fprintf(stderr, "surface_stage_times: cannot write %s\n", path);
    return 1;
  }
  std::size_t rounded = 0;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    if (a.radius >= 100 || std::abs(a.radius * 1000 - std::round(a.radius * 1000)) > 1e-6) ++rounded;
    const std::string name = a.atom_name.size() < 4 ? " " + a.atom_name : a.atom_name.substr(0, 4);
    const char chain = a.chain.empty() ? 'A' : a.chain[0];
    std::fprintf(out, "ATOM  %5zu %-4s %3.3s %c%4d%c   %8.3f%8.3f%8.3f%6.3f%6.2f          %2.2s\n",
                 (i + 1) % 100000, name.c_str(), a.residue_name.c_str(), chain, a.residue_number % 10000,
                 a.insertion_code, a.centre.x, a.centre.y, a.centre.z, a.radius, a.b_factor, a.element.c_str());
  }
  std::fprintf(out, "END\n");
  if (std::fclose(out) != 0) {
    std::fprintf(stderr, "surface_stage_times: cannot write %s\n", path);
    return 1;
  }
  if (rounded > 0)
    std::fprintf(stderr, "surface_stage_times: warning: %zu radii rounded to 3 decimals for FreeSASA\n", rounded);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: surface_stage_times STRUCTURE [--threads N] [--repeat N] [--probe P] [--density D] "
                 "[--header]\n       surface_stage_times STRUCTURE --write-radius-pdb FILE\n");
    return 2;
  }
  ComputeSurfaceOptions options;
  int repeat = 5;
  bool header = false;
  const char* radius_pdb = nullptr;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--threads" && has_value) options.threads = std::atoi(argv[++i]);
    else if (arg == "--repeat" && has_value) repeat = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--probe" && has_value) options.spheres.probe = std::atof(argv[++i]);
    else if (arg == "--density" && has_value) options.spheres.density = std::atof(argv[++i]);
    else if (arg == "--write-radius-pdb" && has_value) radius_pdb = argv[++i];
    else if (arg == "--header") header = true;
    else {
      std::fprintf(stderr, "surface_stage_times: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  try {
    const Structure structure = read_structure(argv[1]);  // molsurf's default selection
    if (radius_pdb) return write_radius_pdb(structure.atoms, radius_pdb);
    options.source = argv[1];

    std::vector<double> union_s, cleanup_s, check_s, measures_s, total_s;
    ComputedSurface last;
    for (int run = 0; run < repeat; ++run) {
      last = {};  // freed first: the peak is one run's
      last = compute_surface(structure.atoms, options);
      union_s.push_back(last.seconds.union_);
      cleanup_s.push_back(last.seconds.cleanup);
      check_s.push_back(last.seconds.check);
      measures_s.push_back(last.seconds.measures);
      total_s.push_back(last.seconds.total);
    }
    if (header)
      std::printf("atoms\tfaces\tvertices\tthreads\truns\tunion_s\tcleanup_s\tcheck_s\tmeasures_s\ttotal_s\t"
                  "peak_mib\tarea\tvolume\tmethod\n");
    std::printf("%zu\t%zu\t%zu\t%d\t%d\t%.4f\t%.4f\t%.4f\t%.4f\t%.4f\t%.0f\t%.3f\t%.3f\t%s\n", structure.atoms.size(),
                last.measures.faces, last.measures.vertices, last.threads, repeat, median(union_s), median(cleanup_s),
                median(check_s), median(measures_s), median(total_s), peak_memory_mib(), last.measures.area,
                last.measures.volume, surface_method_name(last.method));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "surface_stage_times: %s\n", e.what());
    return 1;
  }
  return 0;
}
