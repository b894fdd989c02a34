#include <iostream>

#include "cli/commands.hpp"
#include "cli/validators.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/report.hpp"

namespace molsurf::cli {

void CheckCommand::add_options(CLI::App& app) {
  app.add_option("MESH", mesh, "Mesh file to check")->required()->check(readable_file());
  app.add_flag("--json", json, "Print the result as JSON instead of a table");
  app.add_flag("--no-self-intersections", skip_self_intersections,
               "Skip the (exact, BVH-accelerated) self-intersection test");
}

int CheckCommand::run() const {
  const Mesh m = read_mesh(mesh);
  MeshCheckOptions options;
  options.self_intersections = !skip_self_intersections;
  const MeshCheck result = check_mesh(m, options);
  std::cout << (json ? mesh_check_json(result, mesh.string()) : format_mesh_check(result, mesh.string()));
  return result.verdict() == MeshCheck::Verdict::valid ? 0 : 1;  // an empty mesh is no surface
}

}  // namespace molsurf::cli
