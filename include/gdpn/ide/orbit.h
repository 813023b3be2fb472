#pragma once
/// \file
/// The world view's camera: orbit about a target, pan, zoom, frame a box, standard views and
/// the pick ray under a pixel. Pure math, no OpenGL.

#include <cstdint>
#include <array>
#include <optional>
#include <string_view>

#include "gdpn/core/math.h"
#include "gdpn/render/camera.h"

namespace gdpn::ide {

/// The standard views of the world view's menu.
enum class StandardView : std::uint8_t { Front, Back, Left, Right, Top, Iso };

/// "front", "back", "left", "right", "top", "iso".
[[nodiscard]] const char* standardViewName(StandardView view);
/// The view called `name`, or nullopt.
[[nodiscard]] std::optional<StandardView> parseStandardView(std::string_view name);

/// A camera that turns about a target point (z up).
struct OrbitCamera {
  core::Vec3 target{0, 0, 0};  ///< the point looked at, m (world)
  double distance = 10.0;      ///< from the target to the eye, m
  double yaw = -45.0;          ///< about z, degrees: 0 looks along +x... the eye lies at -x
  double pitch = 30.0;         ///< above the ground plane, degrees, in [-89, 89]
  double fov = 45.0;           ///< vertical field of view, degrees

  /// The same view as `camera` (its eye, target and field of view).
  static OrbitCamera from(const render::Camera& camera);
  /// As the renderer takes it.
  [[nodiscard]] render::Camera camera() const;
  /// The eye, m (world).
  [[nodiscard]] core::Vec3 eye() const;
  /// Turns by a mouse move of (`dx`, `dy`) pixels.
  void orbit(double dx, double dy);
  /// Moves the target with a mouse move of (`dx`, `dy`) pixels in a view `height` pixels tall,
  /// so that the point under the mouse stays under it.
  void pan(double dx, double dy, double height);
  /// Moves in (`clicks` > 0) or out by mouse-wheel clicks.
  void zoom(double clicks);
  /// Looks at `box` from the current direction, near enough that it fills the view.
  void frame(const core::Aabb& box);
  /// Looks at the current target from the direction of `view`.
  void look(StandardView view);
  /// The ray through pixel (`x`, `y`) of a `width` x `height` view (top-left origin).
  [[nodiscard]] core::Ray ray(double x, double y, double width, double height) const;
  /// Where world point `p` appears in a `width` x `height` view (pixels, top-left origin);
  /// nullopt when it lies behind the eye. The inverse of ray().
  [[nodiscard]] std::optional<std::array<double, 2>> project(const core::Vec3& p, double width, double height) const;
};

}  // namespace gdpn::ide
