#pragma once
// What the window and the headless IDE share: ImGui's setup, one frame drawn into the bound
// framebuffer, reading that framebuffer back, and the settings file's splitters.

#include <cstdint>
#include <string>
#include <vector>

namespace gdpn::ide {

class App;

/// Creates ImGui's context with the IDE's style and fonts (no imgui.ini); the OpenGL 3 backend
/// is initialised on the current context. Returns the App's fonts through `app`.
void setUpImGui(App& app);
/// Shuts the OpenGL 3 backend down and destroys ImGui's context.
void tearDownImGui();
/// Draws one frame of `app` into the bound framebuffer (`fb_width` x `fb_height` pixels), laid
/// out in ImGui's display size (io.DisplaySize: smaller on a high-density screen),
/// `wall_seconds` after the last; the platform has set ImGui's input and called its own
/// NewFrame. A screenshot the toolbar asked for is written after the frame.
void drawFrame(App& app, int fb_width, int fb_height, double wall_seconds);
/// The bound framebuffer's picture, RGB, top row first.
std::vector<std::uint8_t> readFramebuffer(int width, int height);
/// Writes the picture and the report files asked for; false (with a message on stderr) on error.
bool writeOutputs(App& app, int width, int height, const std::string& screenshot, const std::string& report);
/// Loads the layout and the recent files from the settings file (when there is one).
void loadSettings(App& app);
/// Saves the layout and the recent files to the settings file.
void saveSettings(App& app);

}  // namespace gdpn::ide
