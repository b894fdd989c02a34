// Structure format from the file name. Content sniffing is deliberately not done: a
// mis-named file should fail loudly rather than be read as something it is not.
#include <cctype>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"

namespace molsurf {

StructureFormat structure_format_from_path(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto ends_with = [&name](const std::string& suffix) {
    return name.size() > suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  const bool gzipped = ends_with(".gz");
  if (gzipped) name.resize(name.size() - 3);
  if (ends_with(".pdb") || ends_with(".ent")) return StructureFormat::pdb;
  if (ends_with(".cif") || ends_with(".mmcif")) return StructureFormat::mmcif;
  if (!gzipped && ends_with(".pqr")) return StructureFormat::pqr;
  if (!gzipped && ends_with(".xyzr")) return StructureFormat::xyzr;
  fail(path, std::string("unknown structure format") + (gzipped ? " inside .gz" : "") +
                 " (expected .pdb .ent .cif .mmcif, optionally .gz, or .pqr .xyzr)");
}

}  // namespace molsurf
