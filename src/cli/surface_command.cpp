// The surface command's runs: one surface (run), the exact areas only (run_areas_only) and
// a surface per model (run_model_meshes). The options are parsed in surface_options.cpp and
// the outputs assembled in surface_outputs.cpp; every rule of the job is the library's.
#include <omp.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <optional>
#include <span>
#include <thread>

#include "blocks/block_share.hpp"
#include "blocks/blocked_surface.hpp"
#include "blocks/first_process_verdict.hpp"
#include "blocks/pvtp_index.hpp"
#include "io/mesh_formats.hpp"
#include "cli/allocation.hpp"
#include "cli/commands.hpp"
#include "cli/progress_bar.hpp"
#include "cli/surface_outputs.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/output_files.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/report.hpp"
#include "molsurf/reported_atom_area.hpp"
#include "molsurf/resource_limits.hpp"
#include "io/standard_output.hpp"
#include "molsurf/surface_files.hpp"
#include "molsurf/surface_report.hpp"
#include "molsurf/threads.hpp"

namespace molsurf::cli {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

// The surface, with a progress bar unless quiet; a surface that fails its check is an
// error that names `out`, which is then not written.
ComputedSurface compute_with_progress(std::span<const Atom> atoms, ComputeSurfaceOptions options, bool quiet,
                                      bool force_progress, const std::filesystem::path& out) {
  const auto print_notes = [quiet](const std::vector<std::string>& notes) {
    if (!quiet)
      for (const std::string& note : notes) std::cerr << "molsurf: note: " << note << "\n";
  };
  try {
    ProgressBar bar(quiet, force_progress);  // its last line ended when the call returns or throws
    options.progress = [&bar](SurfaceStage stage, std::size_t done, std::size_t total) {
      bar.update(surface_stage_name(stage), done, total);
    };
    ComputedSurface computed = compute_surface(atoms, options);
    bar.finish();  // the notes go on lines of their own
    print_notes(computed.notes);
    return computed;
  } catch (const SurfaceCheckFailed& failed) {
    print_notes(failed.notes());
    throw Error(out.string() + ": not written: " + failed.what());
  }
}

// The surface block by block (--blocks), with a progress bar unless quiet. With `blocked`'s
// piece_done, each piece is handed over as soon as it is checked (streamed: only its faces
// away from the seams, which then go to seams_done).
// Empty on every process of an MPI launch but the first, which gets the surface (streamed:
// its measures only).
std::optional<ComputedSurface> compute_blocks_with_progress(std::span<const Atom> atoms, ComputeSurfaceOptions options,
                                                            const blocks::BlockedSurfaceOptions& blocked, bool quiet,
                                                            bool force_progress, const std::filesystem::path& out) {
  try {
    ProgressBar bar(quiet, force_progress);
    options.progress = [&bar](SurfaceStage stage, std::size_t done, std::size_t total) {
      bar.update(surface_stage_name(stage), done, total);
    };
    blocks::BlockedSurface result = blocks::compute_blocked_surface(atoms, options, blocked);
    bar.finish();
    if (!result.root) return std::nullopt;
    return std::move(result.surface);
  } catch (const SurfaceCheckFailed& failed) {
    if (!quiet)
      for (const std::string& note : failed.notes()) std::cerr << "molsurf: note: " << note << "\n";
    throw Error(out.string() + ": not written: " + failed.what());
  }
}

}  // namespace

// ---- the library's options from the command's ----

SurfaceKind SurfaceCommand::kind() const { return surface_kind_from_name(surface); }

std::uint64_t SurfaceCommand::max_memory_bytes() const {
  return max_memory_gb > 0 ? memory_limit_bytes(max_memory_gb) : 0;
}

ReadOptions SurfaceCommand::read_options() const {
  ReadOptions options = read;
  options.chains = chain_list(chains);
  options.max_memory = max_memory_bytes();
  return options;
}

ComputeSurfaceOptions SurfaceCommand::compute_options() const {
  ComputeSurfaceOptions options;
  options.spheres = spheres;
  options.surface = kind();
  options.method = surface_method_from_name(method);
  options.threads = threads;
  options.outer_only = outer_only;
  if (stern_option->count() > 0) options.stern_probe = stern_probe;
  options.cleanup = !skip_cleanup;
  options.check_self_intersections = !skip_check;
  options.true_points = true_points;
  options.max_sphere_faces = max_faces;
  options.max_memory = max_memory_bytes();
  options.source = structure;
  return options;
}

