#include "ses/excluded_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "mesh/topology.hpp"
#include "molsurf/error.hpp"

namespace molsurf::ses_detail {

namespace {

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) { return std::uint64_t(a) << 32 | b; }

// For every corner (3 f + k), the face across its outgoing edge (f[k] -> f[k+1]) and that
// face's corner at the edge's tail f[k].
struct Across {
  std::vector<std::uint32_t> face, corner;
};

Across faces_across(const Mesh& sas) {
  const std::size_t n = sas.face_count();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;  // (u -> v, corner of u)
  edges.reserve(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(pair_key(sas.faces[f][k], sas.faces[f][(k + 1) % 3]), static_cast<std::uint32_t>(3 * f + k));
  std::sort(edges.begin(), edges.end());
  Across across;
  across.face.resize(3 * n);
  across.corner.resize(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t reverse = pair_key(sas.faces[f][(k + 1) % 3], sas.faces[f][k]);
      const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{reverse, std::uint32_t{0}});
      if (it == edges.end() || it->first != reverse || (it + 1 != edges.end() && (it + 1)->first == reverse))
        throw Error("solvent-excluded surface: the solvent-accessible surface is not closed and 2-manifold "
                    "(a molsurf bug; please report it)");
      // The reverse edge v -> u starts at corner `it->second` (at v); its head u is the next corner.
      const std::uint32_t g = it->second / 3, m = it->second % 3;
      across.face[3 * f + k] = g;
      across.corner[3 * f + k] = 3 * g + (m + 1) % 3;
    }
  return across;
}

// Unit vectors a and b interpolated along their great circle (s in [0, 1]).
Vec3 slerp(const Vec3& a, const Vec3& b, double angle, double s) {
  const double sine = std::sin(angle);
  return (a * std::sin((1 - s) * angle) + b * std::sin(s * angle)) / sine;
}

// How far a pinched fan's contact vertex is drawn from its SAS vertex toward the middle of
// the fan's faces (CoreBuilder::contact_source).
constexpr double kPinchedFanStep = 0.1;

// The radius, in probe radii, at which points on the probe sphere are drawn when the arcs
// between them turn through `angle`. A chord lies inside the sphere by probe * angle^2 / 12
// on average and is shorter than its arc by angle^2 / 24: facets concave as seen from the
// solid, they added volume all over the toroidal and reentrant patches (+0.6 % on four
// atoms whose reentrant patches overlap). Drawn farther out by e, the facets' area grows by
// about 2 (e - angle^2 / 24) and the sphere's volume by 3 (e - angle^2 / 12); equal and
// opposite, as for the contact patches (contact_scale.hpp), at e = angle^2 / 15.
double chord_lift(double angle) { return 1 + angle * angle / 15; }

class CoreBuilder {
 public:
  CoreBuilder(const Mesh& sas, std::span<const Atom> atoms, std::span<const double> contact_scale, double probe,
              std::span<const std::uint8_t> ridge, double arc_spacing)
      : sas_(sas), atoms_(atoms), contact_scale_(contact_scale), probe_(probe), ridge_(ridge), spacing_(arc_spacing),
        across_(faces_across(sas)), fans_(3 * sas.face_count()), contact_(3 * sas.face_count(), Index(-1)),
        ridge_index_(sas.vertex_count(), Index(-1)), fan_count_(sas.vertex_count(), 0) {}

  ExcludedCore build() {
    const std::size_t n = sas_.face_count();
    for (std::size_t f = 0; f < n; ++f) {
      const std::int32_t atom = sas_.face_tags[f];
      if (atom < 0 || static_cast<std::size_t>(atom) >= atoms_.size())
        throw Error("solvent-excluded surface: a SAS face's atom tag is out of range (a molsurf bug)");
    }
    join_fans();
    for (std::size_t f = 0; f < n; ++f) {
      add_face({contact(corner(f, 0)), contact(corner(f, 1)), contact(corner(f, 2))}, sas_.face_tags[f], -1, -1);
    }
    for (std::size_t f = 0; f < n; ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t g = across_.face[3 * f + k];
        if (sas_.face_tags[g] != sas_.face_tags[f] && g > f) add_strip(f, k);
      }
    add_patches();
    return std::move(out_);
  }

 private:
  static std::uint32_t corner(std::size_t f, int k) { return static_cast<std::uint32_t>(3 * f + k); }
  Index vertex_of(std::uint32_t c) const { return sas_.faces[c / 3][c % 3]; }
  std::int32_t atom_of(std::uint32_t c) const { return sas_.face_tags[c / 3]; }
  bool rolled(Index v) const { return ridge_.empty() || ridge_[v] == 0; }

