// The hybrid tank (examples/plant/tank): a pump and a valve switched by the net from level
// switches. The reactions start at the step of each crossing, the level stays within the
// switches' band plus what one step adds, the drain follows Torricelli's law, and what the
// pump put in, less what the consumers took, is what the tank gained.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

constexpr double kDt = 0.01;         // settings.dt
constexpr double kPumpRate = 4.0;    // L/s, params.pump_rate
constexpr double kDrain = 0.3;       // L^0.5/s wide open, params.k_drain
constexpr double kLow = 20.0;        // L, params.low
constexpr double kHigh = 80.0;       // L, params.high
constexpr std::int64_t kSteps = 30000;  // 300 s

std::vector<nlohmann::json> traceEvents(const std::string& trace, const std::string& ev) {
  std::vector<nlohmann::json> out;
  std::istringstream lines(trace);
  for (std::string line; std::getline(lines, line);) {
    auto j = nlohmann::json::parse(line);
    if (j["ev"] == ev) out.push_back(std::move(j));
  }
  return out;
}

double amountOf(const Simulation& sim, const char* place) { return sim.kernel().amount(*sim.net().findPlace(place)); }

TEST(Tank, TheSwitchesStartAndStopThePumpInTheStepOfEachCrossing) {
  auto sim = testing::openModelFile("examples/plant/tank/tank.gdpn.yaml");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  std::vector<double> amounts(kSteps + 1, 0.0);  // the tank's, at the end of each step
  for (std::int64_t k = 1; k <= kSteps; ++k) {
    sim->step();
    amounts[static_cast<std::size_t>(k)] = amountOf(*sim, "main/tank");
  }
  const auto crossings = traceEvents(trace.str(), "cross");
  std::vector<std::int64_t> low_falls, high_rises, pump_starts, pump_stops;
  for (const auto& c : crossings) {
    EXPECT_EQ(c["place"], "main/tank");
    const double level = c["level"].get<double>();
    // a crossing lies within the step the trace says: ((step - 1) dt, step dt]
    const auto step = c["step"].get<std::int64_t>();
    EXPECT_GT(c["t"].get<double>(), static_cast<double>(step - 1) * kDt - 1e-9);
    EXPECT_LE(c["t"].get<double>(), static_cast<double>(step) * kDt + 1e-9);
    if (level == kLow && !c["rising"].get<bool>()) low_falls.push_back(step);
    if (level == kHigh && c["rising"].get<bool>()) high_rises.push_back(step);
  }
  for (const auto& s : traceEvents(trace.str(), "start")) {
    if (s["transition"] == "main/start_pump") pump_starts.push_back(s["step"].get<std::int64_t>());
    if (s["transition"] == "main/stop_pump") pump_stops.push_back(s["step"].get<std::int64_t>());
  }
  // the level saws: four teeth in 300 s (the pump runs about 23 s of each 77 s round)
  EXPECT_EQ(low_falls.size(), 4u);
  EXPECT_EQ(high_rises.size(), 4u);
  // each reaction starts at the first step boundary after its crossing: in the same step
  EXPECT_EQ(pump_starts, low_falls);
  EXPECT_EQ(pump_stops, high_rises);
  // within the band, less what one step of the drain takes below the low switch (at most
  // k sqrt(20) L/s, wide open) and plus what one step of the pump adds above the high one
  ASSERT_FALSE(pump_starts.empty());
  const auto from = amounts.begin() + pump_starts.front();
  const double lowest = *std::min_element(from, amounts.end());
  const double highest = *std::max_element(from, amounts.end());
  EXPECT_GE(lowest, kLow - kDrain * std::sqrt(kLow) * kDt);
  EXPECT_LT(lowest, kLow);
  EXPECT_LE(highest, kHigh + kPumpRate * kDt);
  EXPECT_GT(highest, kHigh);
  // the pump flows in the steps after a start up to its stop's (the stop's step included):
  // 4 L/s over them is what the tank gained and the consumers drew
  double pumping = 0.0;
  for (std::size_t i = 0; i < pump_starts.size(); ++i) {
    const auto stop = i < pump_stops.size() ? pump_stops[i] : kSteps;
    pumping += static_cast<double>(stop - pump_starts[i]) * kDt;
  }
  EXPECT_NEAR(amountOf(*sim, "main/tank") + amountOf(*sim, "main/drawn"), 50.0 + kPumpRate * pumping, 1e-6);
}

TEST(Tank, TheOpenValveDrainsAsTorricelliSays) {
  // wide open (90 deg from about 15.3 s) with the pump off, d sqrt(x)/dt = -k/2: the level
  // reaches the low switch 2 (sqrt(x(20 s)) - sqrt(20)) / k after 20 s, to CVODE's tolerance
  // over 12.6 s (1e-13 s here: the solver goes on over the steps without a restart)
  auto sim = testing::openModelFile("examples/plant/tank/tank.gdpn.yaml");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  for (int k = 0; k < 2000; ++k) sim->step();
  EXPECT_NEAR(sim->kernel().nominalRate(*sim->net().findTransition("main/drain")),
              kDrain * std::sqrt(amountOf(*sim, "main/tank")), 1e-9);
  const double at20 = amountOf(*sim, "main/tank");
  EXPECT_LT(at20, 50.0);
  EXPECT_GT(at20, kLow);
  for (int k = 0; k < 2000; ++k) sim->step();
  const auto crossings = traceEvents(trace.str(), "cross");
  ASSERT_FALSE(crossings.empty());
  EXPECT_EQ(crossings[0]["level"].get<double>(), kLow);
  EXPECT_NEAR(crossings[0]["t"].get<double>(), 20.0 + 2.0 * (std::sqrt(at20) - std::sqrt(kLow)) / kDrain, 1e-9);
}

}  // namespace
}  // namespace gdpn::model
