#include "gdpn/scene/terrain.h"

#include <algorithm>
#include <cmath>

#include "detail/gdal_library.h"
#include "gdpn/core/assert.h"
#include "gdpn/core/file.h"

namespace gdpn::scene {

namespace {

using detail::GdalLibrary;

/// GDAL, already loaded: a Geodesy is only made through it.
const GdalLibrary& loadedGdal() {
  std::string why;
  const GdalLibrary* g = detail::gdal(why);
  GDPN_ASSERT(g, "GDAL used before it was loaded");
  return *g;
}

/// The message of GDAL's last error, or `otherwise` when it gave none.
std::string lastError(const GdalLibrary& g, const char* otherwise) {
  return g.lastErrorMsg()[0] ? g.lastErrorMsg() : otherwise;
}

/// The raster at `path` and GDAL in `g`, GDAL's errors kept quiet (pop the handler after
/// closing it); null with `why`, the handler popped, when it cannot be opened.
GDALDatasetH openRaster(const std::string& path, const GdalLibrary*& g, std::string& why) {
  // a regular file within the input limit: GDAL would read a FIFO or /dev/zero forever
  if (!core::inputFileSize(path, why)) return nullptr;
  g = detail::gdal(why);
  if (!g) return nullptr;
  // GDAL reports through a handler; keep its last message for ours
  g->pushErrorHandler(g->quietErrorHandler);
  GDALDatasetH ds = g->open(path.c_str(), GA_ReadOnly);
  if (!ds) {
    why = lastError(*g, "not a raster GDAL can read");
    g->popErrorHandler();
  }
  return ds;
}

/// The most bytes GDAL may allocate to read one block of a raster.
constexpr double kMostBlockBytes = 256.0 * 1024 * 1024;

/// Why reading the first band of `ds` (with `bands` bands) would take too much memory, or
/// empty. GDAL reads a raster a block at a time, and a file whose samples interleave the bands
/// holds all of them in one block: a header of a few bytes can ask for gigabytes.
std::string oversizedBlock(const GdalLibrary& g, GDALDatasetH ds, int bands) {
  GDALRasterBandH band = g.rasterBand(ds, 1);
  int bx = 0, by = 0;
  g.blockSize(band, &bx, &by);
  const int sample = std::max(1, g.dataTypeSizeBytes(g.rasterDataType(band)));
  const double bytes = static_cast<double>(bx) * by * sample * bands;
  if (bytes <= kMostBlockBytes) return {};
  return "reading one block of the raster (" + std::to_string(bx) + " x " + std::to_string(by) + " samples of " +
         std::to_string(bands) + (bands == 1 ? " band" : " bands") + ", " + std::to_string(sample) + " bytes each) takes " +
         std::to_string(static_cast<long long>(bytes / (1024 * 1024))) + " MiB; gdpn reads blocks of at most " +
         std::to_string(static_cast<long long>(kMostBlockBytes / (1024 * 1024))) + " MiB";
}

}  // namespace

std::unique_ptr<Geodesy> Geodesy::open(const std::string& path, double width, double depth, std::string& why) {
  const GdalLibrary* gd = nullptr;
  GDALDatasetH ds = openRaster(path, gd, why);
  if (!ds) return nullptr;
  std::unique_ptr<Geodesy> g(new Geodesy);
  g->width_ = width;
  g->depth_ = depth;
  g->nx_ = gd->rasterXSize(ds);
  g->ny_ = gd->rasterYSize(ds);
  const char* wkt = gd->projectionRef(ds);
  if (gd->geoTransform(ds, g->transform_.data()) != CE_None || !wkt || !*wkt) {
    why = "it is not georeferenced (no coordinate system or no geotransform)";
    g.reset();
  } else {
    OGRSpatialReferenceH from = gd->newSpatialReference(wkt), to = gd->newSpatialReference(nullptr);
    gd->importFromEPSG(to, 4326);
    // longitude first, latitude second, whatever the authorities' axis order
    gd->setAxisMappingStrategy(from, OAMS_TRADITIONAL_GIS_ORDER);
    gd->setAxisMappingStrategy(to, OAMS_TRADITIONAL_GIS_ORDER);
    g->to_wgs84_ = gd->newCoordinateTransformation(from, to);
    gd->destroySpatialReference(from);
    gd->destroySpatialReference(to);
    if (!g->to_wgs84_) {
      why = "its coordinate system cannot be converted to latitude and longitude";
      g.reset();
    }
  }
  gd->close(ds);
  gd->popErrorHandler();
  return g;
}

Geodesy::~Geodesy() {
  if (to_wgs84_) loadedGdal().destroyCoordinateTransformation(static_cast<OGRCoordinateTransformationH>(to_wgs84_));
}

bool Geodesy::toGeodetic(double x, double y, double& latitude, double& longitude) const {
  // the samples span the terrain edge to edge: sample i lies at -width/2 + i * width/(nx-1),
  // and GDAL's pixel i covers [i, i+1), its centre at i + 0.5
  const double col = 0.5 + (x + width_ / 2) / width_ * (nx_ - 1);
  const double row = 0.5 + (depth_ / 2 - y) / depth_ * (ny_ - 1);
  const auto& t = transform_;
  double px = t[0] + col * t[1] + row * t[2], py = t[3] + col * t[4] + row * t[5];
  // a point the projection cannot take is a false answer, not a line of GDAL's on stderr
  const GdalLibrary& gd = loadedGdal();
  gd.pushErrorHandler(gd.quietErrorHandler);
  const bool ok = gd.transform(static_cast<OGRCoordinateTransformationH>(to_wgs84_), 1, &px, &py, nullptr);
  gd.popErrorHandler();
  if (!ok) return false;
  longitude = px;
  latitude = py;
  return std::isfinite(px) && std::isfinite(py);
}

std::optional<HeightGrid> loadHeightGrid(const std::string& path, std::string& why) {
  const GdalLibrary* gd = nullptr;
  GDALDatasetH ds = openRaster(path, gd, why);
  if (!ds) return std::nullopt;
  std::optional<HeightGrid> grid;
  const int nx = gd->rasterXSize(ds), ny = gd->rasterYSize(ds), bands = gd->rasterCount(ds);
  if (bands < 1) {
    why = "the raster has no band";
  } else if (const std::string big = oversizedBlock(*gd, ds, bands); !big.empty()) {
    why = big;
  } else if (nx < 2 || ny < 2 || static_cast<long long>(nx) * ny > 64LL * 1024 * 1024) {
    why = "the raster is " + std::to_string(nx) + " x " + std::to_string(ny) +
          " samples; a terrain needs 2 to 64 M samples, at least 2 each way";
  } else {
    HeightGrid g;
    g.nx = nx;
    g.ny = ny;
    g.height.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    GDALRasterBandH band = gd->rasterBand(ds, 1);
    const CPLErr err = gd->rasterIO(band, GF_Read, 0, 0, nx, ny, g.height.data(), nx, ny, GDT_Float64, 0, 0);
    // a height that is no number would reach the physics as one (NaN or infinite contacts)
    const auto bad = std::find_if(g.height.begin(), g.height.end(), [](double h) { return !std::isfinite(h); });
    if (err != CE_None) {
      why = lastError(*gd, "reading the raster failed");
    } else if (bad != g.height.end()) {
      const auto at = static_cast<std::size_t>(bad - g.height.begin());
      why = "the height at column " + std::to_string(at % static_cast<std::size_t>(nx)) + ", row " +
            std::to_string(at / static_cast<std::size_t>(nx)) + " (from 0) is " + (std::isnan(*bad) ? "NaN" : "infinite") +
            "; every sample must be a finite number";
    } else {
      grid = std::move(g);
    }
  }
  gd->close(ds);
  gd->popErrorHandler();
  return grid;
}

}  // namespace gdpn::scene
