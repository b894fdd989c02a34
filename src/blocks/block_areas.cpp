#include "blocks/block_areas.hpp"

#include <cstdint>
#include <vector>

#include "arrangement/joined_parts.hpp"

namespace molsurf::blocks {

arrangement::ArrangementPart block_arrangement(const BlockAtoms& block, const SphereOptions& spheres, int threads) {
  const std::size_t n = block.atoms.size();
  std::vector<Vec3> centres(n);
  std::vector<double> radii(n);
  for (std::size_t i = 0; i < n; ++i) {
    centres[i] = block.atoms[i].centre;
    radii[i] = sphere_radius(block.atoms[i], spheres);
  }
  return arrangement::arrange_part(centres, radii, block.contained, block.in_block, block.global_index, threads);
}

SphereArrangement joined_block_areas(std::span<const Atom> atoms, const SphereOptions& spheres,
                                     std::span<const arrangement::ArrangementPart> parts) {
  return arrangement::join_parts(parts, atoms.size(), [&](std::uint32_t i) {
    return arrangement::Ball{atoms[i].centre, sphere_radius(atoms[i], spheres)};
  });
}

void put_arrangement_part(std::string& out, const arrangement::ArrangementPart& part) {
  put_array(out, part.sphere_area);
  put(out, static_cast<std::uint64_t>(part.shells.size()));
  for (const arrangement::ShellPart& s : part.shells) {
    put(out, s.moments);
    put(out, s.first_sphere);
    put_array(out, s.patches);
  }
  put_array(out, part.open_keys);
  put_array(out, part.open_vertices);
  put(out, part.stats);
}

arrangement::ArrangementPart get_arrangement_part(ByteReader& in) {
  arrangement::ArrangementPart part;
  part.sphere_area = in.get_array<arrangement::SphereArea>();
  const auto shells = in.get<std::uint64_t>();
  for (std::uint64_t k = 0; k < shells; ++k) {
    arrangement::ShellPart s;
    s.moments = in.get<arrangement::ShellMoments>();
    s.first_sphere = in.get<std::uint32_t>();
    s.patches = in.get_array<arrangement::SphereArea>();
    part.shells.push_back(std::move(s));
  }
  part.open_keys = in.get_array<arrangement::OpenKey>();
  part.open_vertices = in.get_array<arrangement::Key>();
  part.stats = in.get<ArrangementStats>();
  return part;
}

}  // namespace molsurf::blocks
