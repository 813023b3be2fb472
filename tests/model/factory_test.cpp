// The factory case study (examples/factory): the arm's cycle, and the line's figures from a
// whole run.

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "gdpn/model/report.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

TEST(Factory, TheArmDeliversOneBoxPerFourSecondCycle) {
  auto sim = testing::openModelFile("examples/factory/factory.gdpn.yaml");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto outcome = sim->run({40.0, std::nullopt});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  const auto report = makeReport(*sim, outcome);
  // drops start at 3, 7, ..., 39 s: ten boxes in ten cycles
  for (const auto& t : report.transitions) {
    if (t.name == "factory/drop") {
      EXPECT_EQ(t.occurrences, 10);
      EXPECT_NEAR(t.mean_cycle, 4.0, 0.05);
    }
  }
  // the arm's cycle, measured beside its bound from the P-invariant P1 + P2 + P3
  bool found = false;
  for (const auto& c : report.cycles) {
    if (c.invariant != "factory/P1.b0 + factory/P2.b0 + factory/P3.b0") continue;
    found = true;
    EXPECT_EQ(c.bound, 4.0);
    EXPECT_NEAR(c.measured, 4.0, 0.05);
    EXPECT_EQ(c.alike, 2);  // the three joints move together
  }
  EXPECT_TRUE(found);
  // each box was let go of just above the first conveyor's belt (y = 1.6 m, belt top 0.5 m,
  // box centre 0.7 m when resting): in the boxes' order, one per cycle
  const auto lines = testing::logLines(trace.str());
  int released = 0;
  for (const auto& line : lines) {
    char name[64] = {};
    double x = 0, y = 0, z = 0;
    if (std::sscanf(line.c_str(), "released %63s at (%lf, %lf, %lf)", name, &x, &y, &z) != 4) continue;
    char expected[32];
    std::snprintf(expected, sizeof expected, "boxes/b%02d/box", released);
    EXPECT_STREQ(name, expected);
    EXPECT_NEAR(x, -8.0, 0.3) << name;  // the belt starts at x = -8.6 m, the box is 0.4 m wide
    EXPECT_GT(x, -8.4) << name;
    EXPECT_NEAR(y, 1.6, 0.15) << name;
    EXPECT_NEAR(z, 0.8, 0.12) << name;
    ++released;
  }
  EXPECT_EQ(released, 10);
}

std::string figure(const Report& report, const std::string& name) {
  for (const auto& [k, v] : report.figures) {
    if (k == name) return v;
  }
  ADD_FAILURE() << "no figure '" << name << "'";
  return {};
}

TEST(Factory, TheLinePaintsBoxesOnceAndTheRodsStrikeNone) {
  auto sim = testing::openModelFile("examples/factory/factory.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto outcome = sim->run({120.0, std::nullopt});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  const auto report = makeReport(*sim, outcome);
  ASSERT_EQ(report.figures_error, "");
  // every box the arm delivered; each station inserts boxes and works 15 s on each
  EXPECT_EQ(figure(report, "boxes delivered by the arm"), "24");
  for (const char* station : {"stationA", "stationB"}) {
    const std::string cycle = figure(report, std::string(station) + " cycle, measured");
    EXPECT_NE(cycle.find("15.00 s working"), std::string::npos) << cycle;
    EXPECT_GE(std::stoi(figure(report, std::string("painted by ") + station)), 2);
  }
  // the safety checks: no box painted twice, no box struck by a rod
  EXPECT_EQ(figure(report, "boxes painted twice"), "0");
  EXPECT_EQ(figure(report, "rod strikes"), "0");
  // the line's figures, pinned (the run is deterministic): 19 boxes at the end, 5 painted
  EXPECT_EQ(figure(report, "painted by stationA"), "5");
  EXPECT_EQ(figure(report, "painted by stationB"), "2");
  EXPECT_EQ(figure(report, "boxes at the end of the line"), "19");
  EXPECT_EQ(figure(report, "painted among them"), "5");
  EXPECT_EQ(figure(report, "unpainted among them"), "14");
  // the cells' bound is their 15 s circuit (push box, pull rod, push rod, pull box, wait);
  // the skip is a circuit of its own
  int cells = 0;
  for (const auto& c : report.cycles) {
    if (c.invariant.rfind("factory/station", 0) != 0) continue;
    ++cells;
    EXPECT_EQ(c.bound, 15.0) << c.invariant;
    EXPECT_GE(c.measured, 15.0) << c.invariant;
  }
  EXPECT_EQ(cells, 2);
}

TEST(Factory, EveryBoxReachesTheEndOfTheLineWhateverTheSeed) {
  // the seed reorders the solver's constraints, so each seed is another run of the same
  // plant: none may stall a box on the line (the last box is dropped at 96 s and needs
  // about 60 s to the end when no station takes it), none may paint a box twice
  for (const std::uint64_t seed : {1u, 2u}) {
    auto sim = testing::openModelFile("examples/factory/factory.gdpn.yaml", seed);
    ASSERT_TRUE(sim);
    const auto outcome = sim->run({240.0, std::nullopt});
    ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
    const auto report = makeReport(*sim, outcome);
    EXPECT_EQ(figure(report, "boxes at the end of the line"), "24") << "seed " << seed;
    EXPECT_EQ(figure(report, "boxes painted twice"), "0") << "seed " << seed;
    EXPECT_EQ(figure(report, "rod strikes"), "0") << "seed " << seed;
    const int painted = std::stoi(figure(report, "painted among them"));
    EXPECT_GE(painted, 6) << "seed " << seed;  // a quarter or more
    EXPECT_LE(painted, 12) << "seed " << seed;  // at most the dissertation's half
  }
}

TEST(Vehicles, EveryVehicleReachesTheDepotWithoutTouchingARock) {
  auto sim = testing::openModelFile("examples/vehicles/vehicles.gdpn.yaml");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::Stopped) << outcome.message;
  EXPECT_EQ(outcome.message, "all 4 vehicles reached the depot");
  EXPECT_LT(outcome.time, 40.0);
  int arrived = 0;
  for (const auto& line : testing::logLines(trace.str())) {
    char name[16] = {};
    double at = 0, metres = 0;
    if (std::sscanf(line.c_str(), "%15s reached the depot at %lf s after %lf m", name, &at, &metres) != 3) continue;
    ++arrived;
    EXPECT_GT(metres, 20.0) << name;  // every start is over 20 m from the depot
    // each car stands in the depot: its 3 x 3 m region holds some part of the 0.8 m car
    const auto p = sim->plant()->find(std::string(name) + "/body")->world.position;
    EXPECT_NEAR(p.x, 12.0, 2.0) << name;
    EXPECT_NEAR(p.y, 10.0, 2.0) << name;
  }
  EXPECT_EQ(arrived, 4);
  const auto report = makeReport(*sim, outcome);
  const double closest = std::stod(figure(report, "closest approach to a rock"));
  EXPECT_GT(closest, 0.47);  // the car's half-diagonal: it never touched a rock
}

}  // namespace
}  // namespace gdpn::model
