// Value tokens in whole runs (semantics.md, Value tokens): the job shop example, the binding
// scripts see, the report's values and a trace the seed fixes byte for byte.

#include <gtest/gtest.h>

#include <sstream>

#include "gdpn/model/model.h"
#include "gdpn/model/report.h"
#include "gdpn/model/simulation.h"
#include "support/sim_helpers.h"
#include "support/sorted_balls.h"

namespace gdpn::model {
namespace {

std::unique_ptr<Simulation> fromText(const std::string& text, std::optional<std::uint64_t> seed = {}) {
  core::Diagnostics diags;
  auto m = parseModel(text, "value.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return nullptr;
  auto sim = Simulation::create(*m, diags, seed);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

const PlaceFigures& place(const Report& r, const std::string& name) {
  for (const auto& p : r.places) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no place " + name);
}

TEST(ValueRun, TheJobShopShipsEveryJobAndReturnsEveryMachine) {
  auto sim = testing::openModelFile("examples/coloured/job_shop/job_shop.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto outcome = sim->run({});
  const auto r = makeReport(*sim, outcome);
  EXPECT_EQ(place(r, "main/shipped").final_tokens, 4);
  EXPECT_EQ(place(r, "main/shipped").final_values,
            "1'{id = 1, kind = shaft} ++ 1'{id = 2, kind = gear} ++ 1'{id = 3, kind = plate} ++ "
            "1'{id = 4, kind = plate}");
  EXPECT_EQ(place(r, "main/idle").final_values, "1'lathe ++ 1'mill ++ 1'drill");
  EXPECT_EQ(place(r, "main/operators").final_tokens, 2);
  EXPECT_EQ(place(r, "main/waiting").final_values, "empty");
  // the drill never took job 3 (its condition): the trace's bindings say who took what
  std::ostringstream text;
  printSummary(text, r);
  EXPECT_NE(text.str().find("main/shipped: 1'{id = 1, kind = shaft}"), std::string::npos) << text.str();
}

TEST(ValueRun, TheDrillNeverTakesJobThreeAndEveryStartIsASkillOfItsMachine) {
  auto sim = testing::openModelFile("examples/coloured/job_shop/job_shop.gdpn.yaml");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  std::istringstream lines(trace.str());
  std::string line;
  int starts = 0;
  while (std::getline(lines, line)) {
    if (line.find("\"transition\":\"main/load\",\"binding\"") == std::string::npos) continue;
    ++starts;
    EXPECT_EQ(line.find("\"j\":\"{id = 3, kind = plate}\",\"m\":\"drill\""), std::string::npos) << line;
    const bool shaft = line.find("kind = shaft") != std::string::npos, gear = line.find("kind = gear") != std::string::npos;
    if (shaft) {
      EXPECT_NE(line.find("\"m\":\"lathe\""), std::string::npos) << line;
    }
    if (gear) {
      EXPECT_NE(line.find("\"m\":\"mill\""), std::string::npos) << line;
    }
  }
  EXPECT_GE(starts, 4);
}

TEST(ValueRun, TheColouredSortingDevicePutsEachBallInTheBinOfItsColour) {
  // examples/sorting/coloured, seed 7: the sensor's reading becomes a value in `seen`, the
  // conditions on it route blue to the left bin (-y) and red to the right (+y)
  auto sim = testing::openModelFile("examples/sorting/coloured/sorting.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::Dead) << outcome.message;
  // in the plant: every ball landed on the side of its colour (its material says which)
  const auto [blue, red] = testing::sortedBalls(*sim);
  EXPECT_EQ(blue, 23);
  EXPECT_EQ(red, 27);
  // in the net: a value per ball, each bin holding its own colour alone, the gate clear
  const auto r = makeReport(*sim, outcome);
  EXPECT_EQ(place(r, "main/left_bin").final_values, "23'blue");
  EXPECT_EQ(place(r, "main/right_bin").final_values, "27'red");
  EXPECT_EQ(place(r, "main/seen").final_values, "empty");
  EXPECT_EQ(place(r, "main/stock").final_tokens, 0);
  EXPECT_EQ(place(r, "main/clear").final_tokens, 1);
  // the model's summary counts the same from the balls' user data and positions
  std::string error;
  const auto figures = sim->modelFigures(error);
  ASSERT_EQ(error, "");
  std::vector<std::pair<std::string, double>> numbers;
  for (const auto& f : figures) numbers.emplace_back(f.label, f.value.value_or(-1));
  EXPECT_EQ(numbers, (std::vector<std::pair<std::string, double>>{{"balls dropped", 50},
                                                                  {"blue in the left bin", 23},
                                                                  {"red in the left bin", 0},
                                                                  {"red in the right bin", 27},
                                                                  {"blue in the right bin", 0}}));
}

TEST(ValueRun, TheSameSeedGivesTheSameTraceAndAnotherSeedAnotherOne) {
  auto trace = [](std::uint64_t seed) {
    auto sim = testing::openModelFile("examples/coloured/job_shop/job_shop.gdpn.yaml", seed);
    std::ostringstream out;
    if (!sim) return std::string();
    sim->traceTo(out);
    sim->run({});
    return out.str();
  };
  const auto a = trace(11);
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, trace(11));
  EXPECT_NE(a, trace(12));
}

TEST(ValueRun, ScriptsSeeTheBindingOfTheirOccurrence) {
  auto sim = fromText(R"yaml(gdpn: 1
settings: {dt: 1, until: 3}
colours:
  N: {range: [1, 9]}
  Name: string
  Pair: {product: [N, Name]}
  Job: {record: {id: N, who: Name}}
variables:
  n: N
  s: Name
pages:
  main:
    places:
      P: {colour: Pair, values: "1'(4, \"ann\")"}
      Q: {colour: Job}
    transitions:
      T:
        duration: 1
        when: "n > 2"
        pre_fire: sim.log(f"pre {self.binding.n} {self.binding.s}")
        post_fire: sim.log(f"post {self.binding.n * 2} {type(self.binding.s).__name__}")
    arcs:
      - {from: P, to: T, inscription: "(n, s)"}
      - {from: T, to: Q, inscription: "{id = n + 1, who = s}"}
)yaml");
  ASSERT_TRUE(sim);
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  EXPECT_EQ(testing::logLines(trace.str()), (std::vector<std::string>{"pre 4 ann", "post 8 str"}));
  EXPECT_NE(trace.str().find(R"("binding":{"n":"4","s":"\"ann\""})"), std::string::npos) << trace.str();
  EXPECT_NE(trace.str().find(R"("place":"main/Q","slot":"a0","count":1,"values":"1'{id = 5, who = \"ann\"}"})"),
            std::string::npos)
      << trace.str();
}

}  // namespace
}  // namespace gdpn::model
