// Amounts where a user reads or sets a run's numbers (issue 60), against hand-computed
// answers on the fill model: a pump at 0.3 L/s fills a tank; a level switch at 1 L stops it
// at the end of step 34 (3.4 s, 1.02 L). Signals and the io section read amounts; a holding
// register sets one; the report gives each continuous place's extremes and mean and each
// flow's amount and time flowing; the HTML page's run data carries the levels.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/experiments/html_report.h"
#include "gdpn/model/io.h"
#include "gdpn/model/model.h"
#include "gdpn/model/report.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/kernel.h"
#include "gdpn/net/timeline.h"
#include "support/hybrid_models.h"

namespace gdpn::model {
namespace {

struct Run {
  std::optional<Model> model;
  std::unique_ptr<Simulation> sim;
};

Run load(const std::string& text, core::Diagnostics& diags) {
  Run r;
  r.model = parseModel(text, "fill.gdpn.yaml", diags);
  if (r.model) r.sim = Simulation::create(*r.model, diags);
  return r;
}

double amountOf(const Simulation& sim, const char* place) { return sim.kernel().amount(*sim.net().findPlace(place)); }

TEST(HybridFaces, ASignalOnAContinuousPlaceReadsItsAmountAsItsShortestDecimal) {
  core::Diagnostics diags;
  auto r = load(testing::fillModelText() + "signals:\n  level: {place: main/tank}\n  half: {place: main/tank, every: 0.5}\n", diags);
  ASSERT_TRUE(r.sim) << diags.str();
  ASSERT_TRUE(r.sim->recordSignals({}, diags)) << diags.str();
  r.sim->run({.until = 5.0, .steps = {}});
  const SignalTable& t = *r.sim->signals();
  ASSERT_EQ(t.columns, (std::vector<std::string>{"level", "half"}));
  // time 0 and a row per step: 0.3 L/s for 3.4 s, then held
  ASSERT_EQ(t.rows.size(), 36u);
  EXPECT_EQ(*t.rows[0][0], 0.0);
  EXPECT_NEAR(*t.rows[10][0], 0.3, 1e-12);
  EXPECT_NEAR(*t.rows[20][1], 0.6, 1e-12);
  EXPECT_FALSE(t.rows[21][1]);  // half samples every 0.5 s only
  EXPECT_EQ(*t.rows.back()[0], amountOf(*r.sim, "main/tank"));
  EXPECT_NEAR(*t.rows.back()[0], 1.02, 1e-12);
  // the CSV: the shortest text that reads back as the same number
  std::ostringstream csv;
  t.writeCsv(csv);
  std::string line, last;
  for (std::istringstream lines(csv.str()); std::getline(lines, line);) last = line;
  const std::string cell = last.substr(last.find(',') + 1, last.rfind(',') - last.find(',') - 1);
  EXPECT_EQ(cell, core::formatDouble(amountOf(*r.sim, "main/tank")));
  EXPECT_EQ(std::stod(cell), amountOf(*r.sim, "main/tank"));
}

TEST(HybridFaces, TheIoSectionReadsAndSetsAnAmountWithItsScale) {
  core::Diagnostics diags;
  auto r = load(testing::fillModelText() + R"(io:
  discrete_inputs:
    0: {name: wet, place: main/tank}
  input_registers:
    0: {name: level_cl, place: main/tank, scale: 100, unit: cL}
    1: {name: level, place: main/tank, type: float32}
  holding_registers:
    0: {place: main/tank, scale: 10, unit: dL}
)",
                diags);
  ASSERT_TRUE(r.sim) << diags.str();
  auto io = IoMap::create(*r.sim, r.model->io, diags);
  ASSERT_TRUE(io) << diags.str();
  r.sim->start();
  EXPECT_FALSE(io->bit(IoTable::DiscreteInputs, 0));  // empty: 0
  for (int k = 0; k < 5; ++k) r.sim->step();
  // 0.15 L: 15 cL, and 1 while it holds some
  EXPECT_TRUE(io->bit(IoTable::DiscreteInputs, 0));
  EXPECT_EQ(io->word(IoTable::InputRegisters, 0), 15);
  const std::uint32_t high = io->word(IoTable::InputRegisters, 1), low = io->word(IoTable::InputRegisters, 2);
  EXPECT_NEAR(static_cast<double>(std::bit_cast<float>((high << 16) | low)), 0.15, 1e-7);
  // a controller writes 42 dL: 4.2 L
  EXPECT_EQ(io->writeWords(0, {42}, "plc"), IoError::None);
  EXPECT_EQ(amountOf(*r.sim, "main/tank"), 4.2);
  EXPECT_EQ(io->word(IoTable::HoldingRegisters, 0), 42);
  EXPECT_EQ(io->word(IoTable::InputRegisters, 0), 420);
  // 11 L is more than the tank's 10: refused as any refused write, and nothing changes
  EXPECT_EQ(io->writeWords(0, {110}, "plc"), IoError::IllegalValue);
  EXPECT_EQ(amountOf(*r.sim, "main/tank"), 4.2);
  // below 0
  EXPECT_EQ(io->writeWords(0, {static_cast<std::uint16_t>(-5)}, "plc"), IoError::IllegalValue);
  EXPECT_EQ(amountOf(*r.sim, "main/tank"), 4.2);
}

TEST(HybridFaces, ACoilOnAContinuousPlaceIsAnErrorAtItsEntry) {
  core::Diagnostics diags;
  auto r = load(testing::fillModelText() + "io:\n  coils:\n    3: {place: main/tank}\n", diags);
  ASSERT_TRUE(r.sim) << diags.str();
  EXPECT_FALSE(IoMap::create(*r.sim, r.model->io, diags));
  const std::string fill = testing::fillModelText();
  const auto lines = static_cast<int>(std::count(fill.begin(), fill.end(), '\n'));
  EXPECT_NE(diags.str().find("fill.gdpn.yaml:" + std::to_string(lines + 3) + ":5: error: "), std::string::npos)
      << diags.str();
  EXPECT_NE(diags.str().find("place 'main/tank' is continuous: a coil puts a token"), std::string::npos) << diags.str();
}

TEST(HybridFaces, TheReportGivesAmountsExtremesMeansAndWhatEachFlowMoved) {
  core::Diagnostics diags;
  auto r = load(testing::fillModelText(), diags);
  ASSERT_TRUE(r.sim) << diags.str();
  const auto outcome = r.sim->run({.until = 5.0, .steps = {}});
  // stop starts at 3.4 s and completes at 3.5 s: then the net is dead
  EXPECT_EQ(outcome.reason, StopReason::Dead);
  ASSERT_EQ(outcome.steps, 35);
  const Report report = makeReport(*r.sim, outcome);
  ASSERT_EQ(report.amounts.size(), 1u);
  const AmountFigures& tank = report.amounts[0];
  EXPECT_EQ(tank.name, "main/tank");
  EXPECT_EQ(tank.unit, "L");
  EXPECT_NEAR(tank.final_amount, 1.02, 1e-12);
  EXPECT_EQ(tank.lowest, 0.0);
  EXPECT_NEAR(tank.highest, 1.02, 1e-12);
  // 0.3 t rising for 3.4 s, then 1.02 L for 0.1 s: (0.3 x 3.4^2 / 2 + 1.02 x 0.1) / 3.5
  EXPECT_NEAR(tank.mean, (0.3 * 3.4 * 3.4 / 2 + 1.02 * 0.1) / 3.5, 1e-12);
  ASSERT_EQ(report.flows.size(), 1u);
  EXPECT_EQ(report.flows[0].name, "main/pump");
  EXPECT_NEAR(report.flows[0].moved, 1.02, 1e-12);
  EXPECT_EQ(report.flows[0].unit, "L");
  EXPECT_NEAR(report.flows[0].flowing, 3.4 / 3.5, 1e-12);
  // the JSON has them; the summary says them in words, not in the tables of tokens
  const auto json = nlohmann::json::parse(reportJson(report));
  EXPECT_NEAR(json["amounts"][0]["mean"].get<double>(), tank.mean, 1e-15);
  EXPECT_EQ(json["flows"][0]["name"], "main/pump");
  std::ostringstream summary;
  printSummary(summary, report);
  EXPECT_NE(summary.str().find("  main/tank: 1.02 L at the end (0 to 1.02 L, mean 0.5246 L)\n"), std::string::npos)
      << summary.str();
  EXPECT_NE(summary.str().find("  main/pump: moved 1.02 L, flowing 97.1 % of the time\n"), std::string::npos)
      << summary.str();
  EXPECT_EQ(summary.str().find("main/tank   "), std::string::npos) << summary.str();
  std::istringstream lines(summary.str());
  for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 100u) << line;
}

