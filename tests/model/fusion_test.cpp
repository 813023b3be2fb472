// Fusion places in the model file (format.md, "Fusion places"): a place on two top-level pages
// is one place, its tokens the same through either name, its state space that of the net with
// the two merged by hand; the file keeps the sets when saved.

#include <gtest/gtest.h>

#include <sstream>

#include "gdpn/net/analysis.h"
#include "gdpn/net/compile.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"

namespace gdpn::model {
namespace {

// the stock of `inbound` is the shelf of `outbound`: unload fills it, ship empties it
const char* const kFused = R"(gdpn: 1
settings: {seed: 3}
fusion:
  stock: global
pages:
  inbound:
    places:
      dock: {tokens: 3}
      stock: {fusion: stock, tokens: 1, capacity: 2}
    transitions:
      unload: {duration: {uniform: [1, 2]}}
    arcs:
      - dock -> unload
      - unload -> stock
  outbound:
    places:
      shelf: {fusion: stock}
      shipped: {}
    transitions:
      ship: {duration: {uniform: [2, 3]}}
    arcs:
      - shelf -> ship
      - ship -> shipped
)";

// the same net, the two places merged by hand on one page
const char* const kMerged = R"(gdpn: 1
settings: {seed: 3}
pages:
  main:
    places:
      dock: {tokens: 3}
      stock: {tokens: 1, capacity: 2}
      shipped: {}
    transitions:
      unload: {duration: {uniform: [1, 2]}}
      ship: {duration: {uniform: [2, 3]}}
    arcs:
      - dock -> unload
      - unload -> stock
      - stock -> ship
      - ship -> shipped
)";

Model parse(const std::string& text) {
  core::Diagnostics diags;
  auto m = parseModel(text, "m.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  return m ? std::move(*m) : Model{};
}

/// `text` with every `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

/// The trace of a whole run of `model`.
std::string traceOf(const Model& model) {
  core::Diagnostics diags;
  auto sim = Simulation::create(model, diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  return trace.str();
}

TEST(FusionModel, ThePlaceHoldsTheSameTokensThroughEitherPagesName) {
  const Model model = parse(kFused);
  ASSERT_EQ(model.net.fusions.size(), 1u);
  core::Diagnostics diags;
  auto sim = Simulation::create(model, diags);
  ASSERT_TRUE(sim) << diags.str();
  sim->start();
  std::string error;
  double moved = 0;
  for (int i = 0; i < 600; ++i) {
    const auto a = sim->evaluateNumber("len(sim.place('inbound/stock').a0)", error);
    const auto b = sim->evaluateNumber("len(sim.place('outbound/shelf').a0)", error);
    ASSERT_TRUE(a && b) << error;
    EXPECT_EQ(*a, *b) << "step " << i;
    EXPECT_LE(*a, 2);
    sim->step();
    moved = sim->evaluateNumber("len(sim.place('outbound/shipped').a0)", error).value_or(-1);
  }
  EXPECT_EQ(moved, 4);
}

TEST(FusionModel, ARunsTraceIsThatOfTheNetMergedByHandUpToPageNames) {
  const std::string fused = traceOf(parse(kFused));
  const std::string merged = traceOf(parse(kMerged));
  ASSERT_FALSE(fused.empty());
  EXPECT_NE(fused.find("inbound/stock"), std::string::npos) << fused;  // the declaring member's name
  EXPECT_EQ(fused.find("outbound/shelf"), std::string::npos) << fused;
  EXPECT_EQ(replaced(replaced(fused, "inbound/", "main/"), "outbound/", "main/"), merged);
}

TEST(FusionModel, TheStateSpaceIsThatOfTheNetMergedByHand) {
  core::Diagnostics diags;
  const Model fused = parse(kFused), merged = parse(kMerged);
  auto a = net::compile(fused.net, diags), b = net::compile(merged.net, diags);
  ASSERT_TRUE(a && b) << diags.str();
  EXPECT_EQ(a->places().size(), b->places().size());
  const auto x = net::explore(*a), y = net::explore(*b);
  EXPECT_EQ(x.states, y.states);
  EXPECT_EQ(x.edges, y.edges);
  EXPECT_GT(x.states, 4u);
}

TEST(FusionModel, SavingKeepsTheSetsAndTheirMembers) {
  const Model model = parse(kFused);
  const std::string text = writeModel(model);
  EXPECT_NE(text.find("fusion:\n  stock: global\n"), std::string::npos) << text;
  EXPECT_NE(text.find("shelf: {fusion: stock}"), std::string::npos) << text;
  const Model again = parse(text);
  EXPECT_TRUE(again == model) << text;
  EXPECT_EQ(writeModel(again), text);
}

}  // namespace
}  // namespace gdpn::model
