#include "molsurf/patch_types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "geometry/point_grid.hpp"

namespace molsurf {

namespace {

// Per atom, the atoms whose spheres share an exposed arc with its own, sorted.
std::vector<std::vector<std::uint32_t>> partners_of(const SphereArrangement& arrangement, std::size_t n) {
  std::vector<std::vector<std::uint32_t>> partners(n);
  for (const ArrangementArc& arc : arrangement.arcs)
    if (arc.sphere < n && arc.other < n) {
      partners[arc.sphere].push_back(arc.other);
      partners[arc.other].push_back(arc.sphere);
    }
  for (auto& list : partners) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return partners;
}

// first[i]: the number of exposed pairs (a < b) with a < i, so the toroidal faces of the
// pairs (i, j > i) are numbered from first[i]; first.back() counts them all.
std::vector<std::uint32_t> first_pairs(const std::vector<std::vector<std::uint32_t>>& partners) {
  std::vector<std::uint32_t> first(partners.size() + 1, 0);
  for (std::size_t i = 0; i < partners.size(); ++i) {
    const auto above = partners[i].end() - std::upper_bound(partners[i].begin(), partners[i].end(), i);
    first[i + 1] = first[i] + static_cast<std::uint32_t>(above);
  }
  return first;
}

// The candidates for the probe position nearest a point: the exposed sphere patches, arcs and
// vertices of the r + probe spheres around it.
class NearestProbe {
 public:
  NearestProbe(std::span<const Atom> atoms, double probe, const SphereArrangement& arrangement)
      : atoms_(atoms),
        probe_(probe),
        arrangement_(arrangement),
        centres_(centres_of(atoms)),
        partners_(partners_of(arrangement, atoms.size())),
        first_pair_(first_pairs(partners_)),
        atom_grid_(centres_, largest_radius(atoms, probe) + kReach * probe),
        vertex_grid_(vertex_points(arrangement), kReach * probe) {}

  VertexPatch label(const Vec3& p) const {
    std::vector<std::uint32_t> near;  // every ball that can hold a candidate within kReach probes of p
    atom_grid_.for_each_near(p, [&](std::uint32_t i) {
      if (norm(p - centres_[i]) < radius(i) + kReach * probe_) near.push_back(i);
    });
    std::sort(near.begin(), near.end());
    const double reach = kReach * probe_;
    double best = std::numeric_limits<double>::infinity();
    VertexPatch out;
    Vec3 best_q;
    bool found = false;
    auto take = [&](double distance, const Vec3& q, PatchType type, std::uint32_t atom, std::uint32_t face) {
      best = distance;
      best_q = q;
      out.type = type;
      out.atom = atom;
      out.face = face;
      found = true;
    };
    for (std::uint32_t i : near) {  // inside a patch: the radial projection onto sphere i
      const Vec3 v = p - centres_[i];
      const double d = norm(v);
      const double distance = std::fabs(d - radius(i));
      if (!(d > 0) || distance > reach || !(distance < best)) continue;
      const Vec3 q = centres_[i] + v * (radius(i) / d);
      if (exposed(q, near, i, i)) take(distance, q, PatchType::contact, i, i);
    }
    for (std::uint32_t i : near)  // on an arc: the nearest point of the circle spheres i and j share
      for (std::uint32_t j : partners_[i]) {
        if (j < i || !std::binary_search(near.begin(), near.end(), j)) continue;
        const Vec3 axis = centres_[j] - centres_[i];
        const double d = norm(axis);
        const Vec3 n = axis / d;
        const double t = (d * d + radius(i) * radius(i) - radius(j) * radius(j)) / (2 * d);
        const double rho = std::sqrt(std::max(0.0, radius(i) * radius(i) - t * t));
        const Vec3 o = centres_[i] + n * t;
        const Vec3 w = (p - o) - n * dot(p - o, n);
        const double wn = norm(w);
        if (!(wn > 0)) continue;
        const Vec3 q = o + w * (rho / wn);
        const double distance = norm(p - q);
        if (distance > reach || !(distance < best) || !exposed(q, near, i, j)) continue;
        take(distance, q, PatchType::toroidal, nearer_atom(p, i, j), torus_face(i, j));
      }
    // At a vertex: the probe resting on three atoms. The grid visits cell by cell, so equal
    // distances (vertices at one point, where four spheres meet) go to the lower index.
    std::uint32_t best_vertex = std::numeric_limits<std::uint32_t>::max();
    vertex_grid_.for_each_near(p, [&](std::uint32_t k) {
      const ArrangementVertex& vertex = arrangement_.vertices[k];
      const double distance = norm(p - vertex.point);
      const bool nearer = distance < best || (distance == best && out.type == PatchType::reentrant && k < best_vertex);
      if (distance > reach || !nearer) return;
      best_vertex = k;
      std::uint32_t atom = vertex.spheres[0];
      for (std::uint32_t s : vertex.spheres) atom = nearer_atom(p, atom, s);
      take(distance, vertex.point, PatchType::reentrant, atom, probe_face(k));
    });
    if (!found) {  // far from the surface: the nearest atom's radial direction
      out.type = PatchType::contact;
      double nearest = std::numeric_limits<double>::infinity();
      for (std::uint32_t i : near)
        if (const double gap = norm(p - centres_[i]) - atoms_[i].radius; gap < nearest) {
          nearest = gap;
          out.atom = i;
          out.face = i;
        }
    }
    const Vec3 radial = p - centres_[out.atom];
    const Vec3 towards_probe = best_q - p;
    // On a contact patch (and wherever the probe position coincides with the point) the
    // atom's radial direction is the normal, and the more accurate of the two.
    const Vec3 direction = out.type == PatchType::contact || !(norm(towards_probe) > 0) ? radial : towards_probe;
    const double length = norm(direction);
    out.normal = length > 0 ? direction / length : Vec3{0, 0, 0};
    return out;
  }

