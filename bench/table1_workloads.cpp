#include "table1_workloads.hpp"

#include <utility>

#include "mesh/icosphere.hpp"
#include "support/shapes.hpp"

namespace molsurf::bench {

namespace {

// A slab of `size` x `size` x `thickness` centred at the origin, gridded nx x ny on its
// large faces and one cell across its thickness: 4 * (nx*ny + nx + ny) faces. This is the
// paper's "plane", made closed so that it is a valid operand.
Mesh make_slab(double size, double thickness, int nx, int ny) {
  const double h = size / 2, t = thickness / 2;
  return make_box({-h, -h, -t}, {h, h, t}, nx, ny, 1);
}

// Places a mesh built around the origin: rotation about a generic axis, then translation.
Mesh placed(const Mesh& mesh, const Vec3& axis, double angle, const Vec3& translation) {
  return transformed(mesh, RigidTransform{axis, angle, translation});
}

Mesh icosphere(const Vec3& centre, double radius, int frequency) {
  IcosphereOptions options;
  options.frequency = frequency;
  return make_icosphere(centre, radius, options);
}

Workload make(std::string name, Mesh a, Mesh b, std::optional<PaperTime> paper, std::string description) {
  return Workload{std::move(name), std::move(a), std::move(b), paper, std::move(description)};
}

}  // namespace

Workload sphere_and_slab() {
  // The slab (3 x 3, 0.04 thick) is much larger than the unit sphere, as the paper's plane
  // is, so most of its 79 520 faces are culled and only a band of them is cut.
  Mesh sphere = placed(make_uv_sphere({}, 1.0, 41, 38), {0.13, -0.42, 0.9}, 0.1732, {0.0137, -0.0291, 0.0419});
  Mesh slab = placed(make_slab(3.0, 0.04, 140, 140), {0.31, 0.77, 0.21}, 0.2718, {0.0173, 0.0291, 0.1234});
  return make("sphere+slab", std::move(slab), std::move(sphere), PaperTime{8.37, 10.2},
              "A: make_box({-1.5,-1.5,-0.02},{1.5,1.5,0.02},140,140,1) rotated 0.2718 rad about "
              "(0.31,0.77,0.21), moved by (0.0173,0.0291,0.1234); B: make_uv_sphere(0,1,41,38) rotated "
              "0.1732 rad about (0.13,-0.42,0.9), moved by (0.0137,-0.0291,0.0419)");
}

Workload two_cylinders() {
  // Equal radii crossing at right angles: with intersecting axes the two intersection
  // curves would meet (Steinmetz solid); offsetting the axes by 0.0371 keeps them apart
  // but nearly tangent, the hard part of this workload.
  Mesh a = make_capped_cylinder({-2, 0, 0}, {1, 0, 0}, 1.0, 4.0, 100, 40);
  Mesh b = make_capped_cylinder({0.0123, -2, 0.0371}, {0, 1, 0}, 1.0, 4.0, 100, 40);
  return make("two cylinders", std::move(a), std::move(b), PaperTime{31.2, 34.0},
              "A: make_capped_cylinder((-2,0,0),(1,0,0),r=1,len=4,100,40); "
              "B: make_capped_cylinder((0.0123,-2,0.0371),(0,1,0),r=1,len=4,100,40)");
}

Workload planes_and_spheres_small() {
  Mesh sphere = make_uv_sphere({0.0211, -0.0133, 0.0071}, 1.0, 41, 38);
  Mesh slab = placed(make_slab(2.8, 0.1, 27, 28), {0.57, -0.21, 0.79}, 0.4142, {0.0291, 0.0167, 0.3183});
  return make("planes+spheres 3034", std::move(sphere), std::move(slab), PaperTime{0.4, 0.7},
              "A: make_uv_sphere((0.0211,-0.0133,0.0071),1,41,38); B: make_box({-1.4,-1.4,-0.05},"
              "{1.4,1.4,0.05},27,28,1) rotated 0.4142 rad about (0.57,-0.21,0.79), moved by "
              "(0.0291,0.0167,0.3183)");
}

Workload planes_and_spheres_large() {
  Mesh sphere = make_uv_sphere({-0.0173, 0.0243, 0.0119}, 1.0, 57, 56);
  Mesh slab = placed(make_slab(2.8, 0.1, 28, 29), {-0.33, 0.62, 0.17}, 0.6180, {-0.0311, 0.0229, -0.2236});
  return make("planes+spheres 6270", std::move(sphere), std::move(slab), PaperTime{4.5, 6.0},
              "A: make_uv_sphere((-0.0173,0.0243,0.0119),1,57,56); B: make_box({-1.4,-1.4,-0.05},"
              "{1.4,1.4,0.05},28,29,1) rotated 0.6180 rad about (-0.33,0.62,0.17), moved by "
              "(-0.0311,0.0229,-0.2236)");
}

Workload channel_and_sphere() {
  // The sphere (radius 1.1 at x = 1.0317) crosses the duct's wall at x = 1 and the outer
  // wall at x = 2, and pokes out of the duct's y = 1 wall: three separate cut loops on a
  // genus-1 operand.
  Mesh channel = make_channel(4.0, 2.0, 6.0, 24, 8);
  Mesh sphere = placed(make_uv_sphere({}, 1.1, 41, 38), {0.45, 0.11, -0.35}, 0.5772, {1.0317, 0.2718, 3.1416});
  return make("channel+sphere", std::move(channel), std::move(sphere), std::nullopt,
              "A: make_channel(4,2,6,24,8); B: make_uv_sphere(0,1.1,41,38) rotated 0.5772 rad about "
              "(0.45,0.11,-0.35), moved by (1.0317,0.2718,3.1416)");
}

Workload identical_meshes() {
  Mesh a = icosphere({}, 1.0, 8);
  Mesh b = a;
  return make("identical", std::move(a), std::move(b), std::nullopt,
              "A = B = make_icosphere(0,1,frequency 8)");
}

Workload nested() {
  return make("nested", icosphere({}, 1.0, 8), icosphere({0.0123, 0.0311, -0.0271}, 0.5, 6), std::nullopt,
              "A: make_icosphere(0,1,freq 8); B: make_icosphere((0.0123,0.0311,-0.0271),0.5,freq 6)");
}

Workload disjoint() {
  return make("disjoint", icosphere({}, 1.0, 8), icosphere({3.1, 0.27, 0.11}, 1.0, 8), std::nullopt,
              "A: make_icosphere(0,1,freq 8); B: make_icosphere((3.1,0.27,0.11),1,freq 8)");
}

Workload cubes_sharing_face_part() {
  // B's grid lines (at 0.3 + k/4, 0.45 + k/4) do not line up with A's (k/4), so the contact
  // patch cuts across A's triangles inside the shared plane x = 1.
  return make("cubes: part of a face", make_box({0, 0, 0}, {1, 1, 1}, 4, 4, 4),
              make_box({1, 0.3, 0.45}, {2, 1.3, 1.45}, 4, 4, 4), std::nullopt,
              "A: make_box((0,0,0),(1,1,1),4,4,4); B: make_box((1,0.3,0.45),(2,1.3,1.45),4,4,4)");
}

Workload cubes_overlapping_coplanar() {
  return make("cubes: coplanar overlap", make_box({0, 0, 0}, {1, 1, 1}, 4, 4, 4),
              make_box({0.5, 0.3, 0}, {1.5, 1.3, 1}, 4, 4, 4), std::nullopt,
              "A: make_box((0,0,0),(1,1,1),4,4,4); B: make_box((0.5,0.3,0),(1.5,1.3,1),4,4,4)");
}

Workload cubes_touching_vertex() {
  return make("cubes: touch at vertex", make_box({0, 0, 0}, {1, 1, 1}, 4, 4, 4),
              make_box({1, 1, 1}, {2, 2, 2}, 4, 4, 4), std::nullopt,
              "A: make_box((0,0,0),(1,1,1),4,4,4); B: make_box((1,1,1),(2,2,2),4,4,4)");
}

Workload cubes_touching_edge() {
  return make("cubes: touch along edge", make_box({0, 0, 0}, {1, 1, 1}, 4, 4, 4),
              make_box({1, 1, 0}, {2, 2, 1}, 4, 4, 4), std::nullopt,
              "A: make_box((0,0,0),(1,1,1),4,4,4); B: make_box((1,1,0),(2,2,1),4,4,4)");
}

Workload icosphere_rotated_1e12() {
  // A rotation of 1e-12 rad moves vertices by ~1e-12: every face of B nearly coincides with
  // one of A, so nearly every candidate pair is a sliver intersection only exact arithmetic
  // resolves.
  Mesh a = icosphere({}, 1.0, 8);
  Mesh b = placed(a, {0.267, 0.535, 0.802}, 1e-12, {});
  return make("icosphere vs rotated 1e-12", std::move(a), std::move(b), std::nullopt,
              "A: make_icosphere(0,1,freq 8); B: A rotated 1e-12 rad about (0.267,0.535,0.802)");
}

std::vector<Workload> table1_workloads() {
  std::vector<Workload> w;
  w.push_back(sphere_and_slab());
  w.push_back(planes_and_spheres_small());
  w.push_back(planes_and_spheres_large());
  w.push_back(two_cylinders());
  w.push_back(channel_and_sphere());
  return w;
}

std::vector<Workload> degenerate_workloads() {
  std::vector<Workload> w;
  w.push_back(identical_meshes());
  w.push_back(nested());
  w.push_back(disjoint());
  w.push_back(cubes_sharing_face_part());
  w.push_back(cubes_overlapping_coplanar());
  w.push_back(cubes_touching_vertex());
  w.push_back(cubes_touching_edge());
  w.push_back(icosphere_rotated_1e12());
  return w;
}

std::vector<Workload> all_workloads() {
  std::vector<Workload> w = table1_workloads();
  for (Workload& d : degenerate_workloads()) w.push_back(std::move(d));
  return w;
}

}  // namespace molsurf::bench
