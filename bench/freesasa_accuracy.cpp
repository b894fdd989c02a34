// Per-atom accuracy of FreeSASA and of molsurf's mesh against the exact per-atom areas of
// the union of the true spheres (compute_areas: r_vdW + probe, analytic), the same atoms
// and the SAME radii for every method. Prints one Markdown table.
//
// FreeSASA 2.1.2 is called through its library (Debian package `freesasa`: libfreesasa.a
// and freesasa.h), freesasa_calc_coord, with molsurf's centres and van der Waals radii as
// doubles, so nothing is rounded on the way. Two checks that the radii (and atoms) are
// really the same:
//  - FreeSASA's total at 2000 Lee & Richards slices must be within 1e-4 (relative) of the
//    exact total ("radii check" line; the row is also in the table);
//  - unless --no-cli-check: the atoms are written as a PDB with molsurf's radius in the
//    occupancy column and the `freesasa` program is run on it (`--radius-from-occupancy
//    --format=pdb --lee-richards --resolution=200`); its per-atom areas (B-factor column,
//    2 decimals) and radii (occupancy column) must equal the library's to their rounding
//    (at probe 0 the program gets 1e-9: it refuses 0).
//
// Rows (errors are per atom, over ALL atoms of the structure, buried ones included):
//   molsurf mesh       facets per atom (compute_surface measures.atom_area: the area of the
//                      faces tagged with the atom) at the default density (2) and cleanup
//   FreeSASA L-R N     Lee & Richards, N slices per atom (20 is FreeSASA's default)
//   FreeSASA S-R 100   Shrake & Rupley, 100 points per atom (FreeSASA's S-R default);
//                      atoms that touch no other sphere are left out of its call, around
//                      a bug of FreeSASA 2.1.2 (isolated_atoms below)
//   molsurf exact      the reference itself, compared against FreeSASA L-R at
//                      --reference-slices (default 20000) as an independent check: there
//                      the columns are exact minus FreeSASA, and the error is FreeSASA's
//                      residual as much as ours
// Columns: p95 and max of |area - exact| (Å²), (total - exact total) / exact total, and
// the method's wall time in this process (molsurf: --threads, all cores by default;
// FreeSASA: its n_threads, 2 by default).
//
// Usage: freesasa_accuracy [--probes "1.4 0"] [--threads N] [--fs-threads N]
//                          [--reference-slices N] [--no-cli-check] [STRUCTURE...]
//   STRUCTURE: a file, or a name in data/pdb (1crn, 2hhb.cif, ...) or in FreeSASA's test
//   data (/usr/share/freesasa/test-data: 1a0q, ...). Default: 1crn 1ubq 2hhb 3pqr 1a0q;
//   1a0q (a Fab-hapten complex, 3209 atoms as molsurf selects them) is the held-out case:
//   it is not in data/pdb nor in the team's shared corpus, and it comes with the package.
//   --reference-slices 0 leaves out the independent check of the exact areas.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include <unistd.h>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"

#include <freesasa.h>

#ifndef MOLSURF_SOURCE_DIR
#define MOLSURF_SOURCE_DIR "."
#endif

namespace {

using namespace molsurf;
namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Errors {
  double p95 = 0, max = 0, total_relative = 0;
};

// Per-atom |a - reference|: the 95th percentile (nearest rank) and the maximum; and the
// relative error of the totals.
Errors compare(const std::vector<double>& a, const std::vector<double>& reference) {
  std::vector<double> d(a.size());
  double total = 0, total_reference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d[i] = std::abs(a[i] - reference[i]);
    total += a[i];
    total_reference += reference[i];
  }
  Errors e;
  if (d.empty()) return e;
  std::sort(d.begin(), d.end());
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(d.size())));
  e.p95 = d[std::max<std::size_t>(rank, 1) - 1];
  e.max = d.back();
  e.total_relative = total_reference != 0 ? (total - total_reference) / total_reference : 0;
  return e;
}

struct FreesasaRun {
  std::vector<double> area;
  double total = 0, seconds = 0;
};

