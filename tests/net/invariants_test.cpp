// P- and T-invariants against nets whose invariants are known in closed form; every
// invariant reported is checked to really be one; structural properties and cycle-time bounds.

#include "gdpn/net/invariants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "gdpn/net/analysis.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/state_equation.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

using testing::conformanceNet;

/// The invariant's support as place (or transition) names, without the page prefix.
std::set<std::string> support(const Net& net, const Invariant& inv, bool places) {
  std::set<std::string> out;
  for (const auto& [k, w] : inv.weights) {
    std::string n = places ? placeSlotName(net, PlaceSlotId{k}) : net.transitionName(TransitionId{k});
    out.insert(n.substr(n.find('/') + 1));
  }
  return out;
}

void expectAllReal(const Net& net, const Invariants& inv) {
  for (const auto& y : inv.p) EXPECT_TRUE(isPInvariant(net, y));
  for (const auto& x : inv.t) EXPECT_TRUE(isTInvariant(net, x));
  // minimal: no support contains another
  for (std::size_t i = 0; i < inv.p.size(); ++i) {
    for (std::size_t j = 0; j < inv.p.size(); ++j) {
      if (i == j) continue;
      std::set<std::uint32_t> a, b;
      for (auto [k, w] : inv.p[i].weights) a.insert(k);
      for (auto [k, w] : inv.p[j].weights) b.insert(k);
      EXPECT_FALSE(std::includes(a.begin(), a.end(), b.begin(), b.end())) << i << " contains " << j;
    }
  }
}

TEST(Invariants, DiningPhilosophersHaveOnePerForkAndOnePerPhilosopher) {
  // Philosophers-PT-000005: each philosopher's states sum to one, and each fork is either on
  // the table or in one of its two neighbours' hands: 2N minimal P-invariants of weight 1
  auto net = conformanceNet("Philosophers-PT-000005");
  ASSERT_TRUE(net);
  const Invariants inv = invariants(*net);
  ASSERT_TRUE(inv.complete);
  expectAllReal(*net, inv);
  EXPECT_EQ(inv.p.size(), 10u);
  for (const auto& y : inv.p) {
    for (auto [k, w] : y.weights) EXPECT_EQ(w, 1);
  }
  EXPECT_TRUE(inv.conservative);
  EXPECT_TRUE(inv.structurally_bounded);
  // every place bounded by one, as the state space confirms
  for (auto b : inv.bound) EXPECT_EQ(b, 1);
  // T-invariants: each philosopher's eating cycle
  // T-invariants: each philosopher's meal, taking the left fork first or the right one
  EXPECT_EQ(inv.t.size(), 10u);
  for (const auto& x : inv.t) EXPECT_EQ(x.weights.size(), 3u);
  EXPECT_TRUE(inv.consistent);
}

TEST(Invariants, AStateMachineHasOneInvariantAndItsCycles) {
  // a ring of three places with a chord: P-invariant p1+p2+p3; T-invariants: both cycles
  NetBuilder b;
  const auto p1 = b.addPlace("p1"), p2 = b.addPlace("p2"), p3 = b.addPlace("p3");
  b.setSlot(p1, kDefaultSlot, SlotKind::Control, kUnbounded, 2);
  const auto t1 = b.addTransition("t1"), t2 = b.addTransition("t2"), t3 = b.addTransition("t3"),
             t4 = b.addTransition("t4");
  b.addInput(p1, t1), b.addOutput(t1, p2);
  b.addInput(p2, t2), b.addOutput(t2, p3);
  b.addInput(p3, t3), b.addOutput(t3, p1);
  b.addInput(p2, t4), b.addOutput(t4, p1);
  auto net = b.freeze();
  const Invariants inv = invariants(*net);
  expectAllReal(*net, inv);
  ASSERT_EQ(inv.p.size(), 1u);
  EXPECT_EQ(support(*net, inv.p[0], true), (std::set<std::string>{"p1", "p2", "p3"}));
  ASSERT_EQ(inv.t.size(), 2u);
  EXPECT_EQ(support(*net, inv.t[0], false), (std::set<std::string>{"t1", "t2", "t3"}));
  EXPECT_EQ(support(*net, inv.t[1], false), (std::set<std::string>{"t1", "t4"}));
  EXPECT_EQ(inv.bound, (std::vector<std::int64_t>{2, 2, 2}));
}

