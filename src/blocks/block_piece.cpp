#include "blocks/block_piece.hpp"

#include <memory>

#include "geometry/implicit_point.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/one_pass_union.hpp"
#include "surface/one_pass/point_definition.hpp"

namespace molsurf::blocks {

BlockPiece compute_block_piece(const BlockAtoms& block, const SphereOptions& options, int threads) {
  surface_detail::OnePassResult part =
      surface_detail::one_pass_partial_union(block.atoms, block.contained, block.in_block, options, threads);
  BlockPiece piece;
  piece.stats = part.stats;
  piece.mesh = std::move(part.mesh);
  piece.seam = seam_points(piece.mesh, part.origins, block.global_index);
  for (std::int32_t& tag : piece.mesh.face_tags) tag = static_cast<std::int32_t>(block.global_index[tag]);
  return piece;
}

SamePoint exact_same_point(std::span<const Atom> atoms, const SphereOptions& options,
                           std::span<const std::uint8_t> contained) {
  auto polyhedra = std::make_shared<std::unique_ptr<surface_detail::AtomPolyhedra>>();
  return [atoms, options, contained, polyhedra](const surface_detail::PointDefinition& a,
                                                const surface_detail::PointDefinition& b) {
    if (!*polyhedra) *polyhedra = std::make_unique<surface_detail::AtomPolyhedra>(atoms, options, contained);
    return geometry::same_point(surface_detail::construct(a, **polyhedra), surface_detail::construct(b, **polyhedra));
  };
}

}  // namespace molsurf::blocks