  // One contact vertex per fan of an atom's faces around a SAS vertex: corners joined
  // across the edges whose two faces belong to the same atom.
  void join_fans() {
    const std::size_t n = sas_.face_count();
    for (std::size_t f = 0; f < n; ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t g = across_.face[3 * f + k];
        if (sas_.face_tags[g] != sas_.face_tags[f]) continue;
        const std::uint32_t g_at_u = across_.corner[3 * f + k];
        fans_.unite(corner(f, k), g_at_u);
        fans_.unite(corner(f, (k + 1) % 3), 3 * g + (g_at_u % 3 + 2) % 3);
      }
    std::vector<std::uint64_t> vertex_atom;  // per fan
    for (std::uint32_t c = 0; c < 3 * n; ++c)
      if (fans_.find(c) == c) {
        ++fan_count_[vertex_of(c)];
        vertex_atom.push_back(pair_key(vertex_of(c), static_cast<std::uint32_t>(atom_of(c))));
      }
    std::sort(vertex_atom.begin(), vertex_atom.end());
    std::vector<std::uint64_t> pinched;
    for (std::size_t k = 1; k < vertex_atom.size(); ++k)
      if (vertex_atom[k] == vertex_atom[k - 1] && (k == 1 || vertex_atom[k - 1] != vertex_atom[k - 2])) {
        ++out_.pinched_vertices;
        pinched.push_back(vertex_atom[k]);
      }
    // Where one atom's faces form several fans around a SAS vertex (its patch pinched there,
    // as around a hole the probe only just passes), each fan's contact vertex scaled from
    // the SAS vertex would land on the same point, and the fans' faces would touch there:
    // each is drawn from a point inside its own fan instead (below).
    if (pinched.empty()) return;
    for (std::uint32_t c = 0; c < 3 * n; ++c) {
      const std::uint64_t key = pair_key(vertex_of(c), static_cast<std::uint32_t>(atom_of(c)));
      if (!std::binary_search(pinched.begin(), pinched.end(), key)) continue;
      const Triangle& t = sas_.faces[c / 3];
      auto& [sum, count] = fan_middle_[fans_.find(c)];
      sum = sum + (sas_.vertices[t[0]] + sas_.vertices[t[1]] + sas_.vertices[t[2]]) / 3.0;
      ++count;
    }
  }

  // The SAS point a fan's contact vertex is scaled from: its SAS vertex, or for a pinched
  // atom a tenth of the way from it to the middle of the fan's faces (a tenth keeps the
  // point inside a fan that turns through more than half a circle).
  Vec3 contact_source(std::uint32_t root, Index v) const {
    const Vec3& point = sas_.vertices[v];
    const auto it = fan_middle_.find(root);
    if (it == fan_middle_.end()) return point;
    const auto& [sum, count] = it->second;
    return point + (sum / static_cast<double>(count) - point) * kPinchedFanStep;
  }

  Index contact(std::uint32_t c) {
    const std::uint32_t root = fans_.find(c);
    if (contact_[root] == Index(-1)) {
      const auto a = static_cast<std::size_t>(atom_of(c));
      const Vec3& centre = atoms_[a].centre;
      contact_[root] = new_vertex(centre + (contact_source(root, vertex_of(c)) - centre) * contact_scale_[a]);
    }
    return contact_[root];
  }

  Index ridge_point(Index v) {
    if (ridge_index_[v] == Index(-1)) ridge_index_[v] = new_vertex(sas_.vertices[v]);
    return ridge_index_[v];
  }

  Index new_vertex(const Vec3& p) {
    out_.mesh.vertices.push_back(p);
    return static_cast<Index>(out_.mesh.vertices.size() - 1);
  }

  void add_face(const Triangle& t, std::int32_t tag, std::int64_t vertex, std::int64_t other) {
    out_.mesh.faces.push_back(t);
    out_.mesh.face_tags.push_back(tag);
    out_.face_vertex.push_back(vertex);
    out_.face_vertex_other.push_back(other);
  }

