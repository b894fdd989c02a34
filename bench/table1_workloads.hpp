#pragma once
// Operand pairs for benchmarking and testing the union engine: the engineering workloads
// of the paper's Table I (Shostko, Löhner & Sandberg 1999), rebuilt from the shapes in
// tests/support/shapes.hpp with the same face counts, plus degenerate configurations that
// exercise the exact coplanar / touching / coincident rules.
//
// Every generator is deterministic. Generic placements use offsets and angles that look
// irrational (e.g. 0.0371, 0.2718 rad) so that no vertex, edge or face of one operand
// coincides with the other by accident; the degenerate cases coincide on purpose.
#include <optional>
#include <string>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf::bench {

// Times reported in Table I on a 175 MHz MIPS R8000, in seconds.
struct PaperTime {
  double intersection = 0;
  double total = 0;
};

struct Workload {
  std::string name;
  Mesh a, b;
  std::optional<PaperTime> paper;  // set where Table I has a row for this workload
  std::string description;         // shapes and parameters, enough to rebuild it by hand
};

// --- Table I ----------------------------------------------------------------------------

// "Plane and sphere", 80 000 + 3034: a thin slab gridded 140 x 140 (79 520 faces) through a
// 41 x 38 uv sphere (3034 faces), both tilted.
Workload sphere_and_slab();
// "Two cylinders", 8200 + 8200: capped cylinders, 100 segments x 40 rings, crossing at right
// angles with axes 0.0371 apart.
Workload two_cylinders();
// "Planes and spheres", 3034 + 3200: 41 x 38 uv sphere and a slab gridded 27 x 28 (3244 faces).
Workload planes_and_spheres_small();
// "Planes and spheres", 6270 + 3500: 57 x 56 uv sphere (6270 faces) and a slab gridded
// 28 x 29 (3476 faces).
Workload planes_and_spheres_large();
// Not in Table I (the paper shows it as a figure): a square channel with a duct, and a
// sphere cutting through its inner and outer walls.
Workload channel_and_sphere();

// --- Degenerate configurations ----------------------------------------------------------

Workload identical_meshes();           // an icosphere with an exact copy of itself
Workload nested();                     // a small icosphere strictly inside a larger one
Workload disjoint();                   // two icospheres far apart (bounding boxes disjoint)
Workload cubes_sharing_face_part();    // unit cubes in contact over part of a face (coplanar, opposite normals)
Workload cubes_overlapping_coplanar(); // overlapping cubes whose top and bottom faces are coplanar (same normals)
Workload cubes_touching_vertex();      // unit cubes meeting at one corner
Workload cubes_touching_edge();        // unit cubes meeting along a whole edge
Workload icosphere_rotated_1e12();     // an icosphere and a copy rotated by 1e-12 rad

// All of the above: Table I first, then the degenerate cases.
std::vector<Workload> table1_workloads();
std::vector<Workload> degenerate_workloads();
std::vector<Workload> all_workloads();

}  // namespace molsurf::bench
