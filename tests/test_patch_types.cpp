// MSMS patch types, closest atoms and analytic normals of the solvent-excluded surface
// (patch_types.hpp), checked by the geometry of the placements, and as the .vert/.face files
// carry them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/patch_types.hpp"
#include "molsurf/split_components.hpp"
#include "molsurf/surface_files.hpp"
#include "ses_reference.hpp"

namespace molsurf {
namespace {

using ses_reference::atom_at;

constexpr double kProbe = 1.4;

ComputedSurface ses_of(const std::vector<Atom>& atoms, double density = 2) {
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.spheres.probe = kProbe;
  options.spheres.density = density;
  return compute_surface(atoms, options);
}

std::vector<VertexPatch> labels_of(const ComputedSurface& s, const std::vector<Atom>& atoms) {
  EXPECT_TRUE(s.ses_arrangement);
  return ses_vertex_patches(s.mesh.vertices, atoms, kProbe, *s.ses_arrangement);
}

std::array<double, 4> area_by_type(const Mesh& mesh, const std::vector<PatchType>& types) {
  std::array<double, 4> area{};
  for (std::size_t f = 0; f < mesh.face_count(); ++f) area[static_cast<int>(types[f])] += face_area(mesh, f);
  return area;
}

double degrees(const Vec3& a, const Vec3& b) {
  return std::atan2(norm(cross(a, b)), dot(a, b)) * 180 / std::numbers::pi;
}

// The analytic normals are unit, and agree with the mesh's own estimate (the area-weighted
// mean of the normals of the faces around a vertex): a few degrees on average, which is how far
// that estimate strays on strips and faceted spheres (0.9 to 2.3 degrees on contact patches, 3.4
// to 5.4 on saddles and probe caps of two atoms, three and crambin), and off by more than 30
// degrees only at the rare vertices on a crease of the surface (where reentrant patches of
// overlapping probes meet), where a vertex has no one normal.
void expect_normals_fit_the_faces(const Mesh& mesh, const std::vector<VertexPatch>& labels) {
  const std::vector<Vec3> estimate = vertex_normals(mesh);
  double sum = 0;
  std::size_t far = 0;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_NEAR(norm(labels[v].normal), 1.0, 1e-12);
    const double angle = degrees(labels[v].normal, estimate[v]);
    sum += angle;
    far += angle > 30;
  }
  EXPECT_LT(sum / static_cast<double>(labels.size()), 5.0);
  EXPECT_LT(static_cast<double>(far), 0.005 * static_cast<double>(labels.size()));
}

TEST(PatchTypes, TwoAtomsHaveContactPatchesAndAToroidalBandWhereTheGeometrySays) {
  const double r1 = 1.7, r2 = 1.5, d = 3.5;
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, r1), atom_at({d, 0, 0}, r2)};
  const ComputedSurface s = ses_of(atoms);
  const std::vector<VertexPatch> labels = labels_of(s, atoms);
  // The probe touching both atoms has its centre on the circle where the r + probe spheres
  // meet: at t along the axis from atom 0. Atom 0's contact patch is where the ray from its
  // centre meets its r + probe sphere outside the other's: cos(angle to the axis) < t / R1.
  const double R1 = r1 + kProbe, R2 = r2 + kProbe;
  const double t = (d * d + R1 * R1 - R2 * R2) / (2 * d);
  const double limit0 = t / R1, limit1 = (d - t) / R2;
  std::array<std::size_t, 4> count{};
  std::size_t decided = 0;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const Vec3& p = s.mesh.vertices[v];
    const VertexPatch& label = labels[v];
    ++count[static_cast<int>(label.type)];
    EXPECT_NEAR(norm(label.normal), 1.0, 1e-12);
    const double cos0 = (p.x - 0) / norm(p - atoms[0].centre), cos1 = (d - p.x) / norm(p - atoms[1].centre);
    // Away from the seams (0.05 of the cosine), the type follows from the cones alone.
    const PatchType expected = cos0 < limit0 - 0.05   ? PatchType::contact
                               : cos1 < limit1 - 0.05 ? PatchType::contact
                               : cos0 > limit0 + 0.05 && cos1 > limit1 + 0.05 ? PatchType::toroidal
                                                                               : PatchType{0};
    if (expected == PatchType{0}) continue;
    ++decided;
    EXPECT_EQ(label.type, expected) << "vertex " << v << " at " << p.x << " " << p.y << " " << p.z;
    if (label.type == PatchType::contact) {
      const std::uint32_t atom = cos0 < limit0 ? 0 : 1;
      EXPECT_EQ(label.atom, atom);
      // On its atom's van der Waals sphere, as far as the mesh's vertices are (area-corrected
      // icospheres scaled to the atom: within a percent).
      EXPECT_NEAR(norm(p - atoms[atom].centre) / atoms[atom].radius, 1.0, 0.01);
      // The normal is the atom's radial direction.
      EXPECT_LT(degrees(label.normal, p - atoms[atom].centre), 1e-6);
    } else {
      // A saddle point lies a probe radius from the probe's circle.
      const double radial = std::hypot(p.y, p.z), rho = std::sqrt(R1 * R1 - t * t);
      EXPECT_NEAR(std::hypot(p.x - t, radial - rho), kProbe, 0.02 * kProbe);
      // Its normal points to the probe's centre on the circle, in p's meridian plane.
      const Vec3 centre{t, p.y * rho / radial, p.z * rho / radial};
      EXPECT_LT(degrees(label.normal, centre - p), 1e-6);
    }
  }
  EXPECT_GT(decided, labels.size() / 2);
  EXPECT_GT(count[3], 0u);
  EXPECT_GT(count[1], 0u);
  EXPECT_EQ(count[2], 0u);  // two atoms have no reentrant patch
  expect_normals_fit_the_faces(s.mesh, labels);

  // Three analytical faces: the two contact patches (numbered by their atoms) and one torus.
  ASSERT_EQ(ses_face_count(atoms.size(), *s.ses_arrangement), 3u);
  for (const VertexPatch& label : labels)
    EXPECT_EQ(label.face, label.type == PatchType::contact ? label.atom : 2u);

  // The contact area and the saddle's against the closed forms (ses_reference::two_atoms' first
  // terms are the two caps); faces along a seam go to one side or the other, so a few percent.
  const std::array<double, 4> area = area_by_type(s.mesh, face_patch_types(s.mesh, labels));
  const double pi = std::numbers::pi;
  const double contact = 2 * pi * r1 * r1 * (1 + t / R1) + 2 * pi * r2 * r2 * (1 + (d - t) / R2);
  const double total = ses_reference::two_atoms(r1, r2, d, kProbe).area;
  EXPECT_NEAR(area[3] / contact, 1.0, 0.03) << area[3] << " vs " << contact;
  EXPECT_NEAR(area[1] / (total - contact), 1.0, 0.15) << area[1] << " vs " << total - contact;
}

