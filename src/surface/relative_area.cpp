#include "molsurf/relative_area.hpp"

#include <array>

namespace molsurf {

namespace {

struct MaxArea {
  std::string_view name;
  double theoretical, empirical;
};

// Tien et al. 2013, Table 1 (A^2).
constexpr std::array<MaxArea, 20> kMaxArea{{
    {"ALA", 129, 121}, {"ARG", 274, 265}, {"ASN", 195, 187}, {"ASP", 193, 187}, {"CYS", 167, 148},
    {"GLN", 225, 214}, {"GLU", 223, 214}, {"GLY", 104, 97},  {"HIS", 224, 216}, {"ILE", 197, 195},
    {"LEU", 201, 191}, {"LYS", 236, 230}, {"MET", 224, 203}, {"PHE", 240, 228}, {"PRO", 159, 154},
    {"SER", 155, 143}, {"THR", 172, 163}, {"TRP", 285, 264}, {"TYR", 263, 255}, {"VAL", 174, 165},
}};

}  // namespace

std::optional<double> max_residue_area(std::string_view residue_name, MaxAreaScale scale) {
  for (const MaxArea& m : kMaxArea)
    if (m.name == residue_name) return scale == MaxAreaScale::theoretical ? m.theoretical : m.empirical;
  return std::nullopt;
}

}  // namespace molsurf
