#include "molsurf/surface_report.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <functional>
#include <string>

#include "io/atomic_file.hpp"
#include "io/csv_field.hpp"
#include "io/json_writer.hpp"
#include "molsurf/report.hpp"

namespace molsurf {

SurfaceReport make_surface_report(const Mesh& surface, const MeshCheck& check) {
  SurfaceReport r;
  r.faces = surface.faces.size();
  r.vertices = surface.vertices.size();
  r.area = check.area;
  r.components = measure_components(surface);
  r.volume = enclosed_volume(r.components);
  r.quality = check.quality;
  r.valid = check.valid();
  r.defects = check.defects();
  return r;
}

ExactReport make_exact_report(const SphereArrangement& a, std::span<const std::int64_t> component_shells,
                              bool outer_only) {
  ExactReport r;
  r.area = a.area;
  r.volume = a.volume;
  if (outer_only) {
    r.area = r.volume = 0;
    for (const ArrangementShell& s : a.shells)
      if (!s.cavity()) {
        r.area += s.area;
        r.volume += s.volume;
      }
  }
  r.vertices = a.stats.vertices;
  r.arcs = a.stats.arcs;
  r.buried_atoms = a.stats.buried;
  r.exact_decisions = a.stats.exact_decisions;
  r.degenerate_points = a.stats.degenerate_points;
  for (const ArrangementShell& s : a.shells)
    if (!(outer_only && s.cavity())) r.shells.push_back({s.cavity(), s.area, std::abs(s.volume), s.centroid, s.spheres, -1});
  // Each shell's mesh component: the largest component that follows it.
  for (std::size_t c = 0; c < component_shells.size(); ++c) {
    const std::int64_t s = component_shells[c];
    if (s >= 0 && static_cast<std::size_t>(s) < r.shells.size() && r.shells[s].mesh_component < 0)
      r.shells[s].mesh_component = static_cast<std::int64_t>(c);
  }
  return r;
}

std::vector<std::size_t> artefact_components(std::span<const ComponentMeasure> components, const ExactReport& exact) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < components.size(); ++c) {
    if (!components[c].cavity()) continue;
    bool follows_a_cavity = false;
    for (const ShellReport& s : exact.shells)
      follows_a_cavity |= s.cavity && s.mesh_component == static_cast<std::int64_t>(c);
    if (!follows_a_cavity) out.push_back(c);
  }
  return out;
}

