#pragma once
/// \file
/// Pictures for camera sensors during a run: ColorCamera and DepthCamera nodes rendered
/// offscreen through the renderer, in a headless context of their own (EGL; llvmpipe when
/// there is no GPU), made at the first picture asked for.

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/platform/gl_context.h"
#include "gdpn/platform/target.h"
#include "gdpn/render/renderer.h"
#include "gdpn/sensors/hub.h"

namespace gdpn::capture {

/// Renders camera sensors' pictures (sensors::Imager) for a run.
class SensorImager : public sensors::Imager {
 public:
  /// `model_dir`: where the scene's mesh and elevation files are. Pictures are drawn in a
  /// headless context of its own, made at the first picture; the caller's context is current
  /// again after each.
  explicit SensorImager(std::string model_dir);
  ~SensorImager() override;
  SensorImager(const SensorImager&) = delete;
  SensorImager& operator=(const SensorImager&) = delete;
  /// The picture of `camera` as the scene stands: RGB bytes for a ColorCamera; for a
  /// DepthCamera, metres along its view axis (`far` where nothing is within it). Lights,
  /// materials and fog as drawn; no grid, no sensor overlays, no shadows.
  bool render(const scene::Scene& scene, const scene::Node& camera, sensors::Image& out, std::string& why) override;
  /// As render(), at `width` x `height` pixels rather than the camera's own size (`gdpn
  /// render --camera` with --size); `stats` (when given) gets what the draw did. A picture
  /// that fails (a mesh that cannot be read: `why` says where) leaves later ones unharmed.
  bool picture(const scene::Scene& scene, const scene::Node& camera, int width, int height, sensors::Image& out,
               std::string& why, render::DrawStats* stats = nullptr);
  /// Pictures rendered so far.
  [[nodiscard]] std::size_t pictures() const { return pictures_; }

 private:
  std::string model_dir_;
  std::unique_ptr<platform::GlContext> context_;
  std::unique_ptr<render::Renderer> renderer_;
  std::map<std::pair<int, int>, std::unique_ptr<platform::Target>> targets_;  // by width and height
  std::size_t pictures_ = 0;
  std::string failed_;  // why the context could not be made (then asked no more)
};

/// A DepthCamera's picture (`depth`, metres) as grey RGB bytes, 3 a pixel, top row first:
/// near white, far black, linear from `near` (255) to `far` (0) metres, as the IDE shows it.
std::vector<std::uint8_t> depthGrey(const sensors::Image& depth, double near, double far);

/// A SensorImager for the model in `model_dir`: what SessionOptions::imager takes.
std::shared_ptr<sensors::Imager> makeSensorImager(const std::string& model_dir);

}  // namespace gdpn::capture
