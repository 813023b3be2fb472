// GradientSensor: the vector of a gradient field where its body is.

#include <algorithm>

#include "detail/sensor.h"
#include "gdpn/scene/actions.h"

namespace gdpn::sensors::detail {
namespace gradient_sensor {  // named, not anonymous: the kinds share a unity build

constexpr Channel kChannels[] = {
    {"vector", ChannelType::Vector, "", "the field's vector where its body is (world frame, the field's units)"},
    {"magnitude", ChannelType::Number, "", "the vector's length"},
};

/// The field a GradientSensor reads: the one its `field` names, or the scene's first.
const scene::Node* fieldOf(const scene::Scene& scene, const scene::Node& sensor) {
  const std::string& path = sensor.text(scene::field::GradientSensor::Field);
  if (!path.empty()) {
    const scene::Node* f = scene.find(path);
    return f && f->kind() == scene::NodeKind::GradientField ? f : nullptr;
  }
  const scene::Node* first = nullptr;
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (!first && n.kind() == scene::NodeKind::GradientField) first = &n;
  }, {}, scene::Templates::Skip);
  return first;
}

/// The field's vector at world point `p`: bilinear between grid points, held at the edges.
core::Vec3 sample(const scene::Node& field, core::Vec3 p) {
  const core::Vec3 q = field.world.inverse().apply(p);
  using F = scene::field::GradientField;
  const double w = field.number(F::Width), d = field.number(F::Depth);
  const auto nx = static_cast<std::size_t>(field.number(F::Nx)), ny = static_cast<std::size_t>(field.number(F::Ny));
  const auto& v = std::get<std::vector<double>>(field.value(F::Vectors));
  const double u = std::clamp((q.x + w / 2) / w, 0.0, 1.0) * static_cast<double>(nx - 1);
  const double t = std::clamp((q.y + d / 2) / d, 0.0, 1.0) * static_cast<double>(ny - 1);
  const auto i = std::min(static_cast<std::size_t>(u), nx - 2), j = std::min(static_cast<std::size_t>(t), ny - 2);
  const double fu = u - static_cast<double>(i), ft = t - static_cast<double>(j);
  auto at = [&](std::size_t a, std::size_t b, int c) { return v[(b * nx + a) * 2 + static_cast<std::size_t>(c)]; };
  core::Vec3 out;
  for (int c = 0; c < 2; ++c) {
    const double value = (1 - fu) * (1 - ft) * at(i, j, c) + fu * (1 - ft) * at(i + 1, j, c) +
                         (1 - fu) * ft * at(i, j + 1, c) + fu * ft * at(i + 1, j + 1, c);
    (c == 0 ? out.x : out.y) = value;
  }
  return field.world.rotation.rotate(out);
}

bool check(const scene::Scene& scene, const scene::Node& n, core::Diagnostics& diags, const std::string& /*dir*/) {
  bool ok = true;
  if (!bodyAbove(n)) {
    diags.error(n.loc, "a GradientSensor samples the field where its body is, but '" + n.path() +
                           "' has no Body above it");
    ok = false;
  }
  if (!fieldOf(scene, n)) {
    const std::string& named = n.text(scene::field::GradientSensor::Field);
    diags.error(n.loc, "GradientSensor '" + n.path() + "' finds no GradientField to read" +
                           (named.empty() ? "" : " at '" + named + "'"));
    ok = false;
  }
  return ok;
}

class GradientSensor final : public Sensor {
 public:
  using Sensor::Sensor;
  bool read(Context& ctx, const Reading& /*last*/, Reading& next) override {
    const scene::Node* body = bodyAbove(node());
    const scene::Node* field = fieldOf(ctx.scene, node());
    if (!body || !field) return false;
    const core::Vec3 v = sample(*field, body->world.position);
    next.get<core::Vec3>(0) = v;
    next.get<double>(1) = v.length();
    next.active = true;
    return true;
  }
};

}  // namespace gradient_sensor

const KindDef kGradientSensor{{scene::NodeKind::GradientSensor, gradient_sensor::kChannels, 1, "it reads a field", Sampling::EveryStep},
                              gradient_sensor::check,
                              makeSensor<gradient_sensor::GradientSensor>};

}  // namespace gdpn::sensors::detail