// Atoms that overlap no other sphere, by FreeSASA's own neighbour test (nb.c: neighbours
// when dx*dx + dy*dy + dz*dz < (ri + rj)^2, ri = r_i + probe), with the same double
// arithmetic. FreeSASA 2.1.2's Shrake & Rupley reads the first entry of an atom's
// neighbour list without checking that it has one (sasa_sr.c, sr_atom_area: `a =
// nbi[current_nb]`), an uninitialised index for such an atom: harmless by luck with
// glibc's malloc, a segmentation fault with mimalloc (molsurf's allocator) on 2hhb at
// probe 0, where the lone phosphorus atoms of PO4 touch nothing.
std::vector<bool> isolated_atoms(const std::vector<double>& xyz, const std::vector<double>& radii, double probe) {
  const std::size_t n = radii.size();
  std::vector<double> r(n);
  double cell = 0;
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = radii[i] + probe;
    cell = std::max(cell, 2 * r[i]);
  }
  std::vector<bool> isolated(n, true);
  if (n == 0 || cell <= 0) return isolated;
  auto key = [&](std::size_t i, int dx, int dy, int dz) {
    const auto c = [&](int axis, int d) { return static_cast<std::int64_t>(std::floor(xyz[3 * i + axis] / cell)) + d; };
    return ((c(0, dx) * 73856093) ^ (c(1, dy) * 19349663) ^ (c(2, dz) * 83492791));
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < n; ++i) grid[key(i, 0, 0, 0)].push_back(i);
  for (std::size_t i = 0; i < n; ++i)
    for (int dx = -1; dx <= 1 && isolated[i]; ++dx)
      for (int dy = -1; dy <= 1 && isolated[i]; ++dy)
        for (int dz = -1; dz <= 1 && isolated[i]; ++dz) {
          const auto it = grid.find(key(i, dx, dy, dz));
          if (it == grid.end()) continue;  // (a hash collision only adds candidates)
          for (const std::size_t j : it->second) {
            if (j == i) continue;
            const double cut2 = (r[i] + r[j]) * (r[i] + r[j]);
            const double ex = xyz[3 * j] - xyz[3 * i], ey = xyz[3 * j + 1] - xyz[3 * i + 1],
                         ez = xyz[3 * j + 2] - xyz[3 * i + 2];
            if (ex * ex + ey * ey + ez * ez < cut2) {
              isolated[i] = false;
              break;
            }
          }
        }
  return isolated;
}

