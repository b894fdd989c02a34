#pragma once
// What users study on a surface: area and volume, per component (outer surface and
// cavities), per atom and per residue; rendered as text, JSON and CSV.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <optional>

#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

struct ComponentMeasure {
  std::size_t faces = 0;
  double area = 0;
  double volume = 0;  // signed: negative for a cavity (its faces point into it)
  bool cavity() const { return volume < 0; }
};

// Components by shared vertices; the largest outer surface first, then by area.
std::vector<ComponentMeasure> measure_components(const Mesh& mesh);

// The mesh without its cavities (components of negative volume).
Mesh outer_surface_only(const Mesh& mesh);

// Area of the faces tagged with each atom (faces tagged outside [0, atom_count) are ignored).
std::vector<double> area_per_atom(const Mesh& mesh, std::size_t atom_count);

// One residue's share of the surface: the summed area of its atoms.
struct ResidueArea {
  std::string chain;
  std::string residue_name;
  int residue_number = 0;
  char insertion_code = ' ';
  std::size_t atoms = 0;  // atoms of the structure in this residue (buried ones too)
  double area = 0;        // square angstrom
};

// Residues (same chain, number, insertion code and name) in order of first appearance,
// with the summed `atom_area` of their atoms (one value per atom, as area_per_atom gives).
std::vector<ResidueArea> area_per_residue(std::span<const Atom> atoms, std::span<const double> atom_area);

struct StageTimes {  // seconds
  double read = 0, surface = 0, cleanup = 0, write = 0, check = 0;
};

struct SurfaceReport {
  ReadReport input;
  SphereOptions spheres;
  std::size_t faces = 0, vertices = 0;
  double area = 0, volume = 0;
  std::vector<ComponentMeasure> components;
  Quality quality;
  std::optional<CleanupStats> cleanup;  // absent with --no-cleanup
  bool valid = false;  // `check_mesh` on the surface written
  std::vector<std::string> defects;
  StageTimes seconds;
  int threads = 1;
  std::filesystem::path output;
  bool outer_only = false;
};

SurfaceReport make_surface_report(const Mesh& surface, const MeshCheck& check);
std::string format_surface_report(const SurfaceReport& report);
std::string surface_report_json(const SurfaceReport& report);

// CSV tables: one row per atom with its area, and one per residue; as text, or written
// atomically to a file.
std::string per_atom_csv(std::span<const Atom> atoms, std::span<const double> area);
std::string per_residue_csv(std::span<const Atom> atoms, std::span<const double> area);
void write_per_atom_csv(const std::filesystem::path& path, std::span<const Atom> atoms, std::span<const double> area);
void write_per_residue_csv(const std::filesystem::path& path, std::span<const Atom> atoms,
                           std::span<const double> area);

}  // namespace molsurf
