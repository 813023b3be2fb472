// Hybrid nets in whole runs (semantics.md, Hybrid nets), against analytic answers: a
// constant-rate fill crosses its threshold at the exact time, an exponential drain follows
// a e^(-kt), two flows share an emptying place in proportion to their rates, and the
// discrete reaction starts at the first step boundary after a crossing.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "support/hybrid_models.h"

namespace gdpn::model {
namespace {

std::unique_ptr<Simulation> fromText(const std::string& text) {
  core::Diagnostics diags;
  auto m = parseModel(text, "hybrid.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return nullptr;
  auto sim = Simulation::create(*m, diags);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

double amountOf(const Simulation& sim, const std::string& place) {
  return sim.kernel().amount(*sim.net().findPlace(place));
}

std::vector<nlohmann::json> events(const std::string& trace, const std::string& ev) {
  std::vector<nlohmann::json> out;
  std::istringstream lines(trace);
  for (std::string line; std::getline(lines, line);) {
    auto j = nlohmann::json::parse(line);
    if (j["ev"] == ev) out.push_back(j);
  }
  return out;
}

TEST(HybridRun, AConstantFillCrossesItsThresholdAtTheExactTime) {
  auto sim = fromText(testing::fillModelText());
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({.until = 5.0, .steps = {}});
  const auto crossings = events(trace.str(), "cross");
  ASSERT_FALSE(crossings.empty()) << trace.str();
  const auto& c = crossings.front();
  EXPECT_EQ(c["place"], "main/tank");
  EXPECT_EQ(c["level"].get<double>(), 1.0);
  EXPECT_TRUE(c["rising"].get<bool>());
  EXPECT_NEAR(c["t"].get<double>(), 1.0 / 0.3, 1e-9);
  EXPECT_EQ(c["step"], 34);  // the step (3.3, 3.4] holds it
  // the reaction: `stop` starts at the first step boundary after the crossing, 3.4 s
  const auto starts = events(trace.str(), "start");
  ASSERT_EQ(starts.size(), 1u);
  EXPECT_EQ(starts[0]["transition"], "main/stop");
  EXPECT_EQ(starts[0]["step"], 34);
  // the pump ran until then: 0.3 L/s for 3.4 s, and not a drop after
  EXPECT_NEAR(amountOf(*sim, "main/tank"), 0.3 * 3.4, 1e-12);
  EXPECT_FALSE(sim->kernel().flowing());
  // a continuous transition flows; nobody fires it
  EXPECT_EQ(sim->kernel().fire(*sim->net().findTransition("main/pump")),
            "'main/pump' is continuous: it flows while its arcs allow it, and is never fired");
}

TEST(HybridRun, AnExponentialDrainFollowsTheAnalyticCurve) {
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 0.01}
params: {k: 0.5}
pages:
  main:
    places:
      tank: {continuous: {amount: 10, unit: L}}
      half: {}
    transitions:
      drain: {continuous: {rate: k * tank}}
      alarm: {duration: 0.01}
    arcs:
      - {from: tank, to: drain}
      - {from: tank, to: alarm, kind: inhibitor, weight: 5}
      - {from: alarm, to: half}
)");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({.until = 2.0, .steps = {}});
  EXPECT_NEAR(amountOf(*sim, "main/tank"), 10.0 * std::exp(-0.5 * 2.0), 1e-7);
  const auto crossings = events(trace.str(), "cross");
  ASSERT_EQ(crossings.size(), 1u) << trace.str();
  EXPECT_EQ(crossings[0]["level"].get<double>(), 5.0);
  EXPECT_FALSE(crossings[0]["rising"].get<bool>());
  EXPECT_NEAR(crossings[0]["t"].get<double>(), std::log(2.0) / 0.5, 1e-7);
  const auto starts = events(trace.str(), "start");
  ASSERT_FALSE(starts.empty());
  EXPECT_EQ(starts[0]["step"], 139);  // ln 2 / 0.5 = 1.3863 s: the boundary after is 1.39 s
}

TEST(HybridRun, TwoFlowsShareAnEmptyingPlaceInProportionToTheirRates) {
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 0.1}
pages:
  main:
    places:
      tank: {continuous: {amount: 1}}
      a: {continuous: true}
      b: {continuous: true}
    transitions:
      feed: {continuous: {rate: 0.2}}
      fast: {continuous: {rate: 0.3}}
      slow: {continuous: {rate: 0.1}}
    arcs:
      - {from: feed, to: tank}
      - {from: tank, to: fast}
      - {from: fast, to: a}
      - {from: tank, to: slow}
      - {from: slow, to: b}
)");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  double lowest = 1.0;
  for (int k = 0; k < 100; ++k) {
    sim->step();
    lowest = std::min(lowest, amountOf(*sim, "main/tank"));
  }
  // 1 L drains at 0.2 L/s net: empty at 5 s; then the 0.2 L/s coming in is shared 3 : 1
  EXPECT_GE(lowest, 0.0);
  EXPECT_EQ(amountOf(*sim, "main/tank"), 0.0);
  EXPECT_NEAR(amountOf(*sim, "main/a"), 0.3 * 5 + 0.15 * 5, 1e-9);
  EXPECT_NEAR(amountOf(*sim, "main/b"), 0.1 * 5 + 0.05 * 5, 1e-9);
  EXPECT_NEAR(sim->kernel().flowRate(*sim->net().findTransition("main/fast")), 0.15, 1e-12);
  EXPECT_NEAR(sim->kernel().nominalRate(*sim->net().findTransition("main/fast")), 0.3, 1e-12);
  const auto crossings = events(trace.str(), "cross");
  ASSERT_EQ(crossings.size(), 1u) << trace.str();
  EXPECT_EQ(crossings[0]["place"], "main/tank");
  EXPECT_EQ(crossings[0]["level"].get<double>(), 0.0);
  EXPECT_NEAR(crossings[0]["t"].get<double>(), 5.0, 1e-9);
}

