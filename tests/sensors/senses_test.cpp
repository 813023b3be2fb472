// The sensors of issue 23 against analytic answers: an IMU at rest and on a turntable, a
// laser scan in a square room, a GPS on a moving body and over a georeferenced terrain, a
// contact sensor under a box, a force-torque sensor under a hanging arm, and seeded noise.

#include <gdal.h>
#include <cpl_conv.h>
#include <ogr_srs_api.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>

#include "rig.h"

namespace gdpn::sensors {
namespace {

constexpr double kG = 9.81;

TEST(Senses, AnImuAtRestReadsMinusGravityAlongItsUpAxisAndNoRotation) {
  // the IMU lies on its side: its +y is the world's up
  Rig rig(R"(
  - Joint:
      kind: fixed
      children:
        - Transform:
            translation: [0, 0, 1]
            rotation: [1, 0, 0, 90]
            children:
              - Body:
                  name: block
                  mass: 2
                  children: [{Cube: {size: [0.2, 0.2, 0.2]}}, {Imu: {name: imu, rate: 0}}]
)");
  const auto imu = rig.handle("#0/#0/block/imu");
  rig.hub->update(0);
  rig.run(0, 120, 0.01);
  const auto& r = rig.hub->reading(imu);
  EXPECT_TRUE(r.active);
  EXPECT_NEAR(r.vector("acceleration").x, 0, 1e-6);
  EXPECT_NEAR(r.vector("acceleration").y, kG, 1e-6);
  EXPECT_NEAR(r.vector("acceleration").z, 0, 1e-6);
  EXPECT_NEAR(r.vector("angular_velocity").length(), 0, 1e-6);
}

TEST(Senses, AnImuOnATurntableReadsItsRateAndTheCentripetalAcceleration) {
  // a disc turned by a motor at 90 deg/s about z; the IMU sits 0.5 m off the axis
  Rig rig(R"(
  - World: {gravity: [0, 0, 0]}
  - Joint:
      name: spindle
      kind: hinge
      axis1: [0, 0, 1]
      vel1: 90
      fmax1: 1000
      children:
        - Body:
            name: disc
            mass: 1
            children:
              - Cylinder: {radius: 1, height: 0.1}
              - Transform: {translation: [0.5, 0, 0], children: [{Imu: {name: imu, rate: 0}}]}
)");
  const auto imu = rig.handle("#1/disc/#1/imu");
  rig.hub->update(0);
  rig.run(0, 200, 0.005);
  const auto& r = rig.hub->reading(imu);
  const double w = std::numbers::pi / 2;
  EXPECT_NEAR(r.vector("angular_velocity").z, w, 1e-4);
  EXPECT_NEAR(r.vector("angular_velocity").x, 0, 1e-6);
  EXPECT_NEAR(r.vector("angular_velocity").y, 0, 1e-6);
  // towards the axis: -x in the IMU's frame, which turns with the disc
  EXPECT_NEAR(r.vector("acceleration").x, -w * w * 0.5, 1e-3);
  EXPECT_NEAR(r.vector("acceleration").y, 0, 1e-3);
}

TEST(Senses, ALaserScanInASquareRoomReadsTheDistancesToItsWalls) {
  // walls whose inner faces lie 2 m from the scanner on each side; 360 rays, one a degree
  Rig rig(R"(
  - Transform: {translation: [2.5, 0, 0], children: [{Cube: {size: [1, 6, 2]}}]}
  - Transform: {translation: [-2.5, 0, 0], children: [{Cube: {size: [1, 6, 2]}}]}
  - Transform: {translation: [0, 2.5, 0], children: [{Cube: {size: [6, 1, 2]}}]}
  - Transform: {translation: [0, -2.5, 0], children: [{Cube: {size: [6, 1, 2]}}]}
  - LaserScan: {name: lidar, count: 360, length: 10}
)");
  const auto lidar = rig.handle("lidar");
  rig.hub->update(0);
  const auto& r = rig.hub->reading(lidar);
  ASSERT_EQ(r.numbers("ranges").size(), 360u);
  for (std::size_t i = 0; i < 360; ++i) {
    const double a = (-180.0 + static_cast<double>(i)) * std::numbers::pi / 180;
    const double expected = 2.0 / std::max(std::abs(std::cos(a)), std::abs(std::sin(a)));
    EXPECT_NEAR(r.numbers("ranges")[i], expected, 1e-6) << "ray " << i;
  }
  EXPECT_NEAR(r.number("nearest"), 2.0, 1e-6);
}

TEST(Senses, ALaserScanSeesItsLengthWhereNothingIsAndSamplesAtItsRate) {
  Rig rig("  - LaserScan: {name: lidar, count: 3, min_angle: -45, max_angle: 45, length: 4, rate: 10}\n");
  const auto lidar = rig.handle("lidar");
  int samples = 0;
  for (int i = 0; i <= 100; ++i) {
    rig.hub->update(i * 0.01);
    samples += rig.hub->reading(lidar).active ? 1 : 0;
  }
  EXPECT_EQ(samples, 11);  // at 0, 0.1, ..., 1.0 s
  EXPECT_EQ(rig.hub->reading(lidar).numbers("ranges"), (std::vector<double>{4, 4, 4}));
}

TEST(Senses, AGpsFollowsABodyMovingAtAKnownVelocity) {
  Rig rig(R"(
  - World: {gravity: [0, 0, 0]}
  - Transform:
      translation: [1, 2, 3]
      children: [{Body: {name: rover, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}, {Gps: {name: gps, rate: 0}}]}}]
)");
  const auto gps = rig.handle("#1/rover/gps");
  rig.world->setVelocity(*rig.scene->find("#1/rover"), {0.5, -0.25, 1});
  rig.hub->update(0);
  const double t = rig.run(0, 200, 0.01);
  const auto& p = rig.hub->reading(gps).vector("position");
  EXPECT_NEAR(p.x, 1 + 0.5 * t, 1e-9);
  EXPECT_NEAR(p.y, 2 - 0.25 * t, 1e-9);
  EXPECT_NEAR(p.z, 3 + 1.0 * t, 1e-9);
}

