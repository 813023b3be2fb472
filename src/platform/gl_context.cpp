#include "gdpn/platform/gl_context.h"

#include <epoxy/gl.h>

namespace gdpn::platform {

std::string GlContext::renderer() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s != nullptr ? s : "";
}

}  // namespace gdpn::platform
