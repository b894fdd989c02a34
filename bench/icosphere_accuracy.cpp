// Prints the area and volume error of unit icospheres, inscribed and area-corrected.
#include <cstdio>
#include <cmath>
#include <numbers>
#include "mesh/icosphere.hpp"
using namespace molsurf;
int main() {
  const double pi = std::numbers::pi;
  printf("| n | faces | vertices | area error | volume error | area error (corrected) | volume error (corrected) |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : {1, 2, 3, 4, 5, 6, 8, 10, 16}) {
    const Mesh m = make_icosphere({}, 1.0, {.frequency = n});
    const Mesh c = make_icosphere({}, 1.0, {.frequency = n, .area_corrected = true});
    auto pct = [](double x, double ref) { return 100 * (x - ref) / ref; };
    printf("| %d | %zu | %zu | %+.3f%% | %+.3f%% | %+.1e%% | %+.3f%% |\n", n, m.face_count(), m.vertex_count(),
           pct(surface_area(m), 4 * pi), pct(signed_volume(m), 4 * pi / 3), pct(surface_area(c), 4 * pi),
           pct(signed_volume(c), 4 * pi / 3));
  }
}
