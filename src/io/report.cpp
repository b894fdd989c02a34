#include "molsurf/report.hpp"

#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/json_writer.hpp"

namespace molsurf {

namespace {

const char* format_name(StructureFormat f) {
  switch (f) {
    case StructureFormat::pdb: return "PDB";
    case StructureFormat::mmcif: return "mmCIF";
    case StructureFormat::pqr: return "PQR";
    case StructureFormat::xyzr: return "xyzr";
  }
  return "?";
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// Two aligned columns: what, then the value.
class Table {
 public:
  void row(std::string label, std::string value) { rows_.emplace_back(std::move(label), std::move(value)); }
  std::string str() const {
    std::size_t width = 0;
    for (const auto& [label, value] : rows_) width = std::max(width, label.size());
    std::string out;
    for (const auto& [label, value] : rows_) {
      out += "  " + label + std::string(width - label.size() + 2, ' ') + value + "\n";
    }
    return out;
  }

 private:
  std::vector<std::pair<std::string, std::string>> rows_;
};

std::string yes_no(bool ok, std::size_t count, const std::string& what) {
  if (ok) return "yes";
  return "NO (" + std::to_string(count) + " " + what + ")";
}

}  // namespace

std::string format_read_report(const ReadReport& r) {
  Table t;
  std::string model = "model " + std::to_string(r.model_used);
  if (r.models_in_file > 1) model += " of " + std::to_string(r.models_in_file) + " models";
  t.row("structure", r.file.string() + " (" + format_name(r.format) + ", " + model + ")");
  t.row("atoms", std::to_string(r.kept) + " kept of " + std::to_string(r.records) + " atom records");
  std::vector<std::string> dropped;
  auto drop = [&](std::size_t n, const char* why) {
    if (n > 0) dropped.push_back(std::to_string(n) + " " + why);
  };
  drop(r.dropped_water, "water (--keep-water keeps them)");
  // A PQR's hydrogens carry charges: a surface without them leaves those charges outside,
  // which an electrostatics solver on the surface does not expect.
  drop(r.dropped_hydrogen, r.format == StructureFormat::pqr
                               ? "hydrogen/deuterium (--hydrogens keeps them; their charges lie outside a surface "
                                 "made without them: keep them for electrostatics)"
                               : "hydrogen/deuterium (--hydrogens keeps them)");
  drop(r.dropped_altloc, "alternate conformers (one kept per atom)");
  drop(r.dropped_hetatm, "hetero atoms (--no-hetatm)");
  drop(r.dropped_chain, "in other chains (--chains)");
  drop(r.dropped_zero_radius, r.dropped_zero_radius == 1 ? "atom of radius 0 (it adds nothing to the surface)"
                                                          : "atoms of radius 0 (they add nothing to the surface)");
  if (dropped.empty()) t.row("dropped", "none");
  for (std::size_t i = 0; i < dropped.size(); ++i) t.row(i == 0 ? "dropped" : "", dropped[i]);
  std::string elements;
  for (const auto& [element, count] : r.kept_by_element) {
    if (!elements.empty()) elements += "  ";
    elements += element + " " + std::to_string(count);
  }
  t.row("elements", elements);
  const std::size_t from_table = r.kept - r.radius_from_element - r.radius_default;
  std::string radii = r.radius_set;
  if (r.format == StructureFormat::pqr || r.format == StructureFormat::xyzr) {
    radii = "from the file's radius column";
  } else {
    radii += ": " + std::to_string(from_table) + " by residue and atom name";
    if (r.radius_from_element > 0) radii += ", " + std::to_string(r.radius_from_element) + " by element";
    if (r.radius_default > 0) radii += ", " + std::to_string(r.radius_default) + " given the default radius";
  }
  t.row("radii", radii);
  if (!r.fallback_examples.empty()) {
    std::string examples;
    for (const std::string& e : r.fallback_examples) examples += (examples.empty() ? "" : ", ") + e;
    t.row("", "fell back: " + examples);
  }
  return t.str();
}

std::string format_sphere_plan(const SpherePlan& plan, const SphereOptions& options) {
  Table t;
  t.row("probe", fixed(options.probe, 2) + " A" + (options.probe == 0 ? " (van der Waals surface)" : ""));
  if (options.frequency > 0)
    t.row("spheres", "frequency " + std::to_string(options.frequency) + " for every atom");
  else
    t.row("spheres", "density " + fixed(options.density, 2) + " vertices/A^2");
  t.row("polyhedra", options.area_corrected ? "area-corrected (area of each equals its sphere's)"
                                             : "inscribed (vertices on the spheres)");
  t.row("radii + probe", fixed(plan.min_radius, 2) + " - " + fixed(plan.max_radius, 2) + " A");
  std::string freq;
  for (const auto& [n, count] : plan.atoms_by_frequency) {
    if (!freq.empty()) freq += ", ";
    const std::uint64_t faces = 20 * static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n);  // 64-bit
    freq += std::to_string(count) + " atoms at n=" + std::to_string(n) + " (" + std::to_string(faces) + " faces)";
  }
  t.row("icospheres", freq);
  t.row("sphere faces", std::to_string(plan.faces) + " before the union");
  return t.str();
}

namespace {

std::string examples_suffix(const std::vector<std::size_t>& examples, std::size_t count, const char* what) {
  if (examples.empty()) return "";
  std::string s = ": " + std::string(what) + " ";
  for (std::size_t i = 0; i < examples.size(); ++i) s += (i ? ", " : "") + std::to_string(examples[i]);
  if (count > examples.size()) s += ", ...";
  return s;
}

}  // namespace

std::string format_mesh_check(const MeshCheck& c, const std::string& file) {
  Table t;
  t.row("file", file);
  t.row("vertices", std::to_string(c.vertices) +
                        (c.unused_vertices ? " (" + std::to_string(c.unused_vertices) + " unused)" : ""));
  t.row("faces", std::to_string(c.faces));
  t.row("edges", std::to_string(c.edges));
  t.row("components", std::to_string(c.components));
  t.row("Euler characteristic", std::to_string(c.euler_characteristic));
  t.row("area", fixed(c.area, 4));
  t.row("volume", fixed(c.volume, 4));
  t.row("closed", yes_no(c.boundary_edges == 0, c.boundary_edges, "boundary edges") +
                      examples_suffix(c.examples_boundary, c.boundary_edges, "faces"));
  t.row("edge-manifold", yes_no(c.nonmanifold_edges == 0, c.nonmanifold_edges, "edges with more than 2 faces") +
                             examples_suffix(c.examples_nonmanifold_edge, c.nonmanifold_edges, "faces"));
  t.row("vertex-manifold",
        yes_no(c.nonmanifold_vertices == 0, c.nonmanifold_vertices, "vertices joining separate fans") +
            examples_suffix(c.examples_nonmanifold_vertex, c.nonmanifold_vertices, "vertices"));
  t.row("consistently oriented", yes_no(c.misoriented_edges == 0, c.misoriented_edges, "edges") +
                                     examples_suffix(c.examples_misoriented, c.misoriented_edges, "faces"));
  t.row("outward", yes_no(c.inward_components == 0, c.inward_components, "inside-out components"));
  t.row("degenerate faces", std::to_string(c.degenerate_faces) +
                                examples_suffix(c.examples_degenerate, c.degenerate_faces, "faces"));
  if (c.duplicate_faces) t.row("duplicate faces", std::to_string(c.duplicate_faces));
  if (c.self_intersections_checked) {
    t.row("self-intersections",
          (c.intersecting_pairs == 0 ? std::string("none (exact test)")
                                     : (c.defect_pairs_capped ? "at least " : "") + std::to_string(c.intersecting_pairs) +
                                           " crossing face pairs") +
              examples_suffix(c.examples_intersecting, c.intersecting_pairs, "faces"));
    t.row("touching contacts",
          (c.defect_pairs_capped && c.contact_pairs ? "at least " : "") + std::to_string(c.contact_pairs) +
              (c.contact_pairs ? " face pairs touch without crossing" : "") +
              examples_suffix(c.examples_contact, c.contact_pairs, "faces"));
  } else {
    t.row("self-intersections", "not checked");
  }
  const Quality& q = c.quality;
  t.row("min angle", fixed(q.min_angle_deg, 2) + " deg (mean of face minima " + fixed(q.mean_min_angle_deg, 2) +
                         ")");
  t.row("faces < 5 deg / < 1 deg", std::to_string(q.below_5deg) + " / " + std::to_string(q.below_1deg));
  t.row("max aspect ratio", fixed(q.max_aspect_ratio, 2));
  std::string out = t.str();
  if (c.verdict() == MeshCheck::Verdict::empty) {
    out += "EMPTY: no faces, so no closed surface\n";
  } else if (c.valid()) {
    out += "VALID: closed, 2-manifold, outward, no self-intersection\n";
  } else {
    out += "INVALID:\n";
    for (const std::string& d : c.defects()) out += "  - " + d + "\n";
  }
  return out;
}

std::string mesh_check_json(const MeshCheck& c, const std::string& file) {
  io::JsonWriter j;
  auto list = [&](const char* name, const std::vector<std::size_t>& v) {
    j.key(name).begin_array();
    for (std::size_t x : v) j.value(x);
    j.end_array();
  };
  j.begin_object();
  // "valid" is molsurf check's verdict: an empty mesh is not a valid surface ("empty" says why).
  j.field("file", file).field("valid", c.verdict() == MeshCheck::Verdict::valid).field("empty", c.empty());
  j.field("vertices", c.vertices).field("faces", c.faces).field("edges", c.edges);
  j.field("unused_vertices", c.unused_vertices).field("components", c.components);
  j.field("euler_characteristic", c.euler_characteristic).field("area", c.area).field("volume", c.volume);
  j.field("closed", c.closed()).field("manifold", c.manifold()).field("oriented", c.oriented());
  j.field("boundary_edges", c.boundary_edges).field("nonmanifold_edges", c.nonmanifold_edges);
  j.field("nonmanifold_vertices", c.nonmanifold_vertices).field("misoriented_edges", c.misoriented_edges);
  j.field("inward_components", c.inward_components).field("degenerate_faces", c.degenerate_faces);
  j.field("duplicate_faces", c.duplicate_faces);
  j.field("self_intersections_checked", c.self_intersections_checked);
  j.field("intersecting_pairs", c.intersecting_pairs).field("contact_pairs", c.contact_pairs);
  j.field("defect_pairs_capped", c.defect_pairs_capped);  // the two counts above are then lower bounds
  j.field("non_finite_vertices", c.non_finite_vertices).field("non_finite_measures", c.non_finite_measures);
  j.key("quality").begin_object();
  j.field("min_angle_deg", c.quality.min_angle_deg).field("mean_min_angle_deg", c.quality.mean_min_angle_deg);
  j.field("faces_below_5deg", c.quality.below_5deg).field("faces_below_1deg", c.quality.below_1deg);
  j.field("max_aspect_ratio", c.quality.max_aspect_ratio);
  j.end_object();
  j.key("examples").begin_object();
  list("boundary", c.examples_boundary);
  list("nonmanifold_edge", c.examples_nonmanifold_edge);
  list("nonmanifold_vertex", c.examples_nonmanifold_vertex);
  list("misoriented", c.examples_misoriented);
  list("degenerate", c.examples_degenerate);
  list("intersecting", c.examples_intersecting);
  list("contact", c.examples_contact);
  j.end_object();
  j.key("defects").begin_array();
  for (const std::string& d : c.defects()) j.value(d);
  j.end_array();
  j.end_object();
  return j.str();
}

std::string format_volume_mesh_report(const VolumeMeshReport& v, const std::filesystem::path& file) {
  char line[256];
  std::string text;
  std::snprintf(line, sizeof line, "  volume mesh           %s: %zu tetrahedra, %zu nodes (%.2f s)\n", file.string().c_str(),
                v.tetrahedra, v.nodes, v.seconds);
  text += line;
  for (const VolumeRegion& r : v.regions) {
    std::snprintf(line, sizeof line, "    %-19s %zu tetrahedra, volume %.2f A^3 (physical %d)\n", r.name.c_str(),
                  r.tetrahedra, r.volume, r.physical);
    text += line;
  }
  std::snprintf(line, sizeof line, "    quality             min dihedral %.2f deg; radius ratio min %.3f, median %.3f\n",
                v.min_dihedral_deg, v.min_radius_ratio, v.median_radius_ratio);
  text += line;
  return text;
}

}  // namespace molsurf
