// The surface command's options: each translated into the library's options, its range and
// names checked in the library's words (validators.hpp).
#include <optional>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/validators.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf::cli {

void SurfaceCommand::add_options(CLI::App& app) {
  app.add_option("STRUCTURE", structure,
                 "Structure file: PDB (.pdb .ent), mmCIF (.cif .mmcif), either gzipped (.gz),\n"
                 "PQR (.pqr: radius column used) or MSMS sphere list (.xyzr: x y z r [name])")
      ->check(readable_file());
  output_option = app.add_option("-o,--output", output,
                                 "Surface file; the format follows the extension: .vtp .vtk .ply .off .stl .obj,\n"
                                 ".vert (MSMS .vert/.face pair), .msh (gmsh 2.2). Default: STEM.vtp in the current "
                                 "directory.\nNever a symbolic link, device or an input file (refused)");

  auto* input = "Structure selection";
  app.add_option("--model", read.model, "Model number as written in the file (default: the first model)")
      ->group(input);
  app.add_option("--chains", chains, "Keep only these chains, comma-separated (e.g. A,C); default: all")
      ->group(input);
  app.add_flag("--keep-water", read.keep_water, "Keep water molecules (dropped by default)")->group(input);
  app.add_flag("--all-models", all_models,
               "Every model of the file (NMR ensembles, trajectories as multi-model files), with --areas-only:\n"
               "one line and one JSON entry ('models') per model, a 'model' column in the CSV tables")
      ->group(input);
  app.add_flag("--hydrogens", read.keep_hydrogens, "Keep hydrogen and deuterium atoms (dropped by default)")
      ->group(input);
  app.add_flag("--no-hetatm", [this](std::int64_t) { read.keep_hetatm = false; },
               "Drop hetero atoms: ligands, ions, cofactors (kept by default, e.g. haem)")
      ->group(input);
  app.add_option("--radius-set", read.radius_set,
                 "Built-in radii: protor (Tsai et al. 1999, by residue and atom), naccess (NACCESS's, as\n"
                 "FreeSASA has them) or bondi (by element)")
      ->check(radius_set_name())
      ->capture_default_str()
      ->group(input);
  // FreeSASA's spellings: --radii=protor|naccess names a built-in set, --config-file a file.
  app.add_option_function<std::string>(
         "--radii,--config-file",
         [this](const std::string& value) {
           if (RadiusTable::is_builtin(value)) {
             read.radius_set = value;
             read.radius_file.clear();
           } else {
             read.radius_file = value;
           }
         },
         "Radius table: a built-in set's name (protor, naccess, bondi: as --radius-set), or a file in\n"
         "molsurf's format or FreeSASA's classifier configuration, whose polar/apolar classes are used\n"
         "too (docs/radii.md; a file named like a set: ./NAME); overrides --radius-set")
      ->check(CLI::Validator(
          [](std::string& value) {
            return RadiusTable::is_builtin(value) ? std::string() : readable_file()(value);
          },
          "SET|FILE"))
      ->group(input);

  auto* sphere = "Spheres";
  app.add_option("--surface", surface,
                 "Which surface: sas (solvent accessible: spheres of r_vdW + probe), ses (solvent excluded, the "
                 "molecular surface BEM solvers use: where the rolling probe touches the atoms) or vdw (van der "
                 "Waals: the same as --probe 0)")
      ->check(one_of(kSurfaceKindNames))
      ->capture_default_str()
      ->group(sphere);
  auto* probe_option =
      app.add_option("--probe", spheres.probe,
                     "Probe radius in angstrom: added to every atom for the SAS, the rolling ball for the SES; 0 gives "
                     "the vdW surface")
          ->check(number_in(kProbeParameter))
      ->capture_default_str()
      ->group(sphere);
  // The surface kind settles the probe the spheres get, before anything reads it.
  app.parse_complete_callback([this, probe_option] {
    try {
      const std::optional<double> given = probe_option->count() > 0 ? std::optional(spheres.probe) : std::nullopt;
      spheres.probe = surface_probe(surface_kind_from_name(surface), given);
    } catch (const ParameterError& e) {
      throw CLI::ValidationError(option_spelling(e.parameter()), e.problem());
    }
  });
  std::ostringstream density_help;
  density_help << "Icosphere vertices per square angstrom of sphere surface (MSMS's convention); a sphere under "
               << spheres.min_density_radius << " A gets the frequency of one of " << spheres.min_density_radius
               << " A (van der Waals spheres: docs/accuracy.md)";
  app.add_option("--density", spheres.density, density_help.str())
      ->check(number_in(kDensityParameter))
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--frequency", spheres.frequency,
                 "Fixed icosphere frequency n for every atom (20 n^2 faces); overrides --density")
      ->check(whole_number_in(kFrequencyParameter))
      ->group(sphere);
  app.add_option("--max-faces", max_faces,
                 "Refuse to start when the spheres would have more faces than this before the union\n"
                 "(about 80 bytes of memory each; the 272k-atom capsid at density 4 has 253 million)")
      ->check(whole_number_in(kMaxFacesParameter))
      ->capture_default_str()
      ->group(sphere);
  app.add_option("--max-memory", max_memory_gb,
                 "Refuse to start the union when the surface would need more memory than this many GB\n"
                 "(estimated from a sample of atoms, about 180 bytes per face), and a structure whose text\n"
                 "(decompressed) would need more to read (16 bytes per byte); default: this machine's memory")
      ->check(number_in(kMaxMemoryParameter))
      ->group(sphere);
  auto* volume_group = "Volume mesh around the molecule (paper section 3.4)";
  volume_option = app.add_option("--volume-mesh", volume_mesh,
                                 "Also write tetrahedra filling the space between the surface and a box, as gmsh\n"
                                 ".msh 2.2 (regions and boundaries tagged; docs/volume_mesh.md)")
                      ->group(volume_group);
  app.add_option("--box-margin", box_margin, "Angstrom between the molecule's bounding box and the outer box")
      ->check(number_in(kBoxMarginParameter))
      ->capture_default_str()
      ->group(volume_group);
  app.add_option("--volume-size", volume_size,
                 "Tetrahedron size at the box in angstrom (default: the margin / 3, at least 1); near the\n"
                 "molecule the tetrahedra follow its triangles")
      ->check(number_in(kVolumeSizeParameter))
      ->group(volume_group);
  app.add_flag("--fill-inside", fill_inside,
               "Also fill the molecule's inside: the solute region, and each cavity as its own region")
      ->group(volume_group);
  app.add_flag("--inscribed", [this](std::int64_t) { spheres.area_corrected = false; },
               "Put icosphere vertices on the true spheres (inscribed polyhedra: about 1 % less volume).\n"
               "Default: each icosphere scaled so its area equals the sphere's (docs/accuracy.md)")
      ->group(sphere);

  auto* output_group = "Output and reports";
  app.add_flag("--outer-only", outer_only, "Keep the outer surface only, without cavities (as MSMS does by default)")
      ->group(output_group);
  app.add_flag("--split-components", split_components,
               "One file per closed surface: NAME.outer.EXT and NAME.cavity-K.EXT (K from 1, largest cavity\n"
               "first, as in the report) for -o NAME.EXT, each closed and outward on its own")
      ->group(output_group);
  stern_option = app.add_option("--stern", stern,
                                "Also write the Stern layer of the same atoms to this file (any mesh format): their\n"
                                "solvent-accessible surface at --stern-probe, checked as written, in the report too")
                     ->group(output_group);
  stern_probe_option =
      app.add_option("--stern-probe", stern_probe,
                     "The Stern layer's probe in angstrom: each atom's radius grown by it (PyGBe adds 2 A)")
          ->check(number_in(kSternProbeParameter))
          ->capture_default_str()
          ->group(output_group);
  app.add_flag("--ascii", ascii, "Write .ply and .stl as text (binary by default); tetgen needs ASCII PLY")
      ->group(output_group);
  app.add_flag("--no-header", no_header,
               "MSMS .vert/.face: data rows only, all numeric (no header lines, no atom-name column),\n"
               "as numpy.loadtxt readers such as PyGBe need")
      ->group(output_group);
  json_option = app.add_option("--json", json, "Write the report as JSON to this file ('-': standard output)")
                    ->group(output_group);
  per_atom_option =
      app.add_option("--per-atom", per_atom,
                     "Write each atom's exact area (A^2: on the true spheres; for --surface ses its share of the\n"
                     "SES's patches, docs/ses.md) to this CSV file ('-': standard output)")
          ->group(output_group);
  per_residue_option = app.add_option("--per-residue", per_residue,
                                      "Write each residue's area (A^2) to this CSV file ('-': standard output)")
                           ->group(output_group);
  per_chain_option = app.add_option("--per-chain", per_chain,
                                    "Write each chain's area (A^2) to this CSV file ('-': standard output)")
                         ->group(output_group);
  sasa_structure_option =
      app.add_option("--sasa-structure", sasa_structure,
                     "Write the structure with each atom's area (A^2) in the B-factor column and its radius in\n"
                     "the occupancy column, as FreeSASA's --format=pdb does: FILE.pdb or FILE.cif")
          ->group(output_group);
  app.add_flag("--relative", relative,
               "Add relative SASA per residue (area / the residue type's maximum, Tien et al. 2013) to\n"
               "--per-residue's table (column 'relative') and to --json ('residues')")
      ->group(output_group);
  app.add_option("--relative-scale", relative_scale,
                 "The maxima --relative divides by: theoretical (Tien et al. 2013's default) or empirical")
      ->check(CLI::IsMember({"theoretical", "empirical"}))
      ->capture_default_str()
      ->group(output_group);
  app.add_option("--format", formats,
                 "FreeSASA's report formats, on standard output in the order given (repeatable): log (the\n"
                 "text report), json, rsa (NACCESS), seq (per residue), res (per residue type), pdb or cif\n"
                 "(the structure with the areas as B-factors). Without -o no mesh is made (--areas-only)")
      ->check(CLI::IsMember({"log", "json", "rsa", "seq", "res", "pdb", "cif"}))
      ->allow_extra_args(false)
      ->delimiter(',')
      ->group(output_group);
  app.add_option("--depth", depth,
                 "How much the JSON lists, as FreeSASA's --depth: structure or chain (totals, chains and\n"
                 "classes), residue (also each residue), atom (also each atom)")
      ->check(CLI::IsMember({"structure", "chain", "residue", "atom"}))
      ->capture_default_str()
      ->group(output_group);
  app.add_flag("--areas-only", areas_only,
               "Areas and volumes only, exact from the true spheres (per atom, residue, shell, in total):\n"
               "no mesh is made and no surface file written; reports only where --json, --per-atom or\n"
               "--per-residue ask (docs/accuracy.md)")
      ->group(output_group);
  app.add_flag("--true-points", true_points,
               "After cleanup, move every vertex onto the true surface (its sphere, the circle of its two\n"
               "atoms, their triple point) where the mesh stays valid; the facets then inscribe the true\n"
               "surface (docs/accuracy.md)")
      ->group(output_group);
  app.add_flag("--no-cleanup", skip_cleanup,
               "Skip the surface improvement (paper 2.5: collapse of slivers under 5 degrees)")
      ->group(output_group);
  app.add_flag("--no-check", skip_check,
               "Skip the exact self-intersection test of the surface before it is written (closed and\n"
               "manifold are still checked); by default a surface that fails is not written")
      ->group(output_group);
  app.add_option("--method", method,
                 "How the spheres are joined: one-pass (each atom trimmed by its neighbours, all atoms in\n"
                 "parallel) or pairwise (hierarchical pairwise union, the paper's formulation; the reference)")
      ->check(one_of(kSurfaceMethodNames))
      ->capture_default_str();
  app.add_option("--threads", threads,
                 "Threads for the union, 1 to 1024 (default, or 0: all cores); the result does not depend on it")
      ->check(whole_number_in(kThreadsParameter));
  app.add_option("--blocks", blocks,
                 "Compute the surface in N spatial blocks balanced by atom count, one after another (each from\n"
                 "its atoms and the halo that reaches them); with -o NAME.pvtp each block's piece is written as\n"
                 "NAME_K.vtp as soon as it is made, the seams between them as NAME_seams.vtp, beside a ParaView\n"
                 "index NAME.pvtp: the peak memory is then a block's, or at the end the seams', not the\n"
                 "surface's; what each block keeps for the seams waits in a temporary file in TMPDIR\n"
                 "(docs/scale-out.md); at most one block per atom. --surface ses: each block draws its atoms'\n"
                 "SES among a wider halo and the pieces are joined at the end (no seams' file; the whole\n"
                 "cleaned SES is then held at once)")
      ->check(whole_number_in(kBlocksParameter));
  app.add_flag("--merge", merge, "With --blocks: write the blocks glued into one surface file (-o NAME.vtp, ...); the whole\n"
               "surface is then held at once, as with any output but .pvtp");
  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
  // molsurf batch's jobs: their outputs' stale temporaries were removed by the batch, which
  // lists its output folder once; each job listing a folder of a sweep's reports again
  // costs more than a small structure's whole run.
  app.add_flag("--stale-temporaries-removed", stale_listed)->group("");
  app.add_flag("--progress", progress,
               "Show the progress bar of each stage on stderr even when it is not a terminal (it shows on a\n"
               "terminal anyway; -q silences it)");
}

}  // namespace molsurf::cli