  // The profile at a SAS vertex between the fans of corners a and b, from a's contact point
  // to b's: made once per pair of fans and shared, reversed, by the other side.
  std::vector<Index> profile(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ra = fans_.find(a), rb = fans_.find(b);
    const std::uint64_t key = pair_key(std::min(ra, rb), std::max(ra, rb));
    auto it = profiles_.find(key);
    if (it == profiles_.end()) {
      const std::uint32_t low = ra < rb ? a : b, high = ra < rb ? b : a;
      const Index v = vertex_of(a);
      std::vector<Index> line{contact(low)};
      if (!rolled(v)) {
        line.push_back(ridge_point(v));
      } else {
        const Vec3 u = sas_.vertices[v];
        const Vec3 da = normalized(out_.mesh.vertices[line[0]] - u);
        const Vec3 db = normalized(out_.mesh.vertices[contact(high)] - u);
        const double angle = std::acos(std::clamp(dot(da, db), -1.0, 1.0));
        const auto segments = static_cast<std::size_t>(std::ceil(angle * probe_ / spacing_));
        const double lift = probe_ * chord_lift(angle / static_cast<double>(segments));
        if (std::sin(angle) > 1e-9)
          for (std::size_t s = 1; s < segments; ++s)
            line.push_back(new_vertex(u + slerp(da, db, angle, static_cast<double>(s) / static_cast<double>(segments)) * lift));
      }
      line.push_back(contact(high));
      it = profiles_.emplace(key, std::move(line)).first;
    }
    std::vector<Index> line = it->second;
    if (ra > rb) std::reverse(line.begin(), line.end());
    return line;
  }

  // The strip of seam edge u -> v of face f (its atom on the left of the profiles' start),
  // zipped between the profiles at u and at v by the shorter diagonal.
  void add_strip(std::size_t f, int k) {
    const std::uint32_t g_at_u = across_.corner[3 * f + k];
    const std::uint32_t g = g_at_u / 3;
    const std::uint32_t g_at_v = 3 * g + (g_at_u % 3 + 2) % 3;
    const Index u = vertex_of(corner(f, k)), v = vertex_of(corner(f, (k + 1) % 3));
    const std::vector<Index> pu = profile(corner(f, k), g_at_u), pv = profile(corner(f, (k + 1) % 3), g_at_v);
    const std::int32_t atom_f = sas_.face_tags[f], atom_g = sas_.face_tags[g];
    const std::vector<Vec3>& p = out_.mesh.vertices;
    std::size_t a = 0, b = 0;
    while (a + 1 < pu.size() || b + 1 < pv.size()) {
      const bool advance_u =
          b + 1 == pv.size() ||
          (a + 1 < pu.size() && norm(p[pu[a + 1]] - p[pv[b]]) <= norm(p[pv[b + 1]] - p[pu[a]]));
      // Which atom's side of the strip: by how far along both profiles the face lies.
      const double along = (static_cast<double>(a) + 0.5 * advance_u) / static_cast<double>(pu.size() - 1) +
                           (static_cast<double>(b) + 0.5 * !advance_u) / static_cast<double>(pv.size() - 1);
      const std::int32_t tag = along < 1 ? atom_f : atom_g;
      if (advance_u) {
        add_face({pv[b], pu[a], pu[a + 1]}, tag, u, v);
        ++a;
      } else {
        add_face({pv[b], pu[a], pv[b + 1]}, tag, u, v);
        ++b;
      }
      ++out_.strip_faces;
    }
    // A rolled vertex where three or more atoms meet gets a patch; it runs each profile the
    // other way round from the strip: backwards at the tail u, forwards at the head v.
    if (rolled(u) && fan_count_[u] >= 3)
      for (std::size_t t = 0; t + 1 < pu.size(); ++t) patch_edges_.push_back({u, pu[t + 1], pu[t]});
    if (rolled(v) && fan_count_[v] >= 3)
      for (std::size_t t = 0; t + 1 < pv.size(); ++t) patch_edges_.push_back({v, pv[t], pv[t + 1]});
  }

  // Each reentrant patch: rings on the probe sphere between its boundary loop and a point
  // above the loop's middle, one ring point per boundary point along the great circle to
  // that point, as many rings as the arc spacing asks.
  void add_patches() {
    std::sort(patch_edges_.begin(), patch_edges_.end());
    std::vector<std::int32_t> atoms_at;
    for (std::size_t first = 0; first < patch_edges_.size();) {
      const Index u = std::get<0>(patch_edges_[first]);
      std::size_t last = first;
      while (last < patch_edges_.size() && std::get<0>(patch_edges_[last]) == u) ++last;
      add_patch(u, std::span(patch_edges_).subspan(first, last - first), atoms_at);
      first = last;
    }
  }

