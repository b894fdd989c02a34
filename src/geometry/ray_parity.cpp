#include "geometry/ray_parity.hpp"

#include <stdexcept>

#include "geometry/predicates.hpp"

namespace molsurf::geometry {



RayParity::RayParity(const Mesh& solid) : solid_(solid), tree_(BoxBvh::for_faces(solid)) {
  max_x_ = bounding_box(solid).max.x;
}

namespace {

// Sign of orient2d in (y, z) of p, q and the perturbed ray point r = (ry + e, rz + e^2),
// given the unperturbed sign d0: when d0 == 0 the e-term decides, then the e^2-term:
// d = d0 - (qz - pz) e + (qy - py) e^2.
template <class T>
int perturbed_side(int d0, const T& py, const T& pz, const T& qy, const T& qz) {
  if (d0 != 0) return d0;
  if (qz != pz) return pz > qz ? 1 : -1;
  if (qy != py) return qy > py ? 1 : -1;
  return 0;
}

template <class T>
int sign_of(const T& v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

}  // namespace

RayMeets ray_meets(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  const int nx = orient2d(a.y, a.z, b.y, b.z, c.y, c.z);
  if (nx == 0) return RayMeets::misses;  // parallel to the ray: the perturbed ray misses it
  const Vec3* corner[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const Vec3 &p = *corner[i], &q = *corner[(i + 1) % 3];
    const int d0 = orient2d(p.y, p.z, q.y, q.z, x.y, x.z);
    if (perturbed_side(d0, p.y, p.z, q.y, q.z) != nx) return RayMeets::misses;
  }
  const int o = orient3d(a, b, c, x);
  if (o == 0) return RayMeets::origin_on_face;
  return o != nx ? RayMeets::crosses : RayMeets::misses;
}

namespace {

// Does the perturbed ray from x cross triangle abc? Exact, on doubles or on a rational
// point (the slow path).
bool crosses(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  const RayMeets meets = ray_meets(a, b, c, x);
  if (meets == RayMeets::origin_on_face) throw std::logic_error("boolean: ray origin lies on a face of the other solid");
  return meets == RayMeets::crosses;
}

bool crosses(const Vec3& a, const Vec3& b, const Vec3& c, const ExactPoint& x) {
  const mpq_class ay(a.y), az(a.z), by(b.y), bz(b.z), cy(c.y), cz(c.z);
  auto orient_yz = [](const mpq_class& py, const mpq_class& pz, const mpq_class& qy, const mpq_class& qz,
                      const mpq_class& ry, const mpq_class& rz) {
    return sgn(mpq_class((qy - py) * (rz - pz) - (qz - pz) * (ry - py)));
  };
  const int nx = orient_yz(ay, az, by, bz, cy, cz);
  if (nx == 0) return false;
  const mpq_class* ys[3] = {&ay, &by, &cy};
  const mpq_class* zs[3] = {&az, &bz, &cz};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int d0 = orient_yz(*ys[i], *zs[i], *ys[j], *zs[j], x.y, x.z);
    if (perturbed_side(d0, *ys[i], *zs[i], *ys[j], *zs[j]) != nx) return false;
  }
  const mpq_class ax(a.x);
  const mpq_class ux = mpq_class(b.x) - ax, uy = by - ay, uz = bz - az;
  const mpq_class vx = mpq_class(c.x) - ax, vy = cy - ay, vz = cz - az;
  const mpq_class wx = x.x - ax, wy = x.y - ay, wz = x.z - az;
  const int o = sgn(mpq_class(wx * (uy * vz - uz * vy) + wy * (uz * vx - ux * vz) + wz * (ux * vy - uy * vx)));
  if (o == 0) throw std::logic_error("boolean: ray origin lies on a face of the other solid");
  return o != nx;
}

template <class Point>
bool parity(const Mesh& solid, const BoxBvh& tree, const BoundingBox& query, const Point& x) {
  bool inside = false;
  tree.for_each_overlap(query, [&](std::uint32_t f) {
    const Triangle& t = solid.faces[f];
    if (crosses(solid.vertices[t[0]], solid.vertices[t[1]], solid.vertices[t[2]], x)) inside = !inside;
  });
  return inside;
}

}  // namespace

bool RayParity::inside(const Vec3& x) const {
  if (x.x > max_x_) return false;
  BoundingBox query;
  query.min = x;
  query.max = {max_x_, x.y, x.z};
  return parity(solid_, tree_, query, x);
}

bool RayParity::inside(const ExactPoint& x) const {
  // A box around the rational point, rounded outward, is enough for culling.
  const Vec3 lo{std::nextafter(x.x.get_d(), -1e308), std::nextafter(x.y.get_d(), -1e308),
                std::nextafter(x.z.get_d(), -1e308)};
  const Vec3 hi{std::nextafter(x.x.get_d(), 1e308), std::nextafter(x.y.get_d(), 1e308),
                std::nextafter(x.z.get_d(), 1e308)};
  if (lo.x > max_x_) return false;
  BoundingBox query;
  query.min = lo;
  query.max = {max_x_, hi.y, hi.z};
  return parity(solid_, tree_, query, x);
}

}  // namespace molsurf::geometry
