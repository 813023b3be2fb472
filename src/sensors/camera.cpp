// ColorCamera and DepthCamera: pictures of the scene at a rate, rendered only when read.

#include <algorithm>
#include <cmath>

#include "detail/sensor.h"

namespace gdpn::sensors::detail {
namespace camera {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    {"samples", ChannelType::Number, "", "pictures taken so far (each rendered when a script reads it)"},
};

/// A camera's far beyond its near, and within reach of the depth buffer.
bool check(const scene::Scene& /*scene*/, const scene::Node& n, core::Diagnostics& diags, const std::string& /*dir*/) {
  return checkFieldRules(n, diags, "camera", ": ");
}

class Camera final : public SampledSensor {
 public:
  using SampledSensor::SampledSensor;

  std::shared_ptr<const Image> picture(Context& ctx, std::string& why) override {
    if (image_) return image_;
    if (ctx.imager == nullptr) {
      why = "this run renders no camera pictures";
      return nullptr;
    }
    auto picture = std::make_shared<Image>();
    if (!ctx.imager->render(ctx.scene, node(), *picture, why)) return nullptr;
    if (!noise().none()) {
      if (node().kind() == scene::NodeKind::DepthCamera) {
        std::vector<double> d(picture->depth.begin(), picture->depth.end());
        addNoise(d.data(), d.size());
        for (std::size_t i = 0; i < d.size(); ++i) picture->depth[i] = static_cast<float>(d[i]);
      } else {
        std::vector<double> c(picture->rgb.begin(), picture->rgb.end());
        addNoise(c.data(), c.size());
        for (std::size_t i = 0; i < c.size(); ++i) {
          picture->rgb[i] = static_cast<std::uint8_t>(std::clamp(std::round(c[i]), 0.0, 255.0));
        }
      }
    }
    image_ = std::move(picture);
    last_ = image_;
    return image_;
  }

  [[nodiscard]] std::shared_ptr<const Image> lastPicture() const override { return last_; }

 protected:
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::ColorCamera::Noise); }
  [[nodiscard]] double rate() const override { return node().number(F::ColorCamera::Rate); }
  void measure(Context& /*ctx*/, Reading& next) override {
    next.get<double>(0) = static_cast<double>(samples());
    image_.reset();  // rendered when read
  }

 private:
  std::shared_ptr<const Image> image_;  // the latest sample's picture, once read
  std::shared_ptr<const Image> last_;   // the latest picture read, of any sample
};

}  // namespace camera

const KindDef kColorCamera{
    {scene::NodeKind::ColorCamera, camera::kChannels, 0, "it took a picture now", Sampling::Rate, true},
    camera::check,
    makeSensor<camera::Camera>};

const KindDef kDepthCamera{
    {scene::NodeKind::DepthCamera, camera::kChannels, 0, "it took a picture now", Sampling::Rate, true},
    camera::check,
    makeSensor<camera::Camera>};

}  // namespace gdpn::sensors::detail
