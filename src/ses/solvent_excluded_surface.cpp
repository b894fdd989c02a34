#include "ses/solvent_excluded_surface.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/point_grid.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "ses/contact_scale.hpp"
#include "ses/excluded_core.hpp"
#include "ses/probe_sweep.hpp"
#include "surface/cleanup.hpp"
#include "surface/one_pass/one_pass_union.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::ses_detail {

namespace {

// The SES cleanup's volume budget, relative, per component (ses_cleanup_options).
constexpr double kSesMaxVolumeChange = 1e-3;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Whether any of some points lies within `reach` of a query point.
class NearPoints {
 public:
  NearPoints(std::vector<Vec3> points, double reach)
      : points_(std::move(points)), reach_(reach), grid_(points_, reach) {}
  bool near(const Vec3& q) const {
    bool found = false;
    grid_.for_each_near(q, [&](std::uint32_t i) { found = found || norm(points_[i] - q) <= reach_; });
    return found;
  }

 private:
  std::vector<Vec3> points_;
  double reach_;
  geometry::PointGrid grid_;
};

// The SAS vertices whose drawn faces the check found at fault (crossing or touching another
// face, degenerate), and every SAS vertex within `reach` of one: made ridges.
std::size_t mark_ridges(const ExcludedCore& core, const MeshCheck& check, const Mesh& sas, double reach,
                        std::vector<std::uint8_t>& ridge) {
  std::vector<Vec3> seeds;
  for (const auto* list : {&check.examples_intersecting, &check.examples_contact, &check.examples_degenerate,
                           &check.examples_nonmanifold_vertex, &check.examples_nonmanifold_edge,
                           &check.examples_boundary, &check.examples_misoriented})
    for (std::size_t f : *list) {
      if (f >= core.face_vertex.size()) continue;
      for (std::int64_t v : {core.face_vertex[f], core.face_vertex_other[f]})
        if (v >= 0 && !ridge[static_cast<std::size_t>(v)]) seeds.push_back(sas.vertices[static_cast<std::size_t>(v)]);
    }
  if (seeds.empty()) return 0;
  const NearPoints near(std::move(seeds), reach);
  std::size_t marked = 0;
  for (Index v = 0; v < sas.vertex_count(); ++v)
    if (!ridge[v] && near.near(sas.vertices[v])) {
      ridge[v] = 1;
      ++marked;
    }
  return marked;
}

MeshCheck check_all(const Mesh& mesh) {
  MeshCheckOptions options;
  options.max_examples = std::numeric_limits<std::size_t>::max();
  // Every defect, not the first 100 000 pairs the threads happen to reach: the ridges are
  // drawn from them, and the surface may not depend on the thread count.
  options.max_defect_pairs = 0;
  return check_mesh(mesh, options);
}

// The rolled surface, with ridges where it is singular, until it is a valid operand whose
// rolled parts touch nothing. Rounds widen the ridges around what is still at fault; the
// last makes every vertex a ridge.
ExcludedCore valid_core(const Mesh& sas, std::span<const Atom> atoms, const SphereOptions& spheres,
                        std::vector<std::uint8_t>& ridge, ExcludedSurfaceStats& stats) {
  const double probe = spheres.probe;
  const std::vector<double> scale = contact_scales(atoms, spheres);
  ExcludedCore core = excluded_core(sas, atoms, scale, probe, ridge, arc_spacing(spheres.density));
  stats.rolled_faces = core.mesh.face_count();
  for (int round = 0;; ++round) {
    const MeshCheck check = check_all(core.mesh);
    bool rolled_contact = false;
    for (std::size_t f : check.examples_contact)
      rolled_contact |= core.face_vertex[f] >= 0 && !ridge[static_cast<std::size_t>(core.face_vertex[f])];
    if (check.valid() && !rolled_contact) break;
    if (round == 0) stats.singular_faces = check.examples_intersecting.size() + check.examples_contact.size();
    if (round == 4) {
      if (!check.valid()) throw std::logic_error("the ridged core failed its check");
      break;
    }
    // Nothing new to make a ridge (the faults lie in ridges and contact faces already):
    // straight to every vertex a ridge.
    if (round == 3 || mark_ridges(core, check, sas, 0.3 * probe * (1 + round), ridge) == 0) {
      std::fill(ridge.begin(), ridge.end(), std::uint8_t{1});
      round = 3;
    }
    core = excluded_core(sas, atoms, scale, probe, ridge, arc_spacing(spheres.density));
  }
  stats.ridge_vertices = static_cast<std::size_t>(std::count(ridge.begin(), ridge.end(), std::uint8_t{1}));
  return core;
}

// One attempt from one SAS mesh: the core, and where it has ridges, the probe balls near
// them taken away.
Mesh excluded_from(const Mesh& sas, std::span<const Atom> atoms, const SphereOptions& spheres,
                   const SphereArrangement& arrangement, int threads, ExcludedSurfaceStats& stats) {
  auto clock = std::chrono::steady_clock::now();
  std::vector<std::uint8_t> ridge(sas.vertex_count(), 0);
  ExcludedCore core = valid_core(sas, atoms, spheres, ridge, stats);
  stats.core_faces = core.mesh.face_count();
  stats.pinched_vertices = core.pinched_vertices;
  stats.seconds_core = seconds_since(clock);
  if (stats.ridge_vertices == 0) return std::move(core.mesh);

  clock = std::chrono::steady_clock::now();
  std::vector<Vec3> centres(atoms.size());
  std::vector<double> radii(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    centres[i] = atoms[i].centre;
    radii[i] = sphere_radius(atoms[i], spheres);
  }
  std::vector<ProbeCentre> probes = probe_sweep(arrangement, centres, radii, probe_spacing(spheres.density));
  // The balls that carve a ridge: centres within 1.2 probe radii of a ridge vertex (the ridge
  // reaches one probe radius down from it; two radii changed 1crn's volume by 1e-4 and cost
  // half as much again).
  std::vector<Vec3> ridge_points;
  for (Index v = 0; v < ridge.size(); ++v)
    if (ridge[v]) ridge_points.push_back(sas.vertices[v]);
  const NearPoints near_ridge(std::move(ridge_points), 1.2 * spheres.probe);
  std::erase_if(probes, [&](const ProbeCentre& p) { return !near_ridge.near(p.centre); });
  stats.probes = probes.size();
  std::vector<Atom> balls(probes.size());
  for (std::size_t k = 0; k < probes.size(); ++k) {
    balls[k].centre = probes[k].centre;
    balls[k].radius = spheres.probe;
  }
  SphereUnionOptions sweep_options;
  sweep_options.spheres = spheres;
  sweep_options.spheres.probe = 0;
  sweep_options.threads = threads;
  SphereUnion sweep = solvent_accessible_surface(balls, sweep_options);
  if (sweep.one_pass.open_edges > 0)
    throw std::logic_error(surface_detail::open_union_message(sweep.one_pass.open_edges));
  stats.sweep_faces = sweep.mesh.face_count();
  stats.seconds_sweep = seconds_since(clock);

  clock = std::chrono::steady_clock::now();
  BooleanResult ses = boolean(core.mesh, sweep.mesh, BooleanOp::difference);
  stats.seconds_difference = seconds_since(clock);
  Mesh& mesh = ses.mesh;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (ses.face_operand[f] == 0) continue;  // from the core: already an atom
    const ProbeCentre& probe = probes[static_cast<std::size_t>(mesh.face_tags[f])];
    const Triangle& t = mesh.faces[f];
    const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    // The atom a sweep face belongs to: of the atoms its probe touches, the nearest.
    mesh.face_tags[f] = nearest_atom(probe.atoms, atoms, centroid);
  }
  return std::move(mesh);
}

}  // namespace

