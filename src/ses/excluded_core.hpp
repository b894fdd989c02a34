#pragma once
// The solvent-excluded surface drawn from the solvent-accessible surface's mesh, face by
// face, with no Boolean: the inner parallel surface of the SAS at the probe radius.
//  - each atom's SAS faces, scaled about the atom's centre by r_vdW / (r_vdW + probe) (and
//    the facets' balance: contact_scale.hpp), become its contact patch on the van der Waals sphere (one copy of a SAS vertex per fan
//    of one atom's faces around it);
//  - each seam edge between two atoms' faces becomes a strip between the profiles at its two
//    ends, and each SAS vertex where three or more atoms meet a patch closing its profiles.
// A SAS vertex is `rolled` or a `ridge`:
//  - rolled: its profile between two atoms is the probe's meridian arc (the probe centred at
//    the vertex, from one contact point to the other), and where three or more atoms meet,
//    a reentrant patch on the probe sphere closes them (their points drawn a little beyond
//    the sphere, so that the facets between them lie on it on average: chord_lift in
//    excluded_core.cpp). Rolled everywhere, the surface is the
//    SES itself wherever the SES has no singularity; where it has (probes that overlap, a
//    spindle torus), the surface crosses itself;
//  - ridge: its profile runs from one contact point up to the SAS vertex and down to the
//    other. Around ridge vertices the surface bounds the SAS solid minus the probe's sweep
//    over the faces' insides: the core that the union of probe balls then carves exactly.
// Closed, oriented and 2-manifold by construction whatever the modes.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::ses_detail {

struct ExcludedCore {
  Mesh mesh;  // face tags: atom index (the nearest of the atoms a strip or patch joins)
  // Per face, the SAS vertex it was drawn for (a strip: its seam edge's tail; a patch: its
  // vertex), or -1 for a contact face.
  std::vector<std::int64_t> face_vertex;
  std::vector<std::int64_t> face_vertex_other;  // a strip's seam edge head; -1 otherwise
  std::size_t strip_faces = 0, patch_faces = 0;
  std::size_t pinched_vertices = 0;  // SAS vertices where one atom's faces form several fans
};

// Of `candidates` (atom indices; negative ones skipped), the atom whose van der Waals sphere
// lies nearest `point`; -1 if none (MSMS gives each vertex its closest atom likewise).
template <class Indices>
std::int32_t nearest_atom(const Indices& candidates, std::span<const Atom> atoms, const Vec3& point) {
  std::int32_t best = -1;
  double best_gap = 0;
  for (const auto a : candidates) {
    if (static_cast<std::int64_t>(a) < 0) continue;
    const Atom& atom = atoms[static_cast<std::size_t>(a)];
    const double gap = norm(point - atom.centre) - atom.radius;
    if (best < 0 || gap < best_gap) {
      best_gap = gap;
      best = static_cast<std::int32_t>(a);
    }
  }
  return best;
}

// `sas`: the solvent-accessible surface at probe radius `probe`, its face tags atom
// indices. `contact_scale`: per atom, the factor about its centre from its SAS faces to its
// contact patch (contact_scale.hpp). `ridge`: per SAS vertex, 1 for a ridge vertex (empty:
// every vertex rolled). `arc_spacing`: the longest segment of a meridian arc, angstrom.
ExcludedCore excluded_core(const Mesh& sas, std::span<const Atom> atoms, std::span<const double> contact_scale,
                           double probe, std::span<const std::uint8_t> ridge, double arc_spacing);

}  // namespace molsurf::ses_detail
