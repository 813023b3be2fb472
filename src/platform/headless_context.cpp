#include "gdpn/platform/headless_context.h"

#include <epoxy/egl.h>

#include <mutex>

namespace gdpn::platform {

namespace {

/// EGL's surfaceless display is one per process, shared by every headless context (a camera
/// sensor's and the picture being made, say): it is initialised for the first and terminated
/// after the last, not when any one goes.
struct SharedDisplay {
  std::mutex mutex;
  int users = 0;

  /// The display, initialised; EGL_NO_DISPLAY when EGL has none.
  EGLDisplay acquire() {
    const std::lock_guard lock(mutex);
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || eglInitialize(display, &major, &minor) == EGL_FALSE) return EGL_NO_DISPLAY;
    ++users;
    return display;
  }

  void release(EGLDisplay display) {
    const std::lock_guard lock(mutex);
    if (--users == 0) eglTerminate(display);
  }
};

SharedDisplay& sharedDisplay() {
  static SharedDisplay shared;
  return shared;
}

/// An EGL context with no surface; holds its share of the display.
class HeadlessContext final : public GlContext {
 public:
  HeadlessContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
  ~HeadlessContext() override {
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    sharedDisplay().release(display_);
  }
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;
  void makeCurrent() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

}  // namespace

KeptContext::KeptContext()
    : display_(eglGetCurrentDisplay()), context_(eglGetCurrentContext()), draw_(eglGetCurrentSurface(EGL_DRAW)),
      read_(eglGetCurrentSurface(EGL_READ)) {}

KeptContext::~KeptContext() {
  if (context_ != EGL_NO_CONTEXT && display_ != EGL_NO_DISPLAY) eglMakeCurrent(display_, draw_, read_, context_);
}

std::unique_ptr<GlContext> createHeadlessContext(std::string& why) {
  // surfaceless: the default display needs an X or Wayland server, this one needs nothing
  EGLDisplay display = sharedDisplay().acquire();
  if (display == EGL_NO_DISPLAY) {
    why = "EGL has no surfaceless display (is Mesa's libegl1 installed?)";
    return nullptr;
  }
  if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE) {
    why = "EGL cannot bind desktop OpenGL";
    sharedDisplay().release(display);
    return nullptr;
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) {
    why = "EGL gives no OpenGL 3.3 core context";
    sharedDisplay().release(display);
    return nullptr;
  }
  auto out = std::make_unique<HeadlessContext>(display, context);
  out->makeCurrent();
  return out;
}

}  // namespace gdpn::platform
