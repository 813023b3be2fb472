#include "gdpn/render/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "gdpn/scene/actions.h"

namespace gdpn::render {

using core::Vec3;
using scene::Node;
using scene::NodeKind;
namespace field = scene::field;

Camera cameraOf(const Node& camera, double t) {
  Camera c;
  c.eye = camera.world.apply(camera.vec3(field::Camera::Position));
  c.target = camera.world.apply(camera.vec3(field::Camera::Target));
  c.up = camera.world.rotation.rotate(camera.vec3(field::Camera::Up));
  c.fov = camera.number(field::Camera::Fov);
  if (camera.choice<scene::CameraKind>(field::Camera::Kind) == scene::CameraKind::Orbit) {
    const double angle = camera.number(field::Camera::Speed) * t * std::numbers::pi / 180.0;
    c.eye = c.target + core::Quat::axisAngle(c.up.normalized(), angle).rotate(c.eye - c.target);
  }
  const double distance = (c.eye - c.target).length();
  c.far = std::max(2000.0, distance * 10);
  return c;
}

Camera framing(const scene::Scene& scene) {
  const core::Aabb box = scene::boundingBox(scene.root());
  Camera c;
  if (box.empty()) return c;
  const Vec3 centre = (box.lo + box.hi) * 0.5;
  const double radius = std::max(0.5, (box.hi - box.lo).length() * 0.5);
  const double distance = radius / std::sin(c.fov * std::numbers::pi / 360.0);
  c.target = centre;
  c.eye = centre + Vec3{0.6, -0.7, 0.45}.normalized() * distance;
  c.far = std::max(2000.0, distance * 10);
  return c;
}

Camera chooseCamera(const scene::Scene& scene, const std::string& path, double t, std::string& error) {
  error.clear();
  if (!path.empty()) {
    const Node* n = scene.find(path);
    if (n == nullptr || n->kind() != NodeKind::Camera) {
      error = "no Camera node at '" + path + "'";
      return framing(scene);
    }
    return cameraOf(*n, t);
  }
  std::vector<const Node*> todo{&scene.root()};
  while (!todo.empty()) {
    const Node* n = todo.back();
    todo.pop_back();
    if (n->kind() == NodeKind::Camera) return cameraOf(*n, t);
    for (auto it = n->children().rbegin(); it != n->children().rend(); ++it) todo.push_back(it->get());
  }
  return framing(scene);
}

}  // namespace gdpn::render
