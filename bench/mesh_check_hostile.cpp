// How `molsurf check` (read_mesh, then check_mesh) scales on the hostile shapes of issue
// 34: long thin pencils (an n-gon prism whose caps are n-gon faces), disjoint copies of a
// tetrahedron (in a row, nested one inside the other, and piled at one place), and a prism with one huge
// polygon cap, each written as an OFF file with polygon faces and read back as a user's
// file would be. Prints one table; a near-linear check keeps "µs per face" flat down
// each family.
// Usage: mesh_check_hostile [--threads N] [--quick]
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>
#include <unistd.h>

#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

namespace {

struct Off {
  std::string vertices, faces;
  std::size_t vertex_count = 0, face_count = 0;
  void vertex(double x, double y, double z) {
    char line[96];
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", x, y, z);
    vertices += line;
    ++vertex_count;
  }
  void face(std::initializer_list<std::size_t> corners) {
    faces += std::to_string(corners.size());
    for (const std::size_t c : corners) faces += " " + std::to_string(c);
    faces += "\n";
    ++face_count;
  }
  std::string text() const {
    return "OFF\n" + std::to_string(vertex_count) + " " + std::to_string(face_count) + " 0\n" + vertices + faces;
  }
};

// An n-gon prism of the given radius and length along z, caps as single n-gon faces, or
// (`fanned`) as the file's own fan of triangles from one corner.
Off prism(int n, double radius, double length, bool fanned = false) {
  Off off;
  for (const double z : {0.0, length})
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * k / n;
      off.vertex(radius * std::cos(angle), radius * std::sin(angle), z);
    }
  if (fanned) {
    for (std::size_t k = 1; k + 1 < static_cast<std::size_t>(n); ++k) {
      off.face({0, k + 1, k});
      off.face({std::size_t(n), n + k, n + k + 1});
    }
  } else {
    std::string bottom = std::to_string(n), top = std::to_string(n);
    for (int k = n - 1; k >= 0; --k) bottom += " " + std::to_string(k);
    for (int k = 0; k < n; ++k) top += " " + std::to_string(n + k);
    off.faces += bottom + "\n" + top + "\n";
    off.face_count += 2;
  }
  for (int k = 0; k < n; ++k) {
    const std::size_t a = k, b = (k + 1) % n;
    off.face({a, b, b + n, a + n});
  }
  return off;
}

enum class Copies { in_a_row, nested, coincident };

// `count` regular tetrahedra: in a row, 3 apart (disjoint boxes); nested around one
// centre, each 1 % of the first's size beyond the previous (disjoint surfaces, every face's
// box holding the smaller copies; every other one a cavity, facing inward); or all at one
// place (invalid: quadratically many overlapping and touching face pairs).
Off tetrahedra(int count, Copies copies) {
  const bool nested = copies == Copies::nested;
  Off off;
  const double corners[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (int c = 0; c < count; ++c) {
    const double scale = nested ? 1 + 0.01 * c : 1.0, shift = copies == Copies::in_a_row ? 3.0 * c : 0.0;
    const bool inward = nested && (count - 1 - c) % 2 == 1;
    const std::size_t first = off.vertex_count;
    for (const auto& p : corners) off.vertex(scale * p[0] + shift, scale * p[1], scale * p[2]);
    const std::size_t faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    for (const auto& f : faces)
      inward ? off.face({first + f[0], first + f[2], first + f[1]}) : off.face({first + f[0], first + f[1], first + f[2]});
  }
  return off;
}

void row(const char* family, const std::string& size, const Off& off) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("molsurf-check-bench-" + std::to_string(::getpid()) + ".off");
  std::ofstream(file) << off.text();
  const auto start = std::chrono::steady_clock::now();
  const molsurf::Mesh mesh = molsurf::read_mesh(file);
  const auto read = std::chrono::steady_clock::now();
  const molsurf::MeshCheck check = molsurf::check_mesh(mesh);
  const auto end = std::chrono::steady_clock::now();
  std::filesystem::remove(file);
  const double read_s = std::chrono::duration<double>(read - start).count(),
               check_s = std::chrono::duration<double>(end - read).count();
  std::printf("| %s | %s | %zu | %s | %.3f | %.3f | %.2f |\n", family, size.c_str(), check.faces,
              check.valid() ? "yes" : "NO", read_s, check_s, 1e6 * (read_s + check_s) / static_cast<double>(check.faces));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) omp_set_num_threads(std::atoi(argv[++i]));
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
  }
  std::printf("threads: %d\n\n| family | size | faces | valid | read s | check s | µs per face |\n"
              "|---|---:|---:|:---:|---:|---:|---:|\n",
              omp_get_max_threads());
  for (const int n : {250, 1000, 4000})
    row("pencil (n-gon prism, radius 0.5, length 200)", "n = " + std::to_string(n), prism(n, 0.5, 200));
  for (const int n : {250, 1000, 4000})
    row("pencil, caps fanned in the file", "n = " + std::to_string(n), prism(n, 0.5, 200, true));
  for (const int count : {250, 1000, 4000})
    row("tetrahedra in a row", std::to_string(count), tetrahedra(count, Copies::in_a_row));
  for (const int count : {250, 1000, 2000})
    row("nested tetrahedra", std::to_string(count), tetrahedra(count, Copies::nested));
  for (const int count : {250, 1000, 4000})
    row("coincident tetrahedra (a pile)", std::to_string(count), tetrahedra(count, Copies::coincident));
  const std::vector<int> caps = quick ? std::vector<int>{1000, 10000} : std::vector<int>{1000, 10000, 100000};
  for (const int n : caps)
    row("prism with an n-gon cap (radius 10, length 1)", "n = " + std::to_string(n), prism(n, 10, 1));
}
