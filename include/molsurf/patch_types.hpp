#pragma once
// The patch of the solvent-excluded surface each mesh vertex stands for, as MSMS labels its
// .vert/.face rows: contact (on an atom's van der Waals sphere), toroidal (the saddle the
// probe sweeps rolling along two atoms) or reentrant (the probe's own sphere where it rests
// on three), with the closest atom and the analytic outward normal there.
//
// A vertex p of the SES lies one probe radius from the region the probe's centre can reach,
// and the nearest point q of that region is where the probe touches the surface at p. q lies
// on the boundary of the union of the r + probe spheres (the SAS), inside one sphere's exposed
// patch (contact), on an exposed arc where two spheres meet (toroidal) or at a vertex of their
// arrangement where three meet (reentrant). The vertex is labelled by the family of the
// nearest candidate q; its normal is (q - p) / |q - p|, which on a contact patch is the
// direction from the atom's centre, used there as such.
//
// This is a labelling of a rounded mesh for its readers, not a decision the surface depends
// on: candidates are compared by floating-point distance, ties going to the family listed
// first (contact, toroidal, reentrant) and then to the lower atom or vertex index.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf {

// MSMS's numbers for the three kinds of patch (its manual; Chimera's WriteDMS reads them so).
enum class PatchType : std::uint8_t { toroidal = 1, reentrant = 2, contact = 3 };
const char* patch_type_name(PatchType type);  // "toroidal", "reentrant", "contact"

struct VertexPatch {
  PatchType type = PatchType::contact;
  std::uint32_t atom = 0;  // the contact patch's atom; else the nearest (by |p - c| - r) atom the probe touches
  Vec3 normal;             // analytic, unit, outward (pointing from the solid to the probe)
  // The analytical face (0-based), numbered as ses_face_count explains: the contact patch's
  // atom, the torus of the two atoms the probe rolls on, or the probe position on three.
  std::uint32_t face = 0;
};

// The SES's analytical faces are numbered contact first (face i: atom i's contact patch), then
// one toroidal face per pair of atoms whose spheres share an exposed arc (the torus their probe
// sweeps, pairs in increasing order), then one reentrant face per vertex of the arrangement
// (the probe resting there). The count of all three.
std::size_t ses_face_count(std::size_t atoms, const SphereArrangement& arrangement);

// One label per point (the SES mesh's vertices). `arrangement` is that of the atoms' r + probe
// spheres (compute_areas with the same probe), `probe` > 0. Points far from every atom get
// the nearest atom's contact label. Parallel (OpenMP); the result does not depend on threads.
std::vector<VertexPatch> ses_vertex_patches(std::span<const Vec3> points, std::span<const Atom> atoms, double probe,
                                            const SphereArrangement& arrangement);

// A face's type: the type its three vertices share, else the type two of them share, else
// (three different types) toroidal, the patch that lies between contact and reentrant ones.
std::vector<PatchType> face_patch_types(const Mesh& mesh, std::span<const VertexPatch> vertices);

// A face's analytical face: of its corners of the face's type (face_patch_types), the face
// two of them share, else the lowest.
std::vector<std::uint32_t> face_patch_numbers(const Mesh& mesh, std::span<const VertexPatch> vertices);

}  // namespace molsurf
