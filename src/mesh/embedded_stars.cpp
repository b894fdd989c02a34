#include "mesh/embedded_stars.hpp"

#include <algorithm>
#include <cmath>

#include "common/parallel_exceptions.hpp"
#include "common/parallel_threshold.hpp"
#include "geometry/predicates.hpp"

namespace molsurf {

namespace {

// The axis a star is seen along: the one its summed face normal is most along. Any axis
// is sound (the test is exact); a poor one only leaves the star unproved.
int viewing_axis(const Mesh& mesh, std::span<const std::uint32_t> faces) {
  Vec3 sum;
  for (const std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    sum += cross(b - a, c - a);
  }
  const double x = std::fabs(sum.x), y = std::fabs(sum.y), z = std::fabs(sum.z);
  return z >= x && z >= y ? 2 : (x >= y ? 0 : 1);
}

// Along `axis`, the orientation of the projected triangle (geometry::normal_sign_*), and
// a point's second projected coordinate in the same frame: x -> (y, z), y -> (z, x),
// z -> (x, y).
int seen_orientation(const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
  return axis == 0 ? geometry::normal_sign_x(a, b, c)
                   : (axis == 1 ? geometry::normal_sign_y(a, b, c) : geometry::normal_sign_z(a, b, c));
}
double seen_second(const Vec3& p, int axis) { return axis == 0 ? p.z : (axis == 1 ? p.x : p.y); }

bool star_embedded(const Mesh& mesh, Index v, std::span<const std::uint32_t> faces) {
  if (faces.size() < 3) return false;
  const int axis = viewing_axis(mesh, faces);
  const Vec3& centre = mesh.vertices[v];
  const double centre_second = seen_second(centre, axis);
  int turn = 0;
  std::size_t around = 0;
  for (const std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    const int corner = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    const Vec3 &from = mesh.vertices[t[(corner + 1) % 3]], &to = mesh.vertices[t[(corner + 2) % 3]];
    // Each face turns the same way around the vertex, by less than half a turn.
    const int sign = seen_orientation(centre, from, to, axis);
    if (sign == 0 || (turn != 0 && sign != turn)) return false;
    turn = sign;
    // The face's wedge, counter-clockwise from a to b, half open [a, b): it holds the
    // direction of the first projected axis iff a lies on or below the vertex's line and
    // b strictly above it (exact comparisons). Consecutive wedges share their boundary
    // rays, so every direction lies in as many wedges as the star winds around.
    const Vec3 &a = turn > 0 ? from : to, &b = turn > 0 ? to : from;
    around += (seen_second(a, axis) <= centre_second) && (seen_second(b, axis) > centre_second);
  }
  return around == 1;
}

// The chains around a vertex whose star is not embedded (FanKeys), as lists of faces.
std::vector<std::vector<std::uint32_t>> fan_chains(const Mesh& mesh, Index v, std::span<const std::uint32_t> faces) {
  std::vector<std::vector<std::uint32_t>> chains;
  if (faces.size() < 2) return chains;
  const int axis = viewing_axis(mesh, faces);
  const Vec3& centre = mesh.vertices[v];
  // Each face's wedge, counter-clockwise from corner a to corner b as seen, for the faces
  // that turn the way most of the star's area does.
  Vec3 sum;
  for (const std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    sum += cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
  }
  const int turn = (axis == 0 ? sum.x : (axis == 1 ? sum.y : sum.z)) >= 0 ? 1 : -1;
  struct Wedge {
    Index a, b;
    std::uint32_t face;
  };
  std::vector<Wedge> wedges;
  for (const std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    const int corner = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    const Index from = t[(corner + 1) % 3], to = t[(corner + 2) % 3];
    if (seen_orientation(centre, mesh.vertices[from], mesh.vertices[to], axis) != turn) continue;
    wedges.push_back(turn > 0 ? Wedge{from, to, f} : Wedge{to, from, f});
  }
  // Linked where one wedge's end is the next one's start (one each: a manifold star).
  auto by_start = wedges;
  std::sort(by_start.begin(), by_start.end(), [](const Wedge& x, const Wedge& y) { return x.a < y.a; });
  auto starting_at = [&](Index a) -> const Wedge* {
    const auto it = std::lower_bound(by_start.begin(), by_start.end(), a,
                                     [](const Wedge& w, Index x) { return w.a < x; });
    if (it == by_start.end() || it->a != a || (it + 1 != by_start.end() && (it + 1)->a == a)) return nullptr;
    return &*it;
  };
  std::vector<Index> ends;
  for (const Wedge& w : wedges) ends.push_back(w.b);
  std::sort(ends.begin(), ends.end());
  auto seen = [&](const Vec3& p, const Vec3& q) { return seen_orientation(centre, p, q, axis) * turn; };
  for (const Wedge& first : wedges) {
    if (std::binary_search(ends.begin(), ends.end(), first.a)) continue;  // not a chain's start
    std::vector<std::uint32_t> chain{first.face};
    const Vec3& start = mesh.vertices[first.a];
    for (const Wedge* w = starting_at(first.b); w && chain.size() <= wedges.size(); w = starting_at(w->b)) {
      // Less than once around: the start direction lies in no later wedge [a, b).
      const Vec3 &a = mesh.vertices[w->a], &b = mesh.vertices[w->b];
      if (seen(a, start) >= 0 && seen(start, b) > 0) break;
      chain.push_back(w->face);
    }
    if (chain.size() >= 2) chains.push_back(std::move(chain));
  }
  return chains;
}

}  // namespace

FanKeys::FanKeys(const Mesh& mesh, const VertexFaces& around, std::span<const std::uint8_t> embedded)
    : embedded_(embedded), vertex_count_(static_cast<std::uint32_t>(embedded.size())) {
  std::uint32_t chains = 0;
  for (Index v = 0; v < vertex_count_; ++v) {
    if (embedded[v]) continue;
    for (const std::vector<std::uint32_t>& chain : fan_chains(mesh, v, around.of(v))) {
      for (const std::uint32_t f : chain) {
        const Triangle& t = mesh.faces[f];
        const int corner = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
        chain_[std::uint64_t{f} << 2 | static_cast<std::uint64_t>(corner)] = chains;
      }
      ++chains;
    }
  }
}

std::uint32_t FanKeys::key(const Mesh& mesh, std::uint32_t f, int corner) const {
  const Index v = mesh.faces[f][corner];
  if (embedded_[v]) return v;
  if (chain_.empty()) return kNone;
  const auto it = chain_.find(std::uint64_t{f} << 2 | static_cast<std::uint64_t>(corner));
  return it == chain_.end() ? kNone : vertex_count_ + it->second;
}

std::array<std::uint32_t, 3> FanKeys::of(const Mesh& mesh, std::uint32_t f) const {
  std::array<std::uint32_t, 3> keys{key(mesh, f, 0), key(mesh, f, 1), key(mesh, f, 2)};
  std::sort(keys.begin(), keys.end());
  return keys;
}

bool FanKeys::share(const Mesh& mesh, std::uint32_t a, std::uint32_t b) const {
  const Triangle &ta = mesh.faces[a], &tb = mesh.faces[b];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ta[i] == tb[j]) {
        const std::uint32_t k = key(mesh, a, i);
        if (k != kNone && k == key(mesh, b, j)) return true;
      }
  return false;
}

std::vector<std::uint8_t> embedded_stars(const Mesh& mesh, const VertexFaces& around) {
  const auto nv = static_cast<std::int64_t>(around.start.size()) - 1;
  std::vector<std::uint8_t> embedded(static_cast<std::size_t>(std::max<std::int64_t>(nv, 0)), 0);
  ParallelExceptions errors;
#pragma omp parallel for schedule(static) if (nv >= kParallelMinItems)
  for (std::int64_t v = 0; v < nv; ++v)
    errors.run(v, [&] { embedded[v] = star_embedded(mesh, static_cast<Index>(v), around.of(static_cast<Index>(v))); });
  errors.rethrow();
  return embedded;
}

}  // namespace molsurf
