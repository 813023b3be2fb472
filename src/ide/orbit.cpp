// The world view's orbit camera.

#include "gdpn/ide/orbit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gdpn::ide {

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

/// The unit vector from the target towards the eye.
core::Vec3 backward(double yaw, double pitch) {
  return {std::cos(pitch * kRad) * std::cos(yaw * kRad), std::cos(pitch * kRad) * std::sin(yaw * kRad),
          std::sin(pitch * kRad)};
}

}  // namespace

const char* standardViewName(StandardView view) {
  switch (view) {
    case StandardView::Front: return "front";
    case StandardView::Back: return "back";
    case StandardView::Left: return "left";
    case StandardView::Right: return "right";
    case StandardView::Top: return "top";
    case StandardView::Iso: return "iso";
  }
  return "iso";
}

std::optional<StandardView> parseStandardView(std::string_view name) {
  for (auto v : {StandardView::Front, StandardView::Back, StandardView::Left, StandardView::Right, StandardView::Top,
                 StandardView::Iso}) {
    if (name == standardViewName(v)) return v;
  }
  return std::nullopt;
}

OrbitCamera OrbitCamera::from(const render::Camera& camera) {
  OrbitCamera o;
  o.target = camera.target;
  const auto d = camera.eye - camera.target;
  o.distance = std::max(d.length(), 1e-3);
  o.pitch = std::clamp(std::asin(std::clamp(d.z / o.distance, -1.0, 1.0)) / kRad, -89.0, 89.0);
  o.yaw = std::atan2(d.y, d.x) / kRad;
  o.fov = camera.fov;
  return o;
}

core::Vec3 OrbitCamera::eye() const { return target + backward(yaw, pitch) * distance; }

render::Camera OrbitCamera::camera() const {
  render::Camera c;
  c.eye = eye();
  c.target = target;
  c.fov = fov;
  c.near = std::max(0.01, distance * 0.002);
  c.far = std::max(2000.0, distance * 50.0);
  return c;
}

void OrbitCamera::orbit(double dx, double dy) {
  yaw -= dx * 0.3;
  pitch = std::clamp(pitch + dy * 0.3, -89.0, 89.0);
}

void OrbitCamera::pan(double dx, double dy, double height) {
  // metres per pixel at the target's depth
  const double scale = 2.0 * distance * std::tan(fov * kRad / 2) / std::max(height, 1.0);
  const auto back = backward(yaw, pitch);
  const auto right = core::Vec3{0, 0, 1}.cross(back).normalized();
  const auto up = back.cross(right).normalized();
  target = target - right * (dx * scale) + up * (dy * scale);
}

void OrbitCamera::zoom(double clicks) { distance = std::clamp(distance * std::pow(0.85, clicks), 0.05, 1e5); }

void OrbitCamera::frame(const core::Aabb& box) {
  if (box.empty()) return;
  target = (box.lo + box.hi) * 0.5;
  const double radius = std::max((box.hi - box.lo).length() * 0.5, 0.05);
  distance = radius / std::sin(fov * kRad / 2) * 1.1;
}

void OrbitCamera::look(StandardView view) {
  switch (view) {
    case StandardView::Front: yaw = -90; pitch = 0; break;
    case StandardView::Back: yaw = 90; pitch = 0; break;
    case StandardView::Left: yaw = 180; pitch = 0; break;
    case StandardView::Right: yaw = 0; pitch = 0; break;
    case StandardView::Top: yaw = -90; pitch = 89; break;
    case StandardView::Iso: yaw = -45; pitch = 35; break;
  }
}

std::optional<std::array<double, 2>> OrbitCamera::project(const core::Vec3& p, double width, double height) const {
  const auto forward = backward(yaw, pitch) * -1.0;
  const auto right = forward.cross(core::Vec3{0, 0, 1}).normalized();
  const auto up = right.cross(forward).normalized();
  const auto d = p - eye();
  const double depth = d.dot(forward);
  if (depth <= 1e-9) return std::nullopt;
  const double half_h = std::tan(fov * kRad / 2);
  const double half_w = half_h * width / std::max(height, 1.0);
  const double u = d.dot(right) / depth / half_w, v = d.dot(up) / depth / half_h;
  return std::array<double, 2>{(u + 1.0) / 2.0 * width, (1.0 - v) / 2.0 * height};
}

core::Ray OrbitCamera::ray(double x, double y, double width, double height) const {
  const auto back = backward(yaw, pitch);
  const auto forward = back * -1.0;
  const auto right = forward.cross(core::Vec3{0, 0, 1}).normalized();
  const auto up = right.cross(forward).normalized();
  const double half_h = std::tan(fov * kRad / 2);
  const double half_w = half_h * width / std::max(height, 1.0);
  const double u = (2.0 * x / std::max(width, 1.0) - 1.0) * half_w;
  const double v = (1.0 - 2.0 * y / std::max(height, 1.0)) * half_h;
  return {eye(), (forward + right * u + up * v).normalized()};
}

}  // namespace gdpn::ide
