#pragma once
// The mesh's vertices moved onto the true surface, as far as validity allows: a vertex
// whose faces come from one atom onto that atom's sphere, from two onto the nearest point
// of their circle, from three onto their nearer common point. Each move is an edit of the
// editing layer, kept only when no face turns over and the exact crossing test finds
// nothing; a refused move is tried again halfway. The facets then inscribe the true surface
// (their area falls below the true area by the faceting error, about 1 % at density 2);
// the exact areas are the arrangement's (compute_areas.hpp).
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf {

// `mesh`'s face tags are atom indices into `atoms`; spheres of radius r + options.probe.
TruePointStats move_to_true_points(Mesh& mesh, std::span<const Atom> atoms, const SphereOptions& options);

}  // namespace molsurf
