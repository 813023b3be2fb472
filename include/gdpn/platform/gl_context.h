#pragma once
/// \file
/// An OpenGL context, whatever made it: the one thing the renderer needs from the platform is
/// a context current on its thread. Each platform makes its own (headless_context.h today, a
/// window's later) behind this interface.

#include <string>

namespace gdpn::platform {

/// An OpenGL 3.3 core context.
class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  /// Makes it current on this thread.
  virtual void makeCurrent() = 0;
  /// The driver's name for itself ("llvmpipe (LLVM 15.0.6, 256 bits)", ...); the context must
  /// be current.
  [[nodiscard]] std::string renderer() const;

 protected:
  GlContext() = default;
};

}  // namespace gdpn::platform
