// Sensors in the net: sensor slots, their handlers, and arcs whose conditions read them.

#include <gtest/gtest.h>

#include <sstream>

#include "gdpn/model/simulation.h"
#include "support/sim_helpers.h"
#include "support/sorted_balls.h"
#include "gdpn/net/compile.h"

namespace gdpn::model {
namespace {

std::unique_ptr<Simulation> open(const std::string& text, core::Diagnostics& diags) {
  auto m = parseModel(text, "sensors.gdpn.yaml", diags);
  return m ? Simulation::create(*m, diags) : nullptr;
}

using testing::logLines;
auto logs = [](const std::string& trace) { return logLines(trace); };

TEST(SensorNet, ABallThroughARegionEntersOnceAndExitsOnce) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.005, until: 1.5}
scene:
  - Transform: {translation: [0, 0, 1], children: [{Region: {name: gate, size: [0.5, 0.5, 0.2], scope: world}}]}
  - Transform: {name: drop, translation: [0, 0, 3], children: [{Body: {name: ball, mass: 0.1, children: [{Sphere: {radius: 0.05}}]}}]}
pages:
  main:
    places:
      watch:
        sensors: {c0: "#0/gate"}
        on_enter: 'sim.log("enter", item.name, len(items))'
        on_exit: 'sim.log("exit", item.name, len(items))'
)Y", diags);
  ASSERT_FALSE(sim) << "a path with '#' is not a node path";
  core::Diagnostics diags2;
  sim = open(R"Y(gdpn: 1
settings: {dt: 0.005, until: 1.5}
scene:
  - Transform: {name: frame, translation: [0, 0, 1], children: [{Region: {name: gate, size: [0.5, 0.5, 0.2], scope: world}}]}
  - Transform: {name: drop, translation: [0, 0, 3], children: [{Body: {name: ball, mass: 0.1, children: [{Sphere: {radius: 0.05}}]}}]}
pages:
  main:
    places:
      watch:
        sensors: {c0: frame/gate}
        on_enter: 'sim.log("enter", item.name, len(items))'
        on_exit: 'sim.log("exit", item.name, len(items))'
)Y", diags2);
  ASSERT_TRUE(sim) << diags2.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  EXPECT_EQ(logs(trace.str()), (std::vector<std::string>{"enter drop/ball 1", "exit drop/ball 0"}));
  EXPECT_NE(trace.str().find("\"ev\":\"enter\",\"sensor\":\"frame/gate\",\"item\":\"drop/ball\""), std::string::npos);
}

