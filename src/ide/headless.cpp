// The headless IDE: the same frames on an EGL surfaceless context with no window, driven by
// replayed actions; synthetic mouse and keys go through ImGui's input like a user's.

#include "detail/platforms.h"

#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <charconv>
#include <cmath>
#include <iostream>
#include <system_error>
#include <tuple>

#include "app.h"
#include "detail/frame_io.h"
#include "detail/imgui_input.h"
#include "detail/input_queue.h"
#include "detail/key_chord.h"
#include "detail/termination.h"
#include "gdpn/capture/sensor_imager.h"
#include "gdpn/core/text.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/platform/target.h"

namespace gdpn::ide {

namespace {

constexpr double kFrame = 1.0 / 60.0;  // seconds a headless frame stands for

/// Frames with synthetic input: every press, release, character, move and click goes through
/// the input queue, as the window's do, and reaches ImGui a frame at a time.
class Driver {
 public:
  Driver(App& app, int w, int h, platform::Target& target) : app_(app), w_(w), h_(h), target_(target) {}

  /// One frame, with the next frame's input from the queue.
  void frame() {
    auto& io = ImGui::GetIO();
    io.DisplaySize = {static_cast<float>(w_), static_cast<float>(h_)};
    io.DeltaTime = static_cast<float>(seconds);
    feedImGui(queue_, queue_.next(), io);
    io.MousePos = {queue_.mouseX(), queue_.mouseY()};
    ImGui_ImplOpenGL3_NewFrame();
    target_.bind();
    drawFrame(app_, w_, h_, seconds);
  }
  /// Wall seconds a frame stands for: 1/60 s, longer for `frames: {seconds: S}` (a slow machine).
  double seconds = kFrame;
  /// A frame, and more until every queued event has reached the UI.
  void drain() {
    do frame();
    while (!queue_.empty());
  }
  void move(double x, double y) {
    queue_.move(static_cast<float>(x), static_cast<float>(y));
    drain();
  }
  /// Turns the mouse wheel `clicks` clicks at (`x`, `y`).
  void wheel(double x, double y, double clicks) {
    move(x, y);
    queue_.scroll(0, static_cast<float>(clicks));
    drain();
  }
  void button(int b, bool down) {
    queue_.button(b, down);
    drain();
  }
  /// The button a drag with `hold: true` left down (-1: none).
  int held = -1;
  /// Types `text` into the field that has the keyboard: two frames for a field that was just
  /// asked to take the keyboard to take it (ImGui gives it the focus a frame later, and the
  /// keyboard the frame after), then the text.
  void type(const std::string& text) {
    frame();
    frame();
    queue_.text(text);
    drain();
  }
  /// Presses and releases each of `chords` over the world view, all queued before one frame
  /// (as a quick hand does between two frames of a slow window), then frames until each press
  /// and release has reached the UI.
  void keys(const std::vector<KeyChord>& chords) {
    overWorld();
    for (const auto& c : chords) queueChord(queue_, c);
    drain();
  }
  /// Presses (`down`) or releases key `code` over the world view.
  void key(int code, bool down) {
    overWorld();
    queue_.key(code, down);
    drain();
  }

