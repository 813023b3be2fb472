#include "gdpn/core/math.h"

#include <algorithm>
#include <limits>

namespace gdpn::core {

Quat Quat::axisAngle(Vec3 axis, double angle_rad) {
  const Vec3 a = axis.normalized();
  const double s = std::sin(angle_rad / 2);
  return {std::cos(angle_rad / 2), a.x * s, a.y * s, a.z * s};
}

Quat operator*(Quat a, Quat b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Vec3 Quat::rotate(Vec3 v) const {
  // v + 2w (q x v) + 2 q x (q x v)
  const Vec3 q{x, y, z};
  const Vec3 t = q.cross(v) * 2.0;
  return v + t * w + q.cross(t);
}

std::pair<Vec3, double> Quat::toAxisAngle() const {
  const double s = std::sqrt(x * x + y * y + z * z);
  if (s < 1e-15) return {{0, 0, 1}, 0.0};
  double angle = 2 * std::atan2(s, w);
  Vec3 axis{x / s, y / s, z / s};
  if (angle > M_PI) {
    angle = 2 * M_PI - angle;
    axis = -axis;
  }
  return {axis, angle};
}

void Aabb::add(Vec3 p) {
  if (empty()) {
    lo = hi = p;
    return;
  }
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

void Aabb::add(const Aabb& b) {
  if (b.empty()) return;
  add(b.lo);
  add(b.hi);
}

Aabb Aabb::transformed(const Pose& pose) const {
  Aabb out;
  if (empty()) return out;
  for (int i = 0; i < 8; ++i) {
    out.add(pose.apply({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z}));
  }
  return out;
}

double intersect(const Ray& ray, const Aabb& box) {
  if (box.empty()) return -1;
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const double lo[3] = {box.lo.x, box.lo.y, box.lo.z};
  const double hi[3] = {box.hi.x, box.hi.y, box.hi.z};
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-300) {
      if (o[k] < lo[k] || o[k] > hi[k]) return -1;
      continue;
    }
    double a = (lo[k] - o[k]) / d[k];
    double b = (hi[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return -1;
  }
  return t0;
}

}  // namespace gdpn::core
