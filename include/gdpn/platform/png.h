#pragma once
/// \file
/// PNG files of RGB pictures, as Target::readRgb gives them.

#include <cstdint>
#include <string>
#include <vector>

namespace gdpn::platform {

/// Writes an RGB picture (`width` x `height` pixels, top row first, 3 bytes per pixel) as PNG,
/// beside the old file and then renamed over it; false with `why` on failure (a full disk
/// included), the old file then unchanged.
bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb, std::string& why);
/// Reads a PNG as RGB (top row first, 3 bytes per pixel; `width` and `height` in pixels); false
/// with `why` on failure.
bool readPng(const std::string& path, int& width, int& height, std::vector<std::uint8_t>& rgb, std::string& why);

}  // namespace gdpn::platform
