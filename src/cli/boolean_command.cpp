#include <cstdio>
#include <iostream>
#include <optional>

#include "cli/commands.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/output_files.hpp"
#include "molsurf/report.hpp"
#include "io/standard_output.hpp"
#include "molsurf/written_check.hpp"
#include "cli/validators.hpp"

namespace molsurf::cli {

void BooleanCommand::add_options(CLI::App& app) {
  app.add_option("OP", operation, "union, intersection or difference (A minus B)")
      ->required()
      ->check(one_of(kBooleanOpNames));
  app.add_option("A", a, "First mesh: closed, outward, 2-manifold, no self-intersection")
      ->required()
      ->check(readable_file());
  app.add_option("B", b, "Second mesh, same requirements")->required()->check(readable_file());
  app.add_option("-o,--output", output, "Result mesh; the format follows the extension")->required();
  // Its own name: a surface's --outer-only drops cavities by their volume sign, while this is
  // the paper's flood fill (§2.4), which also takes open surfaces. --outer-only stays an alias.
  app.add_flag("--outer-envelope,--outer-only", outer_only,
               "union only: keep the outer envelope, found by the paper's flood fill from outside (no "
               "cavities); A and B may then be open surfaces. --outer-only is the same flag");
  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
}

int BooleanCommand::run() const {
  const std::vector<std::filesystem::path> inputs{a, b};
  const std::vector<OutputRequest> outputs{{output, "-o", true}};
  check_output_paths(inputs, outputs);  // never over an operand, a link or a device
  mesh_format_from_path(output);        // reject an unknown extension before any work
  const BooleanOp op = boolean_op_from_name(operation);
  const Mesh mesh_a = read_mesh(a), mesh_b = read_mesh(b);
  // The operands held to the engine's contract, the operation, the result's check: the library's.
  const CheckedBoolean r = checked_boolean(mesh_a, mesh_b, op, a.string(), b.string(), outer_only);
  const auto acceptable = [&r](const MeshCheck& c) { return r.acceptable(c); };
  // Checked before anything is written, as the file will hold it (.vert, .stl round).
  const bool empty = r.result.mesh.faces.empty();
  std::optional<WrittenCheck> written;
  if (!empty)
    written = check_as_written(output, r.result.mesh, r.check, MeshWriteOptions{}, MeshCheckOptions{}, acceptable);
  const MeshCheck& check = written ? written->check : r.check;
  const bool ok = !empty && acceptable(check);
  // The file goes to its temporary now and replaces the target only after the report is out.
  std::optional<OutputFiles> files;
  if (ok) {
    files.emplace();
    files->add_mesh(output, r.result.mesh, written->options);
  }
  const bool open_result = ok && !check.valid();
  if (!quiet) {
    const BooleanStats& s = r.result.stats;
    std::printf("%s%s of %s (%zu faces) and %s (%zu faces) -> %s\n", boolean_op_name(op),
                outer_only ? " (outer envelope)" : "", a.string().c_str(), s.faces_a, b.string().c_str(), s.faces_b,
                output.string().c_str());
    std::printf("  candidate pairs %zu, intersecting %zu (coplanar %zu), intersection points %zu, faces split %zu\n",
                s.candidate_pairs, s.intersecting_pairs, s.coplanar_pairs, s.intersection_points, s.split_faces);
    if (outer_only)
      std::printf("  outer envelope: kept %zu faces; %zu of %zu connected parts seen from outside, %zu enclosed "
                  "(dropped with every cavity)\n",
                  s.output_faces, s.envelope_components_kept, s.envelope_components,
                  s.envelope_components - s.envelope_components_kept);
    if (s.two_sided_faces)
      std::printf("  %zu faces of open sheets are seen from both sides (kept once, as given)\n", s.two_sided_faces);
    if (s.split_vertices) std::printf("  touching vertices duplicated: %zu\n", s.split_vertices);
    std::printf("  time (ms): cull %.2f  intersect %.2f  split %.2f  %s %.2f  stitch %.2f  total %.2f\n",
                1e3 * s.seconds.cull, 1e3 * s.seconds.intersect, 1e3 * s.seconds.split,
                outer_only ? "flood fill" : "classify", 1e3 * (s.seconds.classify), 1e3 * s.seconds.stitch,
                1e3 * s.seconds.total());
    if (!empty) std::cout << format_mesh_check(check, output.string());
    if (open_result)
      std::printf("the result is an open surface, as an open operand makes it: %zu boundary edges, %zu edges where "
                  "a two-sided sheet meets the rest (expected, not a defect)\n",
                  check.boundary_edges, check.nonmanifold_edges);
    if (const std::string note = boolean_note(r.result.stats); !note.empty()) std::printf("note: %s\n", note.c_str());
    if (written && !written->note.empty()) std::printf("note: %s\n", written->note.c_str());
  }
  if (empty)
    // An empty mesh is no closed surface (molsurf check fails it): no file is made, and an
    // older file at the output path must not pass for the result, so this is an error.
    throw molsurf::Error(output.string() + ": not written: the " + boolean_op_name(op) + " of " + a.string() +
                         " and " + b.string() + " is empty (no faces); an existing file there is left as it was");
  if (!ok) {
    std::fprintf(stderr, "molsurf: error: %s: not written: %s\n", output.string().c_str(), r.problem(check).c_str());
    return 1;
  }
  flush_standard_output();  // the report reached standard output, or nothing is replaced
  const std::vector<std::filesystem::path> written_files = files->commit();
  if (!quiet)
    std::printf("written: %s\n", written_files.size() == 2
                                     ? (written_files[0].string() + ", " + written_files[1].string()).c_str()
                                     : written_files.front().string().c_str());
  return 0;
}

}  // namespace molsurf::cli