FreesasaRun run_freesasa(const std::vector<double>& xyz, const std::vector<double>& radii, double probe,
                         freesasa_algorithm algorithm, int resolution, int threads) {
  if (algorithm == FREESASA_SHRAKE_RUPLEY) {
    // Around the bug above: the isolated atoms are left out of the call (they are no
    // atom's neighbour, so the others' areas do not change) and get what a correct S&R
    // gives them, every test point exposed: 4 pi (r + probe)^2.
    const std::vector<bool> isolated = isolated_atoms(xyz, radii, probe);
    if (std::find(isolated.begin(), isolated.end(), true) != isolated.end()) {
      std::vector<double> sub_xyz, sub_radii;
      std::vector<std::size_t> index;
      for (std::size_t i = 0; i < radii.size(); ++i)
        if (!isolated[i]) {
          sub_xyz.insert(sub_xyz.end(), {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
          sub_radii.push_back(radii[i]);
          index.push_back(i);
        }
      FreesasaRun out;
      out.area.assign(radii.size(), 0);
      for (std::size_t i = 0; i < radii.size(); ++i)
        if (isolated[i]) out.area[i] = 4 * std::numbers::pi * (radii[i] + probe) * (radii[i] + probe);
      if (!index.empty()) {
        FreesasaRun sub = run_freesasa(sub_xyz, sub_radii, probe, algorithm, resolution, threads);
        for (std::size_t k = 0; k < index.size(); ++k) out.area[index[k]] = sub.area[k];
        out.seconds = sub.seconds;
      }
      for (const double a : out.area) out.total += a;
      return out;
    }
  }
  freesasa_parameters p = freesasa_default_parameters;
  p.alg = algorithm;
  p.probe_radius = probe;
  if (algorithm == FREESASA_LEE_RICHARDS) p.lee_richards_n_slices = resolution;
  else p.shrake_rupley_n_points = resolution;
  p.n_threads = threads;
  const auto t0 = std::chrono::steady_clock::now();
  freesasa_result* r = freesasa_calc_coord(xyz.data(), radii.data(), static_cast<int>(radii.size()), &p);
  FreesasaRun out;
  out.seconds = seconds_since(t0);
  if (!r) throw std::runtime_error("freesasa_calc_coord failed");
  out.area.assign(r->sasa, r->sasa + r->n_atoms);
  out.total = r->total;
  freesasa_result_free(r);
  return out;
}

// The atoms as PDB ATOM records with the van der Waals radius in the occupancy column (3
// decimals; the built-in radius sets have 2), for `freesasa --radius-from-occupancy`.
void write_radius_pdb(const std::vector<Atom>& atoms, const fs::path& path) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw std::runtime_error("cannot write " + path.string());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const std::string name = a.atom_name.size() < 4 ? " " + a.atom_name : a.atom_name.substr(0, 4);
    const char chain = a.chain.empty() ? 'A' : a.chain[0];
    std::fprintf(out, "ATOM  %5zu %-4s %3.3s %c%4d%c   %8.3f%8.3f%8.3f%6.3f%6.2f          %2.2s\n",
                 (i + 1) % 100000, name.c_str(), a.residue_name.c_str(), chain, a.residue_number % 10000,
                 a.insertion_code, a.centre.x, a.centre.y, a.centre.z, a.radius, 0.0, a.element.c_str());
  }
  std::fprintf(out, "END\n");
  if (std::fclose(out) != 0) throw std::runtime_error("cannot write " + path.string());
}

// The `freesasa` program on the radius PDB, per-atom output: (radius, area) per ATOM record.
struct CliAtom {
  double radius, area;
};
// The program refuses --probe-radius=0 ("probe radius must be 0 or larger", 2.1.2), so
// probe 0 is passed as 1e-9 A, which moves no area by a printed digit.
std::vector<CliAtom> run_freesasa_cli(const fs::path& pdb, double probe, int slices, int threads) {
  if (probe == 0) probe = 1e-9;
  char command[1024];
  std::snprintf(command, sizeof command,
                "freesasa --radius-from-occupancy --format=pdb --lee-richards --resolution=%d --probe-radius=%.17g "
                "--n-threads=%d --no-warnings '%s'",
                slices, probe, threads, pdb.c_str());
  std::FILE* in = popen(command, "r");
  if (!in) throw std::runtime_error("cannot run freesasa");
  std::vector<CliAtom> atoms;
  char line[256];
  while (std::fgets(line, sizeof line, in)) {
    const std::string s = line;
    if (s.rfind("ATOM  ", 0) != 0 || s.size() < 66) continue;
    atoms.push_back({std::atof(s.substr(54, 6).c_str()), std::atof(s.substr(60, 6).c_str())});
  }
  if (pclose(in) != 0) throw std::runtime_error(std::string("freesasa failed: ") + command);
  return atoms;
}

fs::path resolve(const std::string& name) {
  if (fs::exists(name)) return name;
  for (const fs::path& dir : {fs::path(MOLSURF_SOURCE_DIR) / "data/pdb", fs::path("/usr/share/freesasa/test-data")})
    for (const char* ext : {"", ".pdb", ".cif", ".cif.gz", ".pdb.gz"})
      if (fs::exists(dir / (name + ext))) return dir / (name + ext);
  throw std::runtime_error("no structure " + name);
}

