// The surface command's outputs: which files and reports the options ask for, checked before
// any work, and what goes into them once the surface or areas are computed.
#include "cli/surface_outputs.hpp"

#include <iostream>

#include "molsurf/error.hpp"
#include "molsurf/freesasa_formats.hpp"
#include "molsurf/report.hpp"
#include "molsurf/sasa_structure.hpp"
#include "molsurf/split_components.hpp"
#include "molsurf/surface_files.hpp"
#include "io/standard_output.hpp"

namespace molsurf::cli {

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

namespace {

// The maxima --relative divides by, when it is given.
std::optional<MaxAreaScale> relative_scale(const SurfaceCommand& command) {
  if (!command.relative) return std::nullopt;
  return command.relative_scale == "empirical" ? MaxAreaScale::empirical : MaxAreaScale::theoretical;
}

}  // namespace

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

// Every output the options ask for, the surface first; refuses a volume mesh that cannot be made.
std::vector<OutputRequest> requested_outputs(const SurfaceCommand& command, const std::filesystem::path& out) {
  std::vector<OutputRequest> outputs{{out, "-o", true}};
  add_report_outputs(command, outputs);
  add_sasa_structure_output(command, outputs);
  if (command.stern_option->count() > 0) {
    check_stern_format(command);
    outputs.push_back({command.stern, "--stern", true});
  }
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


// --stern's file: a mesh format, before any work.
void check_stern_format(const SurfaceCommand& command) {
  try {
    mesh_format_from_path(command.stern);
  } catch (const Error& e) {
    throw Error(std::string("--stern: ") + e.what());
  }
}

// The Stern layer's file (--stern), checked as the file will hold it (the MSMS header and
// --ascii as for the surface), and its report: the true spheres' area and volume.
SternReport add_stern_file(const SurfaceCommand& command, const ComputedSurface& stern, std::span<const Atom> atoms,
                           OutputFiles& files) {
  SphereOptions spheres = command.spheres;
  spheres.probe = command.stern_probe;
  const bool msms = mesh_format_from_path(command.stern) == MeshFormat::msms;
  const SurfaceFileOptions file{.ascii = command.ascii, .msms_header = !(command.no_header && msms),
                                .threads = command.threads};
  const WrittenCheck written = check_surface_as_written(
      command.stern, stern, surface_write_options(SurfaceKind::sas, spheres, atoms, command.structure, file));
  if (!written.note.empty() && !command.quiet) std::cerr << "molsurf: note: --stern: " << written.note << "\n";
  files.add_mesh(command.stern, stern.mesh, written.options);
  const SurfaceMeasures measures =
      written.rounded ? measure_surface(*written.rounded, written.check, atoms.size()) : stern.measures;
  const ExactReport exact = make_exact_report(stern.exact, stern.component_shells, command.outer_only);
  SternReport report;
  report.probe = command.stern_probe;
  report.output = command.stern;
  report.faces = measures.faces;
  report.area = exact.area;
  report.volume = exact.volume;
  report.facet_area = measures.area;
  report.facet_volume = measures.volume;
  report.valid = written.check.valid();
  return report;
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
  options.max_memory = command.max_memory_bytes();
  VolumeMesh made = mesh_volume(surface, options);
  if (!command.quiet) text << "\r";
  files.add_text(command.volume_mesh, std::move(made.msh));
  return made.report;
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
                   const char* nothing, std::ostream& text) {
  text << "\n" << format_surface_report(report);
  if (volume) text << format_volume_mesh_report(*volume, volume_mesh);
  std::string list;
  for (const std::filesystem::path& file : written_files) list += (list.empty() ? "" : ", ") + file.string();
  text << "written: " << (list.empty() ? nothing : list) << "\n";
}


}  // namespace molsurf::cli
