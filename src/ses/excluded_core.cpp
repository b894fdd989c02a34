#include "ses/excluded_core.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "mesh/topology.hpp"
#include "molsurf/error.hpp"

namespace molsurf::ses_detail {

namespace {

std::uint64_t directed_key(Index a, Index b) { return std::uint64_t(a) << 32 | b; }

// For every corner (3 f + k), the face across its outgoing edge (f[k] -> f[k+1]) and that
// face's corner at the edge's head.
struct Across {
  std::vector<std::uint32_t> face, corner;
};

Across faces_across(const Mesh& sas) {
  const std::size_t n = sas.face_count();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;  // (u -> v, corner of u)
  edges.reserve(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(directed_key(sas.faces[f][k], sas.faces[f][(k + 1) % 3]), static_cast<std::uint32_t>(3 * f + k));
  std::sort(edges.begin(), edges.end());
  Across across;
  across.face.resize(3 * n);
  across.corner.resize(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const Index u = sas.faces[f][k], v = sas.faces[f][(k + 1) % 3];
      const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{directed_key(v, u), std::uint32_t{0}});
      if (it == edges.end() || it->first != directed_key(v, u) ||
          (it + 1 != edges.end() && (it + 1)->first == directed_key(v, u)))
        throw Error("solvent-excluded surface: the solvent-accessible surface is not closed and 2-manifold "
                    "(a molsurf bug; please report it)");
      // The reverse edge v -> u starts at corner `it->second` (at v); its head u is the next corner.
      const std::uint32_t g = it->second / 3, m = it->second % 3;
      across.face[3 * f + k] = g;
      across.corner[3 * f + k] = 3 * g + (m + 1) % 3;  // g's corner at u
    }
  return across;
}

}  // namespace

ExcludedCore excluded_core(const Mesh& sas, std::span<const Atom> atoms, double probe) {
  ExcludedCore out;
  const std::size_t n = sas.face_count();
  if (n == 0) return out;
  if (sas.face_tags.size() != n) throw Error("solvent-excluded surface: the SAS faces carry no atom tags");
  const Across across = faces_across(sas);

  // One contact vertex per fan of an atom's faces around a SAS vertex: corners joined across
  // the edges whose two faces belong to the same atom.
  DisjointSets fans(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t g = across.face[3 * f + k];
      if (sas.face_tags[g] != sas.face_tags[f]) continue;
      const std::uint32_t g_at_u = across.corner[3 * f + k];          // g's corner at f[k]
      const std::uint32_t g_at_v = 3 * g + (g_at_u % 3 + 2) % 3;       // g's corner at f[k+1]
      fans.unite(static_cast<std::uint32_t>(3 * f + k), g_at_u);
      fans.unite(static_cast<std::uint32_t>(3 * f + (k + 1) % 3), g_at_v);
    }

  Mesh& core = out.mesh;
  std::vector<Index> contact(3 * n, Index(-1));  // by fan root
  auto contact_vertex = [&](std::uint32_t corner) {
    const std::uint32_t root = fans.find(corner);
    if (contact[root] == Index(-1)) {
      const std::size_t f = corner / 3;
      const Atom& atom = atoms[static_cast<std::size_t>(sas.face_tags[f])];
      const double scale = atom.radius / (atom.radius + probe);
      const Vec3& p = sas.vertices[sas.faces[f][corner % 3]];
      contact[root] = static_cast<Index>(core.vertices.size());
      core.vertices.push_back(atom.centre + (p - atom.centre) * scale);
    }
    return contact[root];
  };
  std::vector<Index> ridge(sas.vertex_count(), Index(-1));
  auto ridge_vertex = [&](Index v) {
    if (ridge[v] == Index(-1)) {
      ridge[v] = static_cast<Index>(core.vertices.size());
      core.vertices.push_back(sas.vertices[v]);
    }
    return ridge[v];
  };

  for (std::size_t f = 0; f < n; ++f) {
    const std::int32_t atom = sas.face_tags[f];
    if (atom < 0 || static_cast<std::size_t>(atom) >= atoms.size())
      throw Error("solvent-excluded surface: a SAS face's atom tag is out of range (a molsurf bug)");
    const auto corner = [f](int k) { return static_cast<std::uint32_t>(3 * f + k); };
    core.faces.push_back({contact_vertex(corner(0)), contact_vertex(corner(1)), contact_vertex(corner(2))});
    core.face_tags.push_back(atom);
    for (int k = 0; k < 3; ++k) {
      if (sas.face_tags[across.face[3 * f + k]] == atom) continue;
      // The wall on this atom's side of the seam u -> v: from the scaled edge up to the seam.
      const Index cu = contact_vertex(corner(k)), cv = contact_vertex(corner((k + 1) % 3));
      const Index u = ridge_vertex(sas.faces[f][k]), v = ridge_vertex(sas.faces[f][(k + 1) % 3]);
      core.faces.push_back({cv, cu, u});
      core.faces.push_back({cv, u, v});
      core.face_tags.push_back(atom);
      core.face_tags.push_back(atom);
      out.wall_faces += 2;
    }
  }

  // Pinches: one atom's faces meeting at a SAS vertex in more than one fan.
  std::vector<std::uint64_t> fans_at;  // (vertex, atom) per fan
  for (std::size_t c = 0; c < 3 * n; ++c)
    if (fans.find(static_cast<std::uint32_t>(c)) == c)
      fans_at.push_back(std::uint64_t(sas.faces[c / 3][c % 3]) << 32 |
                        static_cast<std::uint32_t>(sas.face_tags[c / 3]));
  std::sort(fans_at.begin(), fans_at.end());
  for (std::size_t k = 1; k < fans_at.size(); ++k)
    if (fans_at[k] == fans_at[k - 1] && (k == 1 || fans_at[k - 1] != fans_at[k - 2])) ++out.pinched_vertices;
  return out;
}

}  // namespace molsurf::ses_detail