TEST(PatchTypes, ATriangleOfAtomsHasReentrantPatchesOnTheProbesThatRestOnAllThree) {
  const double r = 1.6, side = 3.6;
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, r), atom_at({side, 0, 0}, r),
                                atom_at({side / 2, side * std::sqrt(3.0) / 2, 0}, r)};
  const ComputedSurface s = ses_of(atoms);
  ASSERT_FALSE(s.ses_arrangement->vertices.empty());
  const std::vector<VertexPatch> labels = labels_of(s, atoms);
  std::array<std::size_t, 4> count{};
  for (std::size_t v = 0; v < labels.size(); ++v) {
    ++count[static_cast<int>(labels[v].type)];
    EXPECT_NEAR(norm(labels[v].normal), 1.0, 1e-12);
    if (labels[v].type != PatchType::reentrant) continue;
    // On the sphere of a probe resting on all three atoms.
    double nearest = 1e300;
    for (const ArrangementVertex& probe : s.ses_arrangement->vertices)
      nearest = std::min(nearest, norm(s.mesh.vertices[v] - probe.point));
    EXPECT_NEAR(nearest, kProbe, 0.02 * kProbe);
    // Its normal points to that probe's centre.
    EXPECT_GT(labels[v].normal.z * s.mesh.vertices[v].z, -1e-12);
  }
  EXPECT_GT(count[1], 0u);
  EXPECT_GT(count[2], 0u);
  EXPECT_GT(count[3], 0u);
  expect_normals_fit_the_faces(s.mesh, labels);

  // Analytical faces: three contact patches, three tori (one per pair), and a probe position
  // per arrangement vertex: the probes above and below the triangle's plane number their
  // reentrant faces apart, each side with one number.
  const std::size_t vertices = s.ses_arrangement->vertices.size();
  ASSERT_EQ(ses_face_count(atoms.size(), *s.ses_arrangement), 6 + vertices);
  std::array<std::vector<std::uint32_t>, 2> reentrant;  // below, above
  std::vector<std::uint32_t> toroidal;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const VertexPatch& label = labels[v];
    if (label.type == PatchType::contact) EXPECT_EQ(label.face, label.atom);
    if (label.type == PatchType::toroidal) toroidal.push_back(label.face);
    if (label.type == PatchType::reentrant) reentrant[s.mesh.vertices[v].z > 0].push_back(label.face);
  }
  for (std::vector<std::uint32_t>* faces : {&toroidal, &reentrant[0], &reentrant[1]}) {
    std::sort(faces->begin(), faces->end());
    faces->erase(std::unique(faces->begin(), faces->end()), faces->end());
  }
  EXPECT_EQ(toroidal, (std::vector<std::uint32_t>{3, 4, 5}));
  ASSERT_EQ(reentrant[0].size(), 1u);
  ASSERT_EQ(reentrant[1].size(), 1u);
  EXPECT_NE(reentrant[0][0], reentrant[1][0]);
  for (const auto& side : reentrant) EXPECT_TRUE(side[0] >= 6 && side[0] < 6 + vertices) << side[0];
}

