#pragma once
// Random operand pairs for the Boolean engine: icospheres, grid boxes and capped cylinders
// at random scales, rotations and positions; every other pair is snapped to a coarse grid
// so that coplanar faces, shared vertex positions and edges through edges are common.
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <utility>

#include "mesh/icosphere.hpp"
#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

namespace molsurf::testing {

struct RandomPair {
  Mesh a, b;
  std::string description;
};

inline Mesh random_shape(std::mt19937_64& rng, bool snapped, std::string& what) {
  std::uniform_int_distribution<int> kind(0, 2);
  std::uniform_real_distribution<double> unit(0, 1);
  const int k = kind(rng);
  Mesh m;
  if (k == 0) {
    const int n = 1 + static_cast<int>(unit(rng) * 4);
    m = make_icosphere({}, 1.0, {.frequency = n});
    what += "icosphere(n=" + std::to_string(n) + ")";
  } else if (k == 1) {
    const int nx = 1 + static_cast<int>(unit(rng) * 3), ny = 1 + static_cast<int>(unit(rng) * 3),
              nz = 1 + static_cast<int>(unit(rng) * 3);
    m = make_box({-1, -1, -1}, {1, 1, 1}, nx, ny, nz);
    what += "box(" + std::to_string(nx) + "," + std::to_string(ny) + "," + std::to_string(nz) + ")";
  } else {
    const int segments = 4 + static_cast<int>(unit(rng) * 12);
    m = make_capped_cylinder({0, 0, -1}, {0, 0, 1}, 0.8, 2.0, segments, 2);
    what += "cylinder(" + std::to_string(segments) + ")";
  }
  if (snapped) {
    // Quarter turns, grid scales and grid offsets keep box corners on the grid; then every
    // vertex is snapped to multiples of 1/4 (checked below: snapping may break a sphere).
    const int turns = static_cast<int>(unit(rng) * 4);
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Vec3 axis = axes[static_cast<int>(unit(rng) * 3)];
    const double scale = 0.5 * (1 + static_cast<int>(unit(rng) * 4));
    const Vec3 offset{0.25 * std::floor(unit(rng) * 8 - 4), 0.25 * std::floor(unit(rng) * 8 - 4),
                      0.25 * std::floor(unit(rng) * 8 - 4)};
    for (Vec3& v : m.vertices) {
      v = RigidTransform{.axis = axis, .angle = turns * std::numbers::pi / 2, .translation = {}}.apply(v * scale) + offset;
      v = {std::round(v.x * 4) / 4, std::round(v.y * 4) / 4, std::round(v.z * 4) / 4};
    }
    what += " snapped";
  } else {
    const double scale = 0.5 + 1.5 * unit(rng);
    const Vec3 axis{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5 + 1e-3};
    const Vec3 offset{unit(rng) * 2 - 1, unit(rng) * 2 - 1, unit(rng) * 2 - 1};
    for (Vec3& v : m.vertices) v = v * scale;
    m = transformed(m, {.axis = axis, .angle = unit(rng) * 6.28, .translation = offset});
  }
  return m;
}

// A pair from `seed`; both operands are valid closed surfaces (snapping that breaks a
// shape is retried with the next draw).
inline RandomPair random_pair(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const bool snapped = seed % 2 == 1;
  RandomPair pair;
  for (Mesh* m : {&pair.a, &pair.b}) {
    for (int attempt = 0;; ++attempt) {
      std::string what;
      Mesh candidate = random_shape(rng, snapped, what);
      if (check_mesh(candidate).valid()) {
        *m = std::move(candidate);
        pair.description += (pair.description.empty() ? "" : " + ") + what;
        break;
      }
    }
  }
  return pair;
}

}  // namespace molsurf::testing