TEST(HybridFaces, AnExponentialDrainsMeanIsTheIntegralOverTheRun) {
  // a e^(-kt) from 10 L with k = 0.5 over 2 s: mean 10 (1 - e^-1) / (0.5 x 2); moved 10 (1 - e^-1)
  core::Diagnostics diags;
  auto r = load(R"(gdpn: 1
settings: {dt: 0.01}
pages:
  main:
    places: {tank: {continuous: {amount: 10, unit: L}}, out: {continuous: {unit: L}}}
    transitions: {drain: {continuous: {rate: 0.5 * tank}}}
    arcs: [{from: tank, to: drain}, {from: drain, to: out}]
)",
                diags);
  ASSERT_TRUE(r.sim) << diags.str();
  const auto outcome = r.sim->run({.until = 2.0, .steps = {}});
  const Report report = makeReport(*r.sim, outcome);
  const double gone = 10.0 * (1.0 - std::exp(-1.0));
  EXPECT_NEAR(report.amounts[0].mean, gone / 1.0, 1e-4);
  EXPECT_NEAR(report.amounts[0].lowest, 10.0 - gone, 1e-6);
  EXPECT_EQ(report.amounts[0].highest, 10.0);
  EXPECT_NEAR(report.flows[0].moved, gone, 1e-4);
  EXPECT_NEAR(report.amounts[1].final_amount, gone, 1e-6);
  EXPECT_EQ(report.flows[0].flowing, 1.0);
}

