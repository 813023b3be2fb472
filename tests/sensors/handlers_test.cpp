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

}  // namespace
}  // namespace gdpn::model
