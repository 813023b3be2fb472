#pragma once
/// \file
/// Where a picture is seen from: a Camera node's view, or one that frames the whole scene.

#include <string>

#include "gdpn/core/math.h"
#include "gdpn/scene/node.h"

namespace gdpn::render {

/// Where the picture is seen from.
struct Camera {
  core::Vec3 eye{5, -5, 4};     ///< eye position, m (world)
  core::Vec3 target{0, 0, 0};   ///< the point looked at, m (world)
  core::Vec3 up{0, 0, 1};       ///< which way is up
  double fov = 45.0;            ///< vertical field of view, degrees
  double near = 0.05;           ///< near clipping distance, m
  double far = 2000.0;          ///< far clipping distance, m
};

/// The view of Camera node `camera` at time `t` seconds: its position and target in its
/// parent's frame; an orbit camera turns about its target at its speed.
Camera cameraOf(const scene::Node& camera, double t = 0.0);
/// The view of ColorCamera or DepthCamera node `camera`: from its origin along its +x, +z up,
/// its horizontal field of view over its width and height, its near and far.
Camera sensorCamera(const scene::Node& camera);
/// True for a ColorCamera or DepthCamera node.
bool isCameraSensor(const scene::Node& n);
/// A view from the south-east and above that frames every shape of `scene`.
Camera framing(const scene::Scene& scene);
/// The camera a picture uses: the Camera node or camera sensor at `path` (or the scene's first Camera when
/// `path` is empty, or a framing view when it has none). Null `error` means found; otherwise
/// it says what is wrong.
Camera chooseCamera(const scene::Scene& scene, const std::string& path, double t, std::string& error);
/// "" when `path` is empty or names a Camera node of `scene`; otherwise what is wrong, with
/// the Camera nodes there are (a check made before a run, not after it).
std::string cameraProblem(const scene::Scene& scene, const std::string& path);

}  // namespace gdpn::render
