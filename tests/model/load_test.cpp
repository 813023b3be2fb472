// Reading model files: what each form of the format means.

#include <gtest/gtest.h>

#include "gdpn/model/model.h"
#include "gdpn/net/compile.h"

namespace gdpn::model {
namespace {

Model parse(const std::string& text) {
  core::Diagnostics diags;
  auto m = parseModel(text, "t.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  return m.value_or(Model{});
}

TEST(Load, AModelWithNoSectionsTakesTheDefaults) {
  // (an empty file is refused: see BadInput.AnEmptyFileIsRefusedAtItsFirstLine)
  const Model m = parse("gdpn: 1\n");
  EXPECT_TRUE(m.net.pages.empty());
  EXPECT_DOUBLE_EQ(m.settings.dt, 1.0 / 60.0);
  EXPECT_EQ(m.settings.seed, 1u);
  EXPECT_FALSE(m.settings.until);
}

TEST(Load, ScalarsMeanSlotA0AndMapsNameSlots) {
  const Model m = parse(R"(
pages:
  main:
    places:
      P: {tokens: 2, capacity: 5}
      Q: {tokens: {b3: 1, d0: [x, y/z]}, capacity: {b3: 2}}
)");
  const auto& p = m.net.pages[0].places[0];
  ASSERT_EQ(p.tokens.size(), 1u);
  EXPECT_EQ(p.tokens[0].slot, 0);
  EXPECT_EQ(p.tokens[0].value, 2);
  EXPECT_EQ(p.capacity[0].value, 5);
  const auto& q = m.net.pages[0].places[1];
  EXPECT_EQ(net::slotName(q.tokens[0].slot), "b3");
  ASSERT_EQ(q.nodes.size(), 1u);
  EXPECT_EQ(net::slotName(q.nodes[0].slot), "d0");
  EXPECT_EQ(q.nodes[0].nodes, (std::vector<std::string>{"x", "y/z"}));
}

TEST(Load, ArcShorthandAndMapFormAreTheSame) {
  const Model m = parse(R"(
pages:
  main:
    arcs:
      - P -> T
      - {from: P, to: T}
      - {from: G, to: T, kind: inhibitor, weight: {a0: 2, c1: 1}}
)");
  const auto& arcs = m.net.pages[0].arcs;
  ASSERT_EQ(arcs.size(), 3u);
  EXPECT_EQ(arcs[0], arcs[1]);
  EXPECT_EQ(arcs[2].kind, net::ArcKind::Inhibitor);
  ASSERT_EQ(arcs[2].weights.size(), 2u);
  EXPECT_EQ(arcs[2].weights[1].value, 1);
}

TEST(Load, DurationLaws) {
  const Model m = parse(R"(
pages:
  main:
    transitions:
      a: {duration: 2.5}
      b: {duration: {uniform: [1, 3]}}
      c: {duration: {normal: [4, 0.5]}}
      d: {duration: {exponential: 7}}
      e: {priority: -3, probability: 0.25}
)");
  const auto& t = m.net.pages[0].transitions;
  using Law = net::Duration::Law;
  EXPECT_EQ(t[0].duration, (net::Duration{Law::Fixed, 2.5, 0, {}}));
  EXPECT_EQ(t[1].duration, (net::Duration{Law::Uniform, 1, 3, {}}));
  EXPECT_EQ(t[2].duration, (net::Duration{Law::Normal, 4, 0.5, {}}));
  EXPECT_EQ(t[3].duration, (net::Duration{Law::Exponential, 7, 0, {}}));
  EXPECT_EQ(t[4].priority, -3);
  EXPECT_DOUBLE_EQ(t[4].probability, 0.25);
}

TEST(Load, InstancesInBothForms) {
  const Model m = parse(R"(
pages:
  line:
    instances:
      a: cell
      b: {type: cell, at: [1, 2]}
page_types:
  cell:
    references: [in]
    places:
      in: {}
)");
  const auto& inst = m.net.pages[0].instances;
  EXPECT_EQ(inst[0].type, "cell");
  EXPECT_EQ(inst[1].type, "cell");
  EXPECT_EQ(inst[1].position, (net::EditorPos{1, 2}));
  EXPECT_EQ(m.net.page_types[0].references[0].place, "in");
}

TEST(Load, LocationsPointAtTheConstructs) {
  const Model m = parse("pages:\n  main:\n    places:\n      P: {}\n    transitions:\n      T: {}\n");
  EXPECT_EQ(m.net.pages[0].places[0].loc, (core::SourceLoc{"t.gdpn.yaml", 4, 7}));
  EXPECT_EQ(m.net.pages[0].transitions[0].loc, (core::SourceLoc{"t.gdpn.yaml", 6, 7}));
}

}  // namespace
}  // namespace gdpn::model