// The surface checked as `out` will hold it, its file's options the library's for this
// surface (surface_files.hpp); a note when the format needed more precision.
WrittenCheck SurfaceCommand::checked_as_written(const std::filesystem::path& out, const ComputedSurface& computed,
                                               std::span<const Atom> atoms) const {
  const SurfaceFileOptions file{.ascii = ascii, .msms_header = !no_header, .threads = threads};
  WrittenCheck written =
      check_surface_as_written(out, computed, surface_write_options(kind(), spheres, atoms, structure, file));
  if (!written.note.empty() && !quiet) std::cerr << "molsurf: note: " << written.note << "\n";
  return written;
}

// Every model's exact areas, small models in parallel.
std::vector<FrameAreas> SurfaceCommand::model_areas(std::span<const Structure> models) const {
  return compute_frame_areas(
      models.size(), [&](std::size_t k, std::vector<Atom>& atoms) { atoms = models[k].atoms; }, spheres, outer_only,
      threads,
      [&](std::size_t k) { return "model " + std::to_string(models[k].report.model_used); });
}

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
                                                     {relative, "--relative (relative SASA)"}};
    for (const auto& [given, name] : sas_only)
      if (given) throw Error(std::string("--surface ses: ") + name + " applies to the SAS and vdW surfaces only");
  }
  // The rules between the options, as the library has them (a ParameterError names the option).
  validate(compute_options());
  if (stern_probe_option->count() > 0 && stern_option->count() == 0)
    throw Error("--stern-probe: give --stern FILE as well (the Stern layer's file)");
  if (!formats.empty() && all_models) throw Error("--format writes one model: drop --all-models, or give --model N");
  // Blocks make one mesh; several MPI processes share nothing else.
  const bool launched = exchange && exchange->size() > 1;
  if ((blocks > 0 || launched) && (areas_only || all_models || (!formats.empty() && output_option->count() == 0)))
    throw Error(std::string(launched ? "under mpirun, molsurf makes one surface in blocks" : "--blocks makes one mesh") +
                ": drop --areas-only, --all-models and --format without -o");
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
  // --blocks with -o NAME.pvtp: each block's piece NAME_K.vtp written as soon as it is made
  // and the seams' NAME_seams.vtp beside the index, every check of a surface file made on the
  // pieces' format; the surface is never held whole.
  // Under MPI with more than one process, one block each unless --blocks says otherwise.
  const std::size_t block_count = blocks > 0 ? blocks : exchange && exchange->size() > 1 ? exchange->size() : 0;
  if (merge && block_count == 0) throw Error("--merge glues the pieces of --blocks N: give --blocks as well");
  const bool pieces = block_count > 0 && mesh_io::is_pvtp_path(out);
  if (pieces && merge)
    throw Error("--merge writes one surface file: give -o NAME.vtp (or another mesh format), not " + out.string());
  if (pieces && split_components) throw Error("--split-components writes whole surfaces: give --merge with it");
  if (pieces && volume_option->count() > 0)
    throw Error("--volume-mesh meshes around the whole surface, which -o " + out.string() +
                " never holds at once: give --merge -o NAME.vtp with it");
  const std::filesystem::path mesh_out = pieces ? blocks::piece_path(out, 0) : out;
  // Every output checked before any work: a wrong path costs nothing.
  std::vector<OutputRequest> outputs = requested_outputs(*this, mesh_out);
  if (pieces) {
    for (std::size_t k = 1; k < block_count; ++k) outputs.push_back({blocks::piece_path(out, k), "-o", true});
    outputs.push_back({blocks::seams_path(out), "-o", true});
    outputs.push_back({out, "-o"});
  }
  if (!formats.empty()) outputs.push_back({kStandardOutput, "--format"});
  const std::vector<std::filesystem::path> inputs{structure, read.radius_file};
  check_output_paths(inputs, outputs);
  check_format_options(*this, mesh_out);
  // --format's reports stand alone on standard output, as FreeSASA's do.
  const bool silent = quiet || !formats.empty();
  std::ostream& text = text_stream(outputs);

  note_threads(*this);
  SurfaceReport report;
  const auto read_start = std::chrono::steady_clock::now();
  // Under mpirun the first process alone reads the structure, and every process hears
  // whether it could; the others then receive their blocks' share of it (block_share.hpp)
  // and never hold the whole structure.
  blocks::BlockExchange* launch = launched ? exchange : nullptr;
  std::optional<Structure> read_here;
  blocks::on_first_process(launch, [&] {
    read_here = read_structure(structure, read_options());
    report.seconds.read = seconds_since(read_start);
    // compute_surface refuses the same; checked here too so that nothing is printed first.
    // Streamed pieces hold one block's spheres at a time: the blocked job checks each block.
    // The SES is drawn whole (blocks::streams).
    if (!pieces || kind() == SurfaceKind::ses) check_sphere_resources(structure, read_here->atoms, spheres, max_faces);
  });
  const std::span<const Atom> whole = read_here ? std::span<const Atom>(read_here->atoms) : std::span<const Atom>{};
  // A job that may fill a large share of the memory trades a little time for a smaller
  // footprint (allocation.hpp): decided on the whole structure, by the first process under
  // mpirun, and followed by every process.
  const std::uint64_t memory = max_memory_gb > 0 ? max_memory_bytes() : available_memory_bytes();
  bool large_job = read_here && estimate_resources(whole, spheres).bytes > memory / 32;
  if (launch) large_job = !launch->broadcast(large_job ? "large" : "").empty();
  if (large_job) save_memory();
  if (read_here) {
    const SpherePlan plan = plan_spheres(whole, spheres);
    if (!silent) text << format_read_report(read_here->report) << format_sphere_plan(plan, spheres);
    flush_standard_output();  // shown before the long work, and a broken standard output stops it
  }

  blocks::BlockedSurfaceOptions blocked;
  blocked.blocks = block_count;
  blocked.exchange = exchange;
  blocked.streamed = pieces;
  blocks::BlockShare share;
  if (launch) {
    share = blocks::share_blocks(whole, compute_options(), blocked);
    blocked.share = &share;
  }
  // The atoms this process's files name: the whole structure, or its share (tagged by
  // their index in the whole).
  const std::span<const Atom> named = read_here ? whole : std::span<const Atom>(share.atoms);

  // All or nothing: every file is complete before any replaces an old one (the pieces go to
  // their temporaries as they are made; under MPI each process keeps its own pieces' files,
  // and replaces them once the first has found the whole surface valid).
  OutputFiles files(!stale_listed);
  const SurfaceFileOptions file{.ascii = ascii, .msms_header = !no_header, .threads = threads};
  MeshWriteOptions piece_options = surface_write_options(kind(), spheres, named, structure, file);
  if (!read_here) piece_options.atom_tags = share.global_index;
  bool with_seams = false;
  if (pieces) {
    blocked.piece_done = [&](std::size_t block, const Mesh& piece) {
      files.add_mesh(blocks::piece_path(out, block), piece, piece_options);
    };
    blocked.seams_done = [&](const Mesh& seams) {
      with_seams = !seams.faces.empty();
      if (with_seams) files.add_mesh(blocks::seams_path(out), seams, piece_options);
    };
  }
  std::optional<ComputedSurface> surface_or_none =
      block_count > 0 ? compute_blocks_with_progress(whole, compute_options(), blocked, quiet, progress, out)
                      : compute_with_progress(whole, compute_options(), quiet, progress, out);
  if (!surface_or_none) {  // another process of the launch writes the index and the reports
    files.commit();
    return 0;
  }
  const Structure& s = *read_here;
  const ComputedSurface& computed = *surface_or_none;
  const Mesh& surface = computed.mesh;
  report.seconds.surface = computed.seconds.union_;
  report.seconds.cleanup = computed.seconds.cleanup;
  report.seconds.check = computed.seconds.check;

  // Lossy formats (.vert, .stl): the surface is checked again as the file will hold it.
  auto clock = std::chrono::steady_clock::now();
  const WrittenCheck written = checked_as_written(mesh_out, computed, s.atoms);
  report.seconds.check += seconds_since(clock);

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
  // Per atom and residue: the exact areas (the true spheres', or the SES's patches'), those of
  // the cavities too unless they are dropped.
  const std::vector<double> atom_area = reported_atom_area(computed, outer_only, measures);

  if (pieces)
    files.add_text(out, blocks::pvtp_index(out, block_count, with_seams));
  else
    add_surface_files(*this, out, surface, written, surface_check_options(computed, threads), inputs, outputs, files);
  if (computed.stern) report.stern = add_stern_file(*this, *computed.stern, s.atoms, files);
  report.ses_patches = computed.ses_patches;
  const std::optional<VolumeMeshReport> volume = add_volume_mesh(*this, surface, text, files);
  if (!per_atom.empty()) files.add_text(per_atom, per_atom_csv(s.atoms, atom_area));
  add_area_tables(*this, s.atoms, atom_area, report, files);
  report.seconds.write = computed.seconds.measures + seconds_since(clock);
  add_json_depth(*this, s.atoms, atom_area, report);
  if (!json.empty()) files.add_text(json, surface_report_json(report));
  if (!formats.empty()) files.add_text(kStandardOutput, format_outputs(*this, s.atoms, atom_area, report));
  flush_standard_output();  // the report so far reached standard output, or nothing is replaced
  const std::vector<std::filesystem::path> written_files = files.commit();
  if (!silent) print_summary(report, volume, volume_mesh, written_files, "", text);
  return 0;
}

