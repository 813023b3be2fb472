#include "gdpn/capture/sensor_imager.h"

#include <algorithm>

#include "gdpn/platform/headless_context.h"
#include "gdpn/render/camera.h"

namespace gdpn::capture {

SensorImager::SensorImager(std::string model_dir) : model_dir_(std::move(model_dir)) {}

SensorImager::~SensorImager() {
  // GPU objects go while their context is current; the caller's is current again afterwards
  const platform::KeptContext caller;
  if (context_) context_->makeCurrent();
  targets_.clear();
  renderer_.reset();
}

bool SensorImager::render(const scene::Scene& scene, const scene::Node& camera, sensors::Image& out, std::string& why) {
  using F = scene::field::ColorCamera;
  return picture(scene, camera, static_cast<int>(camera.number(F::Width)), static_cast<int>(camera.number(F::Height)),
                 out, why);
}

bool SensorImager::picture(const scene::Scene& scene, const scene::Node& camera, int width, int height,
                           sensors::Image& out, std::string& why, render::DrawStats* stats) {
  if (!failed_.empty()) {
    why = failed_;
    return false;
  }
  // the caller's context (a picture or a movie being made) is current again afterwards
  const platform::KeptContext caller;
  if (!context_) {
    context_ = platform::createHeadlessContext(failed_);
    if (!context_) {
      failed_ = "no OpenGL context for camera pictures: " + failed_;
      why = failed_;
      return false;
    }
    context_->makeCurrent();
    renderer_ = std::make_unique<render::Renderer>(model_dir_);
  }
  context_->makeCurrent();
  auto& target = targets_[{width, height}];
  // one sample per pixel: a pixel's colour and depth are those of what it sees, not a blend
  if (!target) target = std::make_unique<platform::Target>(width, height, 1);
  target->bind();
  const bool depth = camera.kind() == scene::NodeKind::DepthCamera;
  render::DrawOptions draw;
  draw.width = width;
  draw.height = height;
  draw.shadows = false;
  draw.grid = false;
  draw.sky = !depth;
  draw.markings = false;  // what the plant is, not how people are shown it works
  const render::Camera view = render::sensorCamera(camera);
  const render::DrawStats drawn = renderer_->draw(scene, view, draw);
  if (stats != nullptr) *stats = drawn;
  // what this picture could not draw fails it, and only it
  if (!renderer_->problems().empty()) {
    why = renderer_->problems().front();
    return false;
  }
  out.width = width;
  out.height = height;
  if (depth) {
    // window depth to distance along the view axis (the projection's near and far)
    out.depth = target->readDepth();
    const double n = view.near, f = view.far;
    for (float& d : out.depth) {
      const double ndc = 2.0 * static_cast<double>(d) - 1.0;
      d = d >= 1.0f ? static_cast<float>(f) : static_cast<float>(2.0 * n * f / (f + n - ndc * (f - n)));
    }
  } else {
    out.rgb = target->readRgb();
  }
  ++pictures_;
  return true;
}

std::vector<std::uint8_t> depthGrey(const sensors::Image& depth, double near, double far) {
  std::vector<std::uint8_t> grey(depth.depth.size() * 3);
  const double span = far > near ? far - near : 1.0;
  for (std::size_t i = 0; i < depth.depth.size(); ++i) {
    const double t = std::clamp((static_cast<double>(depth.depth[i]) - near) / span, 0.0, 1.0);
    grey[3 * i] = grey[3 * i + 1] = grey[3 * i + 2] = static_cast<std::uint8_t>(255.0 * (1.0 - t) + 0.5);
  }
  return grey;
}

std::shared_ptr<sensors::Imager> makeSensorImager(const std::string& model_dir) {
  return std::make_shared<SensorImager>(model_dir);
}

}  // namespace gdpn::capture