namespace {

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// A double as the shortest text that reads back to the same double: the areas are exact
// to rounding, and a reader gets all of it.
std::string exact_number(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

// The true shells: the outer surfaces and the cavities, as the text report lists them.
void format_shells(const SurfaceReport& r, const std::function<void(const std::string&, const std::string&)>& row) {
  const ExactReport& e = *r.exact;
  std::size_t cavities = 0;
  for (const ShellReport& s : e.shells) cavities += s.cavity;
  row("shells", std::to_string(e.shells.size() - cavities) + " outer, " + std::to_string(cavities) + " cavit" +
                    (cavities == 1 ? "y" : "ies") + " (true spheres)");
  std::size_t shown = 0;
  for (const ShellReport& s : e.shells) {
    if (shown == 8) {
      row("", "... (" + std::to_string(e.shells.size() - shown) + " more; --json lists all)");
      break;
    }
    std::string mesh;
    if (!r.areas_only && r.models.empty())  // one mesh, whose components the shells follow
      mesh = s.mesh_component >= 0
                 ? ", " + std::to_string(r.components[s.mesh_component].faces) + " faces"
                 : (s.cavity ? ", open in the mesh" : ", not in the mesh");
    char centre[96] = "";
    if (s.cavity) std::snprintf(centre, sizeof centre, " at (%.2f, %.2f, %.2f)", s.centroid.x, s.centroid.y, s.centroid.z);
    row(shown == 0 ? "  by shell" : "",
        std::string(s.cavity ? "cavity " : "outer  ") + "area " + fixed(s.area, 2) + " A^2, volume " +
            fixed(s.volume, 2) + " A^3, " + std::to_string(s.atoms.size()) + " atoms" + centre + mesh);
    ++shown;
  }
  if (!r.artefact_components.empty())
    row("", std::to_string(r.artefact_components.size()) +
                " mesh void(s) inside the true union (facet artefacts; not cavities)");
}

void write_chains(io::JsonWriter& j, std::span<const ChainArea> chains) {
  j.key("chains").begin_array();
  for (const ChainArea& c : chains) {
    j.begin_object();
    j.field("chain", c.chain).field("atoms", c.atoms).field("residues", c.residues).field("area", c.area);
    j.end_object();
  }
  j.end_array();
}

void write_classes(io::JsonWriter& j, const ClassAreas& c) {
  j.key("classes").begin_object();
  j.field("polar", c.polar).field("apolar", c.apolar).field("main_chain", c.main_chain).field("side_chain", c.side_chain);
  j.end_object();
}

// The class areas on one line.
std::string class_line(const ClassAreas& c) {
  return "polar " + fixed(c.polar, 2) + ", apolar " + fixed(c.apolar, 2) + "; main chain " + fixed(c.main_chain, 2) +
         ", side chain " + fixed(c.side_chain, 2) + " A^2";
}

// Each chain's area on one line (eight at most).
std::string chain_areas(const SurfaceReport& r) {
  std::string text;
  for (std::size_t k = 0; k < r.chains.size() && k < 8; ++k)
    text += (k ? ", " : "") + (r.chains[k].chain.empty() ? std::string("(none)") : r.chains[k].chain) + " " +
            fixed(r.chains[k].area, 2);
  if (r.chains.size() > 8) text += ", ... (--per-chain lists all)";
  return text + " A^2";
}

}  // namespace

std::string format_surface_report(const SurfaceReport& r) {
  std::string out;
  auto row = [&](const std::string& label, const std::string& value) {
    out += "  " + label + std::string(label.size() < 22 ? 22 - label.size() : 1, ' ') + value + "\n";
  };
  // Numbers only, or one mesh per model: the first model's numbers, then every model's.
  if (r.areas_only || !r.models.empty()) {
    if (r.exact) {
      row("area", fixed(r.exact->area, 4) + " A^2 (true spheres, exact to rounding)");
      row("volume", fixed(r.exact->volume, 4) + " A^3 (inside the outer surface, minus cavities)");
      format_shells(r, row);
    } else {
      row("area", fixed(r.models.front().area, 2) + " A^2 (the facets')");
      row("volume", fixed(r.models.front().volume, 2) + " A^3 (the facets')");
    }
    if (r.chains.size() > 1) row("by chain", chain_areas(r));
    if (r.classes) row("by class", class_line(*r.classes));
    for (std::size_t k = 0; k < r.models.size(); ++k) {
      const ModelReport& m = r.models[k];
      char line[160];
      std::snprintf(line, sizeof line, "model %d: %zu atoms, area %.2f A^2, volume %.2f A^3, %zu cavit%s", m.model,
                    m.atoms, m.area, m.volume, m.cavities, m.cavities == 1 ? "y" : "ies");
      std::string mesh;
      if (!m.output.empty()) mesh = ", " + std::to_string(m.faces) + " faces in " + m.output.string();
      row(k == 0 ? "every model" : "", line + mesh);
    }
    const std::string threads = " (" + std::to_string(r.threads) + " thread" + (r.threads == 1 ? "" : "s") + ")";
    if (r.areas_only) {
      const ExactReport& e = *r.exact;
      row("arrangement", std::to_string(e.vertices) + " vertices, " + std::to_string(e.arcs) + " arcs, " +
                             std::to_string(e.buried_atoms) + " buried atoms");
    }
    if (r.models.empty()) {
      row("time", "read " + fixed(r.seconds.read, 2) + " s, areas " + fixed(r.exact->seconds, 3) + " s" + threads);
    } else {
      double seconds = 0;  // summed over the models, which may have run side by side
      for (const ModelReport& m : r.models) seconds += m.seconds;
      row("time", "read " + fixed(r.seconds.read, 2) + " s, " + (r.areas_only ? "areas " : "surfaces ") +
                      fixed(seconds, 2) + " s summed over the models" + threads);
    }
    return out;
  }
  const char* kind = r.surface == "ses"   ? " (solvent-excluded)"
                     : r.surface == "vdw" ? " (van der Waals)"
                                          : " (solvent-accessible)";
  row("surface", r.output.string() + kind + (r.outer_only ? ", outer surface only" : ""));
  row("faces / vertices", std::to_string(r.faces) + " / " + std::to_string(r.vertices));
  if (r.exact) {
    row("area", fixed(r.exact->area, 2) + " A^2 (true spheres; the facets: " + fixed(r.area, 2) + " A^2)");
    row("volume", fixed(r.exact->volume, 2) + " A^3 (true spheres; the facets: " + fixed(r.volume, 2) + " A^3)");
  } else if (r.ses_patches) {
    // As the SAS's true spheres: the exact numbers first, which the per-atom areas add up to.
    const SesMeasures& m = *r.ses_patches;
    row("area", fixed(m.area, 2) + " A^2 (its patches: contact " + fixed(m.contact_area, 2) + ", toroidal " +
                    fixed(m.toroidal_area, 2) + ", reentrant " + fixed(m.reentrant_area, 2) +
                    "; the facets: " + fixed(r.area, 2) + " A^2)");
    row("volume", fixed(m.volume, 2) + " A^3 (its patches, inside the outer surface minus cavities; the facets: " +
                      fixed(r.volume, 2) + " A^3)");
  } else {
    row("area", fixed(r.area, 2) + " A^2");
    row("volume", fixed(r.volume, 2) + " A^3 (inside the outer surface, minus cavities)");
  }
  if (r.exact) format_shells(r, row);
  if (r.stern)
    row("stern layer", r.stern->output.string() + " (solvent-accessible at probe " + fixed(r.stern->probe, 2) +
                           " A, " + std::to_string(r.stern->faces) + " faces): area " + fixed(r.stern->area, 2) +
                           " A^2, volume " + fixed(r.stern->volume, 2) + " A^3 (true spheres)");
  if (r.chains.size() > 1) row("by chain", chain_areas(r));
  if (r.classes) row("by class", class_line(*r.classes));
  std::size_t cavities = 0;
  for (const auto& c : r.components) cavities += c.cavity();
  row(r.exact ? "mesh components" : "components", std::to_string(r.components.size() - cavities) + " outer, " + std::to_string(cavities) +
                        " cavit" + (cavities == 1 ? "y" : "ies"));
  std::size_t shown = 0;
  for (const auto& c : r.components) {
    if (shown == 8) {
      row("", "... (" + std::to_string(r.components.size() - shown) + " more; --json lists all)");
      break;
    }
    row(shown == 0 ? "  by component" : "",
        std::string(c.cavity() ? "cavity " : "outer  ") + "area " + fixed(c.area, 2) + " A^2, volume " +
            fixed(std::abs(c.volume), 2) + " A^3, " + std::to_string(c.faces) + " faces");
    ++shown;
  }
  if (r.cleanup) {
    const CleanupStats& c = *r.cleanup;
    row("cleanup", std::to_string(c.collapses) + " edge collapses, " + std::to_string(c.flips) + " flips, " +
                       std::to_string(c.moves) + " vertex moves; area " +
                       (c.area_after >= c.area_before ? "+" : "") +
                       fixed(100 * (c.area_after - c.area_before) / c.area_before, 4) + " %");
    row("quality before", "min angle " + fixed(c.before.min_angle_deg, 3) + " deg; faces < 5 deg: " +
                              std::to_string(c.before.below_5deg) + ", < 1 deg: " + std::to_string(c.before.below_1deg) +
                              " of " + std::to_string(c.before.faces));
  }
  if (r.true_points) {
    const TruePointStats& t = *r.true_points;
    char left[64];
    std::snprintf(left, sizeof left, "%.2g", t.max_distance_left);
    // The SES moves its toroidal and reentrant vertices only (ses_true_points.hpp).
    row("true points", std::to_string(t.on_true_point) + " of " + std::to_string(t.vertices) +
                           (r.surface == "ses" ? " toroidal and reentrant" : "") + " vertices on the true surface, " + std::to_string(t.partly) + " halfway, " +
                           std::to_string(t.not_moved) + " not moved (largest distance left " + left + " A)");
  }
  row(r.cleanup ? "quality after" : "quality",
      "min angle " + fixed(r.quality.min_angle_deg, 3) + " deg; faces < 5 deg: " + std::to_string(r.quality.below_5deg) +
          ", < 1 deg: " + std::to_string(r.quality.below_1deg) + " of " + std::to_string(r.quality.faces));
  row("check", r.valid ? "valid: closed, 2-manifold, outward, no self-intersection" : "INVALID");
  for (const std::string& d : r.defects) row("", "- " + d);
  row("time", "read " + fixed(r.seconds.read, 2) + " s, surface " + fixed(r.seconds.surface, 2) + " s, cleanup " +
                  fixed(r.seconds.cleanup, 2) + " s, check " +
                  fixed(r.seconds.check, 2) + " s, write " + fixed(r.seconds.write, 2) + " s (" +
                  std::to_string(r.threads) + " thread" + (r.threads == 1 ? "" : "s") + ")");
  return out;
}

std::string surface_report_json(const SurfaceReport& r) {
  io::JsonWriter j;
  j.begin_object();
  j.key("input").begin_object();
  j.field("file", r.input.file.string()).field("model", r.input.model_used).field("records", r.input.records);
  j.field("atoms", r.input.kept).field("dropped_water", r.input.dropped_water);
  j.field("dropped_hydrogen", r.input.dropped_hydrogen).field("dropped_altloc", r.input.dropped_altloc);
  j.field("dropped_hetatm", r.input.dropped_hetatm).field("dropped_chain", r.input.dropped_chain);
  j.field("radius_set", r.input.radius_set).field("radius_from_element", r.input.radius_from_element);
  j.field("radius_default", r.input.radius_default).field("dropped_zero_radius", r.input.dropped_zero_radius);
  j.end_object();
  j.field("surface", r.surface);
  j.field("probe", r.spheres.probe).field("density", r.spheres.density).field("frequency", r.spheres.frequency);
  j.field("area_corrected", r.spheres.area_corrected);
  j.field("areas_only", r.areas_only);
  if (r.exact) {
    // area and volume: the true spheres'; facet_area and facet_volume: the mesh's.
    const ExactReport& e = *r.exact;
    j.field("area", e.area).field("volume", e.volume);
    std::size_t cavities = 0;
    for (const ShellReport& s : e.shells) cavities += s.cavity;
    j.field("cavities", cavities);
    j.key("shells").begin_array();
    for (const ShellReport& s : e.shells) {
      j.begin_object();
      j.field("kind", s.cavity ? "cavity" : "outer").field("area", s.area).field("volume", s.volume);
      j.key("centroid").begin_array().value(s.centroid.x).value(s.centroid.y).value(s.centroid.z).end_array();
      j.key("atoms").begin_array();
      for (std::uint32_t a : s.atoms) j.value(a);
      j.end_array();
      if (!r.areas_only && r.models.empty()) {
        j.key("mesh_component");
        if (s.mesh_component >= 0) j.value(s.mesh_component);
        else j.null();
      }
      j.end_object();
    }
    j.end_array();
    j.key("arrangement").begin_object();
    j.field("vertices", e.vertices).field("arcs", e.arcs).field("buried_atoms", e.buried_atoms);
    j.field("exact_decisions", e.exact_decisions).field("degenerate_points", e.degenerate_points);
    j.field("seconds", e.seconds);
    j.end_object();
  }
  if (!r.chains.empty()) write_chains(j, r.chains);
  if (r.classes) write_classes(j, *r.classes);
  if (r.relative)
    j.field("relative_to", *r.relative == MaxAreaScale::theoretical ? "Tien 2013 theoretical" : "Tien 2013 empirical");
  if (!r.residues.empty()) {
    j.key("residues").begin_array();
    for (const ResidueArea& res : r.residues) {
      j.begin_object();
      j.field("chain", res.chain).field("residue_name", res.residue_name).field("residue_number", res.residue_number);
      j.field("insertion_code", std::string(1, res.insertion_code == ' ' ? '_' : res.insertion_code));
      j.field("atoms", res.atoms).field("area", res.area);
      if (r.relative) {
        j.key("relative");
        if (const std::optional<double> max = max_residue_area(res.residue_name, *r.relative)) j.value(res.area / *max);
        else j.null();
      }
      j.end_object();
    }
    j.end_array();
  }
  if (!r.atom_area.empty()) {
    j.key("atoms").begin_array();
    for (std::size_t i = 0; i < r.atoms.size() && i < r.atom_area.size(); ++i) {
      const Atom& a = r.atoms[i];
      j.begin_object();
      j.field("serial", a.serial).field("atom_name", a.atom_name).field("element", a.element);
      j.field("chain", a.chain).field("residue_name", a.residue_name).field("residue_number", a.residue_number);
      j.field("insertion_code", std::string(1, a.insertion_code == ' ' ? '_' : a.insertion_code));
      j.field("radius", a.radius).field("polar", is_polar(a)).field("area", r.atom_area[i]);
      j.end_object();
    }
    j.end_array();
  }
  if (!r.models.empty()) {
    j.key("models").begin_array();
    for (const ModelReport& m : r.models) {
      j.begin_object();
      j.field("model", m.model).field("atoms", m.atoms).field("area", m.area).field("volume", m.volume);
      j.field("cavities", m.cavities).field("seconds", m.seconds);
      if (!m.output.empty()) j.field("output", m.output.string()).field("faces", m.faces);
      write_classes(j, m.classes);
      write_chains(j, m.chains);
      j.end_object();
    }
    j.end_array();
  }
  if (r.areas_only || !r.models.empty()) {
    j.field("threads", r.threads);
    j.key("seconds").begin_object().field("read", r.seconds.read).end_object();
    j.end_object();
    return j.str();
  }
  j.field("output", r.output.string()).field("outer_only", r.outer_only);
  j.field("faces", r.faces).field("vertices", r.vertices);
  // area and volume: the exact ones where there are (the true spheres' above, or the SES's
  // patches'), the facets' otherwise; facet_area and facet_volume: always the mesh's.
  if (!r.exact && r.ses_patches) j.field("area", r.ses_patches->area).field("volume", r.ses_patches->volume);
  else if (!r.exact) j.field("area", r.area).field("volume", r.volume);
  j.field("facet_area", r.area).field("facet_volume", r.volume);
  if (r.ses_patches) {
    const SesMeasures& m = *r.ses_patches;
    j.key("ses_patches").begin_object().field("area", m.area).field("volume", m.volume);
    j.field("contact_area", m.contact_area).field("toroidal_area", m.toroidal_area);
    j.field("reentrant_area", m.reentrant_area).end_object();
  }
  if (r.stern) {
    const SternReport& s = *r.stern;
    j.key("stern").begin_object().field("output", s.output.string()).field("probe", s.probe).field("faces", s.faces);
    j.field("area", s.area).field("volume", s.volume).field("facet_area", s.facet_area);
    j.field("facet_volume", s.facet_volume).field("valid", s.valid).end_object();
  }
  j.key("components").begin_array();
  for (std::size_t k = 0; k < r.components.size(); ++k) {
    const ComponentMeasure& c = r.components[k];
    j.begin_object();
    j.field("kind", c.cavity() ? "cavity" : "outer").field("faces", c.faces).field("area", c.area);
    j.field("volume", std::abs(c.volume));
    if (r.exact)
      j.field("artefact", std::find(r.artefact_components.begin(), r.artefact_components.end(), k) !=
                              r.artefact_components.end());
    j.end_object();
  }
  j.end_array();
  j.key("quality").begin_object();
  j.field("min_angle_deg", r.quality.min_angle_deg).field("faces_below_5deg", r.quality.below_5deg);
  j.field("faces_below_1deg", r.quality.below_1deg).field("max_aspect_ratio", r.quality.max_aspect_ratio);
  j.end_object();
  if (r.cleanup) {
    const CleanupStats& c = *r.cleanup;
    j.key("cleanup").begin_object();
    j.field("collapses", c.collapses).field("flips", c.flips).field("moves", c.moves).field("area_before", c.area_before);
    j.field("area_after", c.area_after).field("min_angle_deg_before", c.before.min_angle_deg);
    j.field("faces_below_5deg_before", c.before.below_5deg).field("faces_below_1deg_before", c.before.below_1deg);
    j.end_object();
  }
  if (r.true_points) {
    const TruePointStats& t = *r.true_points;
    j.key("true_points").begin_object();
    j.field("vertices", t.vertices).field("on_true_point", t.on_true_point).field("halfway", t.partly);
    j.field("not_moved", t.not_moved).field("max_distance_left", t.max_distance_left).field("seconds", t.seconds);
    j.end_object();
  }
  j.field("valid", r.valid);
  j.key("seconds").begin_object();
  j.field("read", r.seconds.read).field("surface", r.seconds.surface).field("cleanup", r.seconds.cleanup);
  j.field("check", r.seconds.check);
  j.field("write", r.seconds.write);
  j.end_object();
  j.field("threads", r.threads);
  j.end_object();
  return j.str();
}

namespace {

// A table's insertion code: '_' when blank, as MSMS's names have it.
std::string insertion_field(char code) { return io::csv_field(std::string_view(code == ' ' ? "_" : &code, 1)); }

}  // namespace

std::string per_atom_csv(std::span<const Atom> atoms, std::span<const double> area) {
  std::string csv = "index,serial,chain,residue_name,residue_number,insertion_code,atom_name,element,radius,area\n";
  char radius[32];
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    std::snprintf(radius, sizeof radius, "%.3f", a.radius);
    csv += std::to_string(i) + ',' + std::to_string(a.serial) + ',' + io::csv_field(a.chain) + ',' +
           io::csv_field(a.residue_name) + ',' + std::to_string(a.residue_number) + ',' +
           insertion_field(a.insertion_code) + ',' + io::csv_field(a.atom_name) + ',' + io::csv_field(a.element) +
           ',' + radius + ',' + exact_number(area[i]) + '\n';
  }
  return csv;
}

