#include <cstdio>
#include <iostream>

#include "cli/commands.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/report.hpp"

namespace molsurf::cli {

void BooleanCommand::add_options(CLI::App& app) {
  app.add_option("OP", operation, "union, intersection or difference (A minus B)")
      ->required()
      ->check(CLI::IsMember({"union", "intersection", "difference"}));
  app.add_option("A", a, "First mesh: closed, outward, 2-manifold, no self-intersection")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("B", b, "Second mesh, same requirements")->required()->check(CLI::ExistingFile);
  app.add_option("-o,--output", output, "Result mesh; the format follows the extension")->required();
  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
}

int BooleanCommand::run() const {
  mesh_format_from_path(output);  // reject an unknown extension before any work
  const BooleanOp op = operation == "union"          ? BooleanOp::union_
                       : operation == "intersection" ? BooleanOp::intersection
                                                     : BooleanOp::difference;
  const Mesh mesh_a = read_mesh(a), mesh_b = read_mesh(b);
  // The engine's contract: refuse operands it cannot promise a valid result for.
  for (const auto& [mesh, path] : {std::pair{&mesh_a, &a}, std::pair{&mesh_b, &b}}) {
    const MeshCheck c = check_mesh(*mesh);
    if (!c.valid()) {
      std::string why;
      for (const std::string& d : c.defects()) why += "\n  - " + d;
      throw molsurf::Error(path->string() + ": not a valid closed surface, so no Boolean is defined:" + why);
    }
  }
  const BooleanResult r = boolean(mesh_a, mesh_b, op);
  write_mesh(output, r.mesh);
  const MeshCheck check = check_mesh(r.mesh);
  if (!quiet) {
    const BooleanStats& s = r.stats;
    std::printf("%s of %s (%zu faces) and %s (%zu faces) -> %s\n", boolean_op_name(op), a.string().c_str(),
                s.faces_a, b.string().c_str(), s.faces_b, output.string().c_str());
    if (r.mesh.faces.empty()) std::printf("the result is empty: written with zero faces\n");
    std::printf("  candidate pairs %zu, intersecting %zu (coplanar %zu), intersection points %zu, faces split %zu\n",
                s.candidate_pairs, s.intersecting_pairs, s.coplanar_pairs, s.intersection_points, s.split_faces);
    if (s.split_vertices) std::printf("  touching vertices duplicated: %zu\n", s.split_vertices);
    std::printf("  time (ms): cull %.2f  intersect %.2f  split %.2f  classify %.2f  stitch %.2f  total %.2f\n",
                1e3 * s.seconds.cull, 1e3 * s.seconds.intersect, 1e3 * s.seconds.split, 1e3 * s.seconds.classify,
                1e3 * s.seconds.stitch, 1e3 * s.seconds.total());
    std::cout << format_mesh_check(check, output.string());
  }
  return check.valid() ? 0 : 1;
}

}  // namespace molsurf::cli
