#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/commands.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/report.hpp"
#include "molsurf/surface_report.hpp"
#include "io/atomic_file.hpp"

namespace molsurf::cli {

void SurfaceCommand::add_options(CLI::App& app) {
  app.add_option("STRUCTURE", structure,
                 "Structure file: PDB (.pdb .ent), mmCIF (.cif .mmcif), either gzipped (.gz),\n"
                 "PQR (.pqr: radius column used) or MSMS sphere list (.xyzr: x y z r [name])")
      ->check(CLI::ExistingFile);
  app.add_option("-o,--output", output,
                 "Surface file; the format follows the extension: .vtp .vtk .ply .off .stl .obj,\n"
                 ".vert (MSMS .vert/.face pair), .msh (gmsh 2.2). Default: STEM.vtp in the current directory");

  auto* input = "Structure selection";
  app.add_option("--model", read.model, "Model number as written in the file (default: the first model)")
      ->group(input);
  app.add_option("--chains", chains, "Keep only these chains, comma-separated (e.g. A,C); default: all")
      ->group(input);
  app.add_flag("--keep-water", read.keep_water, "Keep water molecules (dropped by default)")->group(input);
  app.add_flag("--hydrogens", read.keep_hydrogens, "Keep hydrogen and deuterium atoms (dropped by default)")
      ->group(input);
  app.add_flag("--no-hetatm", [this](std::int64_t) { read.keep_hetatm = false; },
               "Drop hetero atoms: ligands, ions, cofactors (kept by default, e.g. haem)")
      ->group(input);
  app.add_option("--radius-set", read.radius_set,
                 "Built-in radii: protor (Tsai et al. 1999, by residue and atom) or bondi (by element)")
      ->check(CLI::IsMember({"protor", "bondi"}))
      ->capture_default_str()
      ->group(input);
  app.add_option("--radii", read.radius_file, "User radius table (format: docs/radii.md); overrides --radius-set")
      ->check(CLI::ExistingFile)
      ->group(input);

  auto* sphere = "Spheres";
  app.add_option("--probe", spheres.probe, "Probe radius in angstrom added to every atom; 0 gives the vdW surface")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--density", spheres.density,
                 "Icosphere vertices per square angstrom of sphere surface (MSMS's convention)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--frequency", spheres.frequency,
                 "Fixed icosphere frequency n for every atom (20 n^2 faces); overrides --density")
      ->check(CLI::Range(1, 200))
      ->group(sphere);
  app.add_flag("--inscribed", [this](std::int64_t) { spheres.area_corrected = false; },
               "Put icosphere vertices on the true spheres (inscribed polyhedra: about 1 % less volume).\n"
               "Default: each icosphere scaled so its area equals the sphere's (docs/accuracy.md)")
      ->group(sphere);

  auto* output_group = "Output and reports";
  app.add_flag("--outer-only", outer_only, "Keep the outer surface only, without cavities (as MSMS does by default)")
      ->group(output_group);
  app.add_option("--json", json, "Write the report as JSON to this file")->group(output_group);
  app.add_option("--per-atom", per_atom, "Write each atom's area (A^2) to this CSV file")->group(output_group);
  app.add_option("--per-residue", per_residue, "Write each residue's area (A^2) to this CSV file")
      ->group(output_group);
  app.add_flag("--no-cleanup", skip_cleanup,
               "Skip the surface improvement (paper 2.5: collapse of slivers under 5 degrees)")
      ->group(output_group);
  app.add_flag("--no-check", skip_check,
               "Skip the exact self-intersection test of the surface before it is written (closed and\n"
               "manifold are still checked); by default a surface that fails is not written")
      ->group(output_group);
  app.add_option("--method", method,
                 "How the spheres are joined: one-pass (each atom trimmed by its neighbours, all atoms in\n"
                 "parallel) or pairwise (hierarchical pairwise union, the paper's formulation; the reference)")
      ->check(CLI::IsMember({"one-pass", "pairwise"}))
      ->capture_default_str();
  app.add_option("--threads", threads, "Threads for the union (default: all cores); the result does not depend on it")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
}

