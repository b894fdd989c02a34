#pragma once
// The report of a surface job: its measures (surface_measures.hpp), quality, cleanup and
// check, rendered as text, JSON and CSV.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <optional>

#include "molsurf/atom_classes.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/relative_area.hpp"
#include "molsurf/ses_measures.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/surface_measures.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf {

struct StageTimes {  // seconds
  double read = 0, surface = 0, cleanup = 0, write = 0, check = 0;
};

// One shell of the true spheres' union (sphere_arrangement.hpp): the outer surface or a
// cavity, with the mesh component that follows it.
struct ShellReport {
  bool cavity = false;
  double area = 0, volume = 0;  // volume unsigned: a cavity's is the void's
  Vec3 centroid;                // of the shell's surface
  std::vector<std::uint32_t> atoms;  // the atoms lining it (indices into the structure)
  std::int64_t mesh_component = -1;  // index into SurfaceReport::components; -1: none
};

// The exact numbers: from the true spheres, not the facets.
struct ExactReport {
  double area = 0, volume = 0;
  std::vector<ShellReport> shells;  // the largest outer shell first, then by area
  std::size_t vertices = 0, arcs = 0, buried_atoms = 0, exact_decisions = 0, degenerate_points = 0;
  double seconds = 0;
};

// The exact report of `arrangement`; component_shells (shells_of_components) links the
// mesh's components to it (empty without a mesh). outer_only: the cavities left out (area
// and volume those of the outer shells).
ExactReport make_exact_report(const SphereArrangement& arrangement, std::span<const std::int64_t> component_shells,
                              bool outer_only = false);

// The mesh's cavities (indices into `components`) that follow no true cavity as its first
// component: voids of the facets inside the true union, or a second piece of a true cavity
// the facets split.
std::vector<std::size_t> artefact_components(std::span<const ComponentMeasure> components, const ExactReport& exact);

// One model's numbers, for --all-models.
struct ModelReport {
  int model = 1;
  std::size_t atoms = 0, cavities = 0;
  double area = 0, volume = 0;
  std::vector<ChainArea> chains;
  ClassAreas classes;
  double seconds = 0;
  std::filesystem::path output;  // the model's mesh (--all-models -o NAME_{model}.EXT); empty: none
  std::size_t faces = 0;         // the mesh's
};

// The Stern layer made in the same run (--stern): the SAS of the same atoms at its own probe.
struct SternReport {
  double probe = 0;
  std::filesystem::path output;
  std::size_t faces = 0;
  double area = 0, volume = 0;              // the true spheres' (r + probe)
  double facet_area = 0, facet_volume = 0;  // the mesh's, as its file holds it
  bool valid = false;                       // its check as written
};

struct SurfaceReport {
  ReadReport input;
  SphereOptions spheres;
  std::string surface = "sas";  // which surface: sas, ses or vdw (surface_kind_name)
  std::size_t faces = 0, vertices = 0;
  double area = 0, volume = 0;
  std::vector<ComponentMeasure> components;
  Quality quality;
  std::optional<CleanupStats> cleanup;  // absent with --no-cleanup
  std::optional<TruePointStats> true_points;  // with --true-points
  bool valid = false;  // `check_mesh` on the surface written
  std::vector<std::string> defects;
  StageTimes seconds;
  int threads = 1;
  std::filesystem::path output;
  bool outer_only = false;
  // area and volume above are the facets'; these the true spheres' (absent when not computed).
  std::optional<ExactReport> exact;
  // The mesh components (index as in `components`) that no true shell explains: voids of the
  // facets inside the true union (a cavity in the mesh only).
  std::vector<std::size_t> artefact_components;
  bool areas_only = false;  // no mesh: faces, quality, cleanup and check are absent
  std::vector<ChainArea> chains;      // each chain's area (the exact areas when there are)
  std::optional<ClassAreas> classes;  // polar/apolar, main/side chain (atom_classes.hpp)
  std::vector<ResidueArea> residues;  // listed in the JSON when not empty (--relative, --depth residue)
  std::optional<MaxAreaScale> relative;
  // Listed in the JSON when not empty (--depth atom): each atom with its area.
  std::span<const Atom> atoms;
  std::vector<double> atom_area;
  std::vector<ModelReport> models;  // --all-models: every model's numbers (the rest is the first's)
  std::optional<SternReport> stern;  // --stern
  // The SES: its area and volume from the arrangement's patches (ses_measures.hpp), the
  // report's area and volume (exact, as the true spheres' are for the SAS); the facets' above.
  std::optional<SesMeasures> ses_patches;
};

SurfaceReport make_surface_report(const Mesh& surface, const MeshCheck& check);
std::string format_surface_report(const SurfaceReport& report);
std::string surface_report_json(const SurfaceReport& report);

// CSV tables (RFC 4180: a name holding a comma, quote or line break is quoted): one row
// per atom with its area, and one per residue; as text, or written atomically to a file.
std::string per_atom_csv(std::span<const Atom> atoms, std::span<const double> area);
// With `relative`, a `relative` column: the residue's area over its type's maximum
// (relative_area.hpp), empty for residues without one.
std::string per_residue_csv(std::span<const Atom> atoms, std::span<const double> area,
                            std::optional<MaxAreaScale> relative = std::nullopt);
std::string per_chain_csv(std::span<const Atom> atoms, std::span<const double> area);
// One of those tables with a leading `model` column (--all-models): "model" heads it (only
// `with_header`: the first model's table), `model` starts each row.
std::string csv_with_model_column(std::string_view csv, int model, bool with_header);
void write_per_atom_csv(const std::filesystem::path& path, std::span<const Atom> atoms, std::span<const double> area);
void write_per_residue_csv(const std::filesystem::path& path, std::span<const Atom> atoms,
                           std::span<const double> area);

}  // namespace molsurf
