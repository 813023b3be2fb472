// Sensors in a run: what a handler sees, and the sensors of copies that spawn makes.

#include <gtest/gtest.h>

#include <sstream>

#include "gdpn/model/simulation.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

std::unique_ptr<Simulation> open(const std::string& text) {
  core::Diagnostics diags;
  auto m = parseModel(text, "handlers.gdpn.yaml", diags);
  std::unique_ptr<Simulation> sim;
  if (m) sim = Simulation::create(*m, diags);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

TEST(SensorHandlers, OnChangeSeesTheSensorsValueAndTheSensorUnderItsSlotsName) {
  // a TimeSensor ticking at 0.25 and 0.75 s: its value (ticks) is 1, then 2
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.05, until: 1}
scene:
  - TimeSensor: {name: clock, period: 0.5, offset: 0.25}
pages:
  main:
    places:
      watch:
        sensors: {c0: clock}
        on_change: 'sim.log("ticks", type(value).__name__, int(value), value == c0.ticks)'
)Y");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  EXPECT_EQ(testing::logLines(trace.str()),
            (std::vector<std::string>{"ticks float 1 True", "ticks float 2 True"}))
      << trace.str();
}

/// A store of probes (a Region and a RangeFinder looking along +x) to copy, a static cube at
/// (5, 0.15, 0) and a wall whose face is at x = 8.9.
constexpr const char* kProbes = R"Y(gdpn: 1
settings: {dt: 0.01, until: 0.05}
scene:
  - World: {gravity: [0, 0, 0]}
  - Group:
      name: store
      template: true
      children:
        - Transform:
            name: probe
            children:
              - Region: {name: eye, shape: box, size: [0.5, 0.5, 0.5]}
              - RangeFinder: {name: finder, length: 10}
  - Group: {name: area}
  - Transform: {name: thing, translation: [5, 0.15, 0], children: [{Cube: {name: c, size: [0.1, 0.1, 0.1]}}]}
  - Transform: {name: wall, translation: [9, 0, 0], children: [{Cube: {name: w, size: [0.2, 4, 4]}}]}
)Y";

TEST(SensorHandlers, TheSensorsOfASpawnedCopyAreReadAsTheOriginalsWouldBe) {
  auto sim = open(kProbes);
  ASSERT_TRUE(sim);
  scene::Scene& plant = *sim->plant();
  std::string why;
  scene::Node* far = sim->spawn(*plant.find("store/probe"), *plant.find("area"), core::Vec3{5, 0, 0}, why);
  ASSERT_TRUE(far) << why;
  const scene::NodeHandle eye = far->children()[0]->handle(), finder = far->children()[1]->handle();
  sim->run({});
  ASSERT_FALSE(sim->reading(finder).channels().empty()) << "the copy's sensors are read";
  EXPECT_EQ(sim->reading(eye).items(), (std::vector<scene::NodeHandle>{plant.find("thing/c")->handle()}));
  EXPECT_TRUE(sim->reading(eye).active);
  EXPECT_NEAR(sim->reading(finder).number("distance"), 3.9, 1e-6);
  // a second copy while the run goes on, at the origin: it holds nothing and sees the wall
  // 8.9 m off; the first reads on
  scene::Node* near = sim->spawn(*plant.find("store/probe"), *plant.find("area"), core::Vec3{0, 0, 0}, why);
  ASSERT_TRUE(near) << why;
  sim->step();
  EXPECT_TRUE(sim->reading(near->children()[0]->handle()).items().empty());
  EXPECT_NEAR(sim->reading(near->children()[1]->handle()).number("distance"), 8.9, 1e-6);
  EXPECT_EQ(sim->reading(eye).items().size(), 1u);
  // deleted, the first copy's sensors are read no more; the second's still are
  sim->deleteNode(*far);
  sim->step();
  EXPECT_TRUE(sim->reading(eye).items().empty());
  EXPECT_NEAR(sim->reading(near->children()[1]->handle()).number("distance"), 8.9, 1e-6);
}

TEST(SensorHandlers, ACopyWhoseSensorCannotWorkIsRefusedSayingWhy) {
  // an Imu needs a Body above it: the template's has none, so neither would a copy
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 0.05}
scene:
  - Group: {name: store, template: true, children: [{Imu: {name: imu}}]}
  - Group: {name: area}
)Y");
  ASSERT_TRUE(sim);
  scene::Scene& plant = *sim->plant();
  std::string why;
  EXPECT_EQ(sim->spawn(*plant.find("store/imu"), *plant.find("area"), std::nullopt, why), nullptr);
  EXPECT_NE(why.find("handlers.gdpn.yaml:4:"), std::string::npos) << why;
  EXPECT_NE(why.find("Body"), std::string::npos) << why;
  EXPECT_TRUE(plant.find("area")->children().empty());
}

}  // namespace
}  // namespace gdpn::model