double probe_spacing(double density) { return 1.0 / std::sqrt(density); }

double arc_spacing(double density) { return 0.35 / std::sqrt(density); }

double ses_min_edge_length(double density) { return 0.8 / std::sqrt(density); }

double sas_min_edge_length(double density) { return 0.3 / std::sqrt(density); }

CleanupOptions ses_cleanup_options(CleanupOptions options, double density) {
  options.min_edge_length = std::max(options.min_edge_length, ses_min_edge_length(density));
  if (!(options.max_volume_change > 0)) options.max_volume_change = kSesMaxVolumeChange;
  return options;
}

ExcludedSurface solvent_excluded_surface(std::span<const Atom> atoms, const SphereOptions& spheres, int threads) {
  ExcludedSurface out;
  if (!(spheres.probe > 0))
    throw Error("the solvent-excluded surface needs a probe radius above 0 (at 0 it is the van der Waals surface: "
                "--surface vdw)");
  for (std::size_t i = 0; i < atoms.size(); ++i)
    if (!(atoms[i].radius > 0))
      throw Error("atom " + std::to_string(i) +
                  ": radius 0; the solvent-excluded surface needs every atom's radius above 0");
  if (atoms.empty()) return out;

  auto clock = std::chrono::steady_clock::now();
  SphereUnionOptions sas_options;
  sas_options.spheres = spheres;
  sas_options.threads = threads;
  SphereUnion sas = solvent_accessible_surface(atoms, sas_options);
  if (sas.one_pass.open_edges > 0)
    throw Error("solvent-excluded surface: " + surface_detail::open_union_message(sas.one_pass.open_edges));
  out.stats.sas_faces = sas.mesh.face_count();
  out.stats.seconds_sas = seconds_since(clock);
  clock = std::chrono::steady_clock::now();
  out.arrangement = compute_areas(atoms, spheres, threads).arrangement;
  out.stats.seconds_arrangement = seconds_since(clock);

  // First from the SAS as the union left it; where that cannot be finished (its tiny faces
  // and short seams can give contact faces that rounding collapses), from the SAS without
  // its slivers; then from the SAS with its short edges collapsed as well, which removes the SAS vertices crowded around a hole the probe only just
  // passes (a ring of atoms 1e-3 wider than the probe's threshold).
  std::string failures;
  for (int attempt = 0; attempt < 3; ++attempt) {
    try {
      if (attempt == 1) improve_surface(sas.mesh);
      if (attempt == 2) {
        CleanupOptions coarser;
        coarser.min_edge_length = sas_min_edge_length(spheres.density);
        improve_surface(sas.mesh, coarser);
      }
      out.mesh = excluded_from(sas.mesh, atoms, spheres, out.arrangement, threads, out.stats);
      out.stats.attempts += 1;
      return out;
    } catch (const std::logic_error& failure) {
      out.stats.attempts += 1;
      failures += std::string(failures.empty() ? "" : "; ") + failure.what();
    }
  }
  throw Error("solvent-excluded surface: not computed (" + failures + "; a molsurf bug, please report it)");
}

}  // namespace molsurf::ses_detail