TEST(Invariants, WeightsAreFoundWhereArcsCarryThem) {
  // t: 2 a -> b; u: b -> 2 a. Invariant a + 2 b.
  NetBuilder b;
  const auto a = b.addPlace("a"), c = b.addPlace("b");
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 4);
  const auto t = b.addTransition("t"), u = b.addTransition("u");
  b.addInput(a, t, kDefaultSlot, 2), b.addOutput(t, c);
  b.addInput(c, u), b.addOutput(u, a, kDefaultSlot, 2);
  auto net = b.freeze();
  const Invariants inv = invariants(*net);
  expectAllReal(*net, inv);
  ASSERT_EQ(inv.p.size(), 1u);
  EXPECT_EQ(inv.p[0].weights, (std::vector<std::pair<std::uint32_t, std::int64_t>>{{0, 1}, {1, 2}}));
  EXPECT_EQ(inv.bound, (std::vector<std::int64_t>{4, 2}));
  ASSERT_EQ(inv.t.size(), 1u);
  EXPECT_EQ(inv.t[0].weights, (std::vector<std::pair<std::uint32_t, std::int64_t>>{{0, 1}, {1, 1}}));
}

TEST(Invariants, AConsumingNetIsStructurallyBoundedButNotConservative) {
  // t: a -> b + c; u: b + c -> (nothing). No P-invariant covers a, yet a + b (and a + c)
  // never grow: structurally bounded, not conservative. A producer is neither.
  NetBuilder b;
  const auto a = b.addPlace("a"), x = b.addPlace("b"), y = b.addPlace("c");
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 3);
  const auto t = b.addTransition("t"), u = b.addTransition("u");
  b.addInput(a, t), b.addOutput(t, x), b.addOutput(t, y);
  b.addInput(x, u), b.addInput(y, u);
  auto net = b.freeze();
  const Invariants inv = invariants(*net);
  EXPECT_FALSE(inv.conservative);
  EXPECT_TRUE(inv.structurally_bounded);
  EXPECT_EQ(inv.bound, (std::vector<std::int64_t>{3, 3, 3}));
  EXPECT_TRUE(inv.t.empty());

  NetBuilder g;
  const auto p = g.addPlace("p");
  const auto q = g.addPlace("q");
  const auto grow = g.addTransition("grow");
  g.addInput(p, grow), g.addOutput(grow, p), g.addOutput(grow, q);
  auto producer = g.freeze();
  const Invariants pi = invariants(*producer);
  EXPECT_FALSE(pi.structurally_bounded);
  EXPECT_EQ(pi.bound, (std::vector<std::int64_t>{0, -1}));
}

TEST(Invariants, EveryReportedInvariantIsRealOnTheConformanceNets) {
  for (const char* model : {"Philosophers-PT-000010", "Dekker-PT-010", "FMS-PT-00002", "Kanban-PT-00005",
                            "SwimmingPool-PT-02", "RobotManipulation-PT-00002", "TokenRing-PT-005",
                            "CircularTrains-PT-012", "ERK-PT-000001", "ResAllocation-PT-R002C002"}) {
    auto net = conformanceNet(model);
    ASSERT_TRUE(net);
    const Invariants inv = invariants(*net);
    EXPECT_TRUE(inv.complete) << model;
    expectAllReal(*net, inv);
    // the bounds from invariants hold in the state space (the two largest are for benchmarks)
    if (std::string(model).starts_with("Kanban") || std::string(model).starts_with("Swimming")) continue;
    const StateSpace s = explore(*net);
    ASSERT_TRUE(s.complete) << model;
    for (PlaceSlotId ps{0}; ps < net->placeSlots().size(); ++ps) {
      const PlaceId place = net->placeSlots()[ps].place;
      if (inv.bound[ps] >= 0) {
        EXPECT_LE(s.place_bound[place], inv.bound[ps]) << model << " " << placeSlotName(*net, ps);
      }
    }
  }
}

/// Each transition's mean duration, seconds, in transition order.
std::vector<double> meanDurations(const Net& net) {
  std::vector<double> seconds;
  for (const auto& t : net.transitions()) seconds.push_back(meanSeconds(t.duration));
  return seconds;
}

/// Adds transition `name` of `seconds` moving one token from `from` to `to`.
TransitionId addTimed(NetBuilder& b, const std::string& name, double seconds, PlaceId from, PlaceId to) {
  Duration d;
  d.a = seconds;
  const auto t = b.addTransition(name, d);
  b.addInput(from, t);
  b.addOutput(t, to);
  return t;
}

