#include "ses/solvent_excluded_surface.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "molsurf/boolean.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/error.hpp"
#include "ses/excluded_core.hpp"
#include "ses/probe_sweep.hpp"

namespace molsurf::ses_detail {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The atom a sweep face belongs to: of the atoms its probe touches, the one whose van der
// Waals sphere lies nearest the face (MSMS gives each vertex its closest atom likewise).
std::int32_t nearest_touched_atom(const ProbeCentre& probe, std::span<const Atom> atoms, const Vec3& point) {
  std::int32_t best = static_cast<std::int32_t>(probe.atoms[0]);
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::uint32_t a : probe.atoms) {
    const double gap = norm(point - atoms[a].centre) - atoms[a].radius;
    if (gap < best_gap) {
      best_gap = gap;
      best = static_cast<std::int32_t>(a);
    }
  }
  return best;
}

}  // namespace

double probe_spacing(double density) { return 0.5 / std::sqrt(density); }

ExcludedSurface solvent_excluded_surface(std::span<const Atom> atoms, const SphereOptions& spheres, int threads) {
  ExcludedSurface out;
  if (!(spheres.probe > 0)) throw Error("the solvent-excluded surface needs a probe radius above 0 (at 0 it is the van der Waals surface: --surface vdw)");
  for (std::size_t i = 0; i < atoms.size(); ++i)
    if (!(atoms[i].radius > 0))
      throw Error("atom " + std::to_string(i) + ": radius 0; the solvent-excluded surface needs every atom's radius above 0");
  if (atoms.empty()) return out;

  auto clock = std::chrono::steady_clock::now();
  SurfaceOptions sas_options;
  sas_options.spheres = spheres;
  sas_options.threads = threads;
  SurfaceResult sas = solvent_accessible_surface(atoms, sas_options);
  if (!sas.fallback.empty()) throw Error("solvent-excluded surface: " + sas.fallback);
  out.stats.sas_faces = sas.mesh.face_count();
  out.stats.seconds_sas = seconds_since(clock);

  clock = std::chrono::steady_clock::now();
  out.arrangement = compute_areas(atoms, spheres, threads).arrangement;
  out.stats.seconds_arrangement = seconds_since(clock);

  clock = std::chrono::steady_clock::now();
  ExcludedCore core = excluded_core(sas.mesh, atoms, spheres.probe);
  sas.mesh = Mesh{};
  out.stats.core_faces = core.mesh.face_count();
  out.stats.pinched_vertices = core.pinched_vertices;
  out.stats.seconds_core = seconds_since(clock);

  clock = std::chrono::steady_clock::now();
  std::vector<Vec3> centres(atoms.size());
  std::vector<double> radii(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    centres[i] = atoms[i].centre;
    radii[i] = sphere_radius(atoms[i], spheres);
  }
  const std::vector<ProbeCentre> probes = probe_sweep(out.arrangement, centres, radii, probe_spacing(spheres.density));
  out.stats.probes = probes.size();
  std::vector<Atom> balls(probes.size());
  for (std::size_t k = 0; k < probes.size(); ++k) {
    balls[k].centre = probes[k].centre;
    balls[k].radius = spheres.probe;
  }
  SurfaceOptions sweep_options;
  sweep_options.spheres = spheres;
  sweep_options.spheres.probe = 0;
  sweep_options.threads = threads;
  SurfaceResult sweep = solvent_accessible_surface(balls, sweep_options);
  if (!sweep.fallback.empty()) throw Error("solvent-excluded surface: " + sweep.fallback);
  out.stats.sweep_faces = sweep.mesh.face_count();
  out.stats.seconds_sweep = seconds_since(clock);

  clock = std::chrono::steady_clock::now();
  BooleanResult ses = boolean(core.mesh, sweep.mesh, BooleanOp::difference);
  out.stats.seconds_difference = seconds_since(clock);
  Mesh& mesh = ses.mesh;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (ses.face_operand[f] == 0) continue;  // from the core: already an atom
    const ProbeCentre& probe = probes[static_cast<std::size_t>(mesh.face_tags[f])];
    const Triangle& t = mesh.faces[f];
    const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    mesh.face_tags[f] = nearest_touched_atom(probe, atoms, centroid);
  }
  out.mesh = std::move(mesh);
  if (std::getenv("MOLSURF_SES_DEBUG"))
    std::fprintf(stderr, "ses: sas %zu faces %.2fs, arrangement %.2fs, core %zu faces %.2fs (pinched %zu), %zu probes -> sweep %zu faces %.2fs, difference %.2fs -> %zu faces\n",
                 out.stats.sas_faces, out.stats.seconds_sas, out.stats.seconds_arrangement, out.stats.core_faces,
                 out.stats.seconds_core, out.stats.pinched_vertices, out.stats.probes, out.stats.sweep_faces,
                 out.stats.seconds_sweep, out.stats.seconds_difference, out.mesh.face_count());
  return out;
}

}  // namespace molsurf::ses_detail
