// libFuzzer target: any bytes as an elevation file must give a grid of finite heights or a
// reason, never a crash, a hang, unbounded memory or a sanitizer report; the same for its
// georeference. The bytes' opening picks the extension GDAL is shown (as the seeds have it):
// an ESRI ASCII grid, a TIFF, a PNG, else XYZ text. What follows a line "--prj--" becomes the
// grid's .prj file beside it (its coordinate system), so that mutations reach the georeference
// too.

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include "gdpn/core/file.h"
#include "gdpn/scene/terrain.h"

namespace {

/// The extension the file is given, from how it opens.
const char* extensionFor(std::string_view bytes) {
  struct Magic {
    std::string_view start;
    const char* ext;
  };
  static constexpr Magic kMagic[] = {{"ncols", ".asc"}, {"NCOLS", ".asc"}, {"II*", ".tif"}, {"MM", ".tif"}, {"\x89PNG", ".png"}};
  for (const auto& m : kMagic) {
    if (bytes.starts_with(m.start)) return m.ext;
  }
  return ".xyz";
}

void write(const std::string& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // no side files (.aux.xml) written next to the input, and a small block cache (GDAL's
  // default, a share of the machine's memory, would look like a leak)
  ::setenv("GDAL_PAM_ENABLED", "NO", 1);
  ::setenv("GDAL_CACHEMAX", "16", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // a folder of its own: GDAL looks at the files beside the one it opens
  static const std::string dir = [] {
    std::string d = "/tmp/gdpn_elevation_fuzz_XXXXXX";
    if (!::mkdtemp(d.data())) __builtin_trap();
    return d;
  }();
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::string_view prj;
  if (const auto at = bytes.find("\n--prj--\n"); at != std::string_view::npos) {
    prj = bytes.substr(at + 9);
    bytes = bytes.substr(0, at + 1);
  }
  const std::string stem = dir + "/grid";
  const std::string path = stem + extensionFor(bytes);
  write(path, bytes);
  if (!prj.empty()) write(stem + ".prj", prj);
  // a low limit, so that the size check is reached too
  static gdpn::core::InputLimit limit(48 * 1024);
  std::string why;
  const auto grid = gdpn::scene::loadHeightGrid(path, why);
  // a grid has at least 2 x 2 finite heights; a failure has a reason
  if (!grid && why.empty()) __builtin_trap();
  if (grid) {
    if (grid->nx < 2 || grid->ny < 2) __builtin_trap();
    if (grid->height.size() != static_cast<std::size_t>(grid->nx) * static_cast<std::size_t>(grid->ny)) __builtin_trap();
    for (const double h : grid->height) {
      if (!std::isfinite(h)) __builtin_trap();
    }
  }
  why.clear();
  const auto geo = gdpn::scene::Geodesy::open(path, 40.0, 30.0, why);
  if (!geo && why.empty()) __builtin_trap();
  if (geo) {
    double latitude = 0.0, longitude = 0.0;
    if (geo->toGeodetic(5.0, -5.0, latitude, longitude) && (!std::isfinite(latitude) || !std::isfinite(longitude))) {
      __builtin_trap();
    }
  }
  ::unlink(path.c_str());
  ::unlink((stem + ".prj").c_str());
  return 0;
}
