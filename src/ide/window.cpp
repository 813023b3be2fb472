// The IDE in a window: GLFW's key, character, button, move and scroll events go into the
// input queue, which hands them to ImGui a frame at a time (no press or release is lost,
// however short); ImGui's GLFW backend does the rest (the display size, the clipboard, the
// cursor's shape, focus). The frames are the headless IDE's.

#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <GLFW/glfw3.h>

#include <filesystem>
#include <iostream>
#include <string>

#include "app.h"
#include "gdpn/capture/sensor_imager.h"
#include "detail/frame_io.h"
#include "detail/imgui_input.h"
#include "detail/input_queue.h"
#include "detail/platforms.h"
#include "detail/termination.h"

namespace gdpn::ide {

namespace {

/// True while the clipboard is read: an empty one (or one holding no text) is nothing to
/// paste, not an error to print.
bool g_reading_clipboard = false;

void onGlfwError(int code, const char* text) {
  if (code == GLFW_FORMAT_UNAVAILABLE && g_reading_clipboard) return;
  std::cerr << "gdpn ide: GLFW error " << code << ": " << text << "\n";
}

/// The clipboard's text for ImGui (Paste, Ctrl+V in a field); null when it holds none.
const char* clipboardText(void* window) {
  g_reading_clipboard = true;
  const char* text = glfwGetClipboardString(static_cast<GLFWwindow*>(window));
  g_reading_clipboard = false;
  return text;
}

// GLFW's input events, queued (the window's user pointer is the queue)
InputQueue& windowQueue(GLFWwindow* window) { return *static_cast<InputQueue*>(glfwGetWindowUserPointer(window)); }
void onWindowKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  // a key held down repeats in ImGui by itself
  if (action != GLFW_REPEAT) windowQueue(window).key(key, action == GLFW_PRESS);
}
void onWindowChar(GLFWwindow* window, unsigned int c) { windowQueue(window).character(c); }
void onWindowButton(GLFWwindow* window, int button, int action, int /*mods*/) {
  windowQueue(window).button(button, action == GLFW_PRESS);
}
void onWindowMove(GLFWwindow* window, double x, double y) {
  windowQueue(window).move(static_cast<float>(x), static_cast<float>(y));
}
void onWindowScroll(GLFWwindow* window, double dx, double dy) {
  windowQueue(window).scroll(static_cast<float>(dx), static_cast<float>(dy));
}

/// Sends `window`'s input into `queue`; focus and the mouse entering or leaving go to ImGui's
/// backend, which asks for them when it installs no callbacks of its own.
void queueInput(GLFWwindow* window, InputQueue& queue) {
  glfwSetWindowUserPointer(window, &queue);
  glfwSetKeyCallback(window, onWindowKey);
  glfwSetCharCallback(window, onWindowChar);
  glfwSetMouseButtonCallback(window, onWindowButton);
  glfwSetCursorPosCallback(window, onWindowMove);
  glfwSetScrollCallback(window, onWindowScroll);
  glfwSetWindowFocusCallback(window, ImGui_ImplGlfw_WindowFocusCallback);
  glfwSetCursorEnterCallback(window, ImGui_ImplGlfw_CursorEnterCallback);
}

}  // namespace

int runWindow(const IdeOptions& o, std::unique_ptr<Document> doc) {
  glfwSetErrorCallback(onGlfwError);
  if (glfwInit() == GLFW_FALSE) {
    std::cerr << "gdpn ide: error: no display (try --headless)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  // an EGL context, as camera sensors' pictures are drawn in one of their own (EGL
  // surfaceless) and an EGL context is kept and made current again around each; a GLX
  // context cannot be current on the thread at the same time, so a window that has no EGL
  // falls back to the native API without camera pictures
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  const auto title = std::filesystem::path(doc->model().path).filename().string() + " - gdpn ide";
  GLFWwindow* window = glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
  const bool egl = window != nullptr;
  if (!egl) {
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_NATIVE_CONTEXT_API);
    window = glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
  }
  if (window == nullptr) {
    std::cerr << "gdpn ide: error: cannot open a window with OpenGL 3.3\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  int code = 0;
  {
    session::SessionOptions run_options;
    if (egl) run_options.imager = capture::makeSensorImager;
    else std::cerr << "gdpn ide: note: the window has no EGL context: camera sensors render no pictures\n";
    App app(std::move(doc), std::move(run_options));
    app.autosave_seconds = o.autosave;
    setUpImGui(app);
    InputQueue queue;
    ImGui_ImplGlfw_InitForOpenGL(window, false);
    ImGui::GetIO().GetClipboardTextFn = clipboardText;
    queueInput(window, queue);
    loadSettings(app);
    if (o.quit_after > 0) app.run().run(RunSpeed::RealTime);
    const double start = glfwGetTime();
    double last = start;
    int drawn = 0;  // frames drawn, up to 2
    std::string shown_title;
    app.run().stopOn(&terminationFlag());
    while (!app.quitRequested()) {
      glfwPollEvents();
      // a signal asked the IDE to end: now, saving nothing (no question, no settings)
      if (terminationFlag().load()) endByTermination();
      // the window's close button is File > Quit: "save changes?" first where edits would be lost
      if (glfwWindowShouldClose(window) == GLFW_TRUE) {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        if (o.quit_after > 0) break;
        app.quit();
        if (app.quitRequested()) break;
      }
      if (const auto t = app.title(); t != shown_title) {
        glfwSetWindowTitle(window, t.c_str());
        shown_title = t;
      }
      const double now = glfwGetTime();
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      // after the backend, whose mouse buttons are GLFW's state now, not the queue's; input
      // waits until every view has been drawn (ImGui finds what is under the mouse among the
      // last frame's windows), so that a click sent as the window opens is not lost either
      feedImGui(queue, drawn < 2 ? InputFrame{} : queue.next(), ImGui::GetIO());
      if (drawn < 2) ++drawn;
      drawFrame(app, w, h, now - last);
      last = now;
      // a timed session (the smoke test) ends with its outputs
      if (o.quit_after > 0 && now - start >= o.quit_after) {
        if (!writeOutputs(app, w, h, o.screenshot, o.report)) code = 1;
        glfwSwapBuffers(window);
        break;
      }
      glfwSwapBuffers(window);
    }
    saveSettings(app);
    glfwSetWindowUserPointer(window, nullptr);
    ImGui_ImplGlfw_Shutdown();
    tearDownImGui();
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return code;
}

}  // namespace gdpn::ide