int SurfaceCommand::run_areas_only() const {
  // No mesh: the options that shape or write one have nothing to act on.
  const std::pair<const CLI::Option*, const char*> mesh_options[] = {{output_option, "-o"},
                                                                    {volume_option, "--volume-mesh"}};
  for (const auto& [option, name] : mesh_options)
    if (option->count() > 0) throw Error(std::string("--areas-only writes no mesh: drop ") + name);
  if (split_components) throw Error("--areas-only writes no mesh: drop --split-components");
  if (stern_option->count() > 0) throw Error("--areas-only writes no mesh: drop --stern");
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
  const std::vector<Structure> models = all_models ? read_all_models(structure, read_options())
                                                   : std::vector<Structure>{read_structure(structure, read_options())};
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

  OutputFiles files(!stale_listed);
  if (!all_models) {
    if (!per_atom.empty()) files.add_text(per_atom, per_atom_csv(s.atoms, atom_area));
    add_area_tables(*this, s.atoms, atom_area, report, files);
  } else {
    add_model_tables(*this, models, model_areas(models), report, files);
  }
  add_json_depth(*this, s.atoms, atom_area, report);
  if (!json.empty()) files.add_text(json, surface_report_json(report));
  if (!formats.empty()) files.add_text(kStandardOutput, format_outputs(*this, s.atoms, atom_area, report));
  flush_standard_output();  // the report so far reached standard output, or nothing is replaced
  const std::vector<std::filesystem::path> written_files = files.commit();
  if (!silent)
    print_summary(report, std::nullopt, {}, written_files,
                  areas_only ? "nothing (--areas-only)" : "nothing (-o NAME_{model}.vtp writes each model's mesh)",
                  text);
  return 0;
}

