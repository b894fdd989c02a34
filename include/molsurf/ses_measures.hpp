#pragma once
// The solvent-excluded surface's area and volume from the SAS arrangement's patches, not from
// a mesh: the reference the SES mesh's facets are measured against.
//
// Every point of the SES lies one probe radius from its nearest probe position q on the
// boundary of the union of the r + probe spheres, and the three kinds of q give the three
// kinds of patch: inside a sphere's exposed patch, the atom's contact patch (that patch
// scaled onto the van der Waals sphere: exact, from the arrangement's area and vector area);
// on an exposed arc, the toroidal patch (the probe's meridian arcs between its two contact
// points, swept along the arc); at a vertex, the reentrant patch (the spherical triangle on
// the probe spanned by its three contact points, or the convex polygon of four or more atoms
// meeting at one point). Where probes overlap, where a spindle torus passes its axis and
// wherever else a patch point lies nearer than a probe radius to another probe position, the
// point is not on the SES: toroidal and reentrant patches are integrated by Gauss quadrature
// (2 x 2 points) over cells of about `cell` A, each point counted when no probe position is
// nearer, and cells whose points or corners disagree are halved, four times. Where no other
// probe cuts a patch this is exact to a few parts in a million; where one does, halving the
// cells moves crambin's area and volume by about 1e-5 (tests/test_ses_measures.cpp).
//
// The volume is the divergence theorem's integral over the same patches (inside the outer
// surface, cavities excluded, as the arrangement's).
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/sphere_arrangement.hpp"

namespace molsurf {

struct SesMeasures {
  double area = 0, volume = 0;
  double contact_area = 0, toroidal_area = 0, reentrant_area = 0;
  // Contact area to its atom; toroidal and reentrant area to the atom, of those the probe
  // touches, whose van der Waals sphere is nearest (as the mesh's faces go).
  std::vector<double> area_per_atom;
};

// `arrangement`: of the atoms' r + probe spheres (compute_areas with the same probe), probe > 0.
// With `outer_only`, the patches of the probe's cavities are left out (the SES's outer
// surface and its volume, cavities filled). Parallel (OpenMP); the result does not depend on
// the thread count.
SesMeasures measure_ses(std::span<const Atom> atoms, double probe, const SphereArrangement& arrangement,
                        bool outer_only = false, double cell = 0.35);

}  // namespace molsurf
