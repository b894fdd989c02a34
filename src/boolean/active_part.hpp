#pragma once
// Paper §2.2.1 (i), taken further: only faces whose boxes overlap the other solid's box can
// meet it, and a face outside that box is outside the other solid. So a Boolean runs on
// the "active" faces of each operand only, and the "passive" rest is copied or dropped
// whole, by the operation alone. Joining two large meshes then costs in proportion to
// the region where they meet (plus linear copies), which is what makes the hierarchical
// union of many spheres affordable.
#include <cstdint>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf::boolean_engine {

struct ActivePart {
  bool whole = false;  // every face is active: `mesh` is left empty, use the solid itself
  Mesh mesh;           // the active faces; vertices renumbered in increasing original order
  std::vector<std::uint32_t> face_origin;    // part face -> solid face
  std::vector<std::uint32_t> vertex_origin;  // part vertex -> solid vertex
  std::vector<std::uint32_t> passive_faces;  // solid faces outside `other_box`, in order
};

ActivePart active_part(const Mesh& solid, const BoundingBox& other_box);

// Finer: only faces whose boxes overlap some face box of the other solid can meet it. A
// passive face then lies wholly inside or wholly outside the other solid, which
// passive_sides settles per connected run of passive faces, by one exact ray each.
ActivePart active_part_near(const Mesh& solid, const Mesh& other);

// Per passive face (in part.passive_faces' order): 1 if inside `other`, 0 if outside.
std::vector<std::uint8_t> passive_sides(const Mesh& solid, const ActivePart& part, const Mesh& other);

}  // namespace molsurf::boolean_engine
