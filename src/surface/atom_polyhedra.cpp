#include "surface/atom_polyhedra.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "arrangement/contained_spheres.hpp"
#include "common/parallel_exceptions.hpp"
#include "geometry/point_grid.hpp"
#include "mesh/icosphere.hpp"

namespace molsurf::surface_detail {

namespace {

PolyhedronTemplate make_template(int frequency) {
  PolyhedronTemplate t;
  t.frequency = frequency;
  t.unit = make_unit_icosphere(frequency);
  t.area = surface_area(t.unit);
  std::map<std::pair<Index, Index>, std::uint32_t> edge_id;
  t.face_edges.resize(t.unit.faces.size());
  double inradius = 1;
  for (std::size_t f = 0; f < t.unit.faces.size(); ++f) {
    const Triangle& c = t.unit.faces[f];
    for (int k = 0; k < 3; ++k) {
      const Index a = std::min(c[k], c[(k + 1) % 3]), b = std::max(c[k], c[(k + 1) % 3]);
      auto [it, inserted] = edge_id.try_emplace({a, b}, static_cast<std::uint32_t>(t.edges.size()));
      if (inserted) t.edges.push_back({a, b});
      t.face_edges[f][k] = it->second;
    }
    const Vec3 &p = t.unit.vertices[c[0]], &q = t.unit.vertices[c[1]], &r = t.unit.vertices[c[2]];
    const Vec3 n = cross(q - p, r - p);
    inradius = std::min(inradius, dot(n, p) / std::sqrt(dot(n, n)));
    const Vec3 m = (p + q + r) * (1.0 / 3);
    t.face_centre.push_back(m);
    t.face_radius.push_back(std::sqrt(std::max({dot(p - m, p - m), dot(q - m, q - m), dot(r - m, r - m)})) * (1 + 1e-9));
    for (const Vec3& e : {q - p, r - q, p - r}) t.max_edge = std::max(t.max_edge, std::sqrt(dot(e, e)) * (1 + 1e-9));
  }
  t.inradius = inradius;

  std::vector<std::uint32_t> count(t.unit.vertices.size() + 1, 0);
  for (const Triangle& c : t.unit.faces)
    for (Index v : c) ++count[v + 1];
  std::partial_sum(count.begin(), count.end(), count.begin());
  t.vertex_faces_first = count;
  t.vertex_faces.resize(count.back());
  for (std::uint32_t f = 0; f < t.unit.faces.size(); ++f)
    for (Index v : t.unit.faces[f]) t.vertex_faces[count[v]++] = f;

  // The subdivision lays out each icosahedron face's n^2 faces as a block, row i (from the
  // face's first corner towards its second) holding up and down triangles alternately;
  // the block's corners are its first face's corner 0, its last up triangle of column 0's
  // corner 1, and its row 0's last face's corner 2.
  const int n = frequency;
  t.row_start.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) t.row_start[i + 1] = t.row_start[i] + 2 * (n - i) - 1;
  for (int b = 0; b < 20; ++b) {
    const std::size_t block = static_cast<std::size_t>(b) * n * n;
    const Vec3 a = t.unit.vertices[t.unit.faces[block][0]];
    const Vec3 bb = t.unit.vertices[t.unit.faces[block + t.row_start[n - 1]][1]];
    const Vec3 c = t.unit.vertices[t.unit.faces[block + 2 * (n - 1)][2]];
    t.base_normal[b] = normalized(a + bb + c);
    // Inverse of [a bb c] (columns): rows are the cross products over the determinant.
    const double det = dot(a, cross(bb, c));
    t.base_inverse[b] = {cross(bb, c) * (1 / det), cross(c, a) * (1 / det), cross(a, bb) * (1 / det)};
    Vec3 centre{0, 0, 0};
    for (std::size_t f = block; f < block + n * n; ++f) centre = centre + t.face_centre[f];
    centre = centre * (1.0 / (n * n));
    double radius = 0;
    for (std::size_t f = block; f < block + n * n; ++f) {
      const Vec3 d = t.face_centre[f] - centre;
      radius = std::max(radius, std::sqrt(dot(d, d)) + t.face_radius[f]);
    }
    t.block_centre[b] = centre;
    t.block_radius[b] = radius * (1 + 1e-9);
  }
  return t;
}

}  // namespace

