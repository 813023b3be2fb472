// Elevation files: what is not a regular file within the input limit never reaches GDAL (which
// would read /dev/zero or wait on a FIFO for ever); GDAL is loaded only when one is read.

#include "gdpn/scene/terrain.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/core/file.h"
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

}  // namespace
}  // namespace gdpn::scene