 private:
  static constexpr double kReach = 1.5;  // candidates within 1.5 probe radii (the SES's lie at one)

  double radius(std::uint32_t i) const { return atoms_[i].radius + probe_; }

  // The analytical faces (patch_types.hpp): the torus of atoms i < j, the probe at vertex k.
  std::uint32_t torus_face(std::uint32_t i, std::uint32_t j) const {
    const std::vector<std::uint32_t>& list = partners_[i];
    const auto above = std::upper_bound(list.begin(), list.end(), i);
    const auto at = std::lower_bound(above, list.end(), j);
    return static_cast<std::uint32_t>(atoms_.size()) + first_pair_[i] + static_cast<std::uint32_t>(at - above);
  }
  std::uint32_t probe_face(std::uint32_t k) const {
    return static_cast<std::uint32_t>(atoms_.size()) + first_pair_.back() + k;
  }

  // Of two atoms, the one whose van der Waals sphere is nearer p (the lower index on a tie).
  std::uint32_t nearer_atom(const Vec3& p, std::uint32_t a, std::uint32_t b) const {
    const double ga = norm(p - centres_[a]) - atoms_[a].radius, gb = norm(p - centres_[b]) - atoms_[b].radius;
    return gb < ga || (gb == ga && b < a) ? b : a;
  }

  // Whether q lies outside every ball of `near` but spheres a and b (those it lies on).
  bool exposed(const Vec3& q, std::span<const std::uint32_t> near, std::uint32_t a, std::uint32_t b) const {
    for (std::uint32_t k : near)
      if (k != a && k != b && norm(q - centres_[k]) < radius(k)) return false;
    return true;
  }

  static std::vector<Vec3> centres_of(std::span<const Atom> atoms) {
    std::vector<Vec3> centres;
    centres.reserve(atoms.size());
    for (const Atom& a : atoms) centres.push_back(a.centre);
    return centres;
  }
  static double largest_radius(std::span<const Atom> atoms, double probe) {
    double largest = 0;
    for (const Atom& a : atoms) largest = std::max(largest, a.radius + probe);
    return largest;
  }
  static std::vector<Vec3> vertex_points(const SphereArrangement& arrangement) {
    std::vector<Vec3> points;
    points.reserve(arrangement.vertices.size());
    for (const ArrangementVertex& v : arrangement.vertices) points.push_back(v.point);
    return points;
  }

  std::span<const Atom> atoms_;
  double probe_;
  const SphereArrangement& arrangement_;
  std::vector<Vec3> centres_;
  std::vector<std::vector<std::uint32_t>> partners_;
  std::vector<std::uint32_t> first_pair_;
  geometry::PointGrid atom_grid_;
  geometry::PointGrid vertex_grid_;
};

}  // namespace

const char* patch_type_name(PatchType type) {
  switch (type) {
    case PatchType::toroidal: return "toroidal";
    case PatchType::reentrant: return "reentrant";
    case PatchType::contact: return "contact";
  }
  return "?";
}

std::size_t ses_face_count(std::size_t atoms, const SphereArrangement& arrangement) {
  return atoms + first_pairs(partners_of(arrangement, atoms)).back() + arrangement.vertices.size();
}

std::vector<VertexPatch> ses_vertex_patches(std::span<const Vec3> points, std::span<const Atom> atoms, double probe,
                                            const SphereArrangement& arrangement) {
  std::vector<VertexPatch> out(points.size());
  if (atoms.empty() || !(probe > 0)) return out;
  const NearestProbe nearest(atoms, probe, arrangement);
  const auto n = static_cast<std::int64_t>(points.size());
#pragma omp parallel for schedule(dynamic, 512)
  for (std::int64_t k = 0; k < n; ++k) out[static_cast<std::size_t>(k)] = nearest.label(points[static_cast<std::size_t>(k)]);
  return out;
}

std::vector<PatchType> face_patch_types(const Mesh& mesh, std::span<const VertexPatch> vertices) {
  std::vector<PatchType> types(mesh.face_count(), PatchType::contact);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Triangle& t = mesh.faces[f];
    const PatchType a = vertices[t[0]].type, b = vertices[t[1]].type, c = vertices[t[2]].type;
    types[f] = a == b || a == c ? a : b == c ? b : PatchType::toroidal;
  }
  return types;
}

std::vector<std::uint32_t> face_patch_numbers(const Mesh& mesh, std::span<const VertexPatch> vertices) {
  const std::vector<PatchType> types = face_patch_types(mesh, vertices);
  std::vector<std::uint32_t> numbers(mesh.face_count(), 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    // The corners of the face's type: at least one (three different types include toroidal).
    std::array<std::uint32_t, 3> faces{};
    std::size_t n = 0;
    for (Index v : mesh.faces[f])
      if (vertices[v].type == types[f]) faces[n++] = vertices[v].face;
    std::uint32_t number = faces[0];
    for (std::size_t k = 1; k < n; ++k) number = std::min(number, faces[k]);
    if (n == 3 && (faces[1] == faces[2])) number = faces[1];
    if (n >= 2 && (faces[0] == faces[1] || (n == 3 && faces[0] == faces[2]))) number = faces[0];
    numbers[f] = number;
  }
  return numbers;
}

}  // namespace molsurf

