// Elevation files: what is not a regular file within the input limit never reaches GDAL (which
// would read /dev/zero or wait on a FIFO for ever).

#include "gdpn/scene/terrain.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

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

}  // namespace
}  // namespace gdpn::scene