  void add_patch(Index u, std::span<const std::tuple<Index, Index, Index>> edges, std::vector<std::int32_t>& atoms_at) {
    const Vec3 centre = sas_.vertices[u];
    // The boundary as one loop: each edge's head is the next edge's tail.
    std::unordered_map<Index, Index> next;
    for (const auto& [vertex, a, b] : edges) next[a] = b;
    std::vector<Index> loop{std::get<1>(edges[0])};
    while (loop.size() <= edges.size()) {
      const auto it = next.find(loop.back());
      if (it == next.end() || it->second == loop.front()) break;
      loop.push_back(it->second);
    }
    atoms_at.clear();
    for (const auto& e : edges) atoms_at.push_back(contact_atom(std::get<1>(e)));
    std::sort(atoms_at.begin(), atoms_at.end());
    atoms_at.erase(std::unique(atoms_at.begin(), atoms_at.end()), atoms_at.end());
    std::vector<Vec3> direction;
    Vec3 sum{0, 0, 0};
    for (Index b : loop) {
      direction.push_back(normalized(out_.mesh.vertices[b] - centre));
      sum = sum + direction.back();
    }
    const Vec3 middle = normalized(sum);
    double widest = 0;
    for (const Vec3& d : direction) widest = std::max(widest, std::acos(std::clamp(dot(d, middle), -1.0, 1.0)));
    const auto rings = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(widest * probe_ / spacing_)));
    const double lift = probe_ * chord_lift(widest / static_cast<double>(rings));
    const Index apex = new_vertex(centre + middle * lift);
    auto face = [&](Index a, Index b, Index c) {
      const Vec3 m = (out_.mesh.vertices[a] + out_.mesh.vertices[b] + out_.mesh.vertices[c]) / 3.0;
      add_face({a, b, c}, nearest_atom(atoms_at, atoms_, m), u, -1);
      ++out_.patch_faces;
    };
    if (loop.size() != edges.size()) {  // not one loop: a fan over the edges as they are
      for (const auto& [vertex, a, b] : edges) face(apex, a, b);
      return;
    }
    // outer: ring j + 1 (the boundary for j + 1 == rings); inner: ring j (the apex for j == 0).
    std::vector<Index> outer = loop, inner(loop.size());
    for (std::size_t j = rings; j-- > 0;) {
      if (j == 0) {
        std::fill(inner.begin(), inner.end(), apex);
      } else {
        const double s = static_cast<double>(j) / static_cast<double>(rings);
        for (std::size_t t = 0; t < loop.size(); ++t) {
          const double angle = std::acos(std::clamp(dot(direction[t], middle), -1.0, 1.0));
          const Vec3 d = std::sin(angle) > 1e-9 ? slerp(middle, direction[t], angle, s) : middle;
          inner[t] = new_vertex(centre + d * lift);
        }
      }
      for (std::size_t t = 0; t < loop.size(); ++t) {
        const std::size_t n = (t + 1) % loop.size();
        if (j == 0) {
          face(apex, outer[t], outer[n]);
        } else {
          face(inner[t], outer[t], outer[n]);
          face(inner[t], outer[n], inner[n]);
        }
      }
      outer = inner;
    }
  }

  // The atom of a contact vertex, or -1 for a meridian point.
  std::int32_t contact_atom(Index vertex) {
    if (contact_atoms_.empty()) {
      contact_atoms_.assign(out_.mesh.vertices.size(), -1);
      for (std::uint32_t c = 0; c < contact_.size(); ++c)
        if (contact_[c] != Index(-1)) contact_atoms_[contact_[c]] = atom_of(c);
    }
    return vertex < contact_atoms_.size() ? contact_atoms_[vertex] : -1;
  }

  const Mesh& sas_;
  std::span<const Atom> atoms_;
  std::span<const double> contact_scale_;
  double probe_;
  std::span<const std::uint8_t> ridge_;
  double spacing_;
  Across across_;
  DisjointSets fans_;
  std::vector<Index> contact_;      // by fan root
  std::vector<Index> ridge_index_;  // by SAS vertex
  std::vector<std::uint32_t> fan_count_;
  // By the root of a pinched atom's fan: the sum of its faces' centroids, and their count.
  std::unordered_map<std::uint32_t, std::pair<Vec3, std::size_t>> fan_middle_;
  std::unordered_map<std::uint64_t, std::vector<Index>> profiles_;
  std::vector<std::tuple<Index, Index, Index>> patch_edges_;  // (SAS vertex, from, to)
  std::vector<std::int32_t> contact_atoms_;
  ExcludedCore out_;
};

}  // namespace

ExcludedCore excluded_core(const Mesh& sas, std::span<const Atom> atoms, std::span<const double> contact_scale,
                           double probe, std::span<const std::uint8_t> ridge, double arc_spacing) {
  if (sas.face_count() == 0) return {};
  if (sas.face_tags.size() != sas.face_count()) throw Error("solvent-excluded surface: the SAS faces carry no atom tags");
  if (contact_scale.size() != atoms.size()) throw Error("solvent-excluded surface: one contact scale per atom");
  return CoreBuilder(sas, atoms, contact_scale, probe, ridge, arc_spacing).build();
}

}  // namespace molsurf::ses_detail