TEST(Senses, AGeodeticGpsReadsLatitudeAndLongitudeFromTheTerrainsGeoreference) {
  // an 11 x 11 raster in latitude and longitude, 0.001 degrees a pixel, from 10 E, 50 N
  const auto dir = std::filesystem::temp_directory_path() / ("gdpn_gps_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), (dir / "map.tif").c_str(), 11, 11, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  double gt[6] = {10.0, 0.001, 0, 50.0, 0, -0.001};
  GDALSetGeoTransform(ds, gt);
  OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(wgs84, 4326);
  char* wkt = nullptr;
  OSRExportToWkt(wgs84, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(wgs84);
  std::vector<float> h(121, 0.0f);
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 11, 11, h.data(), 11, 11, GDT_Float32, 0, 0), CE_None);
  GDALClose(ds);
  Rig rig(R"(
  - World: {gravity: [0, 0, 0]}
  - Terrain: {name: ground, file: map.tif, width: 100, depth: 100}
  - Transform:
      translation: [50, -25, 7]
      children: [{Body: {name: rover, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}, {Gps: {name: gps, frame: geodetic}}]}}]
)", 1, dir.string());
  core::Diagnostics diags;
  EXPECT_TRUE(Hub::check(*rig.scene, diags, dir.string())) << diags.str();
  rig.hub->update(0);
  const auto& p = rig.hub->reading(rig.handle("#2/rover/gps")).vector("position");
  // the east edge is the last sample's centre: column 10.5; 25 m south of the centre: row 8
  EXPECT_NEAR(p.y, 10.0 + 10.5 * 0.001, 1e-9);
  EXPECT_NEAR(p.x, 50.0 - 8.0 * 0.001, 1e-9);
  EXPECT_NEAR(p.z, 7.0, 1e-9);
  std::filesystem::remove_all(dir);
}

