#pragma once
// The check of a surface as its file will hold it. Most formats store doubles exactly,
// but MSMS .vert prints 3 decimals and STL stores float32: rounding can turn a valid
// surface into one with degenerate or crossing faces (1crn without cleanup: 184
// degenerate faces and 23 crossing pairs at 3 decimals). So the rounded surface is
// checked, and the promise "a file molsurf writes passes `molsurf check`" holds for
// every format.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {

struct WrittenCheck {
  MeshCheck check;           // of the surface as the file holds it
  MeshWriteOptions options;  // to write with: MSMS decimals raised where 3 would break it
  // The surface as the file holds it, when that differs from the computed one (a lossy
  // format that kept it valid); reports should measure this one.
  std::optional<Mesh> rounded;
  std::string note;          // why the precision was raised; empty otherwise
};

// `check` is check_mesh(mesh, check_options), already done by the caller. When `mesh`
// passes (acceptable(check)) and the format is lossy, the rounded surface is checked too:
//  - MSMS: if 3 decimals break it, options.msms_decimals becomes kMsmsExact (exact
//    coordinates, which the checked surface then is) and `note` says so;
//  - STL: if float32 breaks it, throws molsurf::Error naming `output`, what broke, and
//    the exact formats to use instead.
// When `mesh` itself fails, returns `check` unchanged: the caller refuses to write.
WrittenCheck check_as_written(const std::filesystem::path& output, const Mesh& mesh, const MeshCheck& check,
                              const MeshWriteOptions& options, const MeshCheckOptions& check_options,
                              const std::function<bool(const MeshCheck&)>& acceptable);

}  // namespace molsurf
