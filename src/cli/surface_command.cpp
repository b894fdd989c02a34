#include <iostream>
#include <sstream>

#include "cli/commands.hpp"
#include "molsurf/io.hpp"
#include "molsurf/report.hpp"

namespace molsurf::cli {

void SurfaceCommand::add_options(CLI::App& app) {
  app.add_option("STRUCTURE", structure,
                 "Structure file: PDB (.pdb .ent), mmCIF (.cif .mmcif), either gzipped (.gz),\n"
                 "PQR (.pqr: radius column used) or MSMS sphere list (.xyzr: x y z r [name])")
      ->check(CLI::ExistingFile);
  app.add_option("-o,--output", output,
                 "Surface file; the format follows the extension: .vtp .vtk .ply .off .stl .obj,\n"
                 ".vert (MSMS .vert/.face pair), .msh (gmsh 2.2). Default: STEM.vtp in the current directory");

  auto* input = "Structure selection";
  app.add_option("--model", read.model, "Model number as written in the file (default: the first model)")
      ->group(input);
  app.add_option("--chains", chains, "Keep only these chains, comma-separated (e.g. A,C); default: all")
      ->group(input);
  app.add_flag("--keep-water", read.keep_water, "Keep water molecules (dropped by default)")->group(input);
  app.add_flag("--hydrogens", read.keep_hydrogens, "Keep hydrogen and deuterium atoms (dropped by default)")
      ->group(input);
  app.add_flag("--no-hetatm", [this](std::int64_t) { read.keep_hetatm = false; },
               "Drop hetero atoms: ligands, ions, cofactors (kept by default, e.g. haem)")
      ->group(input);
  app.add_option("--radius-set", read.radius_set,
                 "Built-in radii: protor (Tsai et al. 1999, by residue and atom) or bondi (by element)")
      ->check(CLI::IsMember({"protor", "bondi"}))
      ->capture_default_str()
      ->group(input);
  app.add_option("--radii", read.radius_file, "User radius table (format: docs/radii.md); overrides --radius-set")
      ->check(CLI::ExistingFile)
      ->group(input);

  auto* sphere = "Spheres";
  app.add_option("--probe", spheres.probe, "Probe radius in angstrom added to every atom; 0 gives the vdW surface")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--density", spheres.density,
                 "Icosphere vertices per square angstrom of sphere surface (MSMS's convention)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--frequency", spheres.frequency,
                 "Fixed icosphere frequency n for every atom (20 n^2 faces); overrides --density")
      ->check(CLI::Range(1, 200))
      ->group(sphere);
  app.add_flag("--area-corrected", spheres.area_corrected,
               "Scale each icosphere so its area equals the true sphere's (default: vertices on the sphere)")
      ->group(sphere);

  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
}

int SurfaceCommand::run() const {
  std::filesystem::path out = output;
  if (out.empty()) {
    std::filesystem::path stem = structure.filename();
    while (stem.has_extension()) stem = stem.stem();  // 1crn.cif.gz -> 1crn
    out = stem.string() + ".vtp";
  }
  mesh_format_from_path(out);  // reject an unknown extension before any work

  ReadOptions options = read;
  std::stringstream list(chains);
  for (std::string chain; std::getline(list, chain, ',');)
    if (!chain.empty()) options.chains.push_back(chain);

  const Structure s = read_structure(structure, options);
  const SpherePlan plan = plan_spheres(s.atoms, spheres);
  if (!quiet) {
    std::cout << format_read_report(s.report) << format_sphere_plan(plan, spheres);
    std::cout << "\nmolsurf: the union engine is not built yet, so no surface was written (" << out.string()
              << " would be next).\n";
  }
  return 0;
}

}  // namespace molsurf::cli
