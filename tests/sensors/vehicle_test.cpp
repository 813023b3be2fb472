// A vehicle follows a gradient field over a terrain read from a GeoTIFF the test makes.

#include <gdal.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/scene/terrain.h"

namespace gdpn::model {
namespace {

namespace fs = std::filesystem;

/// A 33 x 33 GeoTIFF of gentle hills (up to 0.4 m).
void writeHills(const std::string& path) {
  GDALAllRegister();
  GDALDriverH tiff = GDALGetDriverByName("GTiff");
  ASSERT_NE(tiff, nullptr);
  GDALDatasetH ds = GDALCreate(tiff, path.c_str(), 33, 33, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  std::vector<float> h(33 * 33);
  for (int j = 0; j < 33; ++j) {
    for (int i = 0; i < 33; ++i) {
      h[static_cast<std::size_t>(j * 33 + i)] = static_cast<float>(0.2 + 0.2 * std::sin(i * 0.4) * std::cos(j * 0.3));
    }
  }
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 33, 33, h.data(), 33, 33, GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
}

/// 5 x 5 vectors of 1.5 m/s pointing at `goal` from each grid point of a 20 m field.
std::string fieldTowards(double gx, double gy) {
  std::string v;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const double x = -10 + 5.0 * i, y = -10 + 5.0 * j;
      const double dx = gx - x, dy = gy - y, l = std::max(1e-9, std::hypot(dx, dy));
      v += (v.empty() ? "" : ", ") + core::formatDouble(1.5 * dx / l) + ", " + core::formatDouble(1.5 * dy / l);
    }
  }
  return "[" + v + "]";
}

TEST(Vehicle, FollowsTheGradientFieldOverTheTerrainToItsGoal) {
  const fs::path dir = fs::temp_directory_path() / ("gdpn_vehicle_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  writeHills((dir / "hills.tif").string());
  const std::string model = R"Y(gdpn: 1
settings: {dt: 0.01, until: 30}
scene:
  - Terrain: {name: ground, file: hills.tif, width: 20, depth: 20}
  - GradientField: {name: guide, width: 20, depth: 20, nx: 5, ny: 5, vectors: )Y" + fieldTowards(6, 6) + R"Y(}
  - Transform: {name: goal, translation: [6, 6, 0.5], children: [{Region: {name: zone, size: [1, 1, 3]}}]}
  - Transform:
      name: car
      translation: [-6, -6, 1]
      children:
        - Body:
            name: body
            mass: 5
            children:
              - Cube: {size: [0.4, 0.3, 0.2]}
              - GradientSensor: {name: compass}
pages:
  main:
    places:
      steer:
        sensors: {c0: car/body/compass}
        on_sample: |
          body = sim.node("car/body")
          vx, vy, _ = value.vector
          _, _, vz = body.velocity
          body.set_velocity((vx, vy, vz))
      arrival:
        sensors: {c1: goal/zone}
        on_enter: |
          if item.name == "car/body":  # the zone also holds the ground it stands on
              sim.stop("arrived with " + item.name)
)Y";
  std::ofstream(dir / "vehicle.gdpn.yaml") << model;
  core::Diagnostics diags;
  auto m = loadModel((dir / "vehicle.gdpn.yaml").string(), diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::Stopped) << outcome.message;
  EXPECT_EQ(outcome.message, "arrived with car/body");
  // about 17 m at 1.5 m/s
  EXPECT_LT(outcome.time, 15.0);
  const auto p = sim->plant()->find("car/body")->world.position;
  EXPECT_NEAR(p.x, 6.0, 1.0);
  EXPECT_NEAR(p.y, 6.0, 1.0);
  EXPECT_LT(p.z, 1.0);  // it drove on the ground, not above it
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(Terrain, AGreyscalePngServesAsElevation) {
  // a 4 x 3 greyscale PNG made through GDAL's MEM and PNG drivers
  const std::string path = (fs::temp_directory_path() / ("gdpn_grey_" + std::to_string(::getpid()) + ".png")).string();
  GDALAllRegister();
  GDALDatasetH mem = GDALCreate(GDALGetDriverByName("MEM"), "", 4, 3, 1, GDT_Byte, nullptr);
  std::vector<unsigned char> px = {0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 255};
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(mem, 1), GF_Write, 0, 0, 4, 3, px.data(), 4, 3, GDT_Byte, 0, 0), CE_None);
  GDALDatasetH png = GDALCreateCopy(GDALGetDriverByName("PNG"), path.c_str(), mem, 0, nullptr, nullptr, nullptr);
  ASSERT_NE(png, nullptr);
  GDALClose(png);
  GDALClose(mem);
  std::string why;
  const auto grid = scene::loadHeightGrid(path, why);
  ASSERT_TRUE(grid) << why;
  EXPECT_EQ(grid->nx, 4);
  EXPECT_EQ(grid->ny, 3);
  EXPECT_EQ(grid->height.front(), 0.0);
  EXPECT_EQ(grid->height.back(), 255.0);
  fs::remove(path);
}

}  // namespace
}  // namespace gdpn::model
