#include "gdpn/platform/target.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>

namespace gdpn::platform {

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

std::vector<float> Target::readDepth() {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  const auto w = static_cast<std::size_t>(width_), h = static_cast<std::size_t>(height_);
  std::vector<float> depth(w * h), flipped(w * h);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  for (std::size_t y = 0; y < h; ++y) std::memcpy(&flipped[y * w], &depth[(h - 1 - y) * w], w * sizeof(float));
  bind();
  return flipped;
}

}  // namespace gdpn::platform
