#pragma once
// Test support: a picture compared with its golden picture, with the tolerance every picture
// test uses (rasteriser differences between machines). GDPN_UPDATE_GOLDEN=1 rewrites the
// golden instead.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "gdpn/platform/png.h"

namespace gdpn::testing {

/// Expects the RGB picture `rgb` (`width` x `height`) to look like the PNG at `golden`: at most
/// 0.5 % of pixels off by more than 24 in a channel, and a mean difference under 1.5.
inline void expectLikeGolden(int width, int height, const std::vector<std::uint8_t>& rgb, const std::string& golden) {
  std::string error;
  if (std::getenv("GDPN_UPDATE_GOLDEN") != nullptr) {
    EXPECT_TRUE(platform::writePng(golden, width, height, rgb, error)) << error;
    return;
  }
  int gw = 0, gh = 0;
  std::vector<std::uint8_t> g;
  ASSERT_TRUE(platform::readPng(golden, gw, gh, g, error)) << golden << ": " << error;
  EXPECT_EQ(gw, width);
  EXPECT_EQ(gh, height);
  if (g.size() != rgb.size()) return;
  std::size_t off = 0;
  double total = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int{rgb[i + c]} - int{g[i + c]});
      worst = std::max(worst, d);
      total += d;
    }
    off += worst > 24 ? 1 : 0;
  }
  const double pixels = static_cast<double>(rgb.size() / 3);
  EXPECT_LE(static_cast<double>(off) / pixels, 0.005) << golden << ": " << off << " pixels differ";
  EXPECT_LE(total / static_cast<double>(rgb.size()), 1.5) << golden;
}

}  // namespace gdpn::testing
