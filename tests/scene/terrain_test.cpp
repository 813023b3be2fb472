// Elevation files: what is not a regular file within the input limit never reaches GDAL (which
// would read /dev/zero or wait on a FIFO for ever).

#include "gdpn/scene/terrain.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "gdpn/core/file.h"

namespace gdpn::scene {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  std::string why;
  EXPECT_FALSE(loadHeightGrid(path, why)) << path;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0) << path;
  return why;
}

TEST(TerrainFile, OnlyRegularFilesWithinTheLimitReachGdal) {
  EXPECT_EQ(refusal("/dev/zero"), "is a character device, not a regular file");
  const auto dir = fs::temp_directory_path() / ("gdpn_terrain_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto fifo = (dir / "pipe.tif").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refusal(fifo), "is a FIFO, not a regular file");
  const auto big = (dir / "big.tif").string();
  std::ofstream{big};
  fs::resize_file(big, std::uintmax_t{1} << 30);
  EXPECT_EQ(refusal(big), "the file is 1024 MiB; gdpn reads input files of at most 256 MiB");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gdpn::scene
