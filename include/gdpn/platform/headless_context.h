#pragma once
/// \file
/// A context with no window: EGL surfaceless (Mesa's llvmpipe when there is no GPU), so no
/// display is needed. What `gdpn render`, `gdpn record` and the tests draw in.

#include <memory>
#include <string>

#include "gdpn/platform/gl_context.h"

namespace gdpn::platform {

/// An OpenGL 3.3 core context with no window, current on this thread. Null with `why` when
/// EGL or the driver refuses.
std::unique_ptr<GlContext> createHeadlessContext(std::string& why);

/// Keeps the EGL context current on this thread when made (none is fine) and makes it current
/// again when gone: drawing in a context of one's own without taking the caller's away.
class KeptContext {
 public:
  KeptContext();
  ~KeptContext();
  KeptContext(const KeptContext&) = delete;
  KeptContext& operator=(const KeptContext&) = delete;

 private:
  void* display_;
  void* context_;
  void* draw_;
  void* read_;
};

}  // namespace gdpn::platform
