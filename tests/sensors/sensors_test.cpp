// Sensors against the plant: a region feels a ball pass, a range finder measures exactly.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gdpn/model/model.h"
#include "gdpn/sensors/hub.h"
#include "rig.h"

namespace gdpn::sensors {
namespace {

TEST(Sensors, ABallDroppedThroughARegionEntersOnceAndExitsOnce) {
  Rig rig(R"(
  - Transform:
      translation: [0, 0, 1]
      children: [{Region: {name: gate, shape: box, size: [0.5, 0.5, 0.2], scope: world}}]
  - Transform:
      translation: [0, 0, 3]
      children: [{Body: {name: ball, mass: 0.1, children: [{Sphere: {radius: 0.05}}]}}]
)");
  const auto gate = rig.handle("#0/gate"), ball = rig.handle("#1/ball");
  int entered = 0, exited = 0;
  for (int i = 0; i < 500; ++i) {
    rig.world->step(0.005);
    for (const auto& c : rig.hub->update(i * 0.005)) {
      ASSERT_EQ(c.sensor, gate);
      for (auto h : c.entered) {
        EXPECT_EQ(h, ball);
        ++entered;
      }
      for (auto h : c.exited) {
        EXPECT_EQ(h, ball);
        ++exited;
      }
    }
  }
  EXPECT_EQ(entered, 1);
  EXPECT_EQ(exited, 1);
  EXPECT_FALSE(rig.hub->reading(gate).active);
}

TEST(Sensors, ARangeFinderMeasuresTheDistanceToAFaceExactly) {
  // the finder at x = 0 looks along +x at a box whose near face is at x = 2.35
  Rig rig(R"(
  - World: {gravity: [0, 0, 0]}
  - RangeFinder: {name: eye, length: 10}
  - Transform:
      translation: [2.6, 0, 0]
      children: [{Body: {name: box, mass: 1, children: [{Cube: {size: [0.5, 0.5, 0.5]}}]}}]
)");
  const auto eye = rig.handle("eye");
  auto& box = *rig.scene->find("#2/box");
  rig.world->step(0.01);
  rig.hub->update(0.01);
  EXPECT_NEAR(rig.hub->reading(eye).number("distance"), 2.35, 1e-6);
  EXPECT_EQ(rig.hub->reading(eye).node("hit"), box.handle());
  // the box moves away at 1 m/s: the distance follows
  rig.world->setVelocity(box, {1, 0, 0});
  for (int i = 0; i < 100; ++i) rig.world->step(0.01);
  const auto& changes = rig.hub->update(1.01);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_NEAR(rig.hub->reading(eye).number("distance"), box.world.position.x - 0.25, 1e-6);
  EXPECT_NEAR(rig.hub->reading(eye).number("distance"), 3.35, 1e-3);
}

TEST(Sensors, ARegionFeelsOnlyItsScope) {
  // two boxes inside the region; with scope 'siblings' only the one beside it counts
  Rig rig(R"(
  - World: {gravity: [0, 0, 0]}
  - Group:
      name: cell
      children:
        - Region: {name: inside, shape: sphere, radius: 2, scope: siblings}
        - Body: {name: mine, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
  - Body: {name: other, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
)");
  rig.hub->update(0);
  const auto& items = rig.hub->reading(rig.handle("cell/inside")).items();
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0], rig.handle("cell/mine"));
}

TEST(Sensors, ARegionThatReportsBodiesOnlyLeavesStaticShapesOut) {
  // a box region holds a static shelf and a body; a ray region hits a static wall before a
  // body: reporting bodies only, the box region reports the body, and the ray nothing (the
  // wall still stops it)
  const std::string scene = R"(
  - World: {gravity: [0, 0, 0]}
  - Region: {name: box, size: [2, 2, 2], report: $R}
  - Transform: {translation: [0.5, 0, 0], children: [{Cube: {name: shelf, size: [0.2, 0.2, 0.2]}}]}
  - Transform: {name: at, translation: [-0.5, 0, 0], children: [{Body: {name: b, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
  - Transform: {translation: [0, 5, 0], children: [{Region: {name: ray, shape: ray, length: 10, report: $R}}]}
  - Transform: {translation: [2, 5, 0], children: [{Cube: {name: wall, size: [0.2, 2, 2]}}]}
  - Transform: {name: far, translation: [5, 5, 0], children: [{Body: {name: b, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
)";
  for (const std::string report : {"all", "bodies"}) {
    std::string text = scene;
    for (auto at = text.find("$R"); at != std::string::npos; at = text.find("$R")) text.replace(at, 2, report);
    Rig rig(text);
    rig.hub->update(0);
    const auto& box = rig.hub->reading(rig.handle("box")).items();
    const auto& ray = rig.hub->reading(rig.handle("#4/ray")).items();
    if (report == "all") {
      EXPECT_EQ(box, (std::vector<scene::NodeHandle>{rig.handle("#2/shelf"), rig.handle("at/b")}));
      EXPECT_EQ(ray, (std::vector<scene::NodeHandle>{rig.handle("#5/wall")}));
    } else {
      EXPECT_EQ(box, (std::vector<scene::NodeHandle>{rig.handle("at/b")}));
      EXPECT_TRUE(ray.empty());
    }
  }
}

TEST(Sensors, AConeRegionFeelsWhatIsInsideItsSlantedSurfaceAndNothingOutside) {
  // a cone of radius 1 and height 2 along z, base at z = -1, apex at z = +1: at height z its
  // radius is (1 - z) / 2. Small spheres and cubes 5 cm (along the radius) inside and outside
  // its slanted surface at several heights and bearings, and beyond its apex and base; the
  // cone stands tilted and moved, which moves every item with it
  struct Probe {
    double z, off, bearing;  // height in the cone's frame, radial offset from its surface (m), rad
    bool inside;
  };
  std::vector<Probe> probes;
  int k = 0;
  for (double z : {-0.8, -0.3, 0.2, 0.7}) {
    for (double off : {-0.05, 0.05}) probes.push_back({z, off, 0.4 + 1.3 * k++, off < 0});
  }
  probes.push_back({1.03, -1.0, 0, false});   // above the apex, on the axis
  probes.push_back({0.97, -1.0, 0, true});    // just below it
  probes.push_back({-1.03, -0.5, 1, false});  // below the base
  probes.push_back({-0.97, -0.5, 1, true});   // just above it
  std::string text = R"(
  - World: {gravity: [0, 0, 0]}
  - Transform:
      translation: [3, -2, 1]
      rotation: [1, 1, 0, 40]
      children:
        - Region: {name: cone, shape: cone, radius: 1, height: 2}
)";
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Probe& p = probes[i];
    const double r = std::max(0.0, (1 - p.z) / 2 + p.off);
    const std::string shape = i % 2 == 0 ? "Sphere: {radius: 0.01}" : "Cube: {size: [0.02, 0.02, 0.02]}";
    text += "        - Transform: {name: p" + std::to_string(i) + ", translation: [" +
            std::to_string(r * std::cos(p.bearing)) + ", " + std::to_string(r * std::sin(p.bearing)) + ", " +
            std::to_string(p.z) + "], children: [{" + shape + "}]}\n";
  }
  Rig rig(text);
  rig.hub->update(0);
  const auto& items = rig.hub->reading(rig.handle("#1/cone")).items();
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const scene::Node& probe = *rig.scene->find("#1/p" + std::to_string(i));
    const bool felt = std::find(items.begin(), items.end(), probe.children().front()->handle()) != items.end();
    EXPECT_EQ(felt, probes[i].inside) << "probe " << i << " at height " << probes[i].z << ", " << probes[i].off
                                      << " m from the surface";
  }
}

TEST(Sensors, ATimeSensorTicksAtItsPeriod) {
  Rig rig("  - TimeSensor: {name: clock, period: 0.5, offset: 0.25}\n");
  std::vector<double> ticks;
  for (int i = 0; i <= 150; ++i) {
    const double now = i * 0.01;
    if (!rig.hub->update(now).empty()) ticks.push_back(now);
  }
  ASSERT_EQ(ticks.size(), 3u);
  EXPECT_NEAR(ticks[0], 0.25, 1e-9);
  EXPECT_NEAR(ticks[1], 0.75, 1e-9);
  EXPECT_NEAR(ticks[2], 1.25, 1e-9);
  EXPECT_EQ(rig.hub->reading(rig.handle("clock")).number("ticks"), 3.0);
}

}  // namespace
}  // namespace gdpn::sensors