namespace {

// A one-line progress bar on stderr, drawn only when stderr is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled && isatty(STDERR_FILENO)) {}
  ~ProgressBar() {
    if (drawn_) std::fprintf(stderr, "\r%60s\r", "");
  }
  void update(std::size_t done, std::size_t total) {
    if (!enabled_ || total == 0) return;
    const int width = 30, filled = static_cast<int>(width * done / total);
    std::fprintf(stderr, "\rsurface [%s%s] %zu/%zu", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), done, total);
    std::fflush(stderr);
    drawn_ = true;
  }

 private:
  bool enabled_;
  bool drawn_ = false;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int SurfaceCommand::run() const {
  std::filesystem::path out = output;
  if (out.empty()) {
    std::filesystem::path stem = structure.filename();
    while (stem.has_extension()) stem = stem.stem();  // 1crn.cif.gz -> 1crn
    out = stem.string() + ".vtp";
  }
  mesh_format_from_path(out);  // reject an unknown extension before any work

  ReadOptions options = read;
  std::stringstream list(chains);
  for (std::string chain; std::getline(list, chain, ',');)
    if (!chain.empty()) options.chains.push_back(chain);

  if (threads > 0) omp_set_num_threads(threads);  // for every parallel loop, the engine's too
  SurfaceReport report;
  auto clock = std::chrono::steady_clock::now();
  const Structure s = read_structure(structure, options);
  report.seconds.read = seconds_since(clock);
  const SpherePlan plan = plan_spheres(s.atoms, spheres);
  if (!quiet) std::cout << format_read_report(s.report) << format_sphere_plan(plan, spheres) << std::flush;

  SurfaceOptions surface_options;
  surface_options.spheres = spheres;
  surface_options.threads = threads;
  surface_options.method = method == "pairwise" ? SurfaceMethod::pairwise : SurfaceMethod::one_pass;
  std::optional<CleanupStats> cleanup;
  MeshCheckOptions check_options;
  check_options.self_intersections = !skip_check;
  auto compute = [&](SurfaceMethod chosen) {
    surface_options.method = chosen;
    auto clock = std::chrono::steady_clock::now();
    ProgressBar bar(!quiet);
    surface_options.progress = [&](std::size_t done, std::size_t total) { bar.update(done, total); };
    SurfaceResult sas = solvent_accessible_surface(s.atoms, surface_options);
    if (!sas.fallback.empty() && !quiet) std::cerr << "molsurf: note: " << sas.fallback << "\n";
    Mesh mesh = outer_only ? outer_surface_only(sas.mesh) : std::move(sas.mesh);
    report.seconds.surface += seconds_since(clock);
    clock = std::chrono::steady_clock::now();
    cleanup.reset();
    if (!skip_cleanup) cleanup = improve_surface(mesh);
    report.seconds.cleanup += seconds_since(clock);
    clock = std::chrono::steady_clock::now();
    MeshCheck verdict = check_mesh(mesh, check_options);
    report.seconds.check += seconds_since(clock);
    return std::pair{std::move(mesh), std::move(verdict)};
  };
  auto [surface, check] = compute(surface_options.method);
  if (!check.valid() && surface_options.method == SurfaceMethod::one_pass) {
    // The one-pass surface rounded to doubles can fail where the pairwise one, which
    // repairs rounding between merges, does not: the reference method is the fallback.
    if (!quiet) std::cerr << "molsurf: note: the one-pass surface failed its check; using the pairwise union\n";
    std::tie(surface, check) = compute(SurfaceMethod::pairwise);
  }
  if (!check.valid()) {
    // The promise is a valid surface or none: nothing is written.
    std::string why;
    for (const std::string& d : check.defects()) why += "\n  - " + d;
    throw Error(out.string() + ": not written: the computed surface failed its check (a molsurf bug; please "
                "report it with the input file and options):" + why);
  }

  clock = std::chrono::steady_clock::now();
  MeshWriteOptions write_options;
  write_options.atoms = s.atoms;
  write_options.probe_radius = spheres.probe;
  write_options.density = spheres.density;
  write_mesh(out, surface, write_options);
  const std::vector<double> atom_area = area_per_atom(surface, s.atoms.size());
  if (!per_atom.empty()) write_per_atom_csv(per_atom, s.atoms, atom_area);
  if (!per_residue.empty()) write_per_residue_csv(per_residue, s.atoms, atom_area);
  report.seconds.write = seconds_since(clock);

  const SurfaceReport measured = make_surface_report(surface, check);
  report.faces = measured.faces;
  report.vertices = measured.vertices;
  report.area = measured.area;
  report.volume = measured.volume;
  report.components = measured.components;
  report.quality = measured.quality;
  report.cleanup = cleanup;
  report.valid = measured.valid;
  report.defects = measured.defects;
  report.input = s.report;
  report.spheres = spheres;
  report.threads = threads > 0 ? threads : omp_get_max_threads();
  report.output = out;
  report.outer_only = outer_only;
  if (!json.empty()) write_file_atomically(json, surface_report_json(report));
  if (!quiet) std::cout << "\n" << format_surface_report(report);
  return 0;
}

}  // namespace molsurf::cli
