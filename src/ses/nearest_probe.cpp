#include "ses/nearest_probe.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace molsurf::ses {

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

std::vector<Vec3> centres_of(std::span<const Atom> atoms) {
  std::vector<Vec3> centres;
  centres.reserve(atoms.size());
  for (const Atom& a : atoms) centres.push_back(a.centre);
  return centres;
}

double largest_radius(std::span<const Atom> atoms, double probe) {
  double largest = 0;
  for (const Atom& a : atoms) largest = std::max(largest, a.radius + probe);
  return largest;
}

std::vector<Vec3> vertex_points(const SphereArrangement& arrangement) {
  std::vector<Vec3> points;
  points.reserve(arrangement.vertices.size());
  for (const ArrangementVertex& v : arrangement.vertices) points.push_back(v.point);
  return points;
}

}  // namespace

std::size_t exposed_pair_count(std::size_t atoms, const SphereArrangement& arrangement) {
  return first_pairs(partners_of(arrangement, atoms)).back();
}

NearestProbe::NearestProbe(std::span<const Atom> atoms, double probe, const SphereArrangement& arrangement)
    : atoms_(atoms),
      probe_(probe),
      arrangement_(arrangement),
      centres_(centres_of(atoms)),
      partners_(partners_of(arrangement, atoms.size())),
      first_pair_(first_pairs(partners_)),
      largest_(largest_radius(atoms, probe)),
      atom_grid_(centres_, largest_ + kReach * probe),
      vertex_grid_(vertex_points(arrangement), kReach * probe),
      region_atom_grid_(centres_, 2 * largest_ + 4 * probe),
      region_vertex_grid_(vertex_points(arrangement), largest_ + 3 * probe) {}

ProbePosition NearestProbe::nearest(const Vec3& p) const {
  std::vector<std::uint32_t> near;  // every ball that can hold a candidate within kReach probes of p
  atom_grid_.for_each_near(p, [&](std::uint32_t i) {
    if (norm(p - centres_[i]) < radius(i) + kReach * probe_) near.push_back(i);
  });
  std::sort(near.begin(), near.end());
  const double reach = kReach * probe_;
  ProbePosition out;
  auto take = [&](double distance, const Vec3& q, PatchType type, std::uint32_t atom, std::uint32_t face) {
    out = {distance, q, type, atom, face};
  };
  for (std::uint32_t i : near) {  // inside a patch: the radial projection onto sphere i
    const Vec3 v = p - centres_[i];
    const double d = norm(v);
    const double distance = std::fabs(d - radius(i));
    if (!(d > 0) || distance > reach || !(distance < out.distance)) continue;
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
      if (distance > reach || !(distance < out.distance) || !exposed(q, near, i, j)) continue;
      take(distance, q, PatchType::toroidal, nearer_atom(p, i, j), torus_face(i, j));
    }
  // At a vertex: the probe resting on three atoms. The grid visits cell by cell, so equal
  // distances (vertices at one point, where four spheres meet) go to the lower index.
  std::uint32_t best_vertex = std::numeric_limits<std::uint32_t>::max();
  vertex_grid_.for_each_near(p, [&](std::uint32_t k) {
    const ArrangementVertex& vertex = arrangement_.vertices[k];
    const double distance = norm(p - vertex.point);
    const bool nearer = distance < out.distance ||
                        (distance == out.distance && out.type == PatchType::reentrant && k < best_vertex);
    if (distance > reach || !nearer) return;
    best_vertex = k;
    std::uint32_t atom = vertex.spheres[0];
    for (std::uint32_t s : vertex.spheres) atom = nearer_atom(p, atom, s);
    take(distance, vertex.point, PatchType::reentrant, atom, probe_face(k));
  });
  if (!(out.distance < std::numeric_limits<double>::infinity())) {  // far: the nearest atom
    double nearest = std::numeric_limits<double>::infinity();
    for (std::uint32_t i : near)
      if (const double gap = norm(p - centres_[i]) - atoms_[i].radius; gap < nearest) {
        nearest = gap;
        out.atom = i;
        out.face = i;
      }
    out.point = p;
  }
  return out;
}

VertexPatch NearestProbe::label(const Vec3& p) const {
  const ProbePosition q = nearest(p);
  VertexPatch out;
  out.type = q.type;
  out.atom = q.atom;
  out.face = q.face;
  const Vec3 radial = p - centres_[out.atom];
  const Vec3 towards_probe = q.point - p;
  // On a contact patch (and wherever the probe position coincides with the point) the
  // atom's radial direction is the normal, and the more accurate of the two.
  const Vec3 direction = out.type == PatchType::contact || !(norm(towards_probe) > 0) ? radial : towards_probe;
  const double length = norm(direction);
  out.normal = length > 0 ? direction / length : Vec3{0, 0, 0};
  return out;
}

