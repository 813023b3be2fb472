#include "gdpn/capture/sensor_imager.h"

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
  using F = scene::field::ColorCamera;
  const int w = static_cast<int>(camera.number(F::Width)), h = static_cast<int>(camera.number(F::Height));
  auto& target = targets_[{w, h}];
  // one sample per pixel: a pixel's colour and depth are those of what it sees, not a blend
  if (!target) target = std::make_unique<platform::Target>(w, h, 1);
  target->bind();
  const bool depth = camera.kind() == scene::NodeKind::DepthCamera;
  render::DrawOptions draw;
  draw.width = w;
  draw.height = h;
  draw.shadows = false;
  draw.grid = false;
  draw.sky = !depth;
  draw.markings = false;  // what the plant is, not how people are shown it works
  const render::Camera view = render::sensorCamera(camera);
  renderer_->draw(scene, view, draw);
  if (!renderer_->problems().empty()) {
    why = renderer_->problems().front();
    return false;
  }
  out.width = w;
  out.height = h;
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

std::shared_ptr<sensors::Imager> makeSensorImager(const std::string& model_dir) {
  return std::make_shared<SensorImager>(model_dir);
}

}  // namespace gdpn::capture