/// A 5 kg scale held by a fixed joint, with a Contact sensor `pad`, and a 2 kg box dropped onto
/// it from 5 cm; `box_sensor` (a node of the box's, or "") goes into the box.
std::string scaleAndBox(const std::string& box_sensor) {
  return R"(
  - Joint:
      kind: fixed
      children:
        - Body:
            name: scale
            mass: 5
            children: [{Cube: {size: [1, 1, 0.1]}}, {Contact: {name: pad}}]
  - Transform:
      translation: [0, 0, 0.2]
      children: [{Body: {name: box, mass: 2, children: [{Cube: {size: [0.2, 0.2, 0.2]}})" +
         (box_sensor.empty() ? "" : ", " + box_sensor) + "]}}]\n";
}

TEST(Senses, AContactSensorFeelsTheBoxRestingOnItWithItsWeight) {
  Rig rig(scaleAndBox(""));
  const auto pad = rig.handle("#0/scale/pad");
  rig.hub->update(0);
  rig.run(0, 200, 0.01);
  const auto& r = rig.hub->reading(pad);
  ASSERT_EQ(r.items().size(), 1u);
  EXPECT_EQ(r.items()[0], rig.handle("#1/box"));
  EXPECT_NEAR(r.numbers("forces")[0], 2 * kG, 0.02 * 2 * kG);
  EXPECT_NEAR(r.number("total"), 2 * kG, 0.02 * 2 * kG);
}

TEST(Senses, AContactSensorLetsItsBodySleepAndKeepsItsReadingAsleep) {
  // the box comes to rest and sleeps, with the pad's body: the reading stays m g
  Rig rig(R"(
  - Transform: {translation: [0, 0, 0.05], children: [{Body: {name: scale, mass: 5, children: [{Cube: {size: [1, 1, 0.1]}}, {Contact: {name: pad}}]}}]}
  - Transform: {translation: [0, 0, 0.2], children: [{Body: {name: box, mass: 2, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
  - Plane: {}
)");
  const auto pad = rig.handle("#0/scale/pad");
  rig.hub->update(0);
  double t = 0;
  int steps = 0;
  for (; steps < 3000 && rig.world->awakeCount() > 0; ++steps) t = rig.run(t, 1, 0.01);
  ASSERT_EQ(rig.world->awakeCount(), 0u) << "still awake after " << steps << " steps";
  t = rig.run(t, 50, 0.01);  // asleep all along
  // the box on it with its weight; the ground under it with the box's and its own
  const auto& r = rig.hub->reading(pad);
  ASSERT_EQ(r.items().size(), 2u);
  const std::size_t box = r.items()[0] == rig.handle("#1/box") ? 0 : 1;
  EXPECT_EQ(r.items()[box], rig.handle("#1/box"));
  EXPECT_NEAR(r.numbers("forces")[box], 2 * kG, 0.02 * 2 * kG);
  EXPECT_NEAR(r.numbers("forces")[1 - box], 7 * kG, 0.02 * 7 * kG);
}

TEST(Senses, TwoContactSensorsTouchingEachOtherBothFeelTheForceBetweenThem) {
  // a box with a Contact sensor on a scale with one: each feels the other with the box's weight
  Rig rig(scaleAndBox("{Contact: {name: feel}}"));
  rig.hub->update(0);
  rig.run(0, 200, 0.01);
  const auto& below = rig.hub->reading(rig.handle("#0/scale/pad"));
  const auto& above = rig.hub->reading(rig.handle("#1/box/feel"));
  ASSERT_EQ(below.items().size(), 1u);
  ASSERT_EQ(above.items().size(), 1u);
  EXPECT_EQ(below.items()[0], rig.handle("#1/box"));
  EXPECT_EQ(above.items()[0], rig.handle("#0/scale"));
  EXPECT_NEAR(below.numbers("forces")[0], 2 * kG, 0.02 * 2 * kG);
  EXPECT_NEAR(above.numbers("forces")[0], 2 * kG, 0.02 * 2 * kG);
}

TEST(Senses, ASensorDeletedWithItsBodyIsForgotten) {
  Rig rig(R"(
  - Transform: {name: a, translation: [0, 0, 1], children: [{Body: {name: box, mass: 1, children: [{Cube: {}}, {Imu: {name: imu}}, {Contact: {name: pad}}]}}]}
)");
  const auto imu = rig.handle("a/box/imu");
  rig.hub->update(0);
  double t = rig.run(0, 5, 0.01);
  ASSERT_TRUE(rig.hub->isSensor(imu));
  scene::Node& box = *rig.scene->find("a/box");
  rig.world->remove(box);
  rig.hub->forget(box);
  rig.scene->destroy(box);
  EXPECT_FALSE(rig.hub->isSensor(imu));
  EXPECT_TRUE(rig.hub->reading(imu).channels().empty());
  rig.run(t, 5, 0.01);  // nothing reads the freed nodes (the ASan job would say)
}

TEST(Senses, AForceTorqueSensorReadsTheWeightAndMomentOfAHangingArm) {
  // the arm's centre of mass lies 0.5 m along +x from the joint that holds it
  Rig rig(R"(
  - Joint:
      name: shoulder
      kind: fixed
      children:
        - ForceTorque: {name: ft}
        - Transform:
            translation: [0.5, 0, 0]
            children: [{Body: {name: arm, mass: 3, children: [{Cube: {size: [1, 0.1, 0.1]}}]}}]
)");
  const auto ft = rig.handle("shoulder/ft");
  rig.hub->update(0);
  rig.run(0, 100, 0.01);
  const auto& r = rig.hub->reading(ft);
  const double w = 3 * kG;
  EXPECT_NEAR(r.vector("force").x, 0, 1e-3 * w);
  EXPECT_NEAR(r.vector("force").y, 0, 1e-3 * w);
  EXPECT_NEAR(r.vector("force").z, w, 1e-2 * w);
  EXPECT_NEAR(r.vector("torque").y, -0.5 * w, 1e-2 * w);
  EXPECT_NEAR(r.vector("torque").x, 0, 1e-3 * w);
}

/// A range finder 2 m from a wall, with noise `sd` and bias 0.05 m: `n` samples.
std::vector<double> noisyRanges(std::uint64_t seed, double sd, int n) {
  Rig rig(R"(
  - Transform: {translation: [2.5, 0, 0], children: [{Cube: {size: [1, 4, 4]}}]}
  - RangeFinder: {name: eye, length: 10, noise: )" + std::to_string(sd) + R"(, bias: 0.05}
)", seed);
  const auto eye = rig.handle("eye");
  std::vector<double> out;
  for (int i = 0; i < n; ++i) {
    rig.hub->update(i * 0.01);
    out.push_back(rig.hub->reading(eye).number("distance"));
  }
  return out;
}

TEST(Senses, NoiseIsTheSameForASeedAndHasItsStatedSpreadAndBias) {
  const auto a = noisyRanges(7, 0.01, 10000), b = noisyRanges(7, 0.01, 10000), c = noisyRanges(8, 0.01, 10000);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (const auto* x : {&a, &c}) {
    const double mean = std::accumulate(x->begin(), x->end(), 0.0) / 10000;
    double var = 0;
    for (double v : *x) var += (v - mean) * (v - mean);
    const double sd = std::sqrt(var / 9999);
    EXPECT_NEAR(mean, 2.05, 3 * 0.01 / std::sqrt(10000.0) + 1e-9);
    EXPECT_NEAR(sd, 0.01, 0.03 * 0.01);  // the estimate's own spread is 0.7 %
  }
}

TEST(Senses, ResolutionRoundsEachReading) {
  Rig rig(R"(
  - Transform: {translation: [2.5, 0, 0], children: [{Cube: {size: [1, 4, 4]}}]}
  - Transform: {translation: [0, 0, 0.3], children: [{RangeFinder: {name: eye, length: 10, resolution: 0.25, bias: 0.1}}]}
)");
  rig.hub->update(0);
  EXPECT_DOUBLE_EQ(rig.hub->reading(rig.handle("#1/eye")).number("distance"), 2.0);  // 2.1 to the nearest quarter
}

}  // namespace
}  // namespace gdpn::sensors