TEST(HybridRun, DiscreteTransitionsTakeAndPutAmountsInJumps) {
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 1}
pages:
  main:
    places:
      silo: {continuous: {amount: 6, capacity: 10, unit: kg}}
      bin: {continuous: {capacity: 4, unit: kg}}
      orders: {tokens: 3}
    transitions:
      fill: {duration: 2}
    arcs:
      - {from: orders, to: fill}
      - {from: silo, to: fill, weight: 2.5}
      - {from: fill, to: bin, weight: 2.5}
)");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto outcome = sim->run({.until = 20, .steps = {}});
  // the first fill takes 2.5 kg and puts it in the bin; the second finds no room for 2.5 more
  EXPECT_EQ(outcome.reason, StopReason::Dead);
  EXPECT_EQ(amountOf(*sim, "main/silo"), 3.5);
  EXPECT_EQ(amountOf(*sim, "main/bin"), 2.5);
  const auto removes = events(trace.str(), "remove");
  bool took = false;
  for (const auto& r : removes) took = took || (r["place"] == "main/silo" && r["amount"].get<double>() == 2.5);
  EXPECT_TRUE(took) << trace.str();
  EXPECT_NE(sim->kernel().readinessText(*sim->net().findTransition("main/fill")).find("'main/bin' has no room for 2.5 kg"),
            std::string::npos)
      << sim->kernel().readinessText(*sim->net().findTransition("main/fill"));
}

