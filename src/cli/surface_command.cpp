#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <span>
#include <iostream>
#include <sstream>
#include <thread>

#include "cli/allocation.hpp"
#include "cli/commands.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/freesasa_formats.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/report.hpp"
#include "molsurf/surface_report.hpp"
#include "molsurf/output_files.hpp"
#include "molsurf/resource_limits.hpp"
#include "molsurf/sasa_structure.hpp"
#include "io/standard_output.hpp"
#include "molsurf/split_components.hpp"
#include "molsurf/threads.hpp"
#include "molsurf/volume_mesh.hpp"
#include "molsurf/written_check.hpp"
#include "cli/validators.hpp"

namespace molsurf::cli {

void SurfaceCommand::add_options(CLI::App& app) {
  app.add_option("STRUCTURE", structure,
                 "Structure file: PDB (.pdb .ent), mmCIF (.cif .mmcif), either gzipped (.gz),\n"
                 "PQR (.pqr: radius column used) or MSMS sphere list (.xyzr: x y z r [name])")
      ->check(readable_file());
  output_option = app.add_option("-o,--output", output,
                                 "Surface file; the format follows the extension: .vtp .vtk .ply .off .stl .obj,\n"
                                 ".vert (MSMS .vert/.face pair), .msh (gmsh 2.2). Default: STEM.vtp in the current "
                                 "directory.\nNever a symbolic link, device or an input file (refused)");

  auto* input = "Structure selection";
  app.add_option("--model", read.model, "Model number as written in the file (default: the first model)")
      ->group(input);
  app.add_option("--chains", chains, "Keep only these chains, comma-separated (e.g. A,C); default: all")
      ->group(input);
  app.add_flag("--keep-water", read.keep_water, "Keep water molecules (dropped by default)")->group(input);
  app.add_flag("--all-models", all_models,
               "Every model of the file (NMR ensembles, trajectories as multi-model files), with --areas-only:\n"
               "one line and one JSON entry ('models') per model, a 'model' column in the CSV tables")
      ->group(input);
  app.add_flag("--hydrogens", read.keep_hydrogens, "Keep hydrogen and deuterium atoms (dropped by default)")
      ->group(input);
  app.add_flag("--no-hetatm", [this](std::int64_t) { read.keep_hetatm = false; },
               "Drop hetero atoms: ligands, ions, cofactors (kept by default, e.g. haem)")
      ->group(input);
  app.add_option("--radius-set", read.radius_set,
                 "Built-in radii: protor (Tsai et al. 1999, by residue and atom), naccess (NACCESS's, as\n"
                 "FreeSASA has them) or bondi (by element)")
      ->check(CLI::IsMember({"protor", "naccess", "bondi"}))
      ->capture_default_str()
      ->group(input);
  // FreeSASA's spellings: --radii=protor|naccess names a built-in set, --config-file a file.
  app.add_option_function<std::string>(
         "--radii,--config-file",
         [this](const std::string& value) {
           if (RadiusTable::is_builtin(value)) {
             read.radius_set = value;
             read.radius_file.clear();
           } else {
             read.radius_file = value;
           }
         },
         "Radius table: a built-in set's name (protor, naccess, bondi: as --radius-set), or a file in\n"
         "molsurf's format or FreeSASA's classifier configuration, whose polar/apolar classes are used\n"
         "too (docs/radii.md; a file named like a set: ./NAME); overrides --radius-set")
      ->check(CLI::Validator(
          [](std::string& value) {
            return RadiusTable::is_builtin(value) ? std::string() : readable_file()(value);
          },
          "SET|FILE"))
      ->group(input);

  auto* sphere = "Spheres";
  app.add_option("--surface", surface,
                 "Which surface: sas (solvent accessible: spheres of r_vdW + probe), ses (solvent excluded, the "
                 "molecular surface BEM solvers use: where the rolling probe touches the atoms) or vdw (van der "
                 "Waals: the same as --probe 0)")
      ->check(CLI::IsMember({"sas", "ses", "vdw"}))
      ->capture_default_str()
      ->group(sphere);
  auto* probe_option =
      app.add_option("--probe", spheres.probe,
                     "Probe radius in angstrom: added to every atom for the SAS, the rolling ball for the SES; 0 gives "
                     "the vdW surface")
          ->check(finite_number(0, 1e15))
      ->capture_default_str()
      ->group(sphere);
  // The surface kind settles the probe the spheres get, before anything reads it.
  app.parse_complete_callback([this, probe_option] {
    if (surface == "vdw") {
      if (probe_option->count() > 0 && spheres.probe != 0)
        throw CLI::ValidationError("--surface vdw", "is the surface at probe 0: drop --probe");
      spheres.probe = 0;
    } else if (surface == "ses") {
      if (spheres.probe == 0)
        throw CLI::ValidationError("--surface ses",
                                   "needs a probe radius above 0 (at 0 it is the van der Waals surface: --surface vdw)");
    }
  });
  std::ostringstream density_help;
  density_help << "Icosphere vertices per square angstrom of sphere surface (MSMS's convention); a sphere under "
               << spheres.min_density_radius << " A gets the frequency of one of " << spheres.min_density_radius
               << " A (van der Waals spheres: docs/accuracy.md)";
  app.add_option("--density", spheres.density, density_help.str())
      ->check(finite_number(0, 1e9, true))
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--frequency", spheres.frequency,
                 "Fixed icosphere frequency n for every atom (20 n^2 faces); overrides --density")
      ->check(whole_number(1, 200))
      ->group(sphere);
  app.add_option("--max-faces", max_faces,
                 "Refuse to start when the spheres would have more faces than this before the union\n"
                 "(about 80 bytes of memory each; the 272k-atom capsid at density 4 has 253 million)")
      ->check(whole_number(1, 100'000'000'000))
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--max-memory", max_memory_gb,
                 "Refuse to start the union when the surface would need more memory than this many GB\n"
                 "(estimated from a sample of atoms, about 180 bytes per face), and a structure whose text\n"
                 "(decompressed) would need more to read (16 bytes per byte); default: this machine's memory")
      ->check(finite_number(0, 1e9, true))
      ->group(sphere);
  auto* volume_group = "Volume mesh around the molecule (paper section 3.4)";
  volume_option = app.add_option("--volume-mesh", volume_mesh,
                                 "Also write tetrahedra filling the space between the surface and a box, as gmsh\n"
                                 ".msh 2.2 (regions and boundaries tagged; docs/volume_mesh.md)")
                      ->group(volume_group);
  app.add_option("--box-margin", box_margin, "Angstrom between the molecule's bounding box and the outer box")
      ->check(finite_number(0, 1e6, true))
      ->capture_default_str()
      ->group(volume_group);
  app.add_option("--volume-size", volume_size,
                 "Tetrahedron size at the box in angstrom (default: the margin / 3, at least 1); near the\n"
                 "molecule the tetrahedra follow its triangles")
      ->check(finite_number(0, 1e6, true))
      ->group(volume_group);
  app.add_flag("--fill-inside", fill_inside,
               "Also fill the molecule's inside: the solute region, and each cavity as its own region")
      ->group(volume_group);
  app.add_flag("--inscribed", [this](std::int64_t) { spheres.area_corrected = false; },
               "Put icosphere vertices on the true spheres (inscribed polyhedra: about 1 % less volume).\n"
               "Default: each icosphere scaled so its area equals the sphere's (docs/accuracy.md)")
      ->group(sphere);

  auto* output_group = "Output and reports";
  app.add_flag("--outer-only", outer_only, "Keep the outer surface only, without cavities (as MSMS does by default)")
      ->group(output_group);
  app.add_flag("--split-components", split_components,
               "One file per closed surface: NAME.outer.EXT and NAME.cavity-K.EXT (K from 1, largest cavity\n"
               "first, as in the report) for -o NAME.EXT, each closed and outward on its own")
      ->group(output_group);
  app.add_flag("--ascii", ascii, "Write .ply and .stl as text (binary by default); tetgen needs ASCII PLY")
      ->group(output_group);
  app.add_flag("--no-header", no_header,
               "MSMS .vert/.face: data rows only, all numeric (no header lines, no atom-name column),\n"
               "as numpy.loadtxt readers such as PyGBe need")
      ->group(output_group);
  json_option = app.add_option("--json", json, "Write the report as JSON to this file ('-': standard output)")
                    ->group(output_group);
  per_atom_option =
      app.add_option("--per-atom", per_atom, "Write each atom's area (A^2) to this CSV file ('-': standard output)")
          ->group(output_group);
  per_residue_option = app.add_option("--per-residue", per_residue,
                                      "Write each residue's area (A^2) to this CSV file ('-': standard output)")
                           ->group(output_group);
  per_chain_option = app.add_option("--per-chain", per_chain,
                                    "Write each chain's area (A^2) to this CSV file ('-': standard output)")
                         ->group(output_group);
  sasa_structure_option =
      app.add_option("--sasa-structure", sasa_structure,
                     "Write the structure with each atom's area (A^2) in the B-factor column and its radius in\n"
                     "the occupancy column, as FreeSASA's --format=pdb does: FILE.pdb or FILE.cif")
          ->group(output_group);
  app.add_flag("--relative", relative,
               "Add relative SASA per residue (area / the residue type's maximum, Tien et al. 2013) to\n"
               "--per-residue's table (column 'relative') and to --json ('residues')")
      ->group(output_group);
  app.add_option("--relative-scale", relative_scale,
                 "The maxima --relative divides by: theoretical (Tien et al. 2013's default) or empirical")
      ->check(CLI::IsMember({"theoretical", "empirical"}))
      ->capture_default_str()
      ->group(output_group);
  app.add_option("--format", formats,
                 "FreeSASA's report formats, on standard output in the order given (repeatable): log (the\n"
                 "text report), json, rsa (NACCESS), seq (per residue), res (per residue type), pdb or cif\n"
                 "(the structure with the areas as B-factors). Without -o no mesh is made (--areas-only)")
      ->check(CLI::IsMember({"log", "json", "rsa", "seq", "res", "pdb", "cif"}))
      ->allow_extra_args(false)
      ->delimiter(',')
      ->group(output_group);
  app.add_option("--depth", depth,
                 "How much the JSON lists, as FreeSASA's --depth: structure or chain (totals, chains and\n"
                 "classes), residue (also each residue), atom (also each atom)")
      ->check(CLI::IsMember({"structure", "chain", "residue", "atom"}))
      ->capture_default_str()
      ->group(output_group);
  app.add_flag("--areas-only", areas_only,
               "Areas and volumes only, exact from the true spheres (per atom, residue, shell, in total):\n"
               "no mesh is made and no surface file written; reports only where --json, --per-atom or\n"
               "--per-residue ask (docs/accuracy.md)")
      ->group(output_group);
  app.add_flag("--true-points", true_points,
               "After cleanup, move every vertex onto the true surface (its sphere, the circle of its two\n"
               "atoms, their triple point) where the mesh stays valid; the facets then inscribe the true\n"
               "surface (docs/accuracy.md)")
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
  app.add_option("--threads", threads,
                 "Threads for the union, 1 to 1024 (default, or 0: all cores); the result does not depend on it")
      ->check(whole_number(0, 1024));
  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
  app.add_flag("--progress", progress,
               "Show the progress bar of each stage on stderr even when it is not a terminal (it shows on a\n"
               "terminal anyway; -q silences it)");
}

namespace {

// A progress bar per stage on stderr (percent and the stage's elapsed time), one line per
// stage, drawn when stderr is a terminal or --progress asks, never with -q. Redrawn at most
// ten times a second.
class ProgressBar {
 public:
  ProgressBar(bool quiet, bool force) : enabled_(!quiet && (force || isatty(STDERR_FILENO))) {}
  ~ProgressBar() {
    if (line_open_) std::fputc('\n', stderr);
  }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(const char* stage, std::size_t done, std::size_t total) {
    if (!enabled_ || total == 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (stage != stage_) {
      if (line_open_) std::fputc('\n', stderr);
      stage_ = stage;
      stage_start_ = now;
      drawn_ = {};
    }
    if (done < total && drawn_ != std::chrono::steady_clock::time_point{} &&
        now - drawn_ < std::chrono::milliseconds(100))
      return;
    drawn_ = now;
    const int width = 30, filled = static_cast<int>(width * done / total);
    std::fprintf(stderr, "\r%-8s [%s%s] %3d%% %7.1f s", stage, std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), static_cast<int>(100 * done / total),
                 std::chrono::duration<double>(now - stage_start_).count());
    std::fflush(stderr);
    line_open_ = true;
  }

