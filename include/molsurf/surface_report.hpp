#pragma once
// The report of a surface job: its measures (surface_measures.hpp), quality, cleanup and
// check, rendered as text, JSON and CSV.
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
#include "molsurf/surface_measures.hpp"

namespace molsurf {

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