// Crambin's SES, made once for the tests that read it.
struct CrambinSes {
  std::vector<Atom> atoms;
  ComputedSurface surface;
};
const CrambinSes& crambin() {
  static const CrambinSes made = [] {
    CrambinSes c;
    c.atoms = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb").atoms;
    c.surface = ses_of(c.atoms);
    return c;
  }();
  return made;
}

// Area by face type resolves the patches' borders to about a face, and the mesh's own normal
// estimate strays by about half an edge over the radius: the areas are taken on the surface
// as drawn, before the cleanup coarsens it to the density asked (about 2 vertices per A^2 at
// density 2, where the contact faces by type fall 8 % short of the arrangement's), and the
// normals on the cleaned surface at density 8 (6.5 vertices per A^2; at density 2 they are
// 7.5 degrees off the estimate on average, at density 4 5.6).
TEST(PatchTypes, CrambinHasEveryTypeAndTheContactAreaTheArrangementPredicts) {
  const std::vector<Atom>* atoms_ = &crambin().atoms;
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.spheres.probe = kProbe;
  options.cleanup = false;
  const ComputedSurface s = compute_surface(*atoms_, options);
  const std::vector<VertexPatch> labels = labels_of(s, *atoms_);
  const std::vector<PatchType> types = face_patch_types(s.mesh, labels);
  const std::array<double, 4> area = area_by_type(s.mesh, types);
  for (int type = 1; type <= 3; ++type) EXPECT_GT(area[type], 0) << patch_type_name(PatchType(type));
  EXPECT_NEAR((area[1] + area[2] + area[3]) / surface_area(s.mesh), 1.0, 1e-12);
  // Each atom's contact patch is its exposed r + probe patch scaled by (r / (r + probe))^2.
  double contact = 0;
  for (std::size_t i = 0; i < atoms_->size(); ++i) {
    const double scale = (*atoms_)[i].radius / ((*atoms_)[i].radius + kProbe);
    contact += s.ses_arrangement->area_per_sphere[i] * scale * scale;
  }
  EXPECT_NEAR(area[3] / contact, 1.0, 0.02) << area[3] << " vs " << contact;
  // The rest is saddles and probe caps, each a real share of a protein's surface.
  for (int type : {1, 2}) {
    EXPECT_GT(area[type], 0.05 * surface_area(s.mesh)) << patch_type_name(PatchType(type));
    EXPECT_LT(area[type], 0.5 * surface_area(s.mesh)) << patch_type_name(PatchType(type));
  }
  for (const VertexPatch& label : labels) ASSERT_LT(label.atom, atoms_->size());
  const ComputedSurface fine = ses_of(*atoms_, 8);
  expect_normals_fit_the_faces(fine.mesh, labels_of(fine, *atoms_));
}

std::vector<std::vector<double>> numeric_rows(const std::filesystem::path& file) {
  // As PyGBe reads them (numpy.loadtxt): whitespace-separated numbers, every row as wide.
  std::ifstream in(file);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::vector<double> row;
    std::string field;
    while (fields >> field) {
      std::size_t used = 0;
      row.push_back(std::stod(field, &used));
      EXPECT_EQ(used, field.size()) << file << ": " << line;
    }
    if (!rows.empty()) EXPECT_EQ(row.size(), rows.front().size()) << file << ": " << line;
    rows.push_back(std::move(row));
  }
  return rows;
}

