// Bounds from the state equation (a linear program per place): never below what the state
// space reaches, exact where the answer is known, and a bound where the invariants give none.

#include "gdpn/net/state_equation.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/net/analysis.h"
#include "gdpn/net/builder.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

using testing::conformanceNet;
using testing::kConformanceDir;

std::vector<std::string> conformanceModels() {
  std::vector<std::string> out;
  std::ifstream in(kConformanceDir / "reference.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string model;
    f >> model;
    if (model != "Kanban-PT-00005" && model != "SwimmingPool-PT-02") out.push_back(model);  // benchmark-sized
  }
  return out;
}

TEST(StateEquation, NoBoundFallsBelowWhatTheStateSpaceReaches) {
  std::size_t bounded = 0, checked = 0;
  for (const auto& model : conformanceModels()) {
    SCOPED_TRACE(model);
    const auto net = conformanceNet(model);
    ASSERT_TRUE(net);
    const std::vector<bool> all(net->placeSlots().size(), true);
    const auto lp = stateEquationBounds(*net, all);
    const StateSpace s = explore(*net);
    ASSERT_TRUE(s.complete);
    for (PlaceId p{0}; p < net->places().size(); ++p) {
      // one slot per place in these nets
      const auto ps = net->places()[p].slots_begin;
      if (lp[ps] < 0) continue;
      ++bounded;
      ASSERT_NE(s.place_bound[p], kOmega) << net->placeName(p);
      EXPECT_GE(lp[ps], s.place_bound[p]) << net->placeName(p);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
  EXPECT_EQ(bounded, checked);
}

/// p -> t -> 2 q, q -> u -> p: every firing of t doubles what u can give back, but u takes
/// two from q for one in p: M(p) + M(q) / 2 stays 1, so q holds 2 at most, p 1.
TEST(StateEquation, WeightsBoundPlacesExactly) {
  NetBuilder b;
  const auto p = b.addPlace("p");
  const auto q = b.addPlace("q");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  b.setSlot(q, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
  const auto t = b.addTransition("t");
  const auto u = b.addTransition("u");
  b.addInput(p, t);
  b.addOutput(t, q, kDefaultSlot, 2);
  b.addInput(q, u, kDefaultSlot, 2);
  b.addOutput(u, p);
  const auto net = b.freeze();
  const auto lp = stateEquationBounds(*net, {true, true});
  EXPECT_EQ(lp[0], 1);
  EXPECT_EQ(lp[1], 2);
}

/// A producer without a consumer: its buffer has no bound, and the program says so; a place
/// with a capacity is bounded by it.
TEST(StateEquation, AnUnboundedPlaceHasNoBoundAndACapacityIsOne) {
  NetBuilder b;
  const auto ready = b.addPlace("ready");
  const auto buffer = b.addPlace("buffer");
  const auto box = b.addPlace("box");
  b.setSlot(ready, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  b.setSlot(buffer, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
  b.setSlot(box, kDefaultSlot, SlotKind::Control, 3, 0);
  const auto make = b.addTransition("make");
  b.addInput(ready, make);
  b.addOutput(make, ready);
  b.addOutput(make, buffer);
  const auto fill = b.addTransition("fill");  // the box's capacity stops fill, not make
  b.addInput(ready, fill);
  b.addOutput(fill, ready);
  b.addOutput(fill, box);
  const auto net = b.freeze();
  const auto lp = stateEquationBounds(*net, {true, true, true});
  EXPECT_EQ(lp[0], 1);
  EXPECT_EQ(lp[1], -1);
  EXPECT_EQ(lp[2], 3);
  // only what is asked for is worked out
  const auto some = stateEquationBounds(*net, {true, false, false});
  EXPECT_EQ(some[0], 1);
  EXPECT_EQ(some[2], -1);
}

}  // namespace
}  // namespace gdpn::net
