// The native state space of coloured nets (coloured_search.h): on every coloured contest model
// of tests/data/conformance-col, the same graph as the unfolded net's (markings, edges, dead
// markings, token maxima, reversibility, which transitions and places ever change), and on
// nets by hand, what unfolding cannot build: a colour set of a million integers, strings.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "gdpn/net/analysis.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/coloured_search.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/unfold.h"
#include "support/coloured_spec.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

using testing::colourConformanceNet;
using testing::kColourConformanceDir;

std::shared_ptr<const Net> colouredNet(const std::string& model) {
  core::Diagnostics diags;
  const auto spec = loadPnml((kColourConformanceDir / model / "model.pnml").string(), diags);
  EXPECT_TRUE(spec) << diags.str();
  if (!spec) return nullptr;
  auto net = compile(*spec, diags);
  EXPECT_TRUE(net) << diags.str();
  return net;
}

class NativeAgainstUnfolded : public ::testing::TestWithParam<const char*> {};

TEST_P(NativeAgainstUnfolded, TheGraphsAgree) {
  const std::string model = GetParam();
  const char* full = std::getenv("GDPN_CONTEST_FULL");
  if (model == "SharedMemory-COL-000010" && !(full != nullptr && std::string(full) == "1")) {
    GTEST_SKIP() << model << " is searched in the label full";
  }
  const auto coloured = colouredNet(model);
  const auto unfolded = colourConformanceNet(model);
  ASSERT_TRUE(coloured && unfolded.net);
  ASSERT_TRUE(coloured->colouring());
  ASSERT_EQ(colouredRefusal(*coloured), "");
  const StateSpace n = exploreColoured(*coloured);
  const StateSpace u = explore(*unfolded.net);
  ASSERT_TRUE(n.complete && u.complete);
  EXPECT_EQ(n.states, u.states);
  EXPECT_EQ(n.edges, u.edges);
  EXPECT_EQ(n.deadlock, u.deadlock);
  EXPECT_EQ(n.dead_markings, u.dead_markings);
  EXPECT_EQ(n.max_marking, u.max_marking);
  // one value in one place slot is one place of the unfolded net
  EXPECT_EQ(n.max_value_count, u.max_place);
  EXPECT_EQ(n.reversible, u.reversible);
  // live in the unfolded net: every binding can occur again; natively, some binding of each
  // transition: the first implies the second
  if (u.live) {
    EXPECT_TRUE(n.live);
  }
  if (n.deadlock) {
    // a shortest path: as long as the unfolded net's shortest one
    ExploreOptions shortest;
    shortest.shortest_path = true;
    EXPECT_EQ(n.deadlock_path.size(), explore(*unfolded.net, shortest).deadlock_path.size());
    EXPECT_EQ(n.deadlock_bindings.size(), n.deadlock_path.size());
  }
  // each coloured transition fires natively when some transition it unfolded to fires; each
  // coloured place is constant when every place it unfolded to is; its bound is at least
  // the most any of them holds
  for (const TransitionId t : coloured->transitionIds()) {
    const std::string name = coloured->transitionName(t);
    const auto it = unfolded.names.transitions.find(name);
    bool any = false;
    if (it == unfolded.names.transitions.end()) {
      any = u.fired[*unfolded.net->findTransition(name)];
    } else {
      for (const auto& x : it->second) any = any || u.fired[*unfolded.net->findTransition(x)];
    }
    EXPECT_EQ(n.fired[t], any) << name;
  }
  std::vector<std::string> constant_u, constant_n;
  for (const PlaceId p : u.constant_places) constant_u.push_back(unfolded.net->placeName(p));
  for (const PlaceId p : coloured->placeIds()) {
    const std::string name = coloured->placeName(p);
    const auto it = unfolded.names.places.find(name);
    const std::vector<std::string> parts = it == unfolded.names.places.end() ? std::vector<std::string>{name} : it->second;
    bool constant = true;
    std::int64_t most = 0;
    for (const auto& x : parts) {
      const PlaceId q = *unfolded.net->findPlace(x);
      constant = constant && std::count(constant_u.begin(), constant_u.end(), x) > 0;
      most = std::max(most, u.place_bound[q]);
    }
    const bool native_constant = std::count(n.constant_places.begin(), n.constant_places.end(), p) > 0;
    EXPECT_EQ(native_constant, constant) << name;
    EXPECT_GE(n.place_bound[p], most) << name;
  }
  // the bindings that occur are the unfolded transitions that fire
  const auto fired = static_cast<std::uint64_t>(std::count(u.fired.begin(), u.fired.end(), true));
  std::uint64_t plain = 0;
  for (const TransitionId t : coloured->transitionIds()) plain += !coloured->colouring()->of(t) && n.fired[t];
  EXPECT_EQ(n.bindings + plain, fired);
}

INSTANTIATE_TEST_SUITE_P(Contest, NativeAgainstUnfolded,
                         ::testing::Values("DrinkVendingMachine-COL-02", "LamportFastMutEx-COL-2", "NeoElection-COL-2",
                                           "Philosophers-COL-000005", "SharedMemory-COL-000005", "Sudoku-COL-AN01",
                                           "Sudoku-COL-AN02", "TokenRing-COL-005"));
INSTANTIATE_TEST_SUITE_P(Big, NativeAgainstUnfolded, ::testing::Values("SharedMemory-COL-000010"));

using testing::Coloured;
using testing::range;

