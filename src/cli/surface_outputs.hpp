#pragma once
// The surface command's outputs (surface_outputs.cpp): the files and reports the options ask
// for, checked before any work, and filled once the surface or the areas are computed.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/output_files.hpp"
#include "molsurf/surface_report.hpp"
#include "molsurf/volume_mesh.hpp"
#include "molsurf/written_check.hpp"

namespace molsurf::cli {

// -o, or STEM.vtp in the current directory when it is not given at all.
std::filesystem::path surface_output_path(const SurfaceCommand& command);
// --all-models -o NAME_{model}.EXT: model N's mesh file.
std::filesystem::path model_output_path(const std::filesystem::path& pattern, int model);

// The report files the options ask for: --json, --per-atom, --per-residue, --per-chain.
void add_report_outputs(const SurfaceCommand& command, std::vector<OutputRequest>& outputs);
// --sasa-structure's file, its format checked before any work.
void add_sasa_structure_output(const SurfaceCommand& command, std::vector<OutputRequest>& outputs);
// Every output the options ask for, the surface (`out`) first; refuses a volume mesh that
// cannot be made.
std::vector<OutputRequest> requested_outputs(const SurfaceCommand& command, const std::filesystem::path& out);
// Rejects an unknown extension of `out`, and options that do not apply to it, before any work.
void check_format_options(const SurfaceCommand& command, const std::filesystem::path& out);
// --stern's file: a mesh format, before any work.
void check_stern_format(const SurfaceCommand& command);
// The Stern layer's file (--stern), checked as the file will hold it, and its report.
SternReport add_stern_file(const SurfaceCommand& command, const ComputedSurface& stern, std::span<const Atom> atoms,
                           OutputFiles& files);
// Where the text report goes: standard error when a report takes standard output.
std::ostream& text_stream(std::span<const OutputRequest> outputs);

// The report's description of the surface as the file holds it.
void describe_written_surface(const SurfaceMeasures& measures, const ComputedSurface& computed,
                              const WrittenCheck& written, SurfaceReport& report);
// The surface's file, or with --split-components one file per component, whose names are
// known only now: checked like every output before anything is written.
void add_surface_files(const SurfaceCommand& command, const std::filesystem::path& out, const Mesh& surface,
                       const WrittenCheck& written, const MeshCheckOptions& check_options,
                       std::span<const std::filesystem::path> inputs, std::span<const OutputRequest> outputs,
                       OutputFiles& files);
// The tetrahedra around the surface (--volume-mesh), when asked for.
std::optional<VolumeMeshReport> add_volume_mesh(const SurfaceCommand& command, const Mesh& surface, std::ostream& text,
                                                OutputFiles& files);
// The per-residue and per-chain tables and --sasa-structure the options ask for, and the
// report's chains and classes (and residues, with --relative).
void add_area_tables(const SurfaceCommand& command, std::span<const Atom> atoms, std::span<const double> atom_area,
                     SurfaceReport& report, OutputFiles& files);
// --all-models: every model's numbers in the report, each model's rows in the tables under a
// leading `model` column.
void add_model_tables(const SurfaceCommand& command, std::span<const Structure> models,
                      std::span<const FrameAreas> computed, SurfaceReport& report, OutputFiles& files);
// --depth residue and atom: the JSON's residue and atom lists.
void add_json_depth(const SurfaceCommand& command, std::span<const Atom> atoms, std::span<const double> atom_area,
                    SurfaceReport& report);
// --format: FreeSASA's reports, one after another, for standard output.
std::string format_outputs(const SurfaceCommand& command, std::span<const Atom> atoms,
                           std::span<const double> atom_area, const SurfaceReport& report);
// The text report's end: the report, the volume mesh's lines, and "written: FILES" (or
// `nothing` when no file was).
void print_summary(const SurfaceReport& report, const std::optional<VolumeMeshReport>& volume,
                   const std::filesystem::path& volume_mesh, std::span<const std::filesystem::path> written_files,
                   const char* nothing, std::ostream& text);

}  // namespace molsurf::cli
