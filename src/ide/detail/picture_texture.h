#pragma once
// A camera sensor's picture as a texture that ImGui shows: uploaded again only when the
// picture changes. Needs a current OpenGL context for its whole life.

#include <cstdint>
#include <memory>

#include "gdpn/sensors/hub.h"

namespace gdpn::ide {

/// The picture the inspector shows of a selected camera sensor.
class PictureTexture {
 public:
  PictureTexture() = default;
  ~PictureTexture();
  PictureTexture(const PictureTexture&) = delete;
  PictureTexture& operator=(const PictureTexture&) = delete;
  /// Holds `picture` (kept alive while shown): RGB as it is, depth as grey from `near` (white)
  /// to `far` (black), metres.
  void show(const std::shared_ptr<const sensors::Image>& picture, double near, double far);
  /// The texture, for ImGui::Image (0 before any picture).
  [[nodiscard]] std::uintptr_t texture() const { return texture_; }

 private:
  std::shared_ptr<const sensors::Image> shown_;
  unsigned texture_ = 0;
};

}  // namespace gdpn::ide
