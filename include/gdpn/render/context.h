#pragma once
/// \file
/// OpenGL contexts and render targets. A headless context is EGL surfaceless (Mesa's
/// llvmpipe when there is no GPU): no display is needed.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gdpn::render {

/// An OpenGL 3.3 core context, current on the thread that made it.
class GlContext {
 public:
  /// A context with no window. Null with `why` when EGL or the driver refuses.
  static std::unique_ptr<GlContext> createHeadless(std::string& why);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  /// Makes it current on this thread.
  void makeCurrent();
  /// The driver's name for itself ("llvmpipe (LLVM 15.0.6, 256 bits)", ...).
  [[nodiscard]] std::string renderer() const;

 private:
  GlContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
};

/// An offscreen framebuffer with colour and depth, multisampled when asked; needs a current
/// context.
class Target {
 public:
  /// A `width` x `height` pixel target with `samples` samples per pixel (1: none).
  Target(int width, int height, int samples = 4);
  ~Target();
  Target(const Target&) = delete;
  Target& operator=(const Target&) = delete;
  /// Draws go here from now on.
  void bind();
  /// The picture, RGB, top row first (3 bytes per pixel).
  [[nodiscard]] std::vector<std::uint8_t> readRgb();
  /// Pixels across.
  [[nodiscard]] int width() const { return width_; }
  /// Pixels down.
  [[nodiscard]] int height() const { return height_; }

 private:
  int width_, height_, samples_;
  unsigned fbo_ = 0, color_ = 0, depth_ = 0;  // drawn into (multisampled when samples_ > 1)
  unsigned resolve_fbo_ = 0, resolve_color_ = 0;
};

/// Writes an RGB picture (top row first) as PNG; false with `why` on failure.
bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb, std::string& why);
/// Reads a PNG as RGB (top row first); false with `why` on failure.
bool readPng(const std::string& path, int& width, int& height, std::vector<std::uint8_t>& rgb, std::string& why);

}  // namespace gdpn::render