TEST(HybridFaces, TheHtmlPagesRunDataCarriesEveryContinuousPlacesLevel) {
  core::Diagnostics diags;
  auto r = load(testing::fillModelText(), diags);
  ASSERT_TRUE(r.sim) << diags.str();
  net::Timeline timeline(r.sim->net());
  r.sim->kernel().addObserver(&timeline);
  r.sim->recordLevels();
  const auto outcome = r.sim->run({.until = 5.0, .steps = {}});
  const Report report = makeReport(*r.sim, outcome);
  const auto run = nlohmann::json::parse(
      experiments::runJson(report, r.sim->net(), timeline, r.sim->signals(), r.sim->levels()));
  r.sim->kernel().removeObserver(&timeline);
  const auto& levels = run["levels"];
  ASSERT_EQ(levels["places"].size(), 1u);
  EXPECT_EQ(levels["places"][0]["name"], "main/tank");
  EXPECT_EQ(levels["places"][0]["unit"], "L");
  EXPECT_EQ(levels["places"][0]["capacity"], 10.0);
  ASSERT_EQ(levels["time"].size(), 36u);
  EXPECT_NEAR(levels["time"][17].get<double>(), 1.7, 1e-12);
  EXPECT_NEAR(levels["places"][0]["values"][17].get<double>(), 0.51, 1e-12);
  EXPECT_NEAR(levels["places"][0]["values"][35].get<double>(), 1.02, 1e-12);
}

TEST(HybridFaces, ANetWithoutContinuousPlacesRecordsNoLevels) {
  core::Diagnostics diags;
  auto r = load("gdpn: 1\npages: {main: {places: {a: {tokens: 1}}, transitions: {t: {}}, arcs: [a -> t]}}\n", diags);
  ASSERT_TRUE(r.sim) << diags.str();
  r.sim->recordLevels();
  const auto outcome = r.sim->run({.until = 1.0, .steps = {}});
  EXPECT_EQ(r.sim->levels(), nullptr);
  EXPECT_EQ(r.sim->kernel().fluidTally(), nullptr);
  const Report report = makeReport(*r.sim, outcome);
  EXPECT_TRUE(report.amounts.empty());
  EXPECT_TRUE(report.flows.empty());
  EXPECT_FALSE(nlohmann::json::parse(reportJson(report)).contains("amounts"));
}

}  // namespace
}  // namespace gdpn::model