TEST(PatchTypes, CrambinFilesCarryTheTypesTheNormalsAndTheClosestAtoms) {
  const ComputedSurface& s = crambin().surface;
  const std::vector<Atom>* atoms_ = &crambin().atoms;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "molsurf_test_patch_types";
  std::filesystem::create_directories(dir);
  SurfaceFileOptions file;
  file.msms_header = false;  // as PyGBe needs them
  const MeshWriteOptions options = surface_write_options(SurfaceKind::ses, {.probe = kProbe}, *atoms_, "1crn.pdb", file);
  const std::filesystem::path out = dir / "1crn_ses.vert";
  write_surface(out, s, options);

  const Mesh read = read_mesh(out);
  ASSERT_EQ(read.vertex_count(), s.mesh.vertex_count());
  ASSERT_EQ(read.face_count(), s.mesh.face_count());

  const std::vector<VertexPatch> labels = labels_of(s, *atoms_);
  const std::vector<PatchType> types = face_patch_types(s.mesh, labels);
  const std::vector<std::vector<double>> vert = numeric_rows(out);
  const std::vector<std::vector<double>> face = numeric_rows(dir / "1crn_ses.face");
  ASSERT_EQ(vert.size(), s.mesh.vertex_count());
  ASSERT_EQ(face.size(), s.mesh.face_count());
  ASSERT_EQ(vert.front().size(), 9u);
  ASSERT_EQ(face.front().size(), 5u);
  for (std::size_t v = 0; v < vert.size(); ++v) {
    const Vec3 n{vert[v][3], vert[v][4], vert[v][5]};
    ASSERT_NEAR(norm(n), 1.0, 3e-3);
    ASSERT_LT(norm(n - labels[v].normal), 3e-3);  // printed with 3 decimals
    ASSERT_EQ(vert[v][7], labels[v].atom + 1.0);
    ASSERT_EQ(vert[v][8], static_cast<double>(labels[v].type));
  }
  for (std::size_t f = 0; f < face.size(); ++f) ASSERT_EQ(face[f][3], static_cast<double>(types[f]));

  // The analytical face numbers: each face's is one its corners of its type are labelled with,
  // within that type's range; a vertex's is the one the faces around it share (else <= 0).
  const std::size_t contacts = atoms_->size();
  const std::size_t faces = ses_face_count(contacts, *s.ses_arrangement);
  const std::size_t probes = s.ses_arrangement->vertices.size();
  const std::vector<std::uint32_t> numbers = face_patch_numbers(s.mesh, labels);
  std::vector<std::vector<std::uint32_t>> around(s.mesh.vertex_count());
  for (std::size_t f = 0; f < face.size(); ++f) {
    ASSERT_EQ(face[f][4], numbers[f] + 1.0);
    const std::uint32_t n = numbers[f];
    const bool in_range = types[f] == PatchType::contact     ? n < contacts
                          : types[f] == PatchType::reentrant ? n >= faces - probes && n < faces
                                                             : n >= contacts && n < faces - probes;
    ASSERT_TRUE(in_range) << "face " << f << " type " << static_cast<int>(types[f]) << " number " << n;
    bool labelled = false;
    for (Index v : s.mesh.faces[f]) {
      labelled = labelled || (labels[v].type == types[f] && labels[v].face == n);
      around[v].push_back(n);
    }
    ASSERT_TRUE(labelled) << "face " << f;
  }
  std::size_t inside = 0;
  for (std::size_t v = 0; v < vert.size(); ++v) {
    const bool one = std::all_of(around[v].begin(), around[v].end(), [&](std::uint32_t n) { return n == around[v][0]; });
    ASSERT_EQ(vert[v][6] > 0, one) << "vertex " << v;
    if (one) {
      ASSERT_EQ(vert[v][6], around[v][0] + 1.0);
      ++inside;
    }
  }
  // 45 % of crambin's vertices lie inside one analytical face; the rest are on the seams
  // between them, which the narrow saddles and probe caps are mostly made of.
  EXPECT_GT(inside, vert.size() / 3);
  std::filesystem::remove_all(dir);
}

TEST(PatchTypes, ACavityWrittenOnItsOwnHasItsNormalsTurnedWithItsFaces) {
  const ComputedSurface& s = crambin().surface;
  const std::vector<SurfaceComponent> parts = split_components(s.mesh);
  ASSERT_GE(parts.size(), 2u);
  ASSERT_EQ(parts.back().kind, SurfaceComponent::Kind::cavity);
  const Mesh& cavity = parts.back().mesh;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "molsurf_test_patch_types_cavity";
  std::filesystem::create_directories(dir);
  SurfaceFileOptions file;
  file.msms_header = false;
  MeshWriteOptions options = surface_write_options(SurfaceKind::ses, {.probe = kProbe}, crambin().atoms, "1crn.pdb", file);
  options.ses_arrangement = s.ses_arrangement;
  write_mesh(dir / "cavity.vert", cavity, options);
  const std::vector<std::vector<double>> vert = numeric_rows(dir / "cavity.vert");
  ASSERT_EQ(vert.size(), cavity.vertex_count());
  // The SES's outward normal on a cavity's wall points into the void; the cavity on its own is
  // outward into the molecule, its faces turned, and its normals turned with them.
  const std::vector<VertexPatch> labels = ses_vertex_patches(cavity.vertices, crambin().atoms, kProbe, *s.ses_arrangement);
  std::size_t turned = 0;
  for (std::size_t v = 0; v < vert.size(); ++v)
    turned += norm(Vec3{vert[v][3], vert[v][4], vert[v][5]} + labels[v].normal) < 3e-3;
  EXPECT_GE(static_cast<double>(turned), 0.99 * static_cast<double>(vert.size()));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace molsurf
