#pragma once
// The solvent-excluded surface's toroidal and reentrant vertices moved onto the true SES,
// as far as validity allows. Every point of the SES lies one probe radius from its
// nearest probe position (nearest_probe.hpp); a vertex whose nearest probe position is on
// an arc or at a vertex of the arrangement goes along the line from that position through
// it to that distance: onto the probe's torus or sphere, whatever singularity the rolled
// surface was carved for. Drawn from the SAS mesh, those vertices carry its seams' zigzag
// and its facets' offsets, and that roughness put 0.9 % on crambin's area at density 2;
// after the move it is 0.4 % (docs/ses.md). Contact vertices stay where the rolled
// surface drew them (contact_scale.hpp).
//
// Each move is an edit of the editing layer, kept only when no face turns over, no angle
// of its faces falls below 5 degrees or below what it was, and the exact crossing test
// finds nothing; a refused move is tried again halfway (mesh/move_vertices.hpp). The
// surface stays as valid as it was, and the check after it says so.
#include <cstdint>
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf::ses_detail {

// `arrangement`: the arrangement of the atoms' r + probe spheres that the SES was built on.
// A vertex farther than `max_move` from the true surface stays (ses_max_true_point_move).
// With `frozen` (empty, or one flag per vertex) the flagged vertices stay: a spatial block's
// seam band (src/blocks/).
TruePointStats move_to_ses_points(Mesh& mesh, std::span<const Atom> atoms, double probe,
                                  const SphereArrangement& arrangement, double max_move,
                                  std::span<const std::uint8_t> frozen = {});

// A tenth of the edge of an even mesh with the vertices per A^2 asked (0.076 A at density 2):
// the facets' own offsets from the true surface and the SAS seams' zigzag stay well within
// it, the scallops of carved creases and pinched tunnels do not.
double ses_max_true_point_move(double density);

}  // namespace molsurf::ses_detail
