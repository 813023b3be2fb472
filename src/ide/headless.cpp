// The headless IDE: the same frames on an EGL surfaceless context with no window, driven by
// replayed actions; synthetic mouse and keys go through ImGui's input like a user's.

#include "detail/platforms.h"

#include <epoxy/gl.h>
#include <imgui.h>
#include <GLFW/glfw3.h>
#include <imgui_impl_opengl3.h>

#include <iostream>

#include "app.h"
#include "detail/frame_io.h"
#include "detail/keys.h"
#include "gdpn/capture/sensor_imager.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/platform/target.h"

namespace gdpn::ide {

namespace {

constexpr double kFrame = 1.0 / 60.0;  // seconds a headless frame stands for

/// Frames with synthetic input.
class Driver {
 public:
  Driver(App& app, int w, int h, platform::Target& target) : app_(app), w_(w), h_(h), target_(target) {}

  void frame() {
    auto& io = ImGui::GetIO();
    io.DisplaySize = {static_cast<float>(w_), static_cast<float>(h_)};
    io.DeltaTime = static_cast<float>(kFrame);
    io.MousePos = mouse_;
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = down_[b];
    ImGui_ImplOpenGL3_NewFrame();
    target_.bind();
    drawFrame(app_, w_, h_, kFrame);
  }
  void move(double x, double y) {
    mouse_ = {static_cast<float>(x), static_cast<float>(y)};
    frame();
  }
  /// Turns the mouse wheel `clicks` clicks at (`x`, `y`).
  void wheel(double x, double y, double clicks) {
    move(x, y);
    ImGui::GetIO().MouseWheel = static_cast<float>(clicks);
    frame();
  }
  void button(int b, bool down) {
    down_[b] = down;
    frame();
  }
  /// Types `text` into the field that has the keyboard: two frames for a field that was just
  /// asked to take the keyboard to take it (ImGui gives it the focus a frame later, and the
  /// keyboard the frame after), then the text.
  void type(const std::string& text) {
    frame();
    frame();
    ImGui::GetIO().AddInputCharactersUTF8(text.c_str());
    frame();
  }
  /// Presses (`down`) or releases key `code` over the world view.
  void key(int code, bool down) {
    // keys reach the world view while the mouse is over it
    const auto& world = app_.report()["layout"]["world"];
    if (world.is_array()) move(world[0].get<double>() + world[2].get<double>() / 2, world[1].get<double>() + world[3].get<double>() / 2);
    ImGui::GetIO().KeysDown[code] = down;
    frame();
  }

 private:
  App& app_;
  int w_, h_;
  platform::Target& target_;
  ImVec2 mouse_{-1, -1};
  bool down_[3] = {false, false, false};
};

/// Where the last frame's report placed the item the keys `keys` lead to; false with `error`.
bool placed(const App& app, const std::vector<std::string>& keys, double& x, double& y, std::string& error) {
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
  switch (a.kind) {
    case ActionKind::Key: {
      const int code = keyCode(a.text);
      if (code < 0) error = "unknown key '" + a.text + "' (a-z, 0-9, space, enter, escape, tab, left, right, up, down)";
      else if (a.field == "hold") d.key(code, true);
      else if (a.field == "release") d.key(code, false);
      else {
        d.key(code, true);
        d.key(code, false);
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
      d.move(a.x, a.y);
      d.button(a.button, true);
      constexpr int kSteps = 8;
      for (int i = 1; i <= kSteps; ++i) d.move(a.x + (a.x2 - a.x) * i / kSteps, a.y + (a.y2 - a.y) * i / kSteps);
      d.button(a.button, false);
      break;
    }
    case ActionKind::Wheel:
      d.wheel(a.x, a.y, a.number);
      break;
    case ActionKind::Frames:
      for (int i = 0; i < static_cast<int>(a.number); ++i) d.frame();
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
  // ImGui's own keys (Enter ends a field, Tab moves on, the arrows move the cursor) by the
  // codes the replay's keys use, as the window's GLFW backend maps them
  auto& io = ImGui::GetIO();
  io.KeyMap[ImGuiKey_Tab] = GLFW_KEY_TAB;
  io.KeyMap[ImGuiKey_LeftArrow] = GLFW_KEY_LEFT;
  io.KeyMap[ImGuiKey_RightArrow] = GLFW_KEY_RIGHT;
  io.KeyMap[ImGuiKey_UpArrow] = GLFW_KEY_UP;
  io.KeyMap[ImGuiKey_DownArrow] = GLFW_KEY_DOWN;
  io.KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
  io.KeyMap[ImGuiKey_Escape] = GLFW_KEY_ESCAPE;
  io.KeyMap[ImGuiKey_Space] = GLFW_KEY_SPACE;
  loadSettings(app);
  Driver d(app, o.width, o.height, target);
  // two frames so that every view has its size
  d.frame();
  d.frame();
  int code = 0;
  for (const auto& a : actions) {
    if (!perform(app, d, a, o, o.width, o.height)) {
      code = 1;
      break;
    }
    if (app.quitRequested()) break;  // File > Quit: the actions after it are not done
  }
  if (code == 0) {
    d.frame();
    if (!writeOutputs(app, o.width, o.height, o.screenshot, o.report)) code = 1;
  }
  saveSettings(app);
  tearDownImGui();
  return code;
}

}  // namespace gdpn::ide