 private:
  bool enabled_;
  bool line_open_ = false;
  const char* stage_ = nullptr;
  std::chrono::steady_clock::time_point stage_start_, drawn_;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format_volume_mesh_report(const VolumeMeshReport& v, const std::filesystem::path& file) {
  char line[256];
  std::string text;
  std::snprintf(line, sizeof line, "  volume mesh           %s: %zu tetrahedra, %zu nodes (%.2f s)\n", file.string().c_str(),
                v.tetrahedra, v.nodes, v.seconds);
  text += line;
  for (const VolumeRegion& r : v.regions) {
    std::snprintf(line, sizeof line, "    %-19s %zu tetrahedra, volume %.2f A^3 (physical %d)\n", r.name.c_str(),
                  r.tetrahedra, r.volume, r.physical);
    text += line;
  }
  std::snprintf(line, sizeof line, "    quality             min dihedral %.2f deg; radius ratio min %.3f, median %.3f\n",
                v.min_dihedral_deg, v.min_radius_ratio, v.median_radius_ratio);
  text += line;
  return text;
}

// -o, or STEM.vtp in the current directory when it is not given at all.
std::filesystem::path surface_output_path(const SurfaceCommand& command) {
  std::filesystem::path out = command.output;
  if (out.empty() && command.output_option->count() == 0) {
    std::filesystem::path stem = command.structure.filename();
    while (stem.has_extension()) stem = stem.stem();  // 1crn.cif.gz -> 1crn
    out = stem.string() + ".vtp";
  }
  return out;
}

// --sasa-structure's file, its format checked before any work.
void add_sasa_structure_output(const SurfaceCommand& command, std::vector<OutputRequest>& outputs) {
  if (command.sasa_structure_option->count() == 0) return;
  if (!is_sasa_structure_path(command.sasa_structure))
    throw Error("--sasa-structure: " + command.sasa_structure.string() + " must end in .pdb, .ent, .cif or .mmcif");
  outputs.push_back({command.sasa_structure, "--sasa-structure"});
}

// Every output the options ask for, the surface first; refuses a volume mesh that cannot be made.
// The report files the options ask for: --json, --per-atom, --per-residue, --per-chain.
void add_report_outputs(const SurfaceCommand& command, std::vector<OutputRequest>& outputs) {
  if (command.json_option->count() > 0) outputs.push_back({command.json, "--json"});
  if (command.per_atom_option->count() > 0) outputs.push_back({command.per_atom, "--per-atom"});
  if (command.per_residue_option->count() > 0) outputs.push_back({command.per_residue, "--per-residue"});
  if (command.per_chain_option->count() > 0) outputs.push_back({command.per_chain, "--per-chain"});
}

// Where the text report goes: standard error when a report takes standard output.
std::ostream& text_stream(std::span<const OutputRequest> outputs) {
  for (const OutputRequest& request : outputs)
    if (request.path == kStandardOutput) return std::cerr;
  return std::cout;
}

std::vector<OutputRequest> requested_outputs(const SurfaceCommand& command, const std::filesystem::path& out) {
  std::vector<OutputRequest> outputs{{out, "-o", true}};
  add_report_outputs(command, outputs);
  add_sasa_structure_output(command, outputs);
  if (command.volume_option->count() > 0) {
    outputs.push_back({command.volume_mesh, "--volume-mesh", true});
    if (command.volume_mesh.extension() != ".msh")
      throw Error("--volume-mesh: " + command.volume_mesh.string() +
                  " must end in .msh (gmsh 2.2, the one format written)");
    if (!volume_mesh_available())
      throw Error("--volume-mesh: this molsurf was built without gmsh, which makes the volume mesh "
                  "(Debian: libgmsh-dev; build again)");
  }
  return outputs;
}

// Rejects an unknown extension, and options that do not apply to it, before any work.
void check_format_options(const SurfaceCommand& command, const std::filesystem::path& out) {
  const MeshFormat format = mesh_format_from_path(out);
  if (command.ascii && format != MeshFormat::ply && format != MeshFormat::stl)
    throw Error("--ascii: -o " + out.string() + " is " + mesh_format_name(format) +
                ", which has one form only; --ascii is for .ply and .stl");
  if (command.no_header && format != MeshFormat::msms)
    throw Error("--no-header: -o " + out.string() + " is " + mesh_format_name(format) +
                ", which has no MSMS header; --no-header is for .vert/.face");
}

// The read options with --chains split at its commas.
ReadOptions read_options(const SurfaceCommand& command) {
  ReadOptions options = command.read;
  std::stringstream list(command.chains);
  for (std::string chain; std::getline(list, chain, ',');)
    if (!chain.empty()) options.chains.push_back(chain);
  if (command.max_memory_gb > 0) options.max_memory = static_cast<std::uint64_t>(command.max_memory_gb * 1e9);
  return options;
}

// --threads goes to each library call that runs in parallel (the surface, the check, the
// writing), which sets it for its own duration; here it is only compared with the cores
// (SurfaceCommand::cap_threads has already capped it at what this process can start).
void note_threads(const SurfaceCommand& command) {
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores > 0 && command.threads > static_cast<int>(cores) && !command.quiet)
    std::cerr << "molsurf: note: --threads " << command.threads << " is more than the " << cores
              << " cores available: the result is the same, but not faster\n";
}

ComputeSurfaceOptions surface_compute_options(const SurfaceCommand& command) {
  ComputeSurfaceOptions options;
  options.spheres = command.spheres;
  options.surface = command.surface == "ses" ? SurfaceKind::ses
                    : command.surface == "vdw" ? SurfaceKind::vdw
                                               : SurfaceKind::sas;
  options.method = command.method == "pairwise" ? SurfaceMethod::pairwise : SurfaceMethod::one_pass;
  options.threads = command.threads;
  options.outer_only = command.outer_only;
  options.cleanup = !command.skip_cleanup;
  options.check_self_intersections = !command.skip_check;
  options.true_points = command.true_points;
  options.max_sphere_faces = command.max_faces;
  if (command.max_memory_gb > 0) options.max_memory = static_cast<std::uint64_t>(command.max_memory_gb * 1e9);
  options.source = command.structure;
  return options;
}

// The surface, with a progress bar unless quiet; a surface that fails its check is an
// error that names `out`, which is then not written.
ComputedSurface compute_with_progress(std::span<const Atom> atoms, ComputeSurfaceOptions options, bool quiet,
                                      bool force_progress, const std::filesystem::path& out) {
  try {
    ProgressBar bar(quiet, force_progress);  // its last line ended when the call returns or throws
    options.progress = [&bar](SurfaceStage stage, std::size_t done, std::size_t total) {
      bar.update(surface_stage_name(stage), done, total);
    };
    return compute_surface(atoms, options);
  } catch (const SurfaceCheckFailed& failed) {
    if (!quiet)
      for (const std::string& note : failed.notes()) std::cerr << "molsurf: note: " << note << "\n";
    throw Error(out.string() + ": not written: " + failed.what());
  }
}

MeshWriteOptions surface_write_options(const SurfaceCommand& command, std::span<const Atom> atoms) {
  MeshWriteOptions options;
  options.atoms = atoms;
  options.probe_radius = command.spheres.probe;
  options.density = command.spheres.density;
  options.ascii = command.ascii;
  options.threads = command.threads;
  options.msms_header = !command.no_header;
  options.msms_atom_names = !command.no_header;
  const bool vdw = command.surface == "vdw" || command.spheres.probe == 0;
  options.faces_on_atom_spheres = command.surface != "ses";
  options.surface_description = std::string(vdw                         ? "van der Waals surface"
                                            : command.surface == "ses" ? "solvent excluded surface"
                                                                       : "solvent accessible surface") +
                                " for " + command.structure.filename().string();
  return options;
}

// The report's description of the surface as the file holds it.
void describe_written_surface(const SurfaceMeasures& measures, const ComputedSurface& computed,
                              const WrittenCheck& written, SurfaceReport& report) {
  report.faces = measures.faces;
  report.vertices = measures.vertices;
  report.area = measures.area;
  report.volume = measures.volume;
  report.components = measures.components;
  report.quality = measures.quality;
  report.cleanup = computed.cleanup;
  report.true_points = computed.true_points;
  report.valid = written.check.valid();
  report.defects = written.check.defects();
  report.threads = computed.threads;
}

// The surface's file, or with --split-components one file per component, whose names
// are known only now: checked like every output before anything is written.
void add_surface_files(const SurfaceCommand& command, const std::filesystem::path& out, const Mesh& surface,
                       const WrittenCheck& written, const MeshCheckOptions& check_options,
                       std::span<const std::filesystem::path> inputs, std::span<const OutputRequest> outputs,
                       OutputFiles& files) {
  if (!command.split_components) {
    files.add_mesh(out, surface, written.options);
    return;
  }
  const std::vector<SurfaceComponent> parts = molsurf::split_components(surface);
  std::vector<OutputRequest> part_outputs(outputs.begin() + 1, outputs.end());
  for (const SurfaceComponent& part : parts)
    part_outputs.push_back({component_output_path(out, part), "--split-components", true});
  check_output_paths(inputs, part_outputs);
  for (const SurfaceComponent& part : parts)
    files.add_checked_mesh(component_output_path(out, part), part.mesh, written.options, check_options);
}

// The tetrahedra around the surface (--volume-mesh), when asked for.
std::optional<VolumeMeshReport> add_volume_mesh(const SurfaceCommand& command, const Mesh& surface, std::ostream& text,
                                                OutputFiles& files) {
  if (command.volume_mesh.empty()) return std::nullopt;
  if (!command.quiet) {
    text << "volume mesh ...";
    flush_standard_output();
  }
  VolumeMeshOptions options;
  options.box_margin = command.box_margin;
  options.box_size = command.volume_size;
  options.fill_inside = command.fill_inside;
  if (command.max_memory_gb > 0) options.max_memory = static_cast<std::uint64_t>(command.max_memory_gb * 1e9);
  VolumeMesh made = mesh_volume(surface, options);
  if (!command.quiet) text << "\r";
  files.add_text(command.volume_mesh, std::move(made.msh));
  return made.report;
}

// The maxima --relative divides by, when it is given.
std::optional<MaxAreaScale> relative_scale(const SurfaceCommand& command) {
  if (!command.relative) return std::nullopt;
  return command.relative_scale == "empirical" ? MaxAreaScale::empirical : MaxAreaScale::theoretical;
}

// The per-atom, per-residue and per-chain tables the options ask for, and the report's
// chains (and residues, with --relative).
void add_area_tables(const SurfaceCommand& command, std::span<const Atom> atoms, std::span<const double> atom_area,
                     SurfaceReport& report, OutputFiles& files) {
  const std::optional<MaxAreaScale> relative = relative_scale(command);
  if (!command.per_residue.empty()) files.add_text(command.per_residue, per_residue_csv(atoms, atom_area, relative));
  if (!command.per_chain.empty()) files.add_text(command.per_chain, per_chain_csv(atoms, atom_area));
  if (!command.sasa_structure.empty())
    files.add_text(command.sasa_structure, sasa_structure_text(command.sasa_structure, atoms, atom_area));
  report.chains = area_per_chain(atoms, atom_area);
  report.classes = class_areas(atoms, atom_area);
  report.relative = relative;
  if (relative) report.residues = area_per_residue(atoms, atom_area);
}

// --all-models: every model's numbers in the report, each model's rows in the tables under a
// leading `model` column.
void add_model_tables(const SurfaceCommand& command, std::span<const Structure> models,
                      std::span<const FrameAreas> computed, SurfaceReport& report, OutputFiles& files) {
  const std::optional<MaxAreaScale> relative = relative_scale(command);
  std::string atoms_csv, residues_csv, chains_csv;
  for (std::size_t k = 0; k < models.size(); ++k) {
    const Structure& s = models[k];
    const std::vector<double>& area = computed[k].atom_area;
    ModelReport m;
    m.model = s.report.model_used;
    m.atoms = s.atoms.size();
    m.area = computed[k].area;
    m.volume = computed[k].volume;
    m.cavities = computed[k].cavities;
    m.chains = area_per_chain(s.atoms, area);
    m.classes = class_areas(s.atoms, area);
    m.seconds = computed[k].seconds;
    report.models.push_back(std::move(m));
    if (k == 0) {
      report.chains = report.models.back().chains;
      report.classes = report.models.back().classes;
      report.relative = relative;
      if (relative) report.residues = area_per_residue(s.atoms, area);
    }
    if (!command.per_atom.empty()) atoms_csv += csv_with_model_column(per_atom_csv(s.atoms, area), m.model, k == 0);
    if (!command.per_residue.empty())
      residues_csv += csv_with_model_column(per_residue_csv(s.atoms, area, relative), m.model, k == 0);
    if (!command.per_chain.empty()) chains_csv += csv_with_model_column(per_chain_csv(s.atoms, area), m.model, k == 0);
  }
  if (!command.per_atom.empty()) files.add_text(command.per_atom, atoms_csv);
  if (!command.per_residue.empty()) files.add_text(command.per_residue, residues_csv);
  if (!command.per_chain.empty()) files.add_text(command.per_chain, chains_csv);
}

// --depth residue and atom: the JSON's residue and atom lists.
void add_json_depth(const SurfaceCommand& command, std::span<const Atom> atoms, std::span<const double> atom_area,
                    SurfaceReport& report) {
  if (command.depth == "residue" || command.depth == "atom") report.residues = area_per_residue(atoms, atom_area);
  if (command.depth == "atom") {
    report.atoms = atoms;
    report.atom_area.assign(atom_area.begin(), atom_area.end());
  }
}

// --format: FreeSASA's reports, one after another, for standard output.
std::string format_outputs(const SurfaceCommand& command, std::span<const Atom> atoms,
                           std::span<const double> atom_area, const SurfaceReport& report) {
  const std::string source = command.structure.string();
  std::string out;
  for (const std::string& format : command.formats) {
    if (format == "log") out += format_surface_report(report);
    else if (format == "json") out += surface_report_json(report);
    else if (format == "seq") out += residue_sequence_text(atoms, atom_area, source);
    else if (format == "res") out += residue_type_text(atoms, atom_area, source);
    else if (format == "pdb" || format == "cif") out += sasa_structure_text("out." + format, atoms, atom_area);
    else if (format == "rsa") {
      RsaHeader header;
      header.source = source;
      header.radii = report.input.radius_set;
      header.probe = command.spheres.probe;
      header.scale = command.relative_scale == "empirical" ? MaxAreaScale::empirical : MaxAreaScale::theoretical;
      out += rsa_text(atoms, atom_area, header);
    }
  }
  return out;
}

// Every model's exact areas, small models in parallel.
std::vector<FrameAreas> model_areas(const SurfaceCommand& command, std::span<const Structure> models) {
  return compute_frame_areas(
      models.size(), [&](std::size_t k, std::vector<Atom>& atoms) { atoms = models[k].atoms; }, command.spheres,
      command.outer_only, command.threads,
      [&](std::size_t k) { return "model " + std::to_string(models[k].report.model_used); });
}

// --all-models -o NAME_{model}.EXT: model N's mesh file.
std::filesystem::path model_output_path(const std::filesystem::path& pattern, int model) {
  std::string name = pattern.string();
  const std::string key = "{model}", number = std::to_string(model);
  for (std::size_t at = name.find(key); at != std::string::npos; at = name.find(key, at + number.size()))
    name.replace(at, key.size(), number);
  return name;
}

void print_summary(const SurfaceReport& report, const std::optional<VolumeMeshReport>& volume,
                   const std::filesystem::path& volume_mesh, std::span<const std::filesystem::path> written_files,
                   std::ostream& text) {
  text << "\n" << format_surface_report(report);
  if (volume) text << format_volume_mesh_report(*volume, volume_mesh);
  std::string list;
  for (const std::filesystem::path& file : written_files) list += (list.empty() ? "" : ", ") + file.string();
  text << "written: " << list << "\n";
}

}  // namespace

void SurfaceCommand::cap_threads() {
  const ThreadCount count = startable_threads(threads);
  if (!count.note.empty()) std::cerr << "molsurf: note: --threads: " << count.note << "\n";
  threads = count.threads;
}

int SurfaceCommand::run() const {
  if (surface == "ses") {
    // What reads the true spheres of the SAS has no SES counterpart yet.
    const std::pair<bool, const char*> sas_only[] = {{areas_only, "--areas-only (the SAS's exact areas)"},
                                                     {true_points, "--true-points"},
                                                     {relative, "--relative (relative SASA)"},
                                                     {method != "one-pass", "--method"}};
    for (const auto& [given, name] : sas_only)
      if (given) throw Error(std::string("--surface ses: ") + name + " applies to the SAS and vdW surfaces only");
  }
  if (!formats.empty() && all_models) throw Error("--format writes one model: drop --all-models, or give --model N");
  if (areas_only) return run_areas_only();
  if (!formats.empty() && output_option->count() == 0) {
    // Numbers only, as FreeSASA gives them: no mesh unless -o asks for one.
    if (surface == "ses")
      throw Error("--format --surface ses: the SES's areas come from its mesh; give -o FILE as well");
    return run_areas_only();
  }
  if (all_models) {
    if (output_option->count() > 0) return run_model_meshes();
    // Numbers only unless meshes are asked for, through -o's {model}.
    if (surface == "ses")
      throw Error("--all-models --surface ses: the SES's areas come from its mesh; give -o NAME_{model}.EXT");
    return run_areas_only();
  }
  const std::filesystem::path out = surface_output_path(*this);
  // Every output checked before any work: a wrong path costs nothing.
  std::vector<OutputRequest> outputs = requested_outputs(*this, out);
  if (!formats.empty()) outputs.push_back({kStandardOutput, "--format"});
  const std::vector<std::filesystem::path> inputs{structure, read.radius_file};
  check_output_paths(inputs, outputs);
  check_format_options(*this, out);
  // --format's reports stand alone on standard output, as FreeSASA's do.
  const bool silent = quiet || !formats.empty();
  std::ostream& text = text_stream(outputs);

  const ReadOptions options = read_options(*this);
  note_threads(*this);
  SurfaceReport report;
  const auto read_start = std::chrono::steady_clock::now();
  const Structure s = read_structure(structure, options);
  report.seconds.read = seconds_since(read_start);
  // compute_surface refuses the same; checked here too so that nothing is printed first.
  check_sphere_resources(structure, s.atoms, spheres, max_faces);
  // A job that may fill a large share of the memory trades a little time for a smaller
  // footprint (allocation.hpp).
  const std::uint64_t memory = max_memory_gb > 0 ? static_cast<std::uint64_t>(max_memory_gb * 1e9) : available_memory_bytes();
  if (estimate_resources(s.atoms, spheres).bytes > memory / 32) save_memory();
  const SpherePlan plan = plan_spheres(s.atoms, spheres);
  if (!silent) text << format_read_report(s.report) << format_sphere_plan(plan, spheres);
  flush_standard_output();  // shown before the long work, and a broken standard output stops it

  const ComputedSurface computed = compute_with_progress(s.atoms, surface_compute_options(*this), quiet, progress, out);
  if (!quiet)
    for (const std::string& note : computed.notes) std::cerr << "molsurf: note: " << note << "\n";
  const Mesh& surface = computed.mesh;
  report.seconds.surface = computed.seconds.union_;
  report.seconds.cleanup = computed.seconds.cleanup;
  report.seconds.check = computed.seconds.check;

  const MeshWriteOptions write_options = surface_write_options(*this, s.atoms);
  MeshCheckOptions check_options;
  check_options.self_intersections = !skip_check;
  check_options.threads = threads;
  // Lossy formats (.vert, .stl): the surface is checked again as the file will hold it.
  auto clock = std::chrono::steady_clock::now();
  const WrittenCheck written = check_as_written(out, surface, computed.check, write_options, check_options,
                                                [](const MeshCheck& c) { return c.valid(); });
  report.seconds.check += seconds_since(clock);
  if (!written.note.empty() && !quiet) std::cerr << "molsurf: note: " << written.note << "\n";

  clock = std::chrono::steady_clock::now();
  // The report describes what the file holds: the rounded surface when the format rounds.
  const SurfaceMeasures measures =
      written.rounded ? measure_surface(*written.rounded, written.check, s.atoms.size()) : computed.measures;
  describe_written_surface(measures, computed, written, report);
  report.input = s.report;
  report.spheres = spheres;
  report.surface = this->surface;
  report.output = out;
  report.outer_only = outer_only;
  if (!computed.component_shells.empty() || !computed.exact.area_per_sphere.empty()) {
    report.exact = make_exact_report(computed.exact, computed.component_shells, outer_only);
    report.exact->seconds = computed.seconds.measures;
    report.artefact_components = artefact_components(report.components, *report.exact);
  }
  // Per atom and residue: the true spheres' areas (those of the cavities too unless they are dropped).
  const std::vector<double> atom_area =
      report.exact ? exact_atom_area(computed.exact, outer_only) : measures.atom_area;

  // All or nothing: every file is complete before any replaces an old one.
  OutputFiles files;
  add_surface_files(*this, out, surface, written, check_options, inputs, outputs, files);
  const std::optional<VolumeMeshReport> volume = add_volume_mesh(*this, surface, text, files);
  if (!per_atom.empty()) files.add_text(per_atom, per_atom_csv(s.atoms, atom_area));
  add_area_tables(*this, s.atoms, atom_area, report, files);
  report.seconds.write = computed.seconds.measures + seconds_since(clock);
  add_json_depth(*this, s.atoms, atom_area, report);
  if (!json.empty()) files.add_text(json, surface_report_json(report));
  if (!formats.empty()) files.add_text(kStandardOutput, format_outputs(*this, s.atoms, atom_area, report));
  flush_standard_output();  // the report so far reached standard output, or nothing is replaced
  const std::vector<std::filesystem::path> written_files = files.commit();
  if (!silent) print_summary(report, volume, volume_mesh, written_files, text);
  return 0;
}

int SurfaceCommand::run_areas_only() const {
  // No mesh: the options that shape or write one have nothing to act on.
  const std::pair<const CLI::Option*, const char*> mesh_options[] = {{output_option, "-o"},
                                                                    {volume_option, "--volume-mesh"}};
  for (const auto& [option, name] : mesh_options)
    if (option->count() > 0) throw Error(std::string("--areas-only writes no mesh: drop ") + name);
  if (split_components) throw Error("--areas-only writes no mesh: drop --split-components");
  if (true_points) throw Error("--areas-only writes no mesh: drop --true-points");
  if (all_models && sasa_structure_option->count() > 0)
    throw Error("--sasa-structure writes one model: drop --all-models, or give --model N");
  std::vector<OutputRequest> outputs;
  add_report_outputs(*this, outputs);
  add_sasa_structure_output(*this, outputs);
  if (!formats.empty()) outputs.push_back({kStandardOutput, "--format"});
  const std::vector<std::filesystem::path> inputs{structure, read.radius_file};
  check_output_paths(inputs, outputs);
  const bool silent = quiet || !formats.empty();  // --format's reports stand alone
  std::ostream& text = text_stream(outputs);

  note_threads(*this);
  SurfaceReport report;
  const auto read_start = std::chrono::steady_clock::now();
  const std::vector<Structure> models = all_models ? read_all_models(structure, read_options(*this))
                                                   : std::vector<Structure>{read_structure(structure, read_options(*this))};
  const Structure& s = models.front();
  report.seconds.read = seconds_since(read_start);
  if (!silent) text << format_read_report(s.report);
  flush_standard_output();  // shown before the work, and a broken standard output stops it
  const ComputedAreas computed = compute_areas(s.atoms, spheres, threads);
  report.input = s.report;
  report.spheres = spheres;
  report.areas_only = true;  // no mesh made
  report.outer_only = outer_only;
  report.threads = threads > 0 ? threads : omp_get_max_threads();
  report.exact = make_exact_report(computed.arrangement, {}, outer_only);
  report.exact->seconds = computed.seconds;
  const std::vector<double> atom_area = exact_atom_area(computed.arrangement, outer_only);

  OutputFiles files;
  if (!all_models) {
    if (!per_atom.empty()) files.add_text(per_atom, per_atom_csv(s.atoms, atom_area));
    add_area_tables(*this, s.atoms, atom_area, report, files);
  } else {
    add_model_tables(*this, models, model_areas(*this, models), report, files);
  }
  add_json_depth(*this, s.atoms, atom_area, report);
  if (!json.empty()) files.add_text(json, surface_report_json(report));
  if (!formats.empty()) files.add_text(kStandardOutput, format_outputs(*this, s.atoms, atom_area, report));
  flush_standard_output();  // the report so far reached standard output, or nothing is replaced
  const std::vector<std::filesystem::path> written_files = files.commit();
  if (!silent) {
    text << "\n" << format_surface_report(report);
    std::string list;
    for (const std::filesystem::path& file : written_files) list += (list.empty() ? "" : ", ") + file.string();
    const char* nothing = areas_only ? "nothing (--areas-only)" : "nothing (-o NAME_{model}.vtp writes each model's mesh)";
    text << "written: " << (list.empty() ? nothing : list) << "\n";
  }
  return 0;
}

// --all-models -o NAME_{model}.EXT: each model's surface, checked and written as one
// surface is; the report gives every model's numbers (the true spheres', or the facets' for
// the SES) and the file it went to.
int SurfaceCommand::run_model_meshes() const {
  const std::pair<bool, const char*> single_mesh[] = {{split_components, "--split-components"},
                                                      {volume_option->count() > 0, "--volume-mesh"},
                                                      {true_points, "--true-points"}};
  for (const auto& [given, name] : single_mesh)
    if (given) throw Error(std::string("--all-models writes one mesh per model: drop ") + name);
  if (sasa_structure_option->count() > 0)
    throw Error("--sasa-structure writes one model: drop --all-models, or give --model N");
  if (output.string().find("{model}") == std::string::npos)
    throw Error("--all-models: -o " + output.string() +
                " must hold {model}, which each model's number replaces (e.g. -o 1j8k_{model}.vtp)");
  check_format_options(*this, output);
  std::vector<OutputRequest> outputs;
  add_report_outputs(*this, outputs);
  std::ostream& text = text_stream(outputs);

  note_threads(*this);
  SurfaceReport report;
  const auto read_start = std::chrono::steady_clock::now();
  const std::vector<Structure> models = read_all_models(structure, read_options(*this));
  report.seconds.read = seconds_since(read_start);
  // Every model's file is known now, and checked with the rest before any work.
  const std::vector<std::filesystem::path> inputs{structure, read.radius_file};
  for (const Structure& s : models) outputs.push_back({model_output_path(output, s.report.model_used), "-o", true});
  check_output_paths(inputs, outputs);
  for (const Structure& s : models) check_sphere_resources(structure, s.atoms, spheres, max_faces);
  if (!quiet) text << format_read_report(models.front().report);
  flush_standard_output();

  MeshCheckOptions check_options;
  check_options.self_intersections = !skip_check;
  check_options.threads = threads;
  OutputFiles files;
  std::vector<FrameAreas> areas(models.size());
  std::vector<std::size_t> faces(models.size());
  for (std::size_t k = 0; k < models.size(); ++k) {
    const Structure& s = models[k];
    const std::filesystem::path out = model_output_path(output, s.report.model_used);
    if (!quiet) text << "model " << s.report.model_used << " (" << k + 1 << " of " << models.size() << ")\n" << std::flush;
    const ComputedSurface computed = compute_with_progress(s.atoms, surface_compute_options(*this), quiet, progress, out);
    if (!quiet)
      for (const std::string& note : computed.notes) std::cerr << "molsurf: note: " << note << "\n";
    const MeshWriteOptions write_options = surface_write_options(*this, s.atoms);
    const WrittenCheck written = check_as_written(out, computed.mesh, computed.check, write_options, check_options,
                                                  [](const MeshCheck& c) { return c.valid(); });
    if (!written.note.empty() && !quiet) std::cerr << "molsurf: note: " << written.note << "\n";
    files.add_mesh(out, computed.mesh, written.options);
    const SurfaceMeasures& measures = written.rounded
                                          ? measure_surface(*written.rounded, written.check, s.atoms.size())
                                          : computed.measures;
    faces[k] = measures.faces;
    FrameAreas& a = areas[k];
    a.seconds = computed.seconds.union_ + computed.seconds.cleanup + computed.seconds.check;
    if (computed.exact.area_per_sphere.empty()) {  // the SES: the facets' numbers
      a.area = measures.area;
      a.volume = measures.volume;
      for (const ComponentMeasure& c : measures.components) a.cavities += c.cavity();
      a.atom_area = measures.atom_area;
    } else {
      const ExactReport exact = make_exact_report(computed.exact, {}, outer_only);
      a.area = exact.area;
      a.volume = exact.volume;
      for (const ShellReport& shell : exact.shells) a.cavities += shell.cavity;
      a.atom_area = exact_atom_area(computed.exact, outer_only);
      if (k == 0) report.exact = exact;
    }
  }
  report.input = models.front().report;
  report.spheres = spheres;
  report.surface = surface;
  report.outer_only = outer_only;
  report.threads = threads > 0 ? threads : omp_get_max_threads();
  add_model_tables(*this, models, areas, report, files);
  for (std::size_t k = 0; k < models.size(); ++k) {
    report.models[k].output = model_output_path(output, models[k].report.model_used);
    report.models[k].faces = faces[k];
  }
  if (!json.empty()) files.add_text(json, surface_report_json(report));
  flush_standard_output();  // the report so far reached standard output, or nothing is replaced
  const std::vector<std::filesystem::path> written_files = files.commit();
  if (!quiet) {
    text << "\n" << format_surface_report(report);
    std::string list;
    for (const std::filesystem::path& file : written_files) list += (list.empty() ? "" : ", ") + file.string();
    text << "written: " << list << "\n";
  }
  return 0;
}

}  // namespace molsurf::cli