TEST(CycleBounds, TwoCyclesGiveBothTimesAndTheLargerBounds) {
  // A: 1.5 + 2.5 s on one token = 4 s; B: 0.25 + 0.5 + 0.25 s on one token = 1 s; C: three
  // transitions of 1 s sharing two tokens = 1.5 s
  NetBuilder b;
  auto ring = [&](const std::string& name, std::vector<double> seconds, std::int64_t tokens) {
    std::vector<PlaceId> places;
    for (std::size_t i = 0; i < seconds.size(); ++i) places.push_back(b.addPlace(name + "p" + std::to_string(i)));
    b.setSlot(places[0], kDefaultSlot, SlotKind::Control, kUnbounded, tokens);
    for (std::size_t i = 0; i < seconds.size(); ++i) {
      Duration d;
      d.a = seconds[i];
      const auto t = b.addTransition(name + "t" + std::to_string(i), d);
      b.addInput(places[i], t);
      b.addOutput(t, places[(i + 1) % places.size()]);
    }
  };
  ring("a", {1.5, 2.5}, 1);
  ring("b", {0.25, 0.5, 0.25}, 1);
  ring("c", {1.0, 1.0, 1.0}, 2);
  auto net = b.freeze();
  const Invariants inv = invariants(*net);
  const auto bounds = cycleBounds(*net, inv, meanDurations(*net));
  ASSERT_EQ(bounds.size(), 3u);
  EXPECT_DOUBLE_EQ(bounds[0].seconds, 4.0);
  EXPECT_DOUBLE_EQ(bounds[1].seconds, 1.5);
  EXPECT_EQ(bounds[1].tokens, 2);
  EXPECT_DOUBLE_EQ(bounds[2].seconds, 1.0);
  EXPECT_EQ(bounds[2].transitions.size(), 3u);
}

TEST(CycleBounds, AChoiceIsACircuitOfItsOwnAndTheLongestBounds) {
  // one token: ready -> work (3 s) -> busy -> finish (12 s) -> ready, or ready -> skip (2 s)
  // -> ready. Summing every transition would say 17 s; the token's longest round trip is 15 s.
  NetBuilder b;
  const auto ready = b.addPlace("ready");
  const auto busy = b.addPlace("busy");
  b.setSlot(ready, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto work = addTimed(b, "work", 3.0, ready, busy);
  const auto finish = addTimed(b, "finish", 12.0, busy, ready);
  addTimed(b, "skip", 2.0, ready, ready);
  auto net = b.freeze();
  const Invariants inv = invariants(*net);
  const auto bounds = cycleBounds(*net, inv, meanDurations(*net));
  ASSERT_EQ(bounds.size(), 1u);
  EXPECT_TRUE(bounds[0].circuit);
  EXPECT_DOUBLE_EQ(bounds[0].seconds, 15.0);
  EXPECT_EQ(bounds[0].transitions, (std::vector<TransitionId>{work, finish}));
}

TEST(CycleBounds, TwoTokensKeepTheSum) {
  NetBuilder b;
  const auto p = b.addPlace("p");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 2);
  Duration d;
  d.a = 3.0;
  const auto t = b.addTransition("t", d);
  b.addInput(p, t);
  b.addOutput(t, p);
  auto net = b.freeze();
  const auto bounds = cycleBounds(*net, invariants(*net), std::vector<double>{3.0});
  ASSERT_EQ(bounds.size(), 1u);
  EXPECT_FALSE(bounds[0].circuit);
  EXPECT_FALSE(bounds[0].flow);
  EXPECT_DOUBLE_EQ(bounds[0].seconds, 1.5);
}

TEST(CycleBounds, TokensTakingAlternativePathsAreAFlowWithoutABound) {
  // three boxes: in -> pass (1 s) -> out, or in -> enter (10 s) -> cell -> leave (2 s) -> out,
  // then back (1 s) -> in. Summed over the tokens, (1 + 10 + 2 + 1) / 3 s would claim a bound
  // that a run where every box passes beats (2 s a round, 3 boxes): no bound, a flow.
  NetBuilder b;
  const auto in = b.addPlace("in");
  const auto cell = b.addPlace("cell");
  const auto out = b.addPlace("out");
  b.setSlot(in, kDefaultSlot, SlotKind::Control, kUnbounded, 3);
  addTimed(b, "pass", 1.0, in, out);
  addTimed(b, "enter", 10.0, in, cell);
  addTimed(b, "leave", 2.0, cell, out);
  addTimed(b, "back", 1.0, out, in);
  auto net = b.freeze();
  const auto bounds = cycleBounds(*net, invariants(*net), meanDurations(*net));
  ASSERT_EQ(bounds.size(), 1u);
  EXPECT_TRUE(bounds[0].flow);
  EXPECT_FALSE(bounds[0].circuit);
  EXPECT_EQ(bounds[0].tokens, 3);
  EXPECT_EQ(bounds[0].seconds, 0.0);
  EXPECT_EQ(bounds[0].transitions.size(), 4u);
}

}  // namespace
}  // namespace gdpn::net

