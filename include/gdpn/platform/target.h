#pragma once
/// \file
/// An offscreen render target: a framebuffer whose picture can be read back.

#include <cstdint>
#include <vector>

namespace gdpn::platform {

/// An offscreen framebuffer with colour and depth, multisampled when asked; needs a current
/// context for its whole life.
class Target {
 public:
  /// A `width` x `height` pixel target with `samples` samples per pixel (1: none); bound.
  Target(int width, int height, int samples = 4);
  ~Target();
  Target(const Target&) = delete;
  Target& operator=(const Target&) = delete;
  /// Draws go here from now on.
  void bind();
  /// The picture, RGB, top row first (3 bytes per pixel).
  [[nodiscard]] std::vector<std::uint8_t> readRgb();
  /// The depth buffer, top row first, each in [0, 1] (a target of one sample only).
  [[nodiscard]] std::vector<float> readDepth();
  /// Pixels across.
  [[nodiscard]] int width() const { return width_; }
  /// Pixels down.
  [[nodiscard]] int height() const { return height_; }

 private:
  int width_, height_, samples_;
  unsigned fbo_ = 0, color_ = 0, depth_ = 0;  // drawn into (multisampled when samples_ > 1)
  unsigned resolve_fbo_ = 0, resolve_color_ = 0;
};

}  // namespace gdpn::platform
