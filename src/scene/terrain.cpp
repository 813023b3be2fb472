#include "gdpn/scene/terrain.h"

#include <gdal.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "gdpn/core/file.h"

namespace gdpn::scene {

std::optional<HeightGrid> loadHeightGrid(const std::string& path, std::string& why) {
  // a regular file within the input limit: GDAL would read a FIFO or /dev/zero forever
  if (!core::inputFileSize(path, why)) return std::nullopt;
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
  // GDAL reports through a handler; keep its last message for ours
  CPLPushErrorHandler(CPLQuietErrorHandler);
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  if (!ds) {
    why = CPLGetLastErrorMsg()[0] ? CPLGetLastErrorMsg() : "not a raster GDAL can read";
    CPLPopErrorHandler();
    return std::nullopt;
  }
  std::optional<HeightGrid> grid;
  const int nx = GDALGetRasterXSize(ds), ny = GDALGetRasterYSize(ds);
  if (GDALGetRasterCount(ds) < 1) {
    why = "the raster has no band";
  } else if (nx < 2 || ny < 2 || static_cast<long long>(nx) * ny > 64LL * 1024 * 1024) {
    why = "the raster is " + std::to_string(nx) + " x " + std::to_string(ny) +
          " samples; a terrain needs 2 to 64 M samples, at least 2 each way";
  } else {
    HeightGrid g;
    g.nx = nx;
    g.ny = ny;
    g.height.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    const CPLErr err = GDALRasterIO(band, GF_Read, 0, 0, nx, ny, g.height.data(), nx, ny, GDT_Float64, 0, 0);
    // a height that is no number would reach the physics as one (NaN or infinite contacts)
    const auto bad = std::find_if(g.height.begin(), g.height.end(), [](double h) { return !std::isfinite(h); });
    if (err != CE_None) {
      why = CPLGetLastErrorMsg()[0] ? CPLGetLastErrorMsg() : "reading the raster failed";
    } else if (bad != g.height.end()) {
      const auto at = static_cast<std::size_t>(bad - g.height.begin());
      why = "the height at column " + std::to_string(at % static_cast<std::size_t>(nx)) + ", row " +
            std::to_string(at / static_cast<std::size_t>(nx)) + " (from 0) is " + (std::isnan(*bad) ? "NaN" : "infinite") +
            "; every sample must be a finite number";
    } else {
      grid = std::move(g);
    }
  }
  GDALClose(ds);
  CPLPopErrorHandler();
  return grid;
}

}  // namespace gdpn::scene