std::optional<bool> settled_by_balls(const std::array<geometry::Interval, 3>& box, const Vec3& centre, double inradius,
                                     double circumradius) {
  double nearest2 = 0, farthest2 = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = box[axis].lo - centre[axis], hi = box[axis].hi - centre[axis];
    const double nearest = lo > 0 ? lo : (hi < 0 ? -hi : 0.0), farthest = std::max(std::fabs(lo), std::fabs(hi));
    nearest2 += nearest * nearest;
    farthest2 += farthest * farthest;
  }
  if (farthest2 < inradius * inradius) return true;
  if (nearest2 > circumradius * circumradius) return false;
  return std::nullopt;  // also for a NaN bound
}

namespace {

void sphere_sizes(std::span<const Atom> atoms, const SphereOptions& options, std::vector<Vec3>& centre,
                  std::vector<int>& frequency, std::vector<double>& radius) {
  const std::size_t n = atoms.size();
  centre.resize(n);
  frequency.resize(n);
  radius.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    centre[i] = atoms[i].centre;
    frequency[i] = sphere_frequency(atoms[i], options);
    radius[i] = sphere_radius(atoms[i], options);
  }
}

}  // namespace

AtomPolyhedra::AtomPolyhedra(std::span<const Atom> atoms, const SphereOptions& options) {
  std::vector<int> frequency;
  std::vector<double> radius;
  sphere_sizes(atoms, options, centre_, frequency, radius);
  // Atoms whose sphere another atom's ball holds (copies, the smaller of concentric
  // atoms) add nothing to the union of the true balls: decided exactly on the sphere
  // radii, as the arrangement decides it, so the mesh and the exact areas drop the same.
  // First, so that no template is built for them alone (10 000 concentric atoms of
  // different radii would need hundreds).
  const std::vector<std::uint32_t> container = arrangement::sphere_containers(centre_, radius);
  build(atoms, options, container, frequency, radius);
}

AtomPolyhedra::AtomPolyhedra(std::span<const Atom> atoms, const SphereOptions& options,
                             std::span<const std::uint8_t> contained) {
  if (contained.size() != atoms.size()) throw std::invalid_argument("AtomPolyhedra: one containment flag per atom");
  std::vector<int> frequency;
  std::vector<double> radius;
  sphere_sizes(atoms, options, centre_, frequency, radius);
  // A contained atom's holder may lie outside these atoms: it takes the first free atom's
  // shape instead (contained atoms are never built, only sized).
  std::uint32_t free_atom = 0;
  while (free_atom < atoms.size() && contained[free_atom]) ++free_atom;
  std::vector<std::uint32_t> container(atoms.size());
  for (std::uint32_t i = 0; i < atoms.size(); ++i)
    container[i] = !contained[i] || free_atom == atoms.size() ? i : free_atom;
  build(atoms, options, container, frequency, radius);
  for (std::size_t i = 0; i < atoms.size(); ++i) contained_[i] = contained[i] != 0;
}

void AtomPolyhedra::build(std::span<const Atom> atoms, const SphereOptions& options,
                          std::span<const std::uint32_t> container, std::span<const int> frequency,
                          std::span<const double> radius) {
  const std::size_t n = atoms.size();
  scale_.resize(n);
  circumradius_.resize(n);
  inradius_.resize(n);
  template_of_.resize(n);
  contained_.assign(n, 0);
  std::map<int, std::uint16_t> template_index;
  for (std::size_t i = 0; i < n; ++i) {
    contained_[i] = container[i] != i;
    // A contained atom takes its holder's shape: it is never built, only sized.
    const int f = frequency[container[i]];
    auto [it, inserted] = template_index.try_emplace(f, static_cast<std::uint16_t>(templates_.size()));
    if (inserted) templates_.push_back(make_template(f));
    template_of_[i] = it->second;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const PolyhedronTemplate& t = templates_[template_of_[i]];
    centre_[i] = atoms[i].centre;
    // As make_icosphere: area-corrected, or inscribed just inside the sphere.
    scale_[i] = icosphere_scale(centre_[i], radius[i], t.area, options.area_corrected);
    // Unit vertices have length 1 within a few ulps; the margins cover that and the
    // rounding of centre + u * scale many times over.
    circumradius_[i] = scale_[i] * (1 + 1e-9) + 1e-9 * std::max({std::fabs(centre_[i].x), std::fabs(centre_[i].y),
                                                                  std::fabs(centre_[i].z)});
    inradius_[i] = std::max(0.0, scale_[i] * t.inradius * (1 - 1e-9) -
                                     1e-9 * std::max({std::fabs(centre_[i].x), std::fabs(centre_[i].y),
                                                      std::fabs(centre_[i].z)}));
  }
}