TEST(HybridRun, AFullPlaceTakesInNoMoreThanGoesOut) {
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 0.5}
pages:
  main:
    places:
      tank: {continuous: {capacity: 5}}
    transitions:
      pump: {continuous: {rate: 1}}
      drain: {continuous: {rate: 0.4}}
    arcs:
      - {from: pump, to: tank}
      - {from: tank, to: drain}
)");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({.until = 20.0, .steps = {}});
  // full at 5 / 0.6 s; then the pump is cut to what the drain takes
  EXPECT_EQ(amountOf(*sim, "main/tank"), 5.0);
  EXPECT_NEAR(sim->kernel().flowRate(*sim->net().findTransition("main/pump")), 0.4, 1e-12);
  const auto crossings = events(trace.str(), "cross");
  ASSERT_EQ(crossings.size(), 1u) << trace.str();
  EXPECT_EQ(crossings[0]["level"].get<double>(), 5.0);
  EXPECT_NEAR(crossings[0]["t"].get<double>(), 5.0 / 0.6, 1e-9);
}

TEST(HybridRun, AFlowFillingUpToItsOwnInhibitorHoldsTheLevelThere) {
  // the pump runs while the tank holds less than 8 L; a drain takes 0.5 L/s: at 8 L the pump
  // slides, giving what the drain takes, rather than switching on and off
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 0.1}
pages:
  main:
    places:
      tank: {continuous: {unit: L}}
    transitions:
      pump: {continuous: {rate: 1}}
      drain: {continuous: {rate: 0.5}}
    arcs:
      - {from: pump, to: tank}
      - {from: tank, to: pump, kind: inhibitor, weight: 8}
      - {from: tank, to: drain}
)");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  for (int k = 0; k < 300; ++k) {
    sim->step();
    ASSERT_LE(amountOf(*sim, "main/tank"), 8.0);
  }
  EXPECT_EQ(amountOf(*sim, "main/tank"), 8.0);
  EXPECT_NEAR(sim->kernel().flowRate(*sim->net().findTransition("main/pump")), 0.5, 1e-12);
  const auto crossings = events(trace.str(), "cross");
  ASSERT_EQ(crossings.size(), 1u) << trace.str();
  EXPECT_NEAR(crossings[0]["t"].get<double>(), 16.0, 1e-9);
}

TEST(HybridRun, AnOverflowDrawsDownToItsOwnTestAndNoFurther) {
  // an overflow takes 2 L/s while the tank holds 8 L or more; the pump gives 1 L/s
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 0.1}
pages:
  main:
    places:
      tank: {continuous: {unit: L}}
      spill: {continuous: {unit: L}}
    transitions:
      pump: {continuous: {rate: 1}}
      overflow: {continuous: {rate: 2}}
    arcs:
      - {from: pump, to: tank}
      - {from: tank, to: overflow}
      - {from: tank, to: overflow, kind: test, weight: 8}
      - {from: overflow, to: spill}
)");
  ASSERT_TRUE(sim);
  sim->run({.until = 20.0, .steps = {}});
  EXPECT_EQ(amountOf(*sim, "main/tank"), 8.0);
  EXPECT_NEAR(amountOf(*sim, "main/spill"), 12.0, 1e-9);
  EXPECT_NEAR(sim->kernel().flowRate(*sim->net().findTransition("main/overflow")), 1.0, 1e-12);
}

TEST(HybridRun, PageTypesCarryContinuousPlacesAndTheirFlowsPerInstance) {
  // each cell's tank drains at 10 % a second of what it holds; the main page tests one
  // cell's tank through its port and fills the other's with a jump
  auto sim = fromText(R"(gdpn: 1
settings: {dt: 0.01}
params: {k: 0.1}
pages:
  main:
    places:
      go: {tokens: 1}
    transitions:
      top_up: {duration: 0.01}
      alarm: {duration: 0.01}
    instances:
      a: cell
      b: cell
    arcs:
      - {from: go, to: top_up}
      - {from: top_up, to: b/level, weight: 4.5}
      - {from: a/level, to: alarm, kind: inhibitor, weight: 5}
page_types:
  cell:
    references: [level]
    places:
      level: {continuous: {amount: 10, capacity: 20, unit: L}}
    transitions:
      drain: {continuous: {rate: k * level}}
    arcs:
      - {from: level, to: drain}
)");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({.until = 1.0, .steps = {}});
  // a: 10 e^(-0.1 t); b: the same, and 4.5 L put at 0.01 s (the first completion)
  EXPECT_NEAR(amountOf(*sim, "main/a/level"), 10.0 * std::exp(-0.1), 1e-7);
  EXPECT_NEAR(amountOf(*sim, "main/b/level"), (10.0 * std::exp(-0.1 * 0.01) + 4.5) * std::exp(-0.1 * 0.99), 1e-7);
  EXPECT_TRUE(events(trace.str(), "cross").empty()) << trace.str();
  sim->run({.until = 8.0, .steps = {}});
  // a crosses 5 L at ln 2 / 0.1 s
  const auto crossings = events(trace.str(), "cross");
  ASSERT_FALSE(crossings.empty());
  EXPECT_EQ(crossings[0]["place"], "main/a/level");
  EXPECT_NEAR(crossings[0]["t"].get<double>(), std::log(2.0) / 0.1, 1e-6);
}

