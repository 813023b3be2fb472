#include "gdpn/platform/png.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "gdpn/core/output_file.h"

namespace gdpn::platform {

bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb, std::string& why) {
  // encoded in memory, then written beside the old file and renamed: a failed write loses nothing
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3 ||
      stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3) == 0) {
    why = "cannot encode the picture as PNG";
    return false;
  }
  return core::writeOutput(path, png, why);
}

bool readPng(const std::string& path, int& width, int& height, std::vector<std::uint8_t>& rgb, std::string& why) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (data == nullptr) {
    why = stbi_failure_reason() != nullptr ? stbi_failure_reason() : "cannot read the picture";
    return false;
  }
  rgb.assign(data, data + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  stbi_image_free(data);
  return true;
}

}  // namespace gdpn::platform
