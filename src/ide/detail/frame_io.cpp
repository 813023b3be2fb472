// The frame code the window and the headless IDE share.

#include "frame_io.h"

#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "../app.h"
#include "gdpn/platform/png.h"

namespace gdpn::ide {

void setUpImGui(App& app) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  auto& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout lives in gdpn's own settings file
  ImGui::StyleColorsDark();
  auto& style = ImGui::GetStyle();
  style.FrameRounding = 3;
  style.ChildRounding = 0;
  style.ItemSpacing = {6, 5};
  style.FramePadding = {6, 3};
  style.Colors[ImGuiCol_WindowBg] = {0.13F, 0.14F, 0.16F, 1.0F};
  style.Colors[ImGuiCol_ChildBg] = {0.16F, 0.17F, 0.19F, 1.0F};
  style.Colors[ImGuiCol_Border] = {0.28F, 0.30F, 0.34F, 1.0F};
  app.initGraphics(loadFonts());
  ImGui_ImplOpenGL3_Init("#version 330");
}

void tearDownImGui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void drawFrame(App& app, int fb_width, int fb_height, double wall_seconds) {
  ImGui::NewFrame();
  const auto display = ImGui::GetIO().DisplaySize;
  app.frame(display.x, display.y, wall_seconds);
  ImGui::Render();
  glViewport(0, 0, fb_width, fb_height);
  glClearColor(0.13F, 0.14F, 0.16F, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  // a movie being filmed takes every frame
  if (app.movie) app.filmFrame(fb_width, fb_height, readFramebuffer(fb_width, fb_height));
  // the toolbar's Screenshot: the frame just drawn
  if (app.screenshot_requested) {
    app.screenshot_requested = false;
    const auto name = "gdpn-ide-" + std::to_string(++app.screenshots) + ".png";
    std::string why;
    app.message = platform::writePng(name, fb_width, fb_height, readFramebuffer(fb_width, fb_height), why)
                      ? "saved " + name
                      : name + ": " + why;
  }
}

std::vector<std::uint8_t> readFramebuffer(int width, int height) {
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  std::vector<std::uint8_t> rgb(w * h * 3), flipped(w * h * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  for (std::size_t y = 0; y < h; ++y) std::memcpy(&flipped[y * w * 3], &rgb[(h - 1 - y) * w * 3], w * 3);
  return flipped;
}

bool writeOutputs(App& app, int width, int height, const std::string& screenshot, const std::string& report) {
  bool ok = true;
  if (!screenshot.empty()) {
    std::string why;
    if (!platform::writePng(screenshot, width, height, readFramebuffer(width, height), why)) {
      std::cerr << screenshot << ": error: " << why << "\n";
      ok = false;
    }
  }
  if (!report.empty()) {
    std::ofstream out(report);
    out << app.report().dump(2) << "\n";
    if (!out) {
      std::cerr << report << ": error: cannot write the report\n";
      ok = false;
    }
  }
  return ok;
}

void loadSettings(App& app) {
  if (auto s = loadSettingsFile(settingsPath())) {
    app.splitters() = s->splitters;
    // the model opened from the command line is the latest
    const auto opened = app.recent;
    app.recent = s->recent;
    for (auto it = opened.rbegin(); it != opened.rend(); ++it) app.recent = withRecent(app.recent, *it);
  }
}

void saveSettings(App& app) { (void)saveSettingsFile(settingsPath(), {app.splitters(), app.recent}); }

}  // namespace gdpn::ide
