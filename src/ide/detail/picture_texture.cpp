// The inspector's picture of a camera sensor.

#include "picture_texture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

namespace gdpn::ide {

PictureTexture::~PictureTexture() {
  const GLuint tex = texture_;
  if (tex != 0) glDeleteTextures(1, &tex);
}

void PictureTexture::show(const std::shared_ptr<const sensors::Image>& picture, double near, double far) {
  if (!picture || picture == shown_) return;
  shown_ = picture;
  std::vector<std::uint8_t> grey;
  const std::uint8_t* pixels = picture->rgb.data();
  if (!picture->depth.empty()) {
    // near white, far black: the nearer, the brighter
    grey.resize(picture->depth.size() * 3);
    for (std::size_t i = 0; i < picture->depth.size(); ++i) {
      const double t = std::clamp((static_cast<double>(picture->depth[i]) - near) / (far - near), 0.0, 1.0);
      grey[3 * i] = grey[3 * i + 1] = grey[3 * i + 2] = static_cast<std::uint8_t>(255.0 * (1.0 - t) + 0.5);
    }
    pixels = grey.data();
  }
  if (texture_ == 0) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    texture_ = tex;
  }
  GLint unpack = 4;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpack);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 3 bytes a pixel
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, picture->width, picture->height, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  // a small picture shown large: its pixels, not a blur
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpack);
}

}  // namespace gdpn::ide
