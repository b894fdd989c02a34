#pragma once
// Every atom's polyhedron (its icosphere), without storing them: one unit template per
// frequency, and per atom a centre and a scale. A vertex is computed as centre + u * scale,
// the same doubles make_icosphere() produces, so the one-pass and the pairwise methods
// join exactly the same polyhedra.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/interval.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::surface_detail {

struct PolyhedronTemplate {
  int frequency = 0;
  Mesh unit;                                       // circumradius 1, centred at the origin
  std::vector<std::array<Index, 2>> edges;         // (lower, higher) vertex
  std::vector<std::array<std::uint32_t, 3>> face_edges;  // edge k runs from corner k to k + 1
  double area = 0;                                 // of the unit polyhedron
  double inradius = 0;  // a lower bound on every face plane's distance from the centre
  double max_edge = 0;  // an upper bound on every edge's length
  // Per face, a ball holding it (centre and radius, unit scale): a cheap test of whether
  // a face can reach a region.
  std::vector<Vec3> face_centre;
  std::vector<double> face_radius;
  // The same per block of faces from one icosahedron face (faces b n^2 .. (b+1) n^2 - 1).
  std::array<Vec3, 20> block_centre;
  std::array<double, 20> block_radius;
  // Faces around each vertex (compressed rows).
  std::vector<std::uint32_t> vertex_faces_first, vertex_faces;

  // The face whose cone from the centre holds `direction`, found without a search (the
  // geodesic faces' cones are the flat subdivision's cones of the icosahedron's faces). A
  // guess: rounding of the template can put a direction near a cone's boundary into the
  // neighbouring cone, so callers confirm it exactly.
  std::uint32_t face_towards(const Vec3& direction) const;

  // The icosahedron's faces: their unit normals, and the inverse of the matrix whose
  // columns are their corners (barycentric coordinates of a direction).
  std::array<Vec3, 20> base_normal;
  std::array<std::array<Vec3, 3>, 20> base_inverse;  // rows
  std::vector<std::uint32_t> row_start;  // first face of each row within a base face's block
};

// What a polyhedron's inscribed and circumscribed balls (centre, inradius, circumradius as
// AtomPolyhedra gives them) settle about a point known only to lie in `box`: inside the
// closed polyhedron when the whole box lies in the inscribed ball, outside when it lies
// wholly beyond the circumscribed one, nothing otherwise (an exact test decides). The
// whole box, not its midpoint: a constructed point's box can be wide (a line nearly
// parallel to a plane), and its midpoint then says nothing of where the point is. The
// radii's margins (1e-9 relative) cover the rounding of the distances many times over.
std::optional<bool> settled_by_balls(const std::array<geometry::Interval, 3>& box, const Vec3& centre, double inradius,
                                     double circumradius);

class AtomPolyhedra {
 public:
  AtomPolyhedra(std::span<const Atom> atoms, const SphereOptions& options);
  // The same polyhedra with containment given (contained[i] != 0: atom i is held by another
  // atom's ball), as decided on a larger set of atoms: a spatial block and its halo hold
  // only part of each halo atom's surroundings, so they take the whole structure's decision.
  AtomPolyhedra(std::span<const Atom> atoms, const SphereOptions& options, std::span<const std::uint8_t> contained);

  std::size_t size() const { return centre_.size(); }
  const Vec3& centre(std::size_t atom) const { return centre_[atom]; }
  const PolyhedronTemplate& shape(std::size_t atom) const { return templates_[template_of_[atom]]; }
  // Every vertex lies within circumradius and every face plane beyond inradius of the
  // centre (both with a relative margin far above the rounding of the vertices).
  double circumradius(std::size_t atom) const { return circumradius_[atom]; }
  double inradius(std::size_t atom) const { return inradius_[atom]; }
  double scale(std::size_t atom) const { return scale_[atom]; }
  Vec3 vertex(std::size_t atom, Index v) const { return centre_[atom] + shape(atom).unit.vertices[v] * scale_[atom]; }
  // An upper bound on the rounding error of any of the atom's vertices.
  double vertex_error(std::size_t atom) const { return circumradius_[atom] - scale_[atom]; }
  void vertices(std::size_t atom, std::vector<Vec3>& out) const;
  // Atoms whose true sphere lies in another atom's closed ball (the smaller of concentric
  // atoms; of identical atoms all but the lowest index: arrangement::sphere_containers).
  // They add nothing: no polyhedron, no neighbours, no faces (their area is 0).
  bool contained(std::size_t atom) const { return contained_[atom] != 0; }
  std::size_t contained_count() const;
  std::size_t face_count() const;  // of all polyhedra but the contained atoms'

 private:
  // container[i]: the atom whose ball holds atom i's sphere (i itself when none).
  void build(std::span<const Atom> atoms, const SphereOptions& options, std::span<const std::uint32_t> container,
             std::span<const int> frequency, std::span<const double> radius);

  std::vector<PolyhedronTemplate> templates_;
  std::vector<std::uint16_t> template_of_;
  std::vector<Vec3> centre_;
  std::vector<double> scale_, circumradius_, inradius_;
  std::vector<std::uint8_t> contained_;
};

// Atoms whose polyhedra can meet: centres closer than the sum of circumradii, found with a
// uniform cell grid. Compressed rows, each sorted by atom index; contained atoms have no row.
struct NeighbourList {
  std::vector<std::uint32_t> first;  // size atoms + 1
  std::vector<std::uint32_t> atoms;
  std::span<const std::uint32_t> of(std::size_t atom) const {
    return {atoms.data() + first[atom], atoms.data() + first[atom + 1]};
  }
};
NeighbourList find_neighbours(const AtomPolyhedra& polyhedra);

}  // namespace molsurf::surface_detail