namespace gdpn::net {
namespace {

/// k places p_i emptied into k places q_j by one transition: the k^2 minimal P-invariants
/// p_i + q_j all appear in one elimination step.
std::shared_ptr<const Net> fan(int k) {
  NetBuilder b;
  const auto t = b.addTransition("t");
  for (int i = 0; i < k; ++i) {
    const auto p = b.addPlace("p" + std::to_string(i));
    b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
    b.addInput(p, t);
  }
  for (int i = 0; i < k; ++i) {
    const auto q = b.addPlace("q" + std::to_string(i));
    b.setSlot(q, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
    b.addOutput(t, q);
  }
  return b.freeze();
}

/// A ring of k places, each passing its token on by either of two transitions: 2^k minimal
/// T-invariants (one choice per place), made a doubling at a time.
std::shared_ptr<const Net> diamonds(int k) {
  NetBuilder b;
  std::vector<PlaceId> p;
  for (int i = 0; i < k; ++i) {
    p.push_back(b.addPlace("p" + std::to_string(i)));
    b.setSlot(p.back(), kDefaultSlot, SlotKind::Control, kUnbounded, i == 0 ? 1 : 0);
  }
  for (int i = 0; i < k; ++i) {
    for (const char* side : {"a", "b"}) {
      const auto t = b.addTransition(side + std::to_string(i));
      b.addInput(p[static_cast<std::size_t>(i)], t);
      b.addOutput(t, p[static_cast<std::size_t>((i + 1) % k)]);
    }
  }
  return b.freeze();
}

TEST(InvariantLimits, ASmallRingOfChoicesHasOneTInvariantPerWayRound) {
  const Invariants inv = invariants(*diamonds(6));
  EXPECT_TRUE(inv.complete);
  EXPECT_EQ(inv.t.size(), 64u);
  EXPECT_EQ(inv.p.size(), 1u);
  for (const auto& x : inv.t) EXPECT_TRUE(isTInvariant(*diamonds(6), x));
}

TEST(InvariantLimits, ACutTListLeavesThePListWholeAndTheYesOrNoAnswersToALinearProgram) {
  // 2^40 minimal T-invariants: their list is cut; the one P-invariant is whole, and every
  // transition lies on a way round, which the program says though the list cannot
  const auto net = diamonds(40);
  const Invariants inv = invariants(*net);
  EXPECT_FALSE(inv.complete);
  EXPECT_EQ(inv.stop, ExploreStop::Candidates);
  EXPECT_TRUE(inv.p_complete);
  EXPECT_FALSE(inv.t_complete);
  EXPECT_EQ(inv.p.size(), 1u);
  EXPECT_TRUE(inv.conservative);
  EXPECT_TRUE(inv.structurally_bounded);
  EXPECT_TRUE(inv.consistent);
  // a transition off every way round: the program says no
  NetBuilder b;
  const auto p = b.addPlace("p");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 1);
  const auto q = b.addPlace("q");
  const auto t = b.addTransition("t");
  b.addInput(p, t);
  b.addOutput(t, q);
  const auto back = b.addTransition("back");
  b.addInput(q, back);
  b.addOutput(back, p);
  const auto drain = b.addTransition("drain");
  b.addInput(q, drain);
  const auto small = b.freeze();
  EXPECT_FALSE(*positiveSolution({{{0, -1}, {1, 1}}, {{0, 1}, {1, -1}}, {{1, -1}}}, 2, true));  // t, back, drain
  EXPECT_TRUE(*positiveSolution({{{0, -1}, {1, 1}}, {{0, 1}, {1, -1}}}, 2, true));              // t, back
  EXPECT_FALSE(invariants(*small).consistent);
}

TEST(InvariantLimits, AContestNetThatIsBoundedButNotStructurallyBoundedIsAnsweredWhole) {
  // DoubleExponent-PT-003 (tests/data/bench-nets): the semiflows of y·C <= 0 explode; the
  // invariants phase used to stop there. Its 17 minimal P-invariants and no T-invariant are
  // listed whole (4ti2-rays 1.6.9, an independent count, finds the same 17 rays and none of
  // C·x = 0), and the program says it is not structurally bounded.
  core::Diagnostics diags;
  const auto spec = loadPnml(std::string(GDPN_SOURCE_DIR) + "/tests/data/bench-nets/DoubleExponent-PT-003.pnml", diags);
  ASSERT_TRUE(spec) << diags.str();
  const auto net = compile(*spec, diags);
  ASSERT_TRUE(net) << diags.str();
  const Invariants inv = invariants(*net);
  EXPECT_TRUE(inv.complete);
  EXPECT_TRUE(inv.p_complete);
  EXPECT_TRUE(inv.t_complete);
  EXPECT_EQ(inv.p.size(), 17u);
  EXPECT_TRUE(inv.t.empty());
  EXPECT_FALSE(inv.conservative);
  EXPECT_FALSE(inv.structurally_bounded);
  EXPECT_FALSE(inv.consistent);
  // a second computation: every place on its own row, no slots, no parts alike solved once
  const Incidence c = incidenceMatrix(*net);
  std::vector<std::vector<std::pair<std::uint32_t, std::int64_t>>> rows;
  for (const auto& row : c.by_place) {
    rows.emplace_back();
    for (const auto& [t, v] : row) rows.back().emplace_back(static_cast<std::uint32_t>(t), v);
  }
  InvariantOptions once;
  once.reuse_alike = false;
  ExploreStop stop = ExploreStop::Done;
  auto again = semiflowsOf(rows, net->transitions().size(), once, &stop);
  EXPECT_EQ(stop, ExploreStop::Done);
  auto sorted = [](std::vector<Invariant> v) {
    std::sort(v.begin(), v.end(), [](const Invariant& x, const Invariant& y) { return x.weights < y.weights; });
    return v;
  };
  const auto a = sorted(inv.p), b = sorted(again);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].weights, b[i].weights) << i;
  // each an invariant, none's support within another's
  for (const auto& y : inv.p) EXPECT_TRUE(isPInvariant(*net, y));
  for (const auto& x : inv.p) {
    for (const auto& y : inv.p) {
      if (&x == &y) continue;
      const bool within = std::all_of(x.weights.begin(), x.weights.end(), [&](const auto& e) {
        return std::any_of(y.weights.begin(), y.weights.end(), [&](const auto& f) { return f.first == e.first; });
      });
      EXPECT_FALSE(within) << "a dominated invariant";
    }
  }
}

