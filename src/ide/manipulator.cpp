// The manipulators' geometry.

#include "gdpn/ide/manipulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gdpn::ide {

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kAway = 0.05;         // a face whose normal points this far from the view looks away
constexpr double kAlongSight = 0.966;  // cos 15 degrees: an axis this near the line of sight is not dragged along
constexpr double kEdgeOn = 0.259;      // sin 15 degrees: a plane this near edge on is not dragged in
constexpr double kMinSize = 1e-3;      // m: the least edge a scale drag leaves without snapping

/// The box's own axis `i` (0, 1, 2) in the world.
core::Vec3 boxAxis(const core::Quat& rotation, std::size_t i) {
  return rotation.rotate({i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
}

/// `x` with the binary noise of a sum of decimal steps taken off (0.1 + 0.2 is 0.3), no -0.
double tidy(double x) {
  const double t = std::round(x * 1e9) / 1e9;
  return t == 0.0 ? 0.0 : t;
}
}  // namespace

const char* handleName(Handle handle) {
  switch (handle) {
    case Handle::None: return "";
    case Handle::MoveX: return "move x";
    case Handle::MoveY: return "move y";
    case Handle::MoveZ: return "move z";
    case Handle::TurnX: return "turn x";
    case Handle::TurnY: return "turn y";
    case Handle::TurnZ: return "turn z";
    case Handle::Lo1: return "lo1";
    case Handle::Hi1: return "hi1";
    case Handle::Scale: return "scale";
    case Handle::Aim: return "aim";
    case Handle::Cone: return "cone";
  }
  return "";
}

std::optional<double> alongAxis(const core::Ray& ray, const core::Vec3& origin, const core::Vec3& axis) {
  // the nearest points of two lines: origin + axis t and ray.origin + d s
  const core::Vec3 w = origin - ray.origin;
  const double b = axis.dot(ray.direction);
  const double denom = 1.0 - b * b;  // both unit
  if (denom < 1e-9) return std::nullopt;
  const double d = axis.dot(w), e = ray.direction.dot(w);
  return (b * e - d) / denom;
}

std::optional<double> angleAbout(const core::Ray& ray, const core::Vec3& origin, const core::Vec3& axis,
                                 const core::Vec3& reference) {
  const double along = ray.direction.dot(axis);
  if (std::abs(along) < 1e-9) return std::nullopt;
  const double s = (origin - ray.origin).dot(axis) / along;
  const core::Vec3 hit = ray.origin + ray.direction * s - origin;
  const core::Vec3 side = axis.cross(reference);
  return std::atan2(hit.dot(side), hit.dot(reference)) * kDeg;
}

double snapTo(double value, double step) {
  if (!(step > 0)) return value;
  // whole steps, written without the binary noise of the multiplication (17 * 0.05 is not 0.85)
  const double snapped = std::round(std::round(value / step) * step * 1e9) / 1e9;
  return snapped == 0.0 ? 0.0 : snapped;  // no -0
}

core::Vec3 perpendicular(const core::Vec3& axis) {
  // the world axis least along `axis`, made perpendicular to it
  const core::Vec3 pick = std::abs(axis.x) < 0.9 ? core::Vec3{1, 0, 0} : core::Vec3{0, 1, 0};
  return (pick - axis * pick.dot(axis)).normalized();
}

std::array<double, 4> turned(const std::array<double, 4>& rotation, const core::Vec3& axis, double degrees) {
  const core::Vec3 own{rotation[0], rotation[1], rotation[2]};
  const core::Quat start = own.length() > 0 ? core::Quat::axisAngle(own, rotation[3] / kDeg) : core::Quat{};
  const core::Quat q = core::Quat::axisAngle(axis, degrees / kDeg) * start;
  const auto [a, angle] = q.toAxisAngle();
  const double deg = angle * kDeg;
  if (std::abs(deg) < 1e-9) return {0, 0, 1, 0};
  const auto clean = [](double x) { return std::abs(x) < 1e-12 ? 0.0 : x; };
  return {clean(a.x), clean(a.y), clean(a.z), deg};
}

const std::array<ScaleTab, 18>& scaleTabs() {
  static const std::array<ScaleTab, 18> tabs = {{
      {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},          // faces
      {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0}, {0, 1, 1}, {0, 1, -1},        // edges
      {0, -1, 1}, {0, -1, -1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, 1}, {-1, 0, -1},
  }};
  return tabs;
}

std::string scaleTabName(const ScaleTab& tab) {
  std::string name = "scale ";
  for (std::size_t i = 0; i < 3; ++i) {
    if (tab[i] == 0) continue;
    name += tab[i] > 0 ? '+' : '-';
    name += static_cast<char>('x' + i);
  }
  return name;
}

bool scaleTabShown(const ScaleTab& tab, const core::Quat& rotation, const core::Vec3& forward) {
  // shown when one of its faces does not look away from the view
  bool facing = false;
  int axes = 0;
  std::size_t across = 0;  // an edge tab's third axis: its plane's normal
  for (std::size_t i = 0; i < 3; ++i) {
    if (tab[i] == 0) {
      across = i;
      continue;
    }
    ++axes;
    if ((boxAxis(rotation, i) * tab[i]).dot(forward) <= kAway) facing = true;
  }
  if (!facing) return false;
  // and when its drag does not run along the line of sight
  if (axes == 1) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (tab[i] != 0) return std::abs(boxAxis(rotation, i).dot(forward)) < kAlongSight;
    }
  }
  return axes == 2 && std::abs(boxAxis(rotation, across).dot(forward)) > kEdgeOn;
}

