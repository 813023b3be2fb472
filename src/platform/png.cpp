#include "gdpn/platform/png.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <filesystem>

namespace gdpn::platform {

bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb, std::string& why) {
  // beside the old file, then renamed: a failed write loses nothing
  const std::string tmp = path + ".part";
  if (stbi_write_png(tmp.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
    why = "cannot write the file";
    return false;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    why = ec.message();
    return false;
  }
  return true;
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
