#pragma once
// The molsurf commands: each registers its options on a CLI11 (sub)command and runs
// by calling the library. Exit codes: 0 success, 1 failure (bad input or invalid mesh).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <span>

#include "blocks/block_exchange.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/resource_limits.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/written_check.hpp"

namespace molsurf::cli {

struct SurfaceCommand {
  std::filesystem::path structure;
  std::filesystem::path output;
  ReadOptions read;
  std::string chains;
  SphereOptions spheres;
  std::string surface = "sas";  // sas | ses | vdw
  int threads = 0;
  std::string method = "one-pass";
  bool outer_only = false;
  bool split_components = false;  // one file per closed component
  bool ascii = false;             // .ply and .stl as text
  bool no_header = false;         // MSMS rows only: numbers, no header, no atom names
  bool skip_check = false;
  bool skip_cleanup = false;
  bool areas_only = false;        // the true spheres' areas and volumes, no mesh
  bool all_models = false;        // every model of the file (with areas_only)
  bool true_points = false;       // vertices moved onto the true surface after cleanup
  std::filesystem::path json, per_atom, per_residue, per_chain, sasa_structure;
  bool relative = false;                    // relative SASA per residue (Tien et al. 2013)
  std::string relative_scale = "theoretical";
  std::vector<std::string> formats;  // FreeSASA's --format: reports on standard output, in order
  std::string depth = "chain";       // FreeSASA's --depth: how much the JSON lists
  std::uint64_t max_faces = kDefaultMaxSphereFaces;
  double max_memory_gb = 0;  // 0: the machine's memory
  bool quiet = false;
  bool progress = false;  // the progress bar even when stderr is not a terminal
  std::size_t blocks = 0;  // --blocks N: the surface in N spatial blocks, one after another (0: not)
  bool merge = false;      // --merge: the blocks glued into one file rather than a .pvtp's pieces
  bool stale_listed = false;  // --stale-temporaries-removed (batch's jobs): list no directory
  // The processes of an MPI launch (null: this one alone); with more than one, the blocks
  // are theirs (one each unless --blocks says otherwise).
  blocks::BlockExchange* exchange = nullptr;
  // Set by add_options: whether an option was given at all (an empty value, as in
  // `-o ""`, is then an error rather than the default).
  const CLI::Option* output_option = nullptr;
  const CLI::Option* json_option = nullptr;
  const CLI::Option* per_atom_option = nullptr;
  const CLI::Option* per_residue_option = nullptr;
  const CLI::Option* per_chain_option = nullptr;
  const CLI::Option* sasa_structure_option = nullptr;
  // The volume mesh around the molecule (paper §3.4).
  std::filesystem::path volume_mesh;
  double box_margin = 10;
  double volume_size = 0;
  bool fill_inside = false;
  const CLI::Option* volume_option = nullptr;
  // The Stern layer from the same run (the SAS at stern_probe), for BEM solvers' second surface.
  std::filesystem::path stern;
  double stern_probe = kDefaultSternProbe;
  const CLI::Option* stern_option = nullptr;
  const CLI::Option* stern_probe_option = nullptr;

  void add_options(CLI::App& app);  // surface_options.cpp
  // --threads lowered, with a note, to what this process can start (startable_threads).
  void cap_threads();
  int run() const;
  int run_areas_only() const;
  int run_model_meshes() const;

  // The library's options from these (which the library checks again: parameters.hpp).
  SurfaceKind kind() const;
  std::uint64_t max_memory_bytes() const;  // 0: the machine's
  ReadOptions read_options() const;        // --chains split at its commas
  ComputeSurfaceOptions compute_options() const;
  // The surface checked as `out` will hold it, written as the library writes any surface's
  // file (surface_files.hpp); a note when the format needed more precision.
  WrittenCheck checked_as_written(const std::filesystem::path& out, const ComputedSurface& computed,
                                  std::span<const Atom> atoms) const;
  // Every model's exact areas, small models in parallel.
  std::vector<FrameAreas> model_areas(std::span<const Structure> models) const;
};

struct CheckCommand {
  std::filesystem::path mesh;
  bool json = false;
  bool skip_self_intersections = false;

  void add_options(CLI::App& app);
  int run() const;
};

struct BooleanCommand {
  std::string operation;
  std::filesystem::path a, b, output;
  bool outer_only = false;  // union only: the outer envelope (open operands allowed)
  bool quiet = false;

  void add_options(CLI::App& app);
  int run() const;
};

// molsurf batch: one molsurf job per structure of a list or directory, several at a time,
// each in its own process (a failure, even a crash, is recorded and the rest go on),
// resumable through a manifest in the output directory.
struct BatchCommand {
  std::filesystem::path input;  // a list file or a directory
  std::filesystem::path output_directory;
  int jobs = 0;                      // 0: one per core
  std::string mesh;                  // a mesh format to write per structure (vtp, ply, ...); empty: numbers only
  std::vector<std::string> options;  // passed to every job (after --)
  double timeout = 0;                // seconds per job; 0: none
  bool retry_failed = false;
  bool progress = false;
  bool quiet = false;

  void add_options(CLI::App& app);
  int run() const;
};

}  // namespace molsurf::cli