// --all-models -o NAME_{model}.EXT: each model's surface, checked and written as one
// surface is; the report gives every model's numbers (the true spheres', or the facets' for
// the SES, whose per-atom, residue and chain rows are its patches') and the file it went to.
int SurfaceCommand::run_model_meshes() const {
  const std::pair<bool, const char*> single_mesh[] = {{split_components, "--split-components"},
                                                      {volume_option->count() > 0, "--volume-mesh"},
                                                      {stern_option->count() > 0, "--stern"},
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
  const std::vector<Structure> models = read_all_models(structure, read_options());
  report.seconds.read = seconds_since(read_start);
  // Every model's file is known now, and checked with the rest before any work.
  const std::vector<std::filesystem::path> inputs{structure, read.radius_file};
  for (const Structure& s : models) outputs.push_back({model_output_path(output, s.report.model_used), "-o", true});
  check_output_paths(inputs, outputs);
  for (const Structure& s : models) check_sphere_resources(structure, s.atoms, spheres, max_faces);
  if (!quiet) text << format_read_report(models.front().report);
  flush_standard_output();

  OutputFiles files(!stale_listed);
  std::vector<FrameAreas> areas(models.size());
  std::vector<std::size_t> faces(models.size());
  for (std::size_t k = 0; k < models.size(); ++k) {
    const Structure& s = models[k];
    const std::filesystem::path out = model_output_path(output, s.report.model_used);
    if (!quiet) text << "model " << s.report.model_used << " (" << k + 1 << " of " << models.size() << ")\n" << std::flush;
    const ComputedSurface computed = compute_with_progress(s.atoms, compute_options(), quiet, progress, out);
    const WrittenCheck written = checked_as_written(out, computed, s.atoms);
    files.add_mesh(out, computed.mesh, written.options);
    const SurfaceMeasures& measures = written.rounded
                                          ? measure_surface(*written.rounded, written.check, s.atoms.size())
                                          : computed.measures;
    faces[k] = measures.faces;
    FrameAreas& a = areas[k];
    a.seconds = computed.seconds.union_ + computed.seconds.cleanup + computed.seconds.check;
    a.atom_area = reported_atom_area(computed, outer_only, measures);
    if (computed.exact.area_per_sphere.empty()) {  // the SES: its patches' totals, the facets' cavities
      const ReportedTotals totals = reported_totals(computed, measures);
      a.area = totals.area;
      a.volume = totals.volume;
      for (const ComponentMeasure& c : measures.components) a.cavities += c.cavity();
    } else {
      const ExactReport exact = make_exact_report(computed.exact, {}, outer_only);
      a.area = exact.area;
      a.volume = exact.volume;
      for (const ShellReport& shell : exact.shells) a.cavities += shell.cavity;
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
  if (!quiet) print_summary(report, std::nullopt, {}, written_files, "", text);
  return 0;
}

}  // namespace molsurf::cli
