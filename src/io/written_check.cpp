#include "molsurf/written_check.hpp"

#include "molsurf/error.hpp"

namespace molsurf {

namespace {

std::string defect_list(const MeshCheck& check) {
  std::string list;
  for (const std::string& defect : check.defects()) list += (list.empty() ? "" : "; ") + defect;
  return list;
}

}  // namespace

WrittenCheck check_as_written(const std::filesystem::path& output, const Mesh& mesh, const MeshCheck& check,
                              const MeshWriteOptions& options, const MeshCheckOptions& check_options,
                              const std::function<bool(const MeshCheck&)>& acceptable) {
  WrittenCheck result{check, options, std::nullopt, {}};
  const MeshFormat format = mesh_format_from_path(output);
  if (!acceptable(check) || mesh_format_is_exact(format, options)) return result;

  Mesh rounded = mesh_as_written(mesh, format, options);
  MeshCheck rounded_check = check_mesh(rounded, check_options);
  if (acceptable(rounded_check)) {
    result.check = std::move(rounded_check);
    result.rounded = std::move(rounded);
    return result;
  }
  if (format == MeshFormat::stl)
    fail(output, "not written: STL stores coordinates as float32, and rounded to float32 this surface is not "
                 "valid (" + defect_list(rounded_check) +
                 "); write .vtp, .ply, .off, .obj, .msh or .vert instead, which keep it exact");
  // MSMS: the text format can carry more digits; with exact ones the file holds `mesh`.
  result.options.msms_decimals = kMsmsExact;
  result.note = output.string() + ": coordinates written with full precision, not MSMS's 3 decimals: at " +
                std::to_string(options.msms_decimals) + " decimals the surface would not be valid (" +
                defect_list(rounded_check) + ")";
  return result;
}

}  // namespace molsurf