std::string stem(const fs::path& path) {
  std::string s = path.filename().string();
  for (const char* ext : {".gz", ".pdb", ".cif"})
    if (s.size() > std::string(ext).size() && s.ends_with(ext)) s.resize(s.size() - std::string(ext).size());
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> probes = {1.4, 0};
  int threads = 0, fs_threads = 2, reference_slices = 20000;
  bool cli_check = true;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--probes" && has_value) {
      probes.clear();
      std::string list = argv[++i];
      for (char& c : list)
        if (c == ',') c = ' ';
      char* p = list.data();
      while (*p) {
        char* end = nullptr;
        const double v = std::strtod(p, &end);
        if (end == p) break;
        probes.push_back(v);
        p = end;
      }
    } else if (arg == "--threads" && has_value) threads = std::atoi(argv[++i]);
    else if (arg == "--fs-threads" && has_value) fs_threads = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--reference-slices" && has_value) reference_slices = std::atoi(argv[++i]);
    else if (arg == "--no-cli-check") cli_check = false;
    else if (arg == "-h" || arg == "--help") {
      std::printf("usage: freesasa_accuracy [--probes \"1.4 0\"] [--threads N] [--fs-threads N] "
                  "[--reference-slices N] [--no-cli-check] [STRUCTURE...]\n");
      return 0;
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "freesasa_accuracy: unknown argument %s\n", argv[i]);
      return 2;
    } else names.push_back(arg);
  }
  if (names.empty()) names = {"1crn", "1ubq", "2hhb", "3pqr", "1a0q"};
  freesasa_set_verbosity(FREESASA_V_NOWARNINGS);

  fs::path work;
  if (cli_check) {
    std::string dir = (fs::temp_directory_path() / "freesasa_accuracy.XXXXXX").string();
    if (!mkdtemp(dir.data())) {
      std::fprintf(stderr, "freesasa_accuracy: mkdtemp failed\n");
      return 1;
    }
    work = dir;
  }
  int status = 0;
  std::vector<std::string> rows, notes;
  try {
    for (const std::string& name : names) {
      const fs::path file = resolve(name);
      const Structure structure = read_structure(file);  // molsurf's default selection
      const std::vector<Atom>& atoms = structure.atoms;
      const std::string label = stem(file);
      std::vector<double> xyz, radii;
      for (const Atom& a : atoms) {
        xyz.insert(xyz.end(), {a.centre.x, a.centre.y, a.centre.z});
        radii.push_back(a.radius);
      }
      fs::path radius_pdb;
      if (cli_check) {
        radius_pdb = work / (label + ".radii.pdb");
        write_radius_pdb(atoms, radius_pdb);
      }
      for (const double probe : probes) {
        std::fprintf(stderr, "freesasa_accuracy: %s (%zu atoms), probe %g\n", label.c_str(), atoms.size(), probe);
        SphereOptions spheres;
        spheres.probe = probe;
        auto t0 = std::chrono::steady_clock::now();
        const ComputedAreas exact_run = compute_areas(atoms, spheres, threads);
        const double exact_seconds = seconds_since(t0);
        const std::vector<double>& exact = exact_run.arrangement.area_per_sphere;
        const double exact_total = exact_run.arrangement.area;

        auto row = [&](const std::string& method, const std::string& reference, const Errors& e, double seconds) {
          char line[512];
          std::snprintf(line, sizeof line, "| %s | %zu | %.1f | %s | %s | %.3g | %.3g | %+.2e | %.3f |", label.c_str(),
                        atoms.size(), probe, method.c_str(), reference.c_str(), e.p95, e.max, e.total_relative,
                        seconds);
          rows.push_back(line);
          std::fprintf(stderr, "%s\n", line);  // progress; the table is printed at the end
        };

        // molsurf's mesh at the default density (its own exact areas are computed above).
        ComputeSurfaceOptions options;
        options.spheres = spheres;
        options.threads = threads;
        options.exact_areas = false;
        options.source = file;
        try {
          const ComputedSurface surface = compute_surface(atoms, options);
          char method[96];
          std::snprintf(method, sizeof method, "molsurf mesh, density %g (%zu faces)", spheres.density,
                        surface.measures.faces);
          row(method, "exact", compare(surface.measures.atom_area, exact), surface.seconds.total);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "freesasa_accuracy: %s probe %g: mesh failed: %s\n", label.c_str(), probe, e.what());
          char line[256];
          std::snprintf(line, sizeof line, "| %s | %zu | %.1f | molsurf mesh | exact | failed | | | |", label.c_str(),
                        atoms.size(), probe);
          rows.push_back(line);
          status = 1;
        }

        // FreeSASA at its usual settings.
        for (const int slices : {20, 200}) {
          const FreesasaRun r = run_freesasa(xyz, radii, probe, FREESASA_LEE_RICHARDS, slices, fs_threads);
          row("FreeSASA L-R " + std::to_string(slices) + " slices", "exact", compare(r.area, exact), r.seconds);
          if (cli_check && slices == 200) {
            // The brief's path: the radius PDB through the freesasa program.
            const std::vector<CliAtom> cli = run_freesasa_cli(radius_pdb, probe, slices, fs_threads);
            double max_area = 0, max_radius = 0;
            if (cli.size() != atoms.size()) {
              notes.push_back(label + ": freesasa program read " + std::to_string(cli.size()) + " atoms of " +
                              std::to_string(atoms.size()));
              status = 1;
            } else {
              for (std::size_t i = 0; i < cli.size(); ++i) {
                max_area = std::max(max_area, std::abs(cli[i].area - r.area[i]));
                max_radius = std::max(max_radius, std::abs(cli[i].radius - radii[i]));
              }
              char note[256];
              const bool ok = max_area <= 0.0051 && max_radius <= 0.0051;
              std::snprintf(note, sizeof note,
                            "%s probe %.1f: freesasa program on the radius PDB (--radius-from-occupancy, 200 slices) "
                            "vs the library: max |radius diff| %.3f A, max |area diff| %.4f A^2: %s",
                            label.c_str(), probe, max_radius, max_area, ok ? "same (to its 2 decimals)" : "DIFFERENT");
              notes.push_back(note);
              if (!ok) status = 1;
            }
          }
        }
        {
          const FreesasaRun r = run_freesasa(xyz, radii, probe, FREESASA_SHRAKE_RUPLEY, 100, fs_threads);
          row("FreeSASA S-R 100 points", "exact", compare(r.area, exact), r.seconds);
        }
        {
          // The radii check: at 2000 slices FreeSASA's total is within 1e-4 of the exact total.
          const FreesasaRun r = run_freesasa(xyz, radii, probe, FREESASA_LEE_RICHARDS, 2000, fs_threads);
          row("FreeSASA L-R 2000 slices", "exact", compare(r.area, exact), r.seconds);
          const double rel = (r.total - exact_total) / exact_total;
          const bool ok = std::abs(rel) <= 1e-4;
          char note[256];
          std::snprintf(note, sizeof note,
                        "%s probe %.1f: radii check: FreeSASA L-R 2000 total %.3f A^2, exact %.3f A^2, relative %+.2e: %s",
                        label.c_str(), probe, r.total, exact_total, rel, ok ? "pass (|rel| <= 1e-4)" : "FAIL");
          notes.push_back(note);
          if (!ok) status = 1;
        }
        if (reference_slices > 0) {
          const FreesasaRun r = run_freesasa(xyz, radii, probe, FREESASA_LEE_RICHARDS, reference_slices, fs_threads);
          row("molsurf exact (compute_areas)", "FreeSASA L-R " + std::to_string(reference_slices),
              compare(exact, r.area), exact_seconds);
        } else {
          row("molsurf exact (compute_areas)", "itself", Errors{}, exact_seconds);
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "freesasa_accuracy: %s\n", e.what());
    status = 1;
  }
  if (!work.empty()) fs::remove_all(work);

  std::printf("\n| structure | atoms | probe Å | method | reference | p95 abs err Å² | max abs err Å² | total rel err | s |\n"
              "|---|---:|---:|---|---|---:|---:|---:|---:|\n");
  for (const std::string& r : rows) std::printf("%s\n", r.c_str());
  std::printf("\nPer-atom errors over all atoms (buried ones included). Same atoms and radii for every method "
              "(molsurf's default selection, ProtOr). molsurf threads: %s; FreeSASA 2.1.2 (its library) threads: %d. "
              "Times are wall seconds in this process.\n",
              threads > 0 ? std::to_string(threads).c_str() : "all cores", fs_threads);
  for (const std::string& n : notes) std::printf("- %s\n", n.c_str());
  return status;
}
