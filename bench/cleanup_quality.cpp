// The cleanup on a saved surface, and what it leaves (docs/performance.md):
//   molsurf STRUCTURE --no-cleanup -o raw.ply
//   cleanup_quality raw.ply [--passes N] [--out cleaned.ply]
// prints the quality before and after, the edits and the time, then every face still under
// 1 degree with its edge lengths and whether it lies on a neck (a 3-cycle of edges that is
// not a face, shorter than a third of the face's longest edge), the one configuration the
// cleanup's widening is meant for.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "surface/cleanup.hpp"

namespace {

using molsurf::Index;
using molsurf::Mesh;

std::vector<Index> neighbours(const Mesh& m, const std::vector<std::vector<std::uint32_t>>& faces_of, Index v) {
  std::vector<Index> n;
  for (std::uint32_t f : faces_of[v])
    for (Index w : m.faces[f])
      if (w != v) n.push_back(w);
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cleanup_quality MESH [--passes N] [--out FILE]\n");
    return 2;
  }
  molsurf::CleanupOptions options;
  std::string out;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--passes") options.passes = std::atoi(argv[i + 1]);
    if (flag == "--out") out = argv[i + 1];
  }
  Mesh m = molsurf::read_mesh(argv[1]);
  const auto start = std::chrono::steady_clock::now();
  const molsurf::CleanupStats s = molsurf::improve_surface(m, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %zu -> %zu faces in %.2f s; under 5 deg %zu -> %zu, under 1 deg %zu -> %zu, smallest %.3f deg\n",
              argv[1], s.before.faces, s.after.faces, seconds, s.before.below_5deg, s.after.below_5deg,
              s.before.below_1deg, s.after.below_1deg, s.after.min_angle_deg);
  std::printf("collapses %zu, flips %zu, moves %zu, refused %zu; area %+.4f %%\n", s.collapses, s.flips, s.moves,
              s.refused, 100 * (s.area_after - s.area_before) / s.area_before);
  if (!out.empty()) molsurf::write_mesh(out, m);

  std::vector<std::vector<std::uint32_t>> faces_of(m.vertices.size());
  for (std::uint32_t f = 0; f < m.faces.size(); ++f)
    for (Index v : m.faces[f]) faces_of[v].push_back(f);
  auto length = [&](Index a, Index b) { return molsurf::norm(m.vertices[a] - m.vertices[b]); };
  auto is_face = [&](Index a, Index b, Index c) {
    for (std::uint32_t f : faces_of[a]) {
      const auto& t = m.faces[f];
      if (std::count(t.begin(), t.end(), b) && std::count(t.begin(), t.end(), c)) return true;
    }
    return false;
  };
  std::size_t on_necks = 0, listed = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const double angle = molsurf::min_angle_deg(m, f);
    if (angle >= 1) continue;
    const auto& t = m.faces[f];
    const double longest = std::max({length(t[0], t[1]), length(t[1], t[2]), length(t[2], t[0])});
    double loop = 0;  // the shortest 3-cycle through an edge of f that is not a face, over longest
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[(i + 1) % 3];
      const std::vector<Index> na = neighbours(m, faces_of, a), nb = neighbours(m, faces_of, b);
      for (Index w : na)
        if (std::binary_search(nb.begin(), nb.end(), w) && !is_face(a, b, w)) {
          const double size = std::max({length(a, b), length(a, w), length(b, w)}) / longest;
          loop = loop == 0 ? size : std::min(loop, size);
        }
    }
    const bool neck = loop > 0 && loop < 1.0 / 3;
    on_necks += neck;
    if (++listed <= 50)
      std::printf("  face %zu: %.3f deg, edges %.3g %.3g %.3g A%s\n", f, angle, length(t[0], t[1]), length(t[1], t[2]),
                  length(t[2], t[0]), neck ? ", on a neck" : "");
  }
  std::printf("%zu faces under 1 deg, %zu of them on necks\n", listed, on_necks);
}
