#include "blocks/streamed_piece.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "blocks/band_reach.hpp"
#include "geometry/point_grid.hpp"
#include "geometry/triangle_distance.hpp"
#include "mesh/component_volume.hpp"
#include "mesh/topology.hpp"

namespace molsurf::blocks {

namespace {

constexpr std::uint8_t kFar = 255;

// Added to the border's balls: many orders of magnitude above the rounding of a distance
// (coordinates of hundreds of angstroms, 1e-13 A), and too small to matter to the border's size.
constexpr double kBallMargin = 1e-6;

// Per vertex: its rings from the seam (0 on it), kFar beyond `rings`.
std::vector<std::uint8_t> rings_from_seam(const Mesh& mesh, int rings) {
  std::vector<std::uint8_t> ring(mesh.vertices.size(), kFar);
  for (const auto& e : seam_edges(mesh)) ring[e[0]] = ring[e[1]] = 0;
  // Each sweep carries every distance at least one ring further.
  for (int sweep = 0; sweep < rings; ++sweep)
    for (const Triangle& t : mesh.faces) {
      const std::uint8_t least = std::min({ring[t[0]], ring[t[1]], ring[t[2]]});
      if (least >= rings) continue;
      for (Index v : t) ring[v] = std::min<std::uint8_t>(ring[v], least + 1);
    }
  return ring;
}

// The faces `keep` marks, on their own vertices (in first use order), tags kept.
Mesh faces_marked(const Mesh& mesh, std::span<const std::uint8_t> keep) {
  return faces_where(mesh, [&](std::size_t f) { return keep[f] != 0; });
}

// Some atoms' spheres grown by border_reach, as balls, found by place: a face is near one
// when it comes within the ball's radius of its centre.
class NearBalls {
 public:
  struct Ball {
    Vec3 centre;
    double radius;
  };
  NearBalls(std::vector<Ball> balls, double cell) : balls_(std::move(balls)), cell_(cell) {
    for (std::uint32_t a = 0; a < balls_.size(); ++a) for_cells(box_of(balls_[a]), [&](std::uint64_t key) { cells_[key].push_back(a); });
  }
  bool reach(const Mesh& mesh, std::size_t f) const {
    const BoundingBox box = bounding_box(mesh, f);
    const Triangle& t = mesh.faces[f];
    bool found = false;
    for_cells(box, [&](std::uint64_t key) {
      if (found) return;
      const auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (std::uint32_t a : it->second)
        if (box_of(balls_[a]).overlaps(box) &&
            geometry::distance_to_triangle(balls_[a].centre, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                           mesh.vertices[t[2]]) <= balls_[a].radius) {
          found = true;
          return;
        }
    });
    return found;
  }

