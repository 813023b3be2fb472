#include "gdpn/capture/capture.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <filesystem>
#include <string_view>

#include "gdpn/capture/movie.h"
#include "gdpn/capture/sensor_imager.h"
#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/net_state.h"
#include "gdpn/diagram/picture.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/platform/png.h"
#include "gdpn/platform/target.h"
#include "gdpn/render/camera.h"
#include "gdpn/render/renderer.h"

namespace gdpn::capture {

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  // two whole numbers around an 'x', nothing else, each side within the limits
  const auto side = [](std::string_view digits) -> std::optional<int> {
    int value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    if (value < kMinSide || value > kMaxSide) return std::nullopt;
    return value;
  };
  const auto x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  const auto w = side(std::string_view(text).substr(0, x));
  const auto h = side(std::string_view(text).substr(x + 1));
  if (!w || !h) return std::nullopt;
  return std::pair{*w, *h};
}

std::optional<std::pair<int, int>> cameraSensorSize(const scene::Scene& scene, const std::string& camera) {
  const scene::Node* n = camera.empty() ? nullptr : scene.find(camera);
  if (n == nullptr || !render::isCameraSensor(*n)) return std::nullopt;
  using F = scene::field::ColorCamera;
  return std::pair{static_cast<int>(n->number(F::Width)), static_cast<int>(n->number(F::Height))};
}

namespace {

/// A headless context, a target and a renderer for one model; a DepthCamera's pictures are
/// drawn as its sensor draws them.
struct Studio {
  std::unique_ptr<platform::GlContext> context;
  std::unique_ptr<platform::Target> target;
  std::unique_ptr<render::Renderer> renderer;
  std::unique_ptr<SensorImager> depth;  // made at the first picture from a DepthCamera
  std::string model_dir;
  render::DrawOptions draw;

  bool open(const model::Simulation& sim, const CaptureOptions& o, std::string& error) {
    if (sim.plant() == nullptr) {
      error = "the model has no scene to draw";
      return false;
    }
    // a wrong camera is told now, not after the run to the picture's time
    error = render::cameraProblem(*sim.plant(), o.camera);
    if (!error.empty()) return false;
    context = platform::createHeadlessContext(error);
    if (!context) return false;
    target = std::make_unique<platform::Target>(o.width, o.height, o.samples);
    model_dir = std::filesystem::path(sim.model().path).parent_path().string();
    renderer = std::make_unique<render::Renderer>(model_dir);
    draw.width = o.width;
    draw.height = o.height;
    draw.sensors = o.sensors;
    draw.joints = o.joints;
    draw.shadows = o.shadows;
    draw.sky = draw.grid = o.ground;
    return true;
  }

  bool shoot(const model::Simulation& sim, const CaptureOptions& o, std::vector<std::uint8_t>& rgb,
             render::DrawStats& stats, std::string& error) {
    const render::Camera camera = render::chooseCamera(*sim.plant(), o.camera, sim.kernel().now(), error);
    if (!error.empty()) return false;
    const scene::Node* sensor = o.camera.empty() ? nullptr : sim.plant()->find(o.camera);
    if (sensor != nullptr && sensor->kind() == scene::NodeKind::DepthCamera) {
      return shootDepth(sim, *sensor, o, rgb, stats, error);
    }
    target->bind();
    // the parts' markings: a conveyor's arrows move with time, a visible Region shows when
    // it holds something
    draw.time = sim.kernel().now();
    draw.active = [&sim](const scene::Node& n) { return sim.reading(n.handle()).active; };
    stats = renderer->draw(*sim.plant(), camera, draw);
    if (!renderer->problems().empty()) {
      error = renderer->problems().front();
      return false;
    }
    rgb = target->readRgb();
    return true;
  }

