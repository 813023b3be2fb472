#pragma once
/// \file
/// Elevation grids for Terrain nodes, read through GDAL: GeoTIFF and the other DEM formats,
/// and greyscale images (PNG).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gdpn::scene {

/// A grid of heights: nx columns (along x) by ny rows; row 0 is the first row of the file
/// (north, +y), heights in the file's units.
struct HeightGrid {
  int nx = 0;                  ///< samples along x
  int ny = 0;                  ///< samples along y
  std::vector<double> height;  ///< nx * ny values, row by row
};

/// Reads band 1 of the raster at `path`. On failure, nullopt and `why` says what went wrong
/// (a sample that is NaN or infinite is one: `why` names its column and row, from 0).
std::optional<HeightGrid> loadHeightGrid(const std::string& path, std::string& why);

/// The georeference of an elevation file as a Terrain node lays it out (`width` x `depth` m,
/// centred on the node's origin, the first sample of the first row at (-width/2, +depth/2)):
/// points of the terrain's frame to latitude and longitude on WGS 84.
class Geodesy {
 public:
  /// The georeference of the raster at `path`; null with `why` when it cannot be read or has
  /// none (no coordinate system, or no geotransform).
  static std::unique_ptr<Geodesy> open(const std::string& path, double width, double depth, std::string& why);
  ~Geodesy();
  Geodesy(const Geodesy&) = delete;
  Geodesy& operator=(const Geodesy&) = delete;
  /// Latitude and longitude, degrees, of the point (`x`, `y`) m of the terrain's frame; false
  /// when the projection cannot take it.
  bool toGeodetic(double x, double y, double& latitude, double& longitude) const;

 private:
  Geodesy() = default;
  std::array<double, 6> transform_{};  // GDAL's geotransform: pixel and line to projected x, y
  double width_ = 0, depth_ = 0;       // m
  int nx_ = 0, ny_ = 0;                // samples
  void* to_wgs84_ = nullptr;           // OGRCoordinateTransformationH
};

}  // namespace gdpn::scene