 private:
  static BoundingBox box_of(const Ball& b) {
    BoundingBox box;
    box.extend(b.centre - Vec3{b.radius, b.radius, b.radius});
    box.extend(b.centre + Vec3{b.radius, b.radius, b.radius});
    return box;
  }
  template <class F>
  void for_cells(const BoundingBox& box, F&& f) const {
    std::int64_t lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = static_cast<std::int64_t>(std::floor(box.min[k] / cell_));
      hi[k] = static_cast<std::int64_t>(std::floor(box.max[k] / cell_));
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
          f((static_cast<std::uint64_t>(x & 0x1fffff) << 42) | (static_cast<std::uint64_t>(y & 0x1fffff) << 21) |
            static_cast<std::uint64_t>(z & 0x1fffff));
  }
  std::vector<Ball> balls_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

std::uint64_t edge_key(Index a, Index b) { return (static_cast<std::uint64_t>(a) << 32) | b; }

}  // namespace

BoundingBox sphere_box(const Atom& atom, const SphereOptions& spheres, double reach) {
  const double r = sphere_radius(atom, spheres) + reach;
  BoundingBox box;
  box.extend(atom.centre - Vec3{r, r, r});
  box.extend(atom.centre + Vec3{r, r, r});
  return box;
}

double six_volume_about(const Mesh& mesh, std::size_t face, const Vec3& origin) {
  const Triangle& t = mesh.faces[face];
  const Vec3 a = mesh.vertices[t[0]] - origin, b = mesh.vertices[t[1]] - origin, c = mesh.vertices[t[2]] - origin;
  return dot(a, cross(b, c));
}

double border_reach(const SphereOptions& spheres) {
  return 0.5 + 1.5 * 1.1 / std::sqrt(std::max(spheres.density, 0.01));
}

Vec3 volume_origin(std::span<const Atom> atoms) {
  BoundingBox box;
  for (const Atom& a : atoms) box.extend(a.centre);
  return box.empty() ? Vec3{} : 0.5 * (box.min + box.max);
}

double stray_of(const Mesh& mesh, std::size_t face, const HeldAtoms& held, const SphereOptions& spheres) {
  const std::int32_t tag = mesh.tag(face);
  const std::size_t k = tag < 0 ? HeldAtoms::kNotHeld : held.local(static_cast<std::uint32_t>(tag));
  if (k == HeldAtoms::kNotHeld) return HUGE_VAL;
  const Atom& atom = held.atoms[k];
  const double radius = sphere_radius(atom, spheres);
  double out = 0;
  for (Index v : mesh.faces[face]) out = std::max(out, norm(mesh.vertices[v] - atom.centre) - radius);
  return out;
}

SplitPiece split_piece(PieceMessage&& piece, const HeldAtoms& held, const SphereOptions& spheres, const Vec3& origin) {
  const Mesh& mesh = piece.mesh;
  const std::size_t faces = mesh.faces.size();
  const std::vector<std::uint8_t> ring = rings_from_seam(mesh, kBandRings);
  std::vector<std::uint8_t> in_band(faces), on_band_vertex(mesh.vertices.size(), 0);
  BoundingBox written_box;
  for (std::size_t f = 0; f < faces; ++f) {
    const Triangle& t = mesh.faces[f];
    in_band[f] = std::min({ring[t[0]], ring[t[1]], ring[t[2]]}) <= kBandRings;
    if (in_band[f]) {
      for (Index v : t) on_band_vertex[v] = 1;
    } else {
      written_box.extend(bounding_box(mesh, f));
    }
  }

  // The border: written faces that come within border_reach of the sphere of an atom of
  // another block, or within band_reach of a vertex of the band. A face of another block
  // has every vertex within border_reach of its own atom's sphere, and a band face after
  // the seams' cleanup lies within band_reach of its own block's band vertices (stray_of
  // and BandVertices::drift, measured on every face), so any face either could cross or
  // touch is kept here. Both are widened by kBallMargin, far above a distance's rounding:
  // a face in doubt is kept.
  std::vector<NearBalls::Ball> balls;
  double cell = 0;
  for (std::size_t a = 0; a < held.size(); ++a) {
    if (held.block_of[a] == piece.block) continue;
    const double radius = sphere_radius(held.atoms[a], spheres) + border_reach(spheres) + kBallMargin;
    const BoundingBox box = sphere_box(held.atoms[a], spheres, border_reach(spheres) + kBallMargin);
    if (written_box.empty() || !box.overlaps(written_box)) continue;
    cell = std::max(cell, 2 * radius);
    balls.push_back({held.atoms[a].centre, radius});
  }
  const NearBalls near(std::move(balls), std::max(cell, 1.0));
  const double band_near = band_reach(spheres) + kBallMargin;
  double longest = 0;
  for (std::size_t f = 0; f < faces; ++f)
    if (!in_band[f])
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, norm(mesh.vertices[mesh.faces[f][(k + 1) % 3]] - mesh.vertices[mesh.faces[f][k]]));
  // A point within band_near of a face lies within band_near and the longest edge of its
  // first corner.
  const geometry::PointGrid band_vertices(mesh.vertices, band_near + longest,
                                          [&](std::size_t v) { return on_band_vertex[v] != 0; });
  auto near_band = [&](std::size_t f) {
    const Triangle& t = mesh.faces[f];
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    bool found = false;
    band_vertices.for_each_near(a, [&](std::uint32_t v) {
      if (!found && geometry::distance_to_triangle(mesh.vertices[v], a, b, c) <= band_near) found = true;
    });
    return found;
  };
  std::vector<std::uint8_t> in_border(faces, 0), written(faces, 0);
  SplitPiece out;
  StreamedPiece& kept = out.kept;
  for (std::size_t f = 0; f < faces; ++f) {
    if (in_band[f]) continue;
    written[f] = 1;
    in_border[f] = near.reach(mesh, f) || near_band(f);
    kept.stray = std::max(kept.stray, stray_of(mesh, f, held, spheres));
  }
  {
    std::unordered_set<std::uint64_t> outside;  // directed edges of written faces not in the border
    for (std::size_t f = 0; f < faces; ++f)
      if (written[f] && !in_border[f])
        for (int k = 0; k < 3; ++k) outside.insert(edge_key(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]));
    for (std::size_t f = 0; f < faces; ++f)
      if (in_band[f] || in_border[f])
        for (int k = 0; k < 3; ++k)
          kept.border_open_edges += outside.count(edge_key(mesh.faces[f][(k + 1) % 3], mesh.faces[f][k]));
  }