bool NearestProbe::buried(const Vec3& q, std::uint32_t a, std::uint32_t b) const {
  bool inside = false;
  atom_grid_.for_each_near(q, [&](std::uint32_t k) {
    inside = inside || (k != a && k != b && norm(q - centres_[k]) < radius(k) * (1 - 1e-12));
  });
  return inside;
}

ProbeRegion NearestProbe::region(const Vec3& centre, double extent) const {
  ProbeRegion out;
  // Every ball that can hold a candidate, or a point within a probe radius of one.
  region_atom_grid_.for_each_near(centre, [&](std::uint32_t k) {
    if (norm(centre - centres_[k]) < radius(k) + extent + probe_) out.spheres.push_back(k);
  });
  std::sort(out.spheres.begin(), out.spheres.end());
  for (std::uint32_t i : out.spheres)
    for (std::uint32_t j : partners_[i]) {
      if (j < i || !std::binary_search(out.spheres.begin(), out.spheres.end(), j)) continue;
      const Vec3 axis = centres_[j] - centres_[i];
      const double d = norm(axis);
      const double t = (d * d + radius(i) * radius(i) - radius(j) * radius(j)) / (2 * d);
      out.circles.push_back({i, j, centres_[i] + axis * (t / d), axis / d,
                             std::sqrt(std::max(0.0, radius(i) * radius(i) - t * t))});
    }
  region_vertex_grid_.for_each_near(centre, [&](std::uint32_t k) {
    if (norm(centre - arrangement_.vertices[k].point) < extent + probe_) out.vertices.push_back(arrangement_.vertices[k].point);
  });
  return out;
}

bool NearestProbe::nearer_than(const ProbeRegion& region, const Vec3& x, double limit) const {
  for (const Vec3& v : region.vertices)
    if (norm(x - v) < limit) return true;
  const auto exposed_in_region = [&](const Vec3& q, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t k : region.spheres)
      if (k != a && k != b && norm(q - centres_[k]) < radius(k)) return false;
    return true;
  };
  for (std::uint32_t i : region.spheres) {
    const Vec3 v = x - centres_[i];
    const double d2 = dot(v, v), low = std::max(0.0, radius(i) - limit), high = radius(i) + limit;
    if (!(d2 > low * low && d2 < high * high)) continue;  // |d - R| < limit, without the root
    const double d = std::sqrt(d2);
    if (exposed_in_region(centres_[i] + v * (radius(i) / d), i, i)) return true;
  }
  for (const ProbeRegion::Circle& c : region.circles) {
    const double axial = dot(x - c.centre, c.axis);
    if (!(std::fabs(axial) < limit)) continue;  // the circle's plane is farther than limit
    const Vec3 w = (x - c.centre) - c.axis * axial;
    const double wn = norm(w);
    if (!(wn > 0) || !(axial * axial + (wn - c.radius) * (wn - c.radius) < limit * limit)) continue;
    if (exposed_in_region(c.centre + w * (c.radius / wn), c.a, c.b)) return true;
  }
  return false;
}

std::uint32_t NearestProbe::torus_face(std::uint32_t i, std::uint32_t j) const {
  const std::vector<std::uint32_t>& list = partners_[i];
  const auto above = std::upper_bound(list.begin(), list.end(), i);
  const auto at = std::lower_bound(above, list.end(), j);
  return static_cast<std::uint32_t>(atoms_.size()) + first_pair_[i] + static_cast<std::uint32_t>(at - above);
}

std::uint32_t NearestProbe::probe_face(std::uint32_t vertex) const {
  return static_cast<std::uint32_t>(atoms_.size()) + first_pair_.back() + vertex;
}

// Of two atoms, the one whose van der Waals sphere is nearer p (the lower index on a tie).
std::uint32_t NearestProbe::nearer_atom(const Vec3& p, std::uint32_t a, std::uint32_t b) const {
  const double ga = norm(p - centres_[a]) - atoms_[a].radius, gb = norm(p - centres_[b]) - atoms_[b].radius;
  return gb < ga || (gb == ga && b < a) ? b : a;
}

// Whether q lies outside every ball of `near` but spheres a and b (those it lies on).
bool NearestProbe::exposed(const Vec3& q, std::span<const std::uint32_t> near, std::uint32_t a,
                           std::uint32_t b) const {
  for (std::uint32_t k : near)
    if (k != a && k != b && norm(q - centres_[k]) < radius(k)) return false;
  return true;
}

}  // namespace molsurf::ses
