#pragma once
/// \file
/// Elevation grids for Terrain nodes, read through GDAL: GeoTIFF and the other DEM formats,
/// and greyscale images (PNG).

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

}  // namespace gdpn::scene