 private:
  // keys reach the world view while the mouse is over it
  void overWorld() {
    const auto& world = app_.report()["layout"]["world"];
    if (world.is_array()) move(world[0].get<double>() + world[2].get<double>() / 2, world[1].get<double>() + world[3].get<double>() / 2);
  }
  App& app_;
  int w_, h_;
  platform::Target& target_;
  InputQueue queue_;
};

/// Where the last frame's report placed the item the keys `keys` lead to; false with `error`.
bool placed(const App& app, const std::vector<std::string>& keys, double& x, double& y, std::string& error) {
  // [world, floor, X, Y]: where the floor's point (X, Y) m shows in the world view
  if (keys.size() == 4 && keys[0] == "world" && keys[1] == "floor") {
    double f[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const auto& text = keys[static_cast<std::size_t>(k) + 2];
      const auto r = std::from_chars(text.data(), text.data() + text.size(), f[k]);
      if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(f[k])) {
        error = "[world, floor, X, Y] takes two numbers (metres), got '" + text + "'";
        return false;
      }
    }
    const auto& world = app.report()["world"];
    if (!world.contains("origin") || !world.contains("size")) {
      error = "the last frame showed no world view";
      return false;
    }
    const double w = world["size"][0].get<double>(), h = world["size"][1].get<double>();
    const auto q = app.world.shown.project({f[0], f[1], 0.0}, w, h);
    if (!q || (*q)[0] < 0 || (*q)[1] < 0 || (*q)[0] >= w || (*q)[1] >= h) {
      error = "the floor's point (" + keys[2] + ", " + keys[3] + ") is not in sight in the world view";
      return false;
    }
    x = world["origin"][0].get<double>() + (*q)[0];
    y = world["origin"][1].get<double>() + (*q)[1];
    return true;
  }
  const nlohmann::json* at = &app.report();
  std::string path;
  for (const auto& k : keys) {
    path += (path.empty() ? "" : ", ") + k;
    if (!at->is_object() || !at->contains(k)) {
      error = "the last frame showed no [" + path + "]";
      return false;
    }
    at = &(*at)[k];
  }
  if (!at->is_array() || at->size() != 2 || !(*at)[0].is_number() || !(*at)[1].is_number()) {
    error = "[" + path + "] is not where an item stands";
    return false;
  }
  x = (*at)[0].get<double>();
  y = (*at)[1].get<double>();
  return true;
}

/// Performs `a`; false after printing a located error.
bool perform(App& app, Driver& d, const Action& given, const IdeOptions& o, int w, int h) {
  std::string error;
  Action a = given;
  // an item named by the report is looked up after a frame that shows what the last action did
  if (!a.on.empty()) d.frame();
  if ((!a.on.empty() && !placed(app, a.on, a.x, a.y, error)) || (!a.on2.empty() && !placed(app, a.on2, a.x2, a.y2, error))) {
    std::cerr << a.loc.str() << ": error: " << error << "\n";
    return false;
  }
  // an item the report places out of the window (a field below an inspector's edge) cannot be
  // reached by a hand: scroll it into sight first
  for (const auto& [keys, x, y] : {std::tuple{&a.on, a.x, a.y}, std::tuple{&a.on2, a.x2, a.y2}}) {
    if (keys->empty() || (x >= 0 && y >= 0 && x < w && y < h)) continue;
    std::string path;
    for (const auto& k : *keys) path += (path.empty() ? "" : ", ") + k;
    std::cerr << a.loc.str() << ": error: [" << path << "] stands at (" << core::formatDouble(x) << ", "
              << core::formatDouble(y) << "), out of the " << w << "x" << h << " window: scroll it into sight\n";
    return false;
  }
  switch (a.kind) {
    case ActionKind::Key: {
      if (a.field == "hold" || a.field == "release") {
        const int code = keyByName(a.text);
        if (code < 0) error = "unknown key '" + a.text + "' (" + knownKeyNames() + ")";
        else d.key(code, a.field == "hold");
      } else if (const auto chords = parseChords(a.text, error)) {
        d.keys(*chords);
      }
      break;
    }
    case ActionKind::Type:
      d.type(a.text);
      break;
    case ActionKind::Click:
      d.move(a.x, a.y);
      d.button(a.button, true);
      d.button(a.button, false);
      break;
    case ActionKind::Drag: {
      // a drag held down by the last one goes on from where it is
      if (d.held != a.button) {
        if (d.held >= 0) d.button(d.held, false);
        d.move(a.x, a.y);
        d.button(a.button, true);
      } else {
        a.x = static_cast<double>(ImGui::GetIO().MousePos.x);
        a.y = static_cast<double>(ImGui::GetIO().MousePos.y);
      }
      constexpr int kSteps = 8;
      for (int i = 1; i <= kSteps; ++i) d.move(a.x + (a.x2 - a.x) * i / kSteps, a.y + (a.y2 - a.y) * i / kSteps);
      if (a.hold) {
        d.held = a.button;
      } else {
        d.button(a.button, false);
        d.held = -1;
      }
      break;
    }
    case ActionKind::Wheel:
      d.wheel(a.x, a.y, a.number);
      break;
    case ActionKind::Frames:
      d.seconds = a.seconds > 0 ? a.seconds : kFrame;
      for (int i = 0; i < static_cast<int>(a.number) && !terminationFlag().load(); ++i) d.frame();
      d.seconds = kFrame;
      break;
    case ActionKind::Screenshot:
      d.frame();
      if (!writeOutputs(app, w, h, a.text, "")) return false;
      break;
    // what the document and the views do, then a frame to show it
    case ActionKind::Select:
    case ActionKind::Press:
    case ActionKind::Fire:
    case ActionKind::RunFor:
    case ActionKind::Steps:
    case ActionKind::Set:
    case ActionKind::View:
    case ActionKind::Break:
      if (!app.perform(a, error)) break;
      d.frame();
      break;
  }
  (void)o;
  if (!error.empty()) {
    std::cerr << a.loc.str() << ": error: " << error << "\n";
    return false;
  }
  return true;
}

}  // namespace

int runHeadless(const IdeOptions& o, std::unique_ptr<Document> doc, const std::vector<Action>& actions) {
  std::string why;
  auto context = platform::createHeadlessContext(why);
  if (!context) {
    std::cerr << "gdpn ide: error: no headless OpenGL context: " << why << "\n";
    return 1;
  }
  platform::Target target(o.width, o.height, 1);
  // camera sensors draw in an EGL context of their own; the frame's is current again after
  session::SessionOptions run_options;
  run_options.imager = capture::makeSensorImager;
  App app(std::move(doc), std::move(run_options));
  app.autosave_seconds = o.autosave;
  setUpImGui(app);
  // ImGui's own keys (Enter ends a field, Tab moves on, the arrows move the cursor, Ctrl+A
  // selects all) by the codes the replay's keys use, as the window's GLFW backend maps them
  mapGlfwKeys(ImGui::GetIO());
  loadSettings(app);
  app.run().stopOn(&terminationFlag());
  Driver d(app, o.width, o.height, target);
  // two frames so that every view has its size
  d.frame();
  d.frame();
  int code = 0;
  for (const auto& a : actions) {
    // a signal asked the IDE to end: now, writing nothing (no report, no settings)
    if (terminationFlag().load()) endByTermination();
    if (!perform(app, d, a, o, o.width, o.height)) {
      code = 1;
      break;
    }
    if (app.quitRequested()) break;  // File > Quit: the actions after it are not done
  }
  if (terminationFlag().load()) endByTermination();
  if (code == 0) {
    d.frame();
    if (!writeOutputs(app, o.width, o.height, o.screenshot, o.report)) code = 1;
  }
  saveSettings(app);
  tearDownImGui();
  return code;
}

}  // namespace gdpn::ide