TEST(SensorNet, ATransitionWaitsUntilABoxArrivesInFrontOfIt) {
  // a box rides a 1 m/s belt from x = 0; a region at x = 2 sees it arrive at about 1.9 s
  // (its near edge reaching the region); the grab transition's condition holds only then
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 4}
scene:
  - Transform:
      name: belt
      children:
        - Conveyor: {speed: 1}
        - Cube: {size: [20, 1, 0.1]}
  - Transform: {name: spot, translation: [2, 0, 0.2], children: [{Region: {name: eye, size: [0.1, 1, 0.2]}}]}
  - Transform: {name: start, translation: [0, 0, 0.1], children: [{Body: {name: box, mass: 0.5, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
pages:
  main:
    places:
      front:
        sensors: {c0: spot/eye}
      ready: {tokens: 1}
      done: {}
    transitions:
      grab:
        pre_fire: 'sim.log("grab", round(sim.time, 2), c0.items[0].name)'
    arcs:
      - {from: front, to: grab, condition: 'len(c0.items) > 0'}
      - ready -> grab
      - grab -> done
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  const auto l = logs(trace.str());
  ASSERT_EQ(l.size(), 1u) << trace.str();
  // "grab T start/box" with T when the box reached the region
  const double t = std::stod(l[0].substr(5));
  EXPECT_GT(t, 1.7);
  EXPECT_LT(t, 2.1);
  EXPECT_NE(l[0].find("start/box"), std::string::npos);
}

TEST(SensorNet, ASensorSlotMustReadASensor) {
  core::Diagnostics diags;
  EXPECT_FALSE(open(R"Y(gdpn: 1
scene:
  - Cube: {name: box}
pages:
  main:
    places:
      p: {sensors: {c0: box}}
      q: {sensors: {c1: nothing}}
)Y", diags));
  EXPECT_NE(diags.str().find("sensors.gdpn.yaml:7:25: error: 'box' names no sensor of the scene"), std::string::npos)
      << diags.str();
  EXPECT_NE(diags.str().find("sensors.gdpn.yaml:8:25: error: 'nothing' names no sensor of the scene"), std::string::npos)
      << diags.str();
}

TEST(SensorNet, AConditionMustReadASensorSlotAndSensorSlotsCarryNoTokens) {
  core::Diagnostics diags;
  auto m = parseModel(R"Y(gdpn: 1
pages:
  main:
    places:
      p: {tokens: 1}
      s: {sensors: {c0: eye}}
    transitions:
      t: {}
    arcs:
      - {from: p, to: t, condition: {a0: "True"}}
      - {from: s, to: t, weight: {c0: 1}}
)Y", "cond.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_FALSE(net::compile(m->net, diags));
  EXPECT_NE(diags.str().find("cond.gdpn.yaml:10:43: error: a condition reads a sensor slot, but slot a0 of 'main/p' is not one"),
            std::string::npos)
      << diags.str();
  EXPECT_NE(diags.str().find("cond.gdpn.yaml:11:35: error: slot c0 of 'main/s' reads a sensor and carries no tokens"),
            std::string::npos)
      << diags.str();
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(SortingDevice, EveryOneOfFiftyBallsEndsInItsBin) {
  auto sim = testing::openModelFile("examples/sorting/sorting.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto outcome = sim->run({});
  ASSERT_NE(outcome.reason, StopReason::ScriptError) << outcome.message;
  // the material in the ball's group says its colour; blue goes left (-y), red right
  const auto [blue, red] = testing::sortedBalls(*sim);
  EXPECT_EQ(blue + red, 50);
  EXPECT_EQ(blue, 23);  // seed 7
  EXPECT_EQ(red, 27);
  // the model's summary counts the same from the balls' user data and positions
  std::string error;
  const auto figures = sim->modelFigures(error);
  ASSERT_EQ(error, "");
  std::vector<std::pair<std::string, double>> numbers;
  for (const auto& f : figures) numbers.emplace_back(f.label, f.value.value_or(-1));
  EXPECT_EQ(numbers, (std::vector<std::pair<std::string, double>>{{"balls dropped", 50},
                                                                  {"pushed left (blue)", 23},
                                                                  {"pushed right (red)", 27},
                                                                  {"blue in the left bin", 23},
                                                                  {"red in the left bin", 0},
                                                                  {"red in the right bin", 27},
                                                                  {"blue in the right bin", 0}}));
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(SensorNet, APredicateReadsASensorByName) {
  // boxes queue on a place; the take transition only takes one that the region 'dock' holds
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - World: {gravity: [0, 0, 0]}
  - Region: {name: dock, size: [1, 1, 1]}
  - Transform: {name: far, translation: [5, 0, 0], children: [{Body: {name: a, mass: 1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
  - Transform: {name: near, children: [{Body: {name: b, mass: 1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
pages:
  main:
    places:
      queue: {tokens: {d0: [far/a, near/b]}}
      taken: {}
    transitions:
      take:
        pre_fire: 'sim.log("took", self.d0[0].name)'
    arcs:
      - {from: queue, to: take, weight: {d0: 1}, predicate: 'token in dock'}
      - {from: take, to: taken, weight: {d0: 1}}
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  EXPECT_EQ(logs(trace.str()), (std::vector<std::string>{"took near/b"})) << trace.str();
}

}  // namespace
}  // namespace gdpn::model
