// Elevation files: what is not a regular file within the input limit never reaches GDAL (which
// would read /dev/zero or wait on a FIFO for ever); GDAL is loaded only when one is read.

#include "gdpn/scene/terrain.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/core/file.h"
#include "support/scratch.h"
#include "support/temp_files.h"

namespace gdpn::scene {
namespace {

namespace fs = std::filesystem;

class TerrainFile : public testing::TempDirTest {};

/// The reason loadHeightGrid refuses `path` for, which it must give within seconds.
std::string refusal(const std::string& path) {
  std::string why;
  EXPECT_LT(testing::secondsFor([&] { EXPECT_FALSE(loadHeightGrid(path, why)) << path; }), 5.0) << path;
  return why;
}

TEST_F(TerrainFile, OnlyRegularFilesWithinTheLimitReachGdal) {
  EXPECT_EQ(refusal("/dev/zero"), "is a character device, not a regular file");
  const auto fifo = (dir_ / "pipe.tif").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refusal(fifo), "is a FIFO, not a regular file");
  const auto big = write("big.tif", "");
  fs::resize_file(big, std::uintmax_t{1} << 30);
  EXPECT_EQ(refusal(big), "the file is 1024 MiB; gdpn reads input files of at most 256 MiB");
}

/// Whether a library whose file name holds `name` is mapped into this process.
bool mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  std::stringstream text;
  text << maps.rdbuf();
  return text.str().find(name) != std::string::npos;
}

TEST(TerrainLibrary, GdalIsLoadedWhenTheFirstElevationFileIsRead) {
  // its hundred libraries cost every program's start 0.1 s; only a terrain needs them
  EXPECT_FALSE(mapped("libgdal")) << "before any terrain was read";
  std::string why;
  const auto grid = loadHeightGrid(std::string(GDPN_SOURCE_DIR) + "/examples/vehicles/terrain.png", why);
  ASSERT_TRUE(grid) << why;
  EXPECT_GT(grid->nx, 1);
  EXPECT_TRUE(mapped("libgdal"));
}

const std::string kElevation = std::string(GDPN_SOURCE_DIR) + "/tests/data/elevation/";

/// Expects the elevation file `name` of the test data to hold `nx` x `ny` heights, `rows`.
void expectGrid(const std::string& name, int nx, int ny, const std::vector<double>& rows) {
  std::string why;
  const auto grid = loadHeightGrid(kElevation + name, why);
  ASSERT_TRUE(grid) << why;
  EXPECT_EQ(grid->nx, nx);
  EXPECT_EQ(grid->ny, ny);
  EXPECT_EQ(grid->height, rows);
}

TEST(TerrainGrid, AnAsciiGridIsReadRowByRowFromTheNorth) {
  expectGrid("grid.asc", 4, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
}

TEST(TerrainGrid, ATiffOfFloatsKeepsItsFractionsAndHasNoGeoreference) {
  expectGrid("floats.tif", 3, 2, {1.0, 2.5, 3.0, 4.0, 5.5, 6.0});
  std::string why;
  EXPECT_FALSE(Geodesy::open(kElevation + "floats.tif", 20.0, 10.0, why));
  EXPECT_EQ(why, "it is not georeferenced (no coordinate system or no geotransform)");
}

TEST(TerrainGrid, ARasterWhoseBlockWouldTakeGigabytesIsRefusedBeforeItIsRead) {
  // 137 bytes the fuzz target found: GDAL would allocate 9 GB for the first block
  std::string why;
  EXPECT_FALSE(loadHeightGrid(kElevation + "interleaved-65281-bands.tif", why));
  EXPECT_EQ(why,
            "reading one block of the raster (37123 x 1 samples of 65281 bands, 4 bytes each) takes 9244 MiB; "
            "gdpn reads blocks of at most 256 MiB");
}

/// The length, m, of the meridian on WGS 84 from the equator to latitude `phi` (radians):
/// the series in the eccentricity to its sixth power (within a millimetre).
double meridianArc(double phi) {
  const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f), e4 = e2 * e2, e6 = e4 * e2;
  return a * ((1 - e2 / 4 - 3 * e4 / 64 - 5 * e6 / 256) * phi - (3 * e2 / 8 + 3 * e4 / 32 + 45 * e6 / 1024) * std::sin(2 * phi) +
              (15 * e4 / 256 + 45 * e6 / 1024) * std::sin(4 * phi) - (35 * e6 / 3072) * std::sin(6 * phi));
}

/// After TerrainLibrary's test in the file: the first to load GDAL must come after it.
class TerrainGeoreference : public testing::TempDirTest {};

TEST_F(TerrainGeoreference, AGridInUtmLiesWhereItsCoordinatesSay) {
  // grid.asc in UTM zone 32N (its .prj beside it): 4 x 3 samples 10 m apart, the lower left
  // corner at easting 500 000 m, northing 5 400 000 m. A terrain 30 x 20 m spans the samples'
  // centres; (-20, 10) m lies at the upper left corner of the first sample's cell: easting
  // 500 000 m, on zone 32's central meridian (9 degrees east), northing 5 400 025 m (the
  // sample's centre, half a cell below the top at 5 400 030 m), which UTM makes the meridian's
  // length to the latitude times 0.9996
  const std::string both = testing::fileBytes(kElevation + "georeferenced.asc");
  const auto cut = both.find("--prj--\n");
  ASSERT_NE(cut, std::string::npos);
  const auto grid = write("grid.asc", both.substr(0, cut));
  write("grid.prj", both.substr(cut + 8));
  std::string why;
  const auto geo = Geodesy::open(grid, 30.0, 20.0, why);
  ASSERT_TRUE(geo) << why;
  double latitude = 0.0, longitude = 0.0;
  ASSERT_TRUE(geo->toGeodetic(-20.0, 10.0, latitude, longitude));
  EXPECT_NEAR(longitude, 9.0, 1e-9);
  EXPECT_NEAR(meridianArc(latitude * M_PI / 180) * 0.9996, 5'400'025.0, 0.01) << latitude;
  // 10 m east along the row: the next sample's cell, east of the meridian at the same height
  ASSERT_TRUE(geo->toGeodetic(-10.0, 10.0, latitude, longitude));
  EXPECT_GT(longitude, 9.0);
  EXPECT_NEAR((longitude - 9.0) * M_PI / 180 * 6'378'137.0 * std::cos(latitude * M_PI / 180), 10.0 / 0.9996, 0.05);
}

}  // namespace
}  // namespace gdpn::scene