  kept.block = piece.block;
  kept.band = faces_marked(mesh, in_band);
  kept.border = faces_marked(mesh, in_border);
  out.written = faces_marked(mesh, written);
  kept.seam = std::move(piece.seam);

  // The written faces' summary.
  const Mesh& w = out.written;
  kept.faces = w.faces.size();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) kept.vertices += ring[v] > kBandRings && !on_band_vertex[v];
  kept.quality = mesh_quality(w);
  std::vector<double> area(w.faces.size());
  std::vector<double> six_volume(w.faces.size());
  for (std::size_t f = 0; f < w.faces.size(); ++f) {
    area[f] = face_area(w, f);
    six_volume[f] = six_volume_about(w, f, origin);
    kept.area += area[f];
    kept.volume += six_volume[f] / 6;
  }
  {
    std::unordered_map<std::uint32_t, double> by_atom;
    std::vector<std::uint32_t> order;
    for (std::size_t f = 0; f < w.faces.size(); ++f) {
      const auto a = static_cast<std::uint32_t>(w.tag(f));
      const auto [it, inserted] = by_atom.try_emplace(a, 0.0);
      if (inserted) order.push_back(a);
      it->second += area[f];
    }
    std::sort(order.begin(), order.end());
    for (std::uint32_t a : order) kept.atom_area.push_back({a, by_atom[a]});
  }
  const Components parts = connected_components(w);
  kept.parts.resize(parts.count);
  std::vector<std::uint8_t> is_joint(w.vertices.size(), 0);
  // A written vertex is a joint when a band face has it (the written mesh's vertices are
  // the piece's in first use order).
  {
    std::vector<Index> piece_vertex(w.vertices.size(), 0);
    std::vector<Index> seen(mesh.vertices.size(), ~Index{0});
    Index next = 0;
    for (std::size_t f = 0; f < faces; ++f) {
      if (!written[f]) continue;
      for (Index v : mesh.faces[f])
        if (seen[v] == ~Index{0}) seen[v] = next, piece_vertex[next++] = v;
    }
    for (std::size_t v = 0; v < w.vertices.size(); ++v) is_joint[v] = on_band_vertex[piece_vertex[v]];
  }
  std::vector<std::uint8_t> joint_listed(w.vertices.size(), 0);
  for (std::size_t f = 0; f < w.faces.size(); ++f) {
    WrittenPart& p = kept.parts[parts.face_component[f]];
    ++p.faces;
    p.area += area[f];
    p.volume += six_volume[f] / 6;
    p.atoms.push_back(static_cast<std::uint32_t>(w.tag(f)));
    for (Index v : w.faces[f])
      if (is_joint[v] && !joint_listed[v]) {
        joint_listed[v] = 1;
        p.joints.push_back(w.vertices[v]);
      }
  }
  // A part no band face touches is a closed component on its own: measured about its own
  // vertex with an exact sign, as one process measures it (far from the job's origin a
  // speck's volume is mostly rounding there, and its sign decides cavity or outer surface).
  const ComponentVolumes own = component_volumes(w, parts);
  for (std::size_t c = 0; c < kept.parts.size(); ++c) {
    WrittenPart& p = kept.parts[c];
    if (p.joints.empty()) p.volume = own.volume[c];
    std::sort(p.atoms.begin(), p.atoms.end());
    p.atoms.erase(std::unique(p.atoms.begin(), p.atoms.end()), p.atoms.end());
  }

  kept.stats = piece.stats;
  kept.before = piece.before;
  kept.cleanup = piece.cleanup;
  kept.seconds_union = piece.seconds_union;
  kept.seconds_cleanup = piece.seconds_cleanup;
  kept.seconds_check = piece.seconds_check;
  piece.mesh = {};
  return out;
}

}  // namespace molsurf::blocks
