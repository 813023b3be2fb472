#include "gdpn/render/context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cstring>
#include <filesystem>

namespace gdpn::render {

std::unique_ptr<GlContext> GlContext::createHeadless(std::string& why) {
  // surfaceless: the default display needs an X or Wayland server, this one needs nothing
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || eglInitialize(display, &major, &minor) == EGL_FALSE) {
    why = "EGL has no surfaceless display (is Mesa's libegl1 installed?)";
    return nullptr;
  }
  if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE) {
    why = "EGL cannot bind desktop OpenGL";
    eglTerminate(display);
    return nullptr;
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) {
    why = "EGL gives no OpenGL 3.3 core context";
    eglTerminate(display);
    return nullptr;
  }
  std::unique_ptr<GlContext> out(new GlContext());
  out->display_ = display;
  out->context_ = context;
  out->makeCurrent();
  return out;
}

GlContext::~GlContext() {
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
}

void GlContext::makeCurrent() {
  eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_));
}

std::string GlContext::renderer() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s != nullptr ? s : "";
}

Target::Target(int width, int height, int samples) : width_(width), height_(height), samples_(std::max(1, samples)) {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (samples_ > 1) {
    glGenFramebuffers(1, &resolve_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    glGenRenderbuffers(1, &resolve_color_);
    glBindRenderbuffer(GL_RENDERBUFFER, resolve_color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color_);
  }
  bind();
}

Target::~Target() {
  const GLuint buffers[] = {color_, depth_, resolve_color_};
  glDeleteRenderbuffers(resolve_color_ != 0 ? 3 : 2, buffers);
  glDeleteFramebuffers(1, &fbo_);
  if (resolve_fbo_ != 0) glDeleteFramebuffers(1, &resolve_fbo_);
}

void Target::bind() {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> Target::readRgb() {
  GLuint from = fbo_;
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    from = resolve_fbo_;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const auto w = static_cast<std::size_t>(width_), h = static_cast<std::size_t>(height_);
  std::vector<std::uint8_t> rgb(w * h * 3), flipped(w * h * 3);
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  for (std::size_t y = 0; y < h; ++y) std::memcpy(&flipped[y * w * 3], &rgb[(h - 1 - y) * w * 3], w * 3);
  bind();
  return flipped;
}

bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb, std::string& why) {
  // beside the old file, then renamed: a failed write loses nothing
  const std::string tmp = path + ".part";
  if (stbi_write_png(tmp.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
    why = "cannot write the file";
    return false;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    why = ec.message();
    return false;
  }
  return true;
}

bool readPng(const std::string& path, int& width, int& height, std::vector<std::uint8_t>& rgb, std::string& why) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (data == nullptr) {
    why = stbi_failure_reason() != nullptr ? stbi_failure_reason() : "cannot read the picture";
    return false;
  }
  rgb.assign(data, data + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  stbi_image_free(data);
  return true;
}

}  // namespace gdpn::render