std::uint32_t PolyhedronTemplate::face_towards(const Vec3& direction) const {
  int base = 0;
  double best = dot(direction, base_normal[0]);
  for (int b = 1; b < 20; ++b) {
    const double score = dot(direction, base_normal[b]);
    if (score > best) {
      best = score;
      base = b;
    }
  }
  const auto& m = base_inverse[base];
  const double alpha = dot(m[0], direction), beta = dot(m[1], direction), gamma = dot(m[2], direction);
  const double sum = alpha + beta + gamma;
  const int n = frequency;
  const double fi = std::clamp(beta / sum * n, 0.0, static_cast<double>(n)),
               fj = std::clamp(gamma / sum * n, 0.0, static_cast<double>(n));
  const int i = std::min(static_cast<int>(fi), n - 1);
  const int j = std::clamp(static_cast<int>(fj), 0, n - 1 - i);
  const bool down = i + j < n - 1 && (fi - i) + (fj - j) > 1;
  return static_cast<std::uint32_t>(base * n * n + row_start[i] + 2 * j + (down ? 1 : 0));
}

void AtomPolyhedra::vertices(std::size_t atom, std::vector<Vec3>& out) const {
  const auto& unit = shape(atom).unit.vertices;
  out.resize(unit.size());
  for (std::size_t v = 0; v < unit.size(); ++v) out[v] = centre_[atom] + unit[v] * scale_[atom];
}

std::size_t AtomPolyhedra::contained_count() const {
  return static_cast<std::size_t>(std::count(contained_.begin(), contained_.end(), 1));
}

std::size_t AtomPolyhedra::face_count() const {
  std::size_t faces = 0;
  for (std::size_t i = 0; i < size(); ++i)
    if (!contained(i)) faces += shape(i).unit.faces.size();
  return faces;
}

NeighbourList find_neighbours(const AtomPolyhedra& polyhedra) {
  const std::size_t n = polyhedra.size();
  NeighbourList list;
  list.first.assign(n + 1, 0);
  if (n == 0) return list;
  double largest = 0;
  std::vector<Vec3> centres(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!polyhedra.contained(i)) largest = std::max(largest, polyhedra.circumradius(i));
    centres[i] = polyhedra.centre(i);
  }
  const geometry::PointGrid grid(centres, 2 * largest, [&](std::size_t i) { return !polyhedra.contained(i); });
  std::vector<std::vector<std::uint32_t>> rows(n);
  // Rows are independent (the grid is only read): in parallel, each sorted, so the list
  // does not depend on the thread count.
  const auto count = static_cast<std::int64_t>(n);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 256) if (count >= 4096)
  for (std::int64_t row = 0; row < count; ++row)
    errors.run(row, [&] {
      const auto i = static_cast<std::size_t>(row);
      if (polyhedra.contained(i)) return;
      grid.for_each_near(centres[i], [&](std::uint32_t j) {
        if (j == i) return;
        const Vec3 d = centres[j] - centres[i];
        const double reach = polyhedra.circumradius(i) + polyhedra.circumradius(j);
        if (dot(d, d) <= reach * reach * (1 + 1e-9)) rows[i].push_back(j);
      });
      std::sort(rows[i].begin(), rows[i].end());
      rows[i].erase(std::unique(rows[i].begin(), rows[i].end()), rows[i].end());
    });
  errors.rethrow();
  for (std::size_t i = 0; i < n; ++i) list.first[i + 1] = list.first[i] + static_cast<std::uint32_t>(rows[i].size());
  list.atoms.reserve(list.first[n]);
  for (const auto& row : rows) list.atoms.insert(list.atoms.end(), row.begin(), row.end());
  return list;
}

}  // namespace molsurf::surface_detail