  /// What DepthCamera `camera` sees, at the picture's size: its distances (without noise) in
  /// grey, near white and far black (depthGrey).
  bool shootDepth(const model::Simulation& sim, const scene::Node& camera, const CaptureOptions& o,
                  std::vector<std::uint8_t>& rgb, render::DrawStats& stats, std::string& error) {
    if (!depth) depth = std::make_unique<SensorImager>(model_dir);
    sensors::Image picture;
    if (!depth->picture(*sim.plant(), camera, o.width, o.height, picture, error, &stats)) return false;
    using F = scene::field::ColorCamera;
    rgb = depthGrey(picture, camera.number(F::Near), camera.number(F::Far));
    return true;
  }
};

/// Runs `sim` to `until` seconds. A picture's time is the time asked for: a net that goes
/// dead does not stop the clock (an orbiting camera still turns, a falling box still falls).
model::RunOutcome advance(model::Simulation& sim, double until, const model::ProgressFn& progress,
                          const std::atomic<bool>* interrupt, const std::function<void()>& after_step) {
  auto outcome = sim.run({until, std::nullopt}, progress, interrupt);
  if (outcome.reason != model::StopReason::Dead) return outcome;
  while (sim.kernel().now() + 1e-9 * std::max(1.0, until) < until) {
    sim.step();
    if (after_step) after_step();
  }
  outcome.steps = sim.kernel().steps();
  outcome.time = sim.kernel().now();
  return outcome;
}

}  // namespace

bool renderAt(model::Simulation& sim, double at, const CaptureOptions& options, const std::string& png,
              std::string& error) {
  Studio studio;
  if (!studio.open(sim, options, error)) return false;
  const auto outcome = advance(sim, at, {}, nullptr, {});
  if (outcome.reason == model::StopReason::ScriptError) {
    error = outcome.message;
    return false;
  }
  std::vector<std::uint8_t> rgb;
  render::DrawStats stats;
  if (!studio.shoot(sim, options, rgb, stats, error)) return false;
  return platform::writePng(png, options.width, options.height, rgb, error);
}

bool renderNetAt(model::Simulation& sim, const NetPictureOptions& options, const std::string& out,
                 core::Diagnostics& warnings, std::string& error) {
  // the page first, so that a wrong name costs no run
  core::Diagnostics diags;
  const auto view = diagram::findView(sim.model().net, options.page, diags);
  const auto layout = view.page != nullptr ? diagram::layoutPage(*view.page, diags) : diagram::NetLayout{};
  if (diags.hasErrors()) {
    error = (options.page.empty() ? "" : "--page '" + options.page + "': ") + diags.all().front().message;
    return false;
  }
  warnings.append(diags);
  if (options.at) {
    const auto outcome = advance(sim, *options.at, {}, nullptr, {});
    if (outcome.reason == model::StopReason::ScriptError) {
      error = outcome.message;
      return false;
    }
  }
  const auto state = diagram::netStateOf(sim.kernel(), view, [&](net::NodeRef ref) { return sim.nodeName(ref); });
  auto [width, height] = diagram::naturalSize(layout);
  if (options.width > 0 && options.height > 0) {
    width = options.width;
    height = options.height;
  }
  return diagram::writeNetPicture(layout, &state, width, height, out, error);
}

bool record(model::Simulation& sim, double until, const CaptureOptions& options, const std::string& movie,
            const model::ProgressFn& progress, const std::atomic<bool>* interrupt, RecordResult& result,
            std::string& error) {
  Studio studio;
  if (!studio.open(sim, options, error)) return false;
  if (options.fps <= 0) {
    error = "--fps must be above 0";
    return false;
  }
  MovieWriter writer;
  if (!writer.open(movie, options.width, options.height, options.fps, error)) return false;
  // frame k shows the model at k / fps seconds; a frame is taken at the first step that reaches it
  const auto frames = static_cast<std::int64_t>(std::ceil(until * options.fps - 1e-9));
  std::int64_t next = 0;
  std::vector<std::uint8_t> rgb;
  render::DrawStats stats;
  bool ok = true;
  auto take = [&] {
    while (ok && next < frames && sim.kernel().now() + 1e-9 >= static_cast<double>(next) / options.fps) {
      ok = studio.shoot(sim, options, rgb, stats, error) && writer.write(rgb);
      if (ok) ++next;
      result.triangles = stats.triangles;
    }
  };
  sim.start();
  take();
  sim.setStepHook(take);
  result.outcome = advance(sim, until, progress, interrupt, take);
  sim.setStepHook({});
  // a run stopped early (by a script, or Ctrl-C) still fills the movie with its last picture
  while (ok && next < frames) {
    ok = writer.write(rgb);
    ++next;
  }
  result.frames = writer.frames();
  // a movie with a missing frame is not kept: the old file stays
  if (!ok) {
    std::string why;
    if (!writer.close(why, false) && error.empty()) error = why;
    if (error.empty()) error = "ffmpeg stopped taking frames";
    return false;
  }
  return writer.close(error);
}

}  // namespace gdpn::capture
