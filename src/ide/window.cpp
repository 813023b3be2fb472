// The IDE in a window: GLFW and ImGui's GLFW backend feed the input, the frames are the
// headless IDE's.

#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <GLFW/glfw3.h>

#include <iostream>

#include "app.h"
#include "gdpn/capture/sensor_imager.h"
#include "detail/frame_io.h"
#include "detail/platforms.h"

namespace gdpn::ide {

namespace {

void onGlfwError(int code, const char* text) { std::cerr << "gdpn ide: GLFW error " << code << ": " << text << "\n"; }

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
  const auto title = "gdpn ide - " + doc->model().path;
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
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    loadSettings(app);
    if (o.quit_after > 0) app.run().run(RunSpeed::RealTime);
    const double start = glfwGetTime();
    double last = start;
    while (glfwWindowShouldClose(window) == GLFW_FALSE) {
      glfwPollEvents();
      const double now = glfwGetTime();
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      drawFrame(app, w, h, now - last);
      last = now;
      // a timed session (the smoke test) ends with its outputs
      if (o.quit_after > 0 && now - start >= o.quit_after) {
        if (!writeOutputs(app, w, h, o.screenshot, o.report)) code = 1;
        glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
      glfwSwapBuffers(window);
    }
    saveSettings(app);
    ImGui_ImplGlfw_Shutdown();
    tearDownImGui();
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return code;
}

}  // namespace gdpn::ide
