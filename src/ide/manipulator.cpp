// The manipulators' geometry.

#include "gdpn/ide/manipulator.h"

#include <cmath>
#include <numbers>

namespace gdpn::ide {

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
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

}  // namespace gdpn::ide
