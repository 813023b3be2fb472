#include "gdpn/render/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "gdpn/core/text.h"
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

Camera sensorCamera(const Node& camera) {
  using F = field::ColorCamera;
  Camera c;
  c.eye = camera.world.position;
  c.target = c.eye + camera.world.rotation.rotate({1, 0, 0});
  c.up = camera.world.rotation.rotate({0, 0, 1});
  const double aspect = camera.number(F::Width) / camera.number(F::Height);
  c.fov = 2.0 * std::atan(std::tan(camera.number(F::Fov) * std::numbers::pi / 360.0) / aspect) * 180.0 / std::numbers::pi;
  c.near = camera.number(F::Near);
  c.far = camera.number(F::Far);
  return c;
}

bool isCameraSensor(const Node& n) { return n.kind() == NodeKind::ColorCamera || n.kind() == NodeKind::DepthCamera; }

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

namespace {

/// The scene's Camera nodes, in tree order (depth first, children in order), none in templates.
std::vector<const Node*> cameraNodes(const scene::Scene& scene) {
  std::vector<const Node*> out, todo{&scene.root()};
  while (!todo.empty()) {
    const Node* n = todo.back();
    todo.pop_back();
    if (n->is_template) continue;
    if (n->kind() == NodeKind::Camera || isCameraSensor(*n)) out.push_back(n);
    for (auto it = n->children().rbegin(); it != n->children().rend(); ++it) todo.push_back(it->get());
  }
  return out;
}

}  // namespace

std::string cameraProblem(const scene::Scene& scene, const std::string& path) {
  if (path.empty()) return {};
  const Node* n = scene.find(path);
  const bool camera = n != nullptr && (n->kind() == NodeKind::Camera || isCameraSensor(*n));
  if (camera && !scene::inTemplate(*n)) return {};
  std::vector<std::string> cameras;
  for (const Node* c : cameraNodes(scene)) cameras.push_back(c->path());
  std::string why = n == nullptr                        ? "no node at '" + path + "'"
                    : !camera ? "'" + path + "' is a " + n->type().name + ", not a Camera or a camera sensor"
                              : "'" + path + "' is a " + n->type().name + " in a template, which is not drawn";
  if (cameras.empty()) return why + "; the scene has no Camera node (leave --camera out for a framing view)";
  std::string list;
  for (const auto& c : cameras) list += (list.empty() ? "" : ", ") + c;
  return why + core::didYouMean(path, cameras) + "; the scene's cameras: " + list;
}

Camera chooseCamera(const scene::Scene& scene, const std::string& path, double t, std::string& error) {
  error.clear();
  if (!path.empty()) {
    error = cameraProblem(scene, path);
    if (!error.empty()) return framing(scene);
    const Node& n = *scene.find(path);
    return isCameraSensor(n) ? sensorCamera(n) : cameraOf(n, t);
  }
  // the first Camera node (a camera sensor is chosen only by its path)
  for (const Node* n : cameraNodes(scene)) {
    if (n->kind() == NodeKind::Camera) return cameraOf(*n, t);
  }
  return framing(scene);
}

}  // namespace gdpn::render
