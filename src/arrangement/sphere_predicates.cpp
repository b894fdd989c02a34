#include "arrangement/sphere_predicates.hpp"

namespace molsurf::arrangement {

int sign_plus_root(const mpq_class& x, const mpq_class& y, const mpq_class& z) {
  const int sx = sgn(x), sy = sgn(z) == 0 ? 0 : sgn(y);
  if (sy == 0) return sx;
  if (sx == 0 || sx == sy) return sy;
  // Opposite signs: the larger magnitude wins; compare x^2 with y^2 z.
  const mpq_class d = x * x - y * y * z;
  return sx * sgn(d);
}

}  // namespace molsurf::arrangement