TEST(InvariantLimits, AnExplodingComputationStopsAtItsDeadlineAndSaysSo) {
  const auto net = diamonds(40);
  InvariantOptions options;
  options.max_candidates = std::size_t{1} << 40;
  options.deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  std::size_t reports = 0;
  options.progress = [&](const InvariantProgress& p) {
    ++reports;
    EXPECT_LE(p.rows, 4 * options.max_candidates);
  };
  const Invariants inv = invariants(*net, options);
  EXPECT_FALSE(inv.complete);
  EXPECT_EQ(inv.stop, ExploreStop::TimeLimit);
  EXPECT_STREQ(stopReason(inv.stop), "partial: --time-limit reached");
  EXPECT_GT(reports, 0u);
}

TEST(InvariantLimits, MemoryAndCandidateLimitsStopItToo) {
  const auto net = fan(280);
  InvariantOptions options;
  options.max_candidates = 100'000;  // fan 280's 78,400 are allowed: memory stops it first
  options.max_bytes = 1 << 20;
  Invariants inv = invariants(*net, options);
  EXPECT_FALSE(inv.complete);
  EXPECT_EQ(inv.stop, ExploreStop::MaxMemory);
  options = {};
  options.max_candidates = 100;
  inv = invariants(*net, options);
  EXPECT_FALSE(inv.complete);
  EXPECT_EQ(inv.stop, ExploreStop::Candidates);
  // small enough: all k^2 of them
  inv = invariants(*fan(6));
  EXPECT_TRUE(inv.complete);
  EXPECT_EQ(inv.stop, ExploreStop::Done);
  EXPECT_EQ(inv.p.size(), 36u);
}

TEST(InvariantLimits, TheStateSpaceStopsAtItsDeadline) {
  // a ring of 40 places, 20 tokens: far too many markings to list in no time
  NetBuilder b;
  for (int i = 0; i < 40; ++i) b.setSlot(b.addPlace("p" + std::to_string(i)), kDefaultSlot, SlotKind::Control, kUnbounded, i % 2);
  for (int i = 0; i < 40; ++i) {
    const auto t = b.addTransition("t" + std::to_string(i));
    b.addInput(static_cast<PlaceId>(i), t);
    b.addOutput(t, static_cast<PlaceId>((i + 1) % 40));
  }
  ExploreOptions options;
  options.deadline = std::chrono::steady_clock::now();
  const StateSpace s = explore(*b.freeze(), options);
  EXPECT_FALSE(s.complete);
  EXPECT_EQ(s.stop, ExploreStop::TimeLimit);
}

}  // namespace
}  // namespace gdpn::net
