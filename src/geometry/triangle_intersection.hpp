#pragma once
// Exact intersection tests between segments and triangles and between two faces of a
// mesh, on the input doubles. Every decision is a sign of orient3d / orient2d
// (geometry/predicates.hpp): no tolerance anywhere.
#include <cstddef>

#include "molsurf/mesh.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

struct SegmentTriangleMeeting {
  bool meets = false;   // the closed segment meets the closed triangle
  // The segment passes through the triangle's interior transversally: its endpoints are
  // strictly on opposite sides of the triangle's plane and its line passes strictly
  // inside the three edges (orient3d(p,q,a,b), (p,q,b,c), (p,q,c,a) all strictly equal).
  bool proper = false;
};

// Closed segment pq against closed triangle abc. Requires a non-degenerate triangle
// (a, b, c not collinear) and p != q; otherwise the answer is unspecified (no crash).
//  - Not coplanar: if orient3d(a,b,c,p) and orient3d(a,b,c,q) are strictly the same
//    sign there is no meeting; otherwise the line pq pierces the plane at one point of
//    the segment, which is in the closed triangle iff the three line-edge orientations
//    orient3d(p,q,a,b), orient3d(p,q,b,c), orient3d(p,q,c,a) are all >= 0 or all <= 0.
//  - Coplanar (both zero): projected onto the coordinate plane dropping an axis along
//    which the triangle's normal has an exactly nonzero component, it is a closed 2D
//    segment-triangle test (an endpoint in the triangle, or the segment meets an edge,
//    collinear overlaps included). A coplanar meeting is never proper.
SegmentTriangleMeeting segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a,
                                              const Vec3& b, const Vec3& c);

// Exactly degenerate face: a repeated vertex index, or three exactly collinear corners
// (all three coordinate-plane projections have orient2d == 0), coincident corners included.
bool is_degenerate_face(const Mesh& mesh, std::size_t face);

enum class TrianglePairRelation {
  apart,         // no common point, or only what their shared vertex/edge implies
  contact,       // no shared index, they touch without crossing (see below)
  intersecting,  // they cross, overlap, or fold onto each other: a defect
  duplicate,     // the same three vertex indices (a separate defect)
};

// How two faces of one mesh relate. Shared vertex INDICES say what they are allowed to
// share; coincident vertices at different indices count as different vertices.
//  - 3 shared indices: duplicate.
//  - A shared edge uv with opposite corners a (face i) and b (face j): intersecting iff
//    they are coplanar (orient3d(u,v,a,b) == 0) and a, b lie on the same side of line uv
//    in that plane (the faces fold onto each other); otherwise apart.
//  - One shared vertex v, faces (v,a,b) and (v,c,d): apart if c, d are strictly on the
//    same side of plane vab, or a, b strictly on the same side of plane vcd (they meet
//    only at v). Otherwise they meet beyond v iff segment ab meets closed triangle vcd or
//    segment cd meets closed triangle vab (their intersection is convex and contains v;
//    any other point needs a boundary piece not on a line through v). Meeting beyond v is
//    intersecting when ab or cd properly crosses the other face, or when the faces are
//    coplanar with overlapping interiors facing the same way; otherwise it is a contact
//    (the faces touch along a segment from v, or lie face to face).
//  - No shared index: they meet iff an edge of one meets the other closed triangle (both
//    directions). If so it is intersecting when some edge properly crosses the other
//    triangle (see SegmentTriangleMeeting::proper), or when the faces are coplanar,
//    their interiors overlap (no edge line of either separates them, tested exactly in
//    2D) and they face the same way (equal normals: both solids on the same side, so
//    their volumes overlap; a coincident copy of a face at other indices is such a
//    pair). Otherwise it is only a contact: vertex on vertex (coincident vertices at
//    different indices), vertex on edge, vertex on face, edge on edge, a coplanar touch
//    along a segment, or coplanar faces overlapping with OPPOSITE normals (two solids
//    pressed face to face, lying on opposite sides of the common plane).
// Contacts are reported apart from crossings and do not make a mesh invalid: the union
// engine represents solids that only touch by a duplicated touching point.
// Known limit: a degenerate pair, e.g. an edge passing exactly through another edge, or a
// vertex lying exactly in the other face with its two edges on both sides, is reported
// as a contact even if the two sheets pass through each other there; deciding that needs
// the faces around the touching point and is left for later.
// Both faces must be non-degenerate (see is_degenerate_face); otherwise unspecified.
TrianglePairRelation classify_triangle_pair(const Mesh& mesh, std::size_t face_i, std::size_t face_j);

// The same for two triangles given by vertex indices into `mesh` (they need not be faces
// of it: edits test their new faces before committing).
TrianglePairRelation classify_triangle_pair(const Mesh& mesh, const Triangle& a, const Triangle& b);

// Two faces with exactly one vertex index in common, coplanar, whose interiors overlap
// with opposite normals: at that vertex the surface doubles back flat onto itself (a
// sliver whose rounded corner landed exactly in its neighbour's plane). classify_triangle_pair
// calls this a contact, as it must for two solids pressed face to face; the rounding
// repair of a Boolean's result, whose sheets still share their touching points (the
// stitch keeps them apart afterwards), counts it as a fold: a later Boolean on that
// result meets the two sheets along overlapping segments and cannot stitch them apart.
// Exact; both faces must be non-degenerate.
bool folded_flat(const Mesh& mesh, const Triangle& a, const Triangle& b);

}  // namespace molsurf::geometry
