// The Boolean of two meshes as the front ends run it: operands held to the engine's
// contract, the result checked (boolean.hpp, checked_boolean).
#include <cstdio>

#include "molsurf/boolean.hpp"
#include "molsurf/error.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf {

namespace {

// An operand the outer envelope accepts besides a valid one: open, but otherwise sound
// (2-manifold, oriented, no degenerate face, no self-intersection).
bool open_but_sound(const MeshCheck& c) {
  return c.nonmanifold_edges == 0 && c.nonmanifold_vertices == 0 && c.misoriented_edges == 0 &&
         c.degenerate_faces == 0 && c.duplicate_faces == 0 && c.intersecting_pairs == 0;
}

std::string joined(const std::vector<std::string>& defects) {
  std::string text;
  for (const std::string& defect : defects) text += (text.empty() ? "" : "; ") + defect;
  return text;
}

}  // namespace

bool CheckedBoolean::acceptable(const MeshCheck& c) const {
  // From an open operand the envelope is open: its free boundary and the edges where a
  // sheet seen from both sides meets the rest are expected there, nothing else.
  return c.valid() || (open_input && c.misoriented_edges == 0 && c.degenerate_faces == 0 &&
                       c.duplicate_faces == 0 && c.intersecting_pairs == 0);
}

std::string CheckedBoolean::problem(const MeshCheck& c) const {
  if (acceptable(c)) return {};
  std::string why = joined(c.defects());
  if (c.contact_pairs > 0 && !c.examples_contact.empty()) {
    // Solids that meet without overlapping there: no valid surface holds both sheets.
    const Triangle& t = result.mesh.faces[c.examples_contact.front()];
    const Vec3 p = (1.0 / 3) * (result.mesh.vertices[t[0]] + result.mesh.vertices[t[1]] + result.mesh.vertices[t[2]]);
    char where[160];
    std::snprintf(where, sizeof where,
                  " (A and B touch without overlapping near (%.6g, %.6g, %.6g): move one apart, or into the other)",
                  p.x, p.y, p.z);
    why += where;
  }
  return "the result failed its check: " + why;
}

CheckedBoolean checked_boolean(const Mesh& a, const Mesh& b, BooleanOp op, std::string_view name_a,
                               std::string_view name_b, bool outer_envelope) {
  if (outer_envelope && op != BooleanOp::union_)
    throw ParameterError("outer_only", std::string("keeps the outer envelope of a union; it does not apply to ") +
                                           boolean_op_name(op));
  CheckedBoolean out;
  // The engine's contract: refuse operands it cannot promise a valid result for.
  for (const auto& [mesh, name] : {std::pair{&a, name_a}, std::pair{&b, name_b}}) {
    const MeshCheck c = check_mesh(*mesh);
    if (c.valid() && !c.empty()) continue;
    if (outer_envelope && !c.empty() && open_but_sound(c)) {
      out.open_input = true;
      continue;
    }
    throw Error(std::string(name) +
                (outer_envelope ? ": not a valid surface (closed or open), so no outer envelope is defined: "
                                : ": not a valid closed surface, so no Boolean is defined: ") +
                (c.empty() ? std::string("no faces") : joined(c.defects())));
  }
  out.result = outer_envelope ? union_outer_envelope(a, b) : boolean(a, b, op);
  out.check = check_mesh(out.result.mesh);
  return out;
}

}  // namespace molsurf
