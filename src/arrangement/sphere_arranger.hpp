#pragma once
// The arrangement on one sphere (the steps of sphere_arrangement.cpp, which joins the
// spheres' results): which neighbours cut it, the circles they cut and where those cross,
// the exposed arcs, and the patches they bound with their areas. Sphere by sphere and
// independent of the others, so the spheres run in parallel; the vertices are named by
// keys that every sphere through a vertex computes alike.
#include <algorithm>
#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "arrangement/arc_integrals.hpp"
#include "arrangement/power_neighbours.hpp"
#include "arrangement/sphere_predicates.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

constexpr double kPi = std::numbers::pi, kTwoPi = 2 * std::numbers::pi;

// A vertex (three spheres and a side) or, with c == kWholeCircle, the whole circle of two.
struct Key {
  std::uint32_t a = 0, b = 0, c = 0;
  std::int32_t side = 0;
  friend auto operator<=>(const Key&, const Key&) = default;
};
constexpr std::uint32_t kWholeCircle = 0xffffffffu;

// The vertex on sphere i where circles j and k cross, on side s of w = D_j x D_k.
inline Key vertex_key(std::uint32_t i, std::uint32_t j, std::uint32_t k, int s) {
  std::uint32_t v[3] = {i, j, k};
  int parity = 1;
  for (int x = 0; x < 3; ++x)
    for (int y = x + 1; y < 3; ++y)
      if (v[y] < v[x]) parity = -parity;
  std::sort(v, v + 3);
  return {v[0], v[1], v[2], s * parity};
}

struct Cap {
  std::uint32_t other = 0;
  Vec3 d;           // c_other - c_i
  CircleFrame frame;
  bool covered = false;  // its circle lies in another cap (and so does the cap)
};

// The whole circle where spheres i and j meet.
inline Key circle_key(std::uint32_t i, std::uint32_t j) { return {std::min(i, j), std::max(i, j), kWholeCircle, 0}; }

struct Endpoint {
  std::uint32_t circle = 0;  // the cap whose circle it lies on
  double theta = 0;   // pseudo-angle on the circle
  double margin = 0;  // bound on theta's rounding
  std::uint32_t cap = 0;  // the cap whose boundary it is (index into caps)
  int s = 0;              // -1: entering that cap counter-clockwise, +1: leaving it
  Vec3 y;                 // relative to c_i
};

struct LocalArc {
  std::uint32_t cap = 0, other = 0;
  double theta = 0, delta = 0;  // runs from theta to theta - delta (clockwise)
  Key from, to;                 // unused for a whole circle
  Vec3 from_point;              // relative to c_i
  bool whole = false;
  std::uint32_t patch = 0;      // local
};

struct LocalPatch {
  double area = 0;
  Vec3 vector_area;
  std::vector<Key> keys;  // vertices and whole circles on its boundary
};

struct SphereResult {
  bool buried = false, duplicate = false, broken = false;
  bool covered = false;  // two caps cover the whole sphere
  std::size_t circles = 0, degenerate = 0;
  double area = 0;
  Vec3 vector_area;
  std::vector<LocalArc> arcs;
  std::vector<Cap> caps;  // released once the sphere is measured
  std::vector<LocalPatch> patches;
  std::vector<std::pair<Key, Key>> aliases;  // two keys of one point (four or more spheres through it)
  DecisionCounter decisions;
};

// Positions on a circle by a pseudo-angle in [0, 4) (the "diamond angle" of the point's
// coordinates in the circle's frame): increasing with the angle, with a derivative between
// 1/2 and 1 per radian, so an angle's error bound bounds it too; no transcendental call.
constexpr double kTurn = 4;
inline double pseudo_angle(double x, double y) {
  const double ax = std::fabs(x), ay = std::fabs(y), t = ay / (ax + ay);  // 0/0 only at the axis
  const double q = y >= 0 ? (x >= 0 ? t : 2 - t) : (x < 0 ? 2 + t : 4 - t);
  return q >= kTurn || q != q ? 0 : q;
}
inline double wrap(double a) {  // a in (-2 turns, 2 turns) into [0, 1 turn)
  a = a < 0 ? a + kTurn : a;
  a = a < 0 ? a + kTurn : a;
  a = a >= kTurn ? a - kTurn : a;
  return a >= kTurn ? a - kTurn : a;
}

// One thread's view of the spheres; arrange() runs the steps on sphere i.
class SphereArranger {
 public:
  SphereArranger(std::span<const Vec3> c, std::span<const double> r, const PowerNeighbours& neighbours)
      : c_(c), r_(r), neighbours_(neighbours) {}

  SphereResult arrange(std::uint32_t i) const;

 private:
  // Steps 1 and 2 (sphere_arranger.cpp): the caps, and the ends of the arcs their circles
  // cover on each other.
  bool find_caps(std::uint32_t i, SphereResult& out) const;
  void cross_circles(std::uint32_t i, std::vector<Endpoint>& ends, SphereResult& out) const;
  void add_crossing(std::uint32_t i, std::uint32_t x, std::uint32_t y, std::vector<Endpoint>& ends,
                    SphereResult& out) const;
  // Step 3 (exposed_arcs.cpp).
  int vertex_inside(std::uint32_t i, const SphereResult& out, std::uint32_t j, std::uint32_t k, int s,
                    std::uint32_t l, DecisionCounter& decisions) const;
  void exposed_arcs(std::uint32_t i, std::uint32_t j, std::span<const Endpoint> ends, SphereResult& out) const;
  int centre_in_cap(std::uint32_t i, SphereResult& out, std::uint32_t j, std::uint32_t k) const;
  // Step 4 (sphere_patches.cpp): area, vector area, cycles and patches, and the keys on
  // each patch's boundary that join it into shells.
  void measure(std::uint32_t i, SphereResult& out) const;
  void add_keys(std::uint32_t i, SphereResult& out) const;

  std::span<const Vec3> c_;
  std::span<const double> r_;
  const PowerNeighbours& neighbours_;
};

}  // namespace molsurf::arrangement
