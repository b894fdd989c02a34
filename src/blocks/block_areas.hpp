#pragma once
// A block's exact areas: the true spheres of its atoms arranged among its halo (the halo
// holds every ball that overlaps a block atom's, as the one-pass union's neighbour rule
// reaches further), summarised as an arrangement part (arrangement/arrangement_part.hpp)
// that travels to the first process as bytes; there the parts are joined into the whole
// structure's exact report (arrangement/joined_parts.hpp). No process arranges the whole
// structure's spheres.
#include <span>
#include <string>
#include <vector>

#include "arrangement/arrangement_part.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "blocks/block_partition.hpp"
#include "blocks/byte_stream.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::blocks {

// threads: 0 keeps OpenMP's default.
arrangement::ArrangementPart block_arrangement(const BlockAtoms& block, const SphereOptions& spheres, int threads);

// The whole structure's arrangement, as the reports read it (joined_parts.hpp), from every
// block's part.
SphereArrangement joined_block_areas(std::span<const Atom> atoms, const SphereOptions& spheres,
                                     std::span<const arrangement::ArrangementPart> parts);

void put_arrangement_part(std::string& out, const arrangement::ArrangementPart& part);
// std::invalid_argument for bytes put_arrangement_part did not write.
arrangement::ArrangementPart get_arrangement_part(ByteReader& in);

}  // namespace molsurf::blocks
