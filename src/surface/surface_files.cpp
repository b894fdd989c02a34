#include "molsurf/surface_files.hpp"

#include "molsurf/output_files.hpp"

namespace molsurf {

MeshWriteOptions surface_write_options(SurfaceKind kind, const SphereOptions& spheres, std::span<const Atom> atoms,
                                       const std::filesystem::path& source, const SurfaceFileOptions& file) {
  MeshWriteOptions options;
  options.atoms = atoms;
  options.probe_radius = spheres.probe;
  options.density = spheres.density;
  options.ascii = file.ascii;
  options.threads = file.threads;
  options.msms_header = file.msms_header;
  options.msms_atom_names = file.msms_header;
  options.msms_decimals = file.msms_decimals;
  // The SES's toroidal and reentrant faces lie on no atom's sphere (MSMS normals).
  options.faces_on_atom_spheres = kind != SurfaceKind::ses;
  const bool vdw = kind == SurfaceKind::vdw || (kind == SurfaceKind::sas && spheres.probe == 0);
  options.surface_description = std::string(vdw                          ? "van der Waals surface"
                                            : kind == SurfaceKind::ses ? "solvent excluded surface"
                                                                       : "solvent accessible surface") +
                                " for " + source.filename().string();
  return options;
}

MeshCheckOptions surface_check_options(const ComputedSurface& surface, int threads) {
  MeshCheckOptions options;
  options.self_intersections = surface.check.self_intersections_checked;
  options.threads = threads;
  return options;
}

WrittenCheck check_surface_as_written(const std::filesystem::path& path, const ComputedSurface& surface,
                                      const MeshWriteOptions& options) {
  MeshWriteOptions with_patches = options;
  if (!options.faces_on_atom_spheres) with_patches.ses_arrangement = surface.ses_arrangement;
  return check_as_written(path, surface.mesh, surface.check, with_patches,
                          surface_check_options(surface, options.threads), [](const MeshCheck& c) { return c.valid(); });
}

WrittenSurface write_surface(const std::filesystem::path& path, const ComputedSurface& surface,
                             const MeshWriteOptions& options) {
  const OutputRequest output{path, "path", true};
  check_output_paths({}, std::span(&output, 1));
  const WrittenCheck written = check_surface_as_written(path, surface, options);
  OutputFiles files;
  files.add_mesh(path, surface.mesh, written.options);
  return {files.commit(), written.note};
}

}  // namespace molsurf
