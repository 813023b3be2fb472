// The world view's offscreen picture.

#include "world_texture.h"

#include <epoxy/gl.h>

namespace gdpn::ide {

WorldTexture::~WorldTexture() { release(); }

void WorldTexture::release() {
  if (fbo_ == 0) return;
  const GLuint buffers[] = {color_, depth_};
  glDeleteRenderbuffers(2, buffers);
  const GLuint fbos[] = {fbo_, resolve_fbo_};
  glDeleteFramebuffers(2, fbos);
  const GLuint tex = texture_;
  glDeleteTextures(1, &tex);
  fbo_ = color_ = depth_ = resolve_fbo_ = texture_ = 0;
}

void WorldTexture::begin(int width, int height, int samples) {
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_fbo_);
  glGetIntegerv(GL_VIEWPORT, previous_viewport_);
  if (width != width_ || height != height_ || samples != samples_ || fbo_ == 0) {
    release();
    width_ = width;
    height_ = height;
    samples_ = samples;
    // the multisampled picture
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glGenRenderbuffers(1, &color_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    // the texture it resolves into
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glGenFramebuffers(1, &resolve_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width, height);
}

void WorldTexture::end() {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_fbo_));
  glViewport(previous_viewport_[0], previous_viewport_[1], previous_viewport_[2], previous_viewport_[3]);
}

}  // namespace gdpn::ide
