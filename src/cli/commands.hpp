#pragma once
// The molsurf commands: each registers its options on a CLI11 (sub)command and runs
// by calling the library. Exit codes: 0 success, 1 failure (bad input or invalid mesh).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::cli {

struct SurfaceCommand {
  std::filesystem::path structure;
  std::filesystem::path output;
  ReadOptions read;
  std::string chains;
  SphereOptions spheres;
  int threads = 0;
  std::string method = "one-pass";
  bool outer_only = false;
  bool skip_check = false;
  bool skip_cleanup = false;
  std::filesystem::path json, per_atom, per_residue;
  bool quiet = false;

  void add_options(CLI::App& app);
  int run() const;
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

}  // namespace molsurf::cli
