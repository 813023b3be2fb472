#pragma once
// Where the world view draws: a multisampled framebuffer resolved into a texture that ImGui
// shows as an image. Needs a current OpenGL context for its whole life.

#include <cstdint>

namespace gdpn::ide {

/// An offscreen picture the world view draws into and ImGui shows.
class WorldTexture {
 public:
  WorldTexture() = default;
  ~WorldTexture();
  WorldTexture(const WorldTexture&) = delete;
  WorldTexture& operator=(const WorldTexture&) = delete;
  /// Makes it `width` x `height` pixels with `samples` samples each (kept when already so) and
  /// binds it for drawing, remembering the framebuffer and viewport that were bound.
  void begin(int width, int height, int samples);
  /// Resolves the picture into the texture and binds back what begin() found.
  void end();
  /// The texture, for ImGui::Image.
  [[nodiscard]] std::uintptr_t texture() const { return texture_; }

 private:
  void release();
  int width_ = 0, height_ = 0, samples_ = 0;
  unsigned fbo_ = 0, color_ = 0, depth_ = 0, resolve_fbo_ = 0, texture_ = 0;
  int previous_fbo_ = 0;
  int previous_viewport_[4] = {0, 0, 0, 0};
};

}  // namespace gdpn::ide