TEST(ColouredSearch, ACounterOverAMillionIntegersIsSearchedWhereUnfoldingRefuses) {
  // x counts from 0 to 999 in a set of 10^6 values: 1,000 markings in a row
  Coloured c;
  c.set(range("N", 0, 999'999)).variable("x", "N").place("count", "N", "0").transition("inc", "x < 999");
  c.arc("count", "inc", "x").arc("inc", "count", "x + 1");
  const auto net = c.compiled();
  ASSERT_TRUE(net);
  core::Diagnostics diags;
  EXPECT_FALSE(unfold(c.spec, diags, 100'000)) << "unfolding would need a place per value";
  const StateSpace s = exploreColoured(*net);
  ASSERT_TRUE(s.complete);
  EXPECT_EQ(s.states, 1000u);
  EXPECT_EQ(s.edges, 999u);
  EXPECT_EQ(s.bindings, 999u);
  EXPECT_TRUE(s.deadlock);
  EXPECT_EQ(s.dead_markings, 1u);
  ASSERT_EQ(s.deadlock_path.size(), 999u);
  EXPECT_EQ(s.deadlock_bindings.front(), "x=0");
  EXPECT_EQ(s.deadlock_bindings.back(), "x=998");
  EXPECT_EQ(s.max_value_count, 1);
  EXPECT_EQ(s.max_place, 1);
  EXPECT_TRUE(s.one_safe);
  EXPECT_FALSE(s.reversible);
  EXPECT_FALSE(s.live);
  EXPECT_TRUE(s.quasi_live);
}

TEST(ColouredSearch, RecordsWithStringsMoveOneByOne) {
  Coloured c;
  ColourSetSpec job;
  job.name = "Job";
  job.kind = ColourKind::Record;
  job.components = {"int", "string"};
  job.fields = {"id", "name"};
  c.set(job).variable("j", "Job");
  c.place("queue", "Job", "1'{id = 1, name = \"saw\"} ++ 2'{id = 2, name = \"drill\"}").place("done", "Job");
  c.transition("work").arc("queue", "work", "j").arc("work", "done", "{id = j.id + 10, name = j.name}");
  const auto net = c.compiled();
  ASSERT_TRUE(net);
  const StateSpace s = exploreColoured(*net);
  ASSERT_TRUE(s.complete);
  // (saw moved or not) x (0, 1 or 2 drills moved)
  EXPECT_EQ(s.states, 6u);
  EXPECT_EQ(s.edges, 7u);
  EXPECT_EQ(s.bindings, 2u);
  EXPECT_EQ(s.dead_markings, 1u);
  EXPECT_EQ(s.deadlock_path.size(), 3u);
  EXPECT_EQ(s.max_value_count, 2);
  EXPECT_EQ(s.max_place, 3);
  EXPECT_EQ(s.max_marking, 3);
}

TEST(ColouredSearch, ACapacityOnAValueSlotCountsEveryValue) {
  // three balls into a bin that holds two: the empty bin, three with one, three with two
  Coloured c;
  ColourSetSpec colour;
  colour.name = "Colour";
  colour.kind = ColourKind::Enum;
  colour.constants = {"red", "green", "blue"};
  c.set(colour).variable("b", "Colour");
  c.place("belt", "Colour", "red ++ green ++ blue").place("bin", "Colour", "", 2);
  c.transition("drop").arc("belt", "drop", "b").arc("drop", "bin", "b");
  const auto net = c.compiled();
  ASSERT_TRUE(net);
  const StateSpace s = exploreColoured(*net);
  ASSERT_TRUE(s.complete);
  EXPECT_EQ(s.states, 7u);
  EXPECT_EQ(s.edges, 9u);
  EXPECT_EQ(s.dead_markings, 3u);
  EXPECT_EQ(s.deadlock_path.size(), 2u);
  EXPECT_EQ(s.place_bound[*net->findPlace("main/bin")], 2);
  EXPECT_EQ(s.place_bound[*net->findPlace("main/belt")], 3);
  EXPECT_TRUE(s.constant_places.empty());
}

TEST(ColouredSearch, AStartThatIsNeverMetAgainLeavesTheNetLive) {
  // 0 -> 1 -> 2 -> 1 -> 2 ...: the start is a component of its own that the first firing
  // leaves; the bottom one {1, 2} fires both transitions
  Coloured c;
  c.set(range("N", 0, 2)).variable("x", "N").place("p", "N", "0").transition("t").transition("u", "x > 0");
  c.arc("p", "t", "x").arc("t", "p", "if x = 2 then 1 else x + 1").arc("p", "u", "x").arc("u", "p", "x");
  const auto net = c.compiled();
  ASSERT_TRUE(net);
  const StateSpace s = exploreColoured(*net);
  ASSERT_TRUE(s.complete);
  EXPECT_EQ(s.states, 3u);
  EXPECT_EQ(s.edges, 5u);
  EXPECT_TRUE(s.live);
  EXPECT_FALSE(s.reversible);
}

TEST(ColouredSearch, LimitsCutItShort) {
  Coloured c;
  c.set(range("N", 0, 999'999)).variable("x", "N").place("count", "N", "0").transition("inc", "x < 999");
  c.arc("count", "inc", "x").arc("inc", "count", "x + 1");
  const auto net = c.compiled();
  ASSERT_TRUE(net);
  ExploreOptions o;
  o.max_states = 100;
  const StateSpace s = exploreColoured(*net, o);
  EXPECT_FALSE(s.complete);
  EXPECT_EQ(s.stop, ExploreStop::MaxStates);
  EXPECT_FALSE(s.decided);
  EXPECT_LE(s.states, 102u);
}

}  // namespace
}  // namespace gdpn::net