TEST(HybridRun, AnArcsRealWeightMayComeFromAParameter) {
  const char* text = R"(gdpn: 1
params: {dose: 2.5}
pages:
  main:
    places:
      tank: {continuous: {amount: 6}}
      bin: {continuous: true}
    transitions:
      dose: {duration: 1}
    arcs:
      - {from: tank, to: dose, weight: $dose}
      - {from: dose, to: bin, weight: 2}
)";
  core::Diagnostics diags;
  auto m = parseModel(text, "dose.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(m->net.pages[0].arcs[0].amount, 2.5);
  EXPECT_EQ(m->net.pages[0].arcs[0].amount_param, "dose");
  // saved as the reference it was written as
  const std::string saved = writeModel(*m);
  EXPECT_NE(saved.find("weight: $dose"), std::string::npos) << saved;
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  sim->run({.until = 10.0, .steps = {}});
  EXPECT_EQ(amountOf(*sim, "main/tank"), 1.0);  // two doses of 2.5 L; 1 L is too little for a third
  EXPECT_EQ(amountOf(*sim, "main/bin"), 4.0);
}

TEST(HybridRun, AContinuousPlaceCarriesNoColours) {
  core::Diagnostics diags;
  auto m = parseModel(R"(gdpn: 1
colours:
  P: {enum: [p1, p2]}
pages:
  main:
    places:
      tank: {continuous: true, colour: P}
)", "colour.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(Simulation::create(*m, diags), nullptr);
  EXPECT_NE(diags.str().find("colour.gdpn.yaml:7:14: error: continuous place 'tank' holds an amount, not tokens"),
            std::string::npos)
      << diags.str();
}

TEST(HybridRun, TheSameRunTwiceGivesTheSameTraceByteForByte) {
  std::string traces[2];
  for (auto& t : traces) {
    auto sim = fromText(testing::fillModelText());
    ASSERT_TRUE(sim);
    std::ostringstream trace;
    sim->traceTo(trace);
    sim->run({.until = 5.0, .steps = {}});
    t = trace.str();
  }
  EXPECT_FALSE(traces[0].empty());
  EXPECT_EQ(traces[0], traces[1]);
}

TEST(HybridRun, MistakesAreLocatedInTheFile) {
  core::Diagnostics diags;
  auto m = parseModel(R"(gdpn: 1
pages:
  main:
    places:
      tank: {continuous: {amount: 1}, tokens: 2}
    transitions:
      drain: {continuous: {rate: 0.5 * tnak}}
    arcs:
      - {from: tank, to: drain}
)", "bad.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(Simulation::create(*m, diags), nullptr);
  const std::string text = diags.str();
  EXPECT_NE(text.find("bad.gdpn.yaml:5:14: error: continuous place 'tank' holds an amount, not tokens"), std::string::npos)
      << text;
  EXPECT_NE(text.find("bad.gdpn.yaml:7:40: error: rate of continuous transition 'drain': no name 'tnak' (did you mean "
                      "'tank'?)"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace gdpn::model
