#pragma once
// The probe position nearest a point: of the boundary of the union of the atoms' r + probe
// spheres (where the probe's centre can be), the nearest point to p among the candidates the
// arrangement names: radial projections onto the spheres, the nearest points of the circles
// that carry exposed arcs, and the arrangement's vertices, each kept only when no other ball
// holds it. A point of the solvent-excluded surface lies one probe radius from it; the patch
// labels (patch_types.hpp) and the SES's measures (ses_measures.hpp) both ask it.
//
// Floating-point throughout: it labels and measures, it decides nothing the surface depends on.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/point_grid.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/patch_types.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::ses {

struct ProbePosition {
  double distance = std::numeric_limits<double>::infinity();  // from the point; infinite: none within reach
  Vec3 point;                                                 // the probe's centre
  PatchType type = PatchType::contact;
  std::uint32_t atom = 0;  // as VertexPatch::atom
  std::uint32_t face = 0;  // as VertexPatch::face
};

// What can lie nearer than a probe radius to the points within `extent` of a centre: the
// balls, the circles of exposed pairs among them and the arrangement's vertices.
struct ProbeRegion {
  struct Circle {
    std::uint32_t a = 0, b = 0;
    Vec3 centre, axis;
    double radius = 0;
  };
  std::vector<std::uint32_t> spheres;
  std::vector<Circle> circles;
  std::vector<Vec3> vertices;
};

class NearestProbe {
 public:
  NearestProbe(std::span<const Atom> atoms, double probe, const SphereArrangement& arrangement);

  // Candidates within 1.5 probe radii of p (the SES's lie at one).
  ProbePosition nearest(const Vec3& p) const;
  VertexPatch label(const Vec3& p) const;

  // Whether q lies inside a ball r + probe other than a's and b's (by more than rounding).
  bool buried(const Vec3& q, std::uint32_t a, std::uint32_t b) const;

  // The candidates for points within `extent` (at most the largest r + 2 probe) of `centre`,
  // and whether one of them lies nearer than `limit` (at most the probe radius) to x: the
  // same answer as nearest(x).distance < limit, asked many times over one patch.
  ProbeRegion region(const Vec3& centre, double extent) const;
  bool nearer_than(const ProbeRegion& region, const Vec3& x, double limit) const;

  std::uint32_t torus_face(std::uint32_t i, std::uint32_t j) const;  // atoms i < j
  std::uint32_t probe_face(std::uint32_t vertex) const;

 private:
  static constexpr double kReach = 1.5;

  double radius(std::uint32_t i) const { return atoms_[i].radius + probe_; }
  std::uint32_t nearer_atom(const Vec3& p, std::uint32_t a, std::uint32_t b) const;
  bool exposed(const Vec3& q, std::span<const std::uint32_t> near, std::uint32_t a, std::uint32_t b) const;

  std::span<const Atom> atoms_;
  double probe_;
  const SphereArrangement& arrangement_;
  std::vector<Vec3> centres_;
  std::vector<std::vector<std::uint32_t>> partners_;
  std::vector<std::uint32_t> first_pair_;
  double largest_ = 0;
  geometry::PointGrid atom_grid_;
  geometry::PointGrid vertex_grid_;
  geometry::PointGrid region_atom_grid_;    // reach 2 largest + 4 probe
  geometry::PointGrid region_vertex_grid_;  // reach largest + 3 probe
};

// The number of exposed pairs of atoms (one toroidal face each).
std::size_t exposed_pair_count(std::size_t atoms, const SphereArrangement& arrangement);

}  // namespace molsurf::ses
