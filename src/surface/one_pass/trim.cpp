// One atom's trim, face by face: cull, intersect, then split and classify (atom_trimmer.hpp).
#include <string>

#include "molsurf/error.hpp"
#include "surface/one_pass/atom_trimmer.hpp"

namespace molsurf::surface_detail::one_pass {

namespace {

// Molecular inputs cross a face with a few traces (each neighbour that reaches it adds one
// or two). Hundreds mean spheres that nearly coincide, whose union's boundary has a number
// of pieces quadratic in them on every face: refused plainly instead of running for hours.
constexpr std::size_t kMaxTracesPerFace = 256;

}  // namespace

void AtomTrimmer::load_neighbours(std::uint32_t atom) {
  const auto row = neighbours_.of(atom);
  if (nbr_.size() < row.size()) nbr_.resize(row.size());
  if (reaching_.size() < row.size()) reaching_.resize(row.size());
  nbr_count_ = row.size();
  for (std::size_t k = 0; k < row.size(); ++k) {
    Neighbour& n = nbr_[k];
    n.atom = row[k];
    n.centre = polyhedra_.centre(n.atom);
    n.scale = polyhedra_.scale(n.atom);
    n.inradius = polyhedra_.inradius(n.atom);
    n.circumradius = polyhedra_.circumradius(n.atom);
    n.shape = &polyhedra_.shape(n.atom);
    n.box = BoundingBox{};
    n.box.extend(n.centre - Vec3{n.circumradius, n.circumradius, n.circumradius});
    n.box.extend(n.centre + Vec3{n.circumradius, n.circumradius, n.circumradius});
    n.lens_found = false;
  }
}

AtomPieces AtomTrimmer::trim(std::uint32_t atom) {
  AtomPieces out;
  if (polyhedra_.contained(atom)) return out;
  atom_ = atom;
  work_.atom = atom;
  work_.own_edge_points.clear();
  centre_ = polyhedra_.centre(atom);
  polyhedra_.vertices(atom, vertices_);
  load_neighbours(atom);
  if (work_.plane_kind.size() < nbr_count_) work_.plane_kind.resize(nbr_count_);
  PointTable table;
  const PolyhedronTemplate& shape = polyhedra_.shape(atom);
  crossings_ = 0;
  find_covering();
  const std::uint32_t block_faces = static_cast<std::uint32_t>(shape.frequency * shape.frequency);
  corner_id_.assign(vertices_.size(), ~0u);
  for (std::uint32_t f = 0; f < shape.unit.faces.size(); ++f) {
    const std::uint32_t block = f / block_faces;
    if (buried_[block]) {  // f is the block's first face: the whole block is inside a neighbour
      out.faces_inside += block_faces;
      f += block_faces - 1;
      continue;
    }
    if (culled(f, block) || !intersect()) {
      ++out.faces_inside;
      continue;
    }
    if (work_.segments.size() > kMaxTracesPerFace)
      throw Error("the union is too complex to build: a face of atom " + std::to_string(atom + 1) +
                  " (counting from 1) is crossed by " + std::to_string(work_.segments.size()) +
                  " faces of its neighbours, more than " + std::to_string(kMaxTracesPerFace) +
                  "; its sphere nearly coincides with many others (a --probe far larger than the atoms' spacing?)");
    if (work_.relevant.empty()) {
      ++out.faces_whole;
      std::array<std::uint32_t, 3> local;
      for (std::uint8_t k = 0; k < 3; ++k)
        local[k] = work_.add(PointDefinition::vertex(atom_, f_index_[k]), polyhedra_, {boolean_engine::Where::corner, k},
                             ~0u);
      emit(local, out, table);
      continue;
    }
    ++out.faces_cut;
    add_crossings();
    split_and_classify(out, table);
  }
  out.crossings = crossings_;
  for (const PointDefinition& d : out.points) out.implicit_points += !d.is_explicit();
  // Every atom's pieces wait for the join together: grown by doubling, they would hold a
  // quarter more than they use.
  out.points.shrink_to_fit();
  out.coordinates.shrink_to_fit();
  out.triangles.shrink_to_fit();
  return out;
}

}  // namespace molsurf::surface_detail::one_pass
