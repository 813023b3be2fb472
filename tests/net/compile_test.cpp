// compile(): slot-kind propagation and the structural checks (locations are checked in the
// model tests, where the input is a file).

#include "gdpn/net/compile.h"

#include <gtest/gtest.h>

#include "support/spec_helpers.h"

namespace gdpn::net {
namespace {

using namespace gdpn::testing;
constexpr SlotId d0 = 24;

TEST(Compile, NodeKindPropagatesAlongArcs) {
  // P declares d0 as node (by its tokens); Q and R only meet d0 through arcs
  NetSpec spec;
  PageSpec page;
  page.name = "main";
  PlaceSpec p = place("P");
  p.nodes.push_back({d0, {"box"}, {}});
  page.places = {p, place("Q"), place("R")};
  page.transitions = {transition("T"), transition("U")};
  page.arcs = {arc("P", "T", {{d0, 1, {}}}), arc("T", "Q", {{d0, 1, {}}}), arc("Q", "U", {{d0, 1, {}}}),
               arc("U", "R", {{d0, 1, {}}})};
  spec.pages = {page};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  for (const char* name : {"main/P", "main/Q", "main/R"}) {
    const auto ps = net->findPlaceSlot(*net->findPlace(name), d0);
    ASSERT_TRUE(ps) << name;
    EXPECT_EQ(net->placeSlots()[*ps].kind, SlotKind::Node) << name;
  }
  EXPECT_EQ(net->transitions()[0].node_slot_mask, 1u << d0);
}

TEST(Compile, UnconnectedSlotsDefaultToControl) {
  NetSpec spec;
  PageSpec page;
  page.name = "main";
  page.places = {place("P", 2)};
  spec.pages = {page};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net);
  EXPECT_EQ(net->placeSlots()[0].kind, SlotKind::Control);
  EXPECT_EQ(net->placeSlots()[0].initial, 2);
}

TEST(Compile, TwoKindsForOneSlotNamesBothPlaces) {
  NetSpec spec;
  PageSpec page;
  page.name = "main";
  PlaceSpec p = place("P");
  p.nodes.push_back({d0, {"box"}, {"f", 2, 3}});
  PlaceSpec q = place("Q");
  q.tokens.push_back({d0, 1, {"f", 5, 3}});
  page.places = {p, q};
  page.transitions = {transition("T")};
  page.arcs = {arc("P", "T", {{d0, 1, {}}}), arc("T", "Q", {{d0, 1, {}}})};
  spec.pages = {page};
  core::Diagnostics diags;
  EXPECT_FALSE(compile(spec, diags));
  EXPECT_NE(diags.str().find("f:5:3: error: slot d0 is control on place 'main/Q' but node on place 'main/P'"),
            std::string::npos)
      << diags.str();
  EXPECT_NE(diags.str().find("f:2:3: note:"), std::string::npos);
}

TEST(Compile, OutputTakesWhatItsTransitionRemovesFromTheSamePlace) {
  NetSpec spec;
  PageSpec page;
  page.name = "main";
  page.places = {place("P", 1, 1)};
  page.transitions = {transition("T")};
  page.arcs = {arc("P", "T"), arc("T", "P")};
  spec.pages = {page};
  core::Diagnostics diags;
  auto net = compile(spec, diags);
  ASSERT_TRUE(net);
  const auto terms = net->termsOf(TransitionId{0});
  ASSERT_EQ(terms.size(), 2u);
  EXPECT_EQ(terms[1].kind, TermKind::Output);
  EXPECT_EQ(terms[1].take, 1);
}

}  // namespace
}  // namespace gdpn::net