std::optional<core::Vec3> onPlane(const core::Ray& ray, const core::Vec3& point, const core::Vec3& normal) {
  const double along = ray.direction.dot(normal);
  if (std::abs(along) < 1e-9) return std::nullopt;
  const double t = (point - ray.origin).dot(normal) / along;
  if (t < 0) return std::nullopt;
  return ray.origin + ray.direction * t;
}

std::array<double, 3> scaledSize(const std::array<double, 3>& size, const ScaleTab& tab, const core::Vec3& moved,
                                 const core::Vec3& scale, double step) {
  const std::array<double, 3> m = {moved.x, moved.y, moved.z}, s = {scale.x, scale.y, scale.z};
  std::array<double, 3> out = size;
  for (std::size_t i = 0; i < 3; ++i) {
    if (tab[i] == 0 || s[i] == 0.0) continue;
    // both faces move by the drag along the tab's side (in the box's unscaled metres)
    double change = 2.0 * tab[i] * m[i] / s[i];
    if (step > 0) change = snapTo(change, step);
    const double least = std::min(size[i], step > 0 ? step : kMinSize);
    out[i] = std::max(step > 0 ? tidy(size[i] + change) : size[i] + change, least);
  }
  return out;
}

std::optional<core::Vec3> aimAt(const core::Ray& ray, const core::Vec3& apex, const core::Vec3& point,
                                const core::Vec3& normal) {
  const auto hit = onPlane(ray, point, normal);
  if (!hit) return std::nullopt;
  return aimToward(apex, *hit);
}

std::optional<core::Vec3> aimToward(const core::Vec3& apex, const core::Vec3& target) {
  const core::Vec3 to = target - apex;
  if (to.length() < 1e-9) return std::nullopt;
  return to.normalized();
}

core::Vec3 snapDirection(const core::Vec3& direction, double step) {
  const core::Vec3 u = direction.normalized();
  if (!(step > 0)) return u;
  const double heading = snapTo(std::atan2(u.y, u.x) * kDeg, step) / kDeg;
  const double elevation = std::clamp(snapTo(std::asin(std::clamp(u.z, -1.0, 1.0)) * kDeg, step), -90.0, 90.0) / kDeg;
  const auto clean = [](double x) { return std::abs(x) < 1e-12 ? 0.0 : x; };
  return {clean(std::cos(elevation) * std::cos(heading)), clean(std::cos(elevation) * std::sin(heading)),
          clean(std::sin(elevation))};
}

core::Vec3 coneSide(const core::Vec3& axis, const core::Vec3& forward) {
  const core::Vec3 side = axis.cross(forward);
  if (side.length() < 1e-6) return perpendicular(axis);
  return side.normalized();
}

std::optional<double> coneAngle(const core::Ray& ray, const core::Vec3& apex, const core::Vec3& axis,
                                const core::Vec3& side) {
  const core::Vec3 normal = axis.cross(side);
  if (normal.length() < 1e-9) return std::nullopt;
  const auto hit = onPlane(ray, apex, normal.normalized());
  if (!hit) return std::nullopt;
  const core::Vec3 to = *hit - apex;
  if (to.length() < 1e-9) return std::nullopt;
  return std::atan2(std::abs(to.dot(side)), to.dot(axis)) * kDeg;
}

}  // namespace gdpn::ide