void write_per_atom_csv(const std::filesystem::path& path, std::span<const Atom> atoms, std::span<const double> area) {
  write_file_atomically(path, per_atom_csv(atoms, area));
}

std::string per_residue_csv(std::span<const Atom> atoms, std::span<const double> area,
                            std::optional<MaxAreaScale> relative) {
  std::string csv = std::string("chain,residue_name,residue_number,insertion_code,atoms,area") +
                    (relative ? ",relative\n" : "\n");
  for (const ResidueArea& r : area_per_residue(atoms, area)) {
    csv += io::csv_field(r.chain) + ',' + io::csv_field(r.residue_name) + ',' + std::to_string(r.residue_number) +
           ',' + insertion_field(r.insertion_code) + ',' + std::to_string(r.atoms) + ',' + exact_number(r.area);
    if (relative) {
      csv += ',';
      if (const std::optional<double> max = max_residue_area(r.residue_name, *relative)) csv += exact_number(r.area / *max);
    }
    csv += '\n';
  }
  return csv;
}

std::string per_chain_csv(std::span<const Atom> atoms, std::span<const double> area) {
  std::string csv = "chain,atoms,residues,area\n";
  for (const ChainArea& c : area_per_chain(atoms, area))
    csv += io::csv_field(c.chain) + "," + std::to_string(c.atoms) + "," + std::to_string(c.residues) + "," +
           exact_number(c.area) + "\n";
  return csv;
}

std::string csv_with_model_column(std::string_view csv, int model, bool with_header) {
  return io::prepend_csv_column(csv, "model", std::to_string(model), with_header);
}

void write_per_residue_csv(const std::filesystem::path& path, std::span<const Atom> atoms,
                           std::span<const double> area) {
  write_file_atomically(path, per_residue_csv(atoms, area));
}

}  // namespace molsurf
