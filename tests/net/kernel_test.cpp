// The kernel against the rules of semantics.md §5-§7, one test per rule.

#include "gdpn/net/kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "gdpn/net/builder.h"
#include "net/detail/sort_keys.h"
#include "support/recorder.h"

namespace gdpn::net {
namespace {

using testing::Recorder;

constexpr SlotKind kControl = SlotKind::Control;

Duration seconds(double s) { return Duration{Duration::Law::Fixed, s, 0.0, {}}; }

/// Marking of place `name` at slot a0.
std::int64_t tokens(const Kernel& k, const char* name) {
  const auto p = k.net().findPlace(name);
  if (!p) {
    ADD_FAILURE() << "no place " << name;
    return -1;
  }
  const auto ps = k.net().findPlaceSlot(*p, kDefaultSlot);
  return ps ? k.marking(*ps) : 0;
}

bool enabled(const Kernel& k, const char* name) {
  return k.enabled(*k.net().findTransition(name));
}

// Figure 3.1: T1 takes P1 and P2 into P3; T2 moves P3 to P4 and refills P2. All capacities 1.
std::shared_ptr<const Net> figure31() {
  NetBuilder b;
  PlaceId p[4];
  for (int i = 0; i < 4; ++i) {
    p[i] = b.addPlace("P" + std::to_string(i + 1));
    b.setSlot(p[i], kDefaultSlot, kControl, 1, i < 2 ? 1 : 0);
  }
  const auto t1 = b.addTransition("T1");
  const auto t2 = b.addTransition("T2");
  b.addInput(p[0], t1);
  b.addInput(p[1], t1);
  b.addOutput(t1, p[2]);
  b.addInput(p[2], t2);
  b.addOutput(t2, p[3]);
  b.addOutput(t2, p[1]);
  return b.freeze();
}

TEST(Figure31, GoesThroughItsThreeMarkingsThenHalts) {
  Kernel k(figure31(), {1.0, 1});
  // marking a: tokens on P1 and P2; only T1 is enabled
  EXPECT_EQ((std::vector<std::int64_t>{tokens(k, "P1"), tokens(k, "P2"), tokens(k, "P3"), tokens(k, "P4")}),
            (std::vector<std::int64_t>{1, 1, 0, 0}));
  EXPECT_TRUE(enabled(k, "T1"));
  EXPECT_FALSE(enabled(k, "T2"));
  k.start();
  k.beginStep();
  k.completeOccurrences();
  // marking b: T1 has put its token on P3; T2 is enabled because T1 emptied P2
  EXPECT_EQ((std::vector<std::int64_t>{tokens(k, "P1"), tokens(k, "P2"), tokens(k, "P3"), tokens(k, "P4")}),
            (std::vector<std::int64_t>{0, 0, 1, 0}));
  EXPECT_FALSE(enabled(k, "T1"));
  EXPECT_TRUE(enabled(k, "T2"));
  k.fireEnabled();
  k.step();
  // marking c: nothing is enabled and nothing occurs
  EXPECT_EQ((std::vector<std::int64_t>{tokens(k, "P1"), tokens(k, "P2"), tokens(k, "P3"), tokens(k, "P4")}),
            (std::vector<std::int64_t>{0, 1, 0, 1}));
  EXPECT_TRUE(k.dead());
}

TEST(Figure31, OutputPlaceAlreadyFullBlocksT2) {
  // with P2 still marked, T2 has no room on P2 even when P3 holds a token
  NetBuilder b;
  const auto p2 = b.addPlace("P2");
  const auto p3 = b.addPlace("P3");
  b.setSlot(p2, kDefaultSlot, kControl, 1, 1);
  b.setSlot(p3, kDefaultSlot, kControl, 1, 1);
  const auto t2 = b.addTransition("T2");
  b.addInput(p3, t2);
  b.addOutput(t2, p2);
  Kernel k(b.freeze(), {1.0, 1});
  EXPECT_FALSE(k.enabled(t2));
}

TEST(NetKernel, NormalArcNeedsItsWeightAndTakesIt) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 3);
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(p, t, kDefaultSlot, 2);
  b.addOutput(t, q);
  Kernel k(b.freeze(), {1.0, 1});
  EXPECT_TRUE(k.enabled(t));
  k.start();
  EXPECT_EQ(tokens(k, "P"), 1);
  EXPECT_EQ(tokens(k, "Q"), 0);  // deposited only on completion
  k.step();
  EXPECT_EQ(tokens(k, "Q"), 1);
  EXPECT_FALSE(k.enabled(t));  // one token left, weight 2
  EXPECT_TRUE(k.dead());
}

TEST(NetKernel, ATokenSetBetweenStepsEnablesInTheNextStep) {
  // a marking set from outside between two steps (a Modbus controller, the Python module)
  // makes the transition a candidate of the next step's firing phase, and of every later one
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  const auto t = b.addTransition("T", seconds(0.5));
  b.addInput(p, t);
  b.addOutput(t, q);
  Kernel k(b.freeze(), {1.0, 1});
  k.start();
  k.step();
  const auto ps = k.net().findPlaceSlot(*k.net().findPlace("P"), kDefaultSlot);
  ASSERT_TRUE(ps);
  ASSERT_EQ(k.setMarking(*ps, 2), "");
  EXPECT_TRUE(k.enabled(t));
  k.step();
  EXPECT_EQ(tokens(k, "P"), 1) << "T started in the step after the tokens came";
  k.step();
  EXPECT_EQ(tokens(k, "Q"), 1);
  EXPECT_EQ(tokens(k, "P"), 0) << "and again, once its first occurrence ended";
}

TEST(NetKernel, TestArcNeedsTokensButLeavesThem) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 2);
  const auto t1 = b.addTransition("T1", seconds(5));
  const auto t2 = b.addTransition("T2", seconds(5));
  b.addInput(p, t1, kDefaultSlot, 2, ArcKind::Test);
  b.addInput(p, t2, kDefaultSlot, 2, ArcKind::Test);
  Kernel k(b.freeze(), {1.0, 1});
  k.start();
  // both start in the same step: neither takes the tokens the other needs
  EXPECT_TRUE(k.occurring(t1));
  EXPECT_TRUE(k.occurring(t2));
  EXPECT_EQ(tokens(k, "P"), 2);
}

TEST(NetKernel, InhibitorArcBlocksWhileMarked) {
  NetBuilder b;
  const auto guard = b.addPlace("Guard");
  const auto src = b.addPlace("Src");
  b.setSlot(guard, kDefaultSlot, kControl, kUnbounded, 2);
  b.setSlot(src, kDefaultSlot, kControl, kUnbounded, 5);
  const auto drain = b.addTransition("Drain", seconds(1));
  b.addInput(guard, drain);
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(guard, t, kDefaultSlot, 1, ArcKind::Inhibitor);  // allowed only while Guard < 1
  b.addInput(src, t);
  Kernel k(b.freeze(), {1.0, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  EXPECT_FALSE(k.enabled(t));
  k.start();  // Drain takes one of the two guard tokens
  EXPECT_FALSE(k.enabled(t));
  k.step();   // Drain starts again and takes the second: now T is allowed,
  EXPECT_TRUE(k.enabled(t));  // but it became enabled during the firing phase, so it waits
  EXPECT_TRUE(rec.startsOf("T").empty());
  k.step();
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{2}));
}

TEST(NetKernel, InhibitorWeightIsAThreshold) {
  NetBuilder b;
  const auto g = b.addPlace("G");
  b.setSlot(g, kDefaultSlot, kControl, kUnbounded, 2);
  const auto t = b.addTransition("T");
  b.addInput(g, t, kDefaultSlot, 3, ArcKind::Inhibitor);  // 2 < 3: allowed
  Kernel k(b.freeze(), {1.0, 1});
  EXPECT_TRUE(k.enabled(t));
}

TEST(NetKernel, ReserveKeepsRoomForAnOccurringTransition) {
  // A and B both feed Out (capacity 1). A starts at 0 and occurs for 3 steps, holding the only
  // room in reserve. Feeder gives B its input at step 1: B stays disabled though Out is empty.
  NetBuilder b;
  const auto a_in = b.addPlace("Ain");
  const auto b_in = b.addPlace("Bin");
  const auto seed = b.addPlace("Seed");
  const auto out = b.addPlace("Out");
  b.setSlot(a_in, kDefaultSlot, kControl, kUnbounded, 1);
  b.setSlot(seed, kDefaultSlot, kControl, kUnbounded, 1);
  b.setSlot(out, kDefaultSlot, kControl, 1, 0);
  const auto ta = b.addTransition("A", seconds(3));
  const auto tb = b.addTransition("B", seconds(1));
  const auto feeder = b.addTransition("Feeder", seconds(1));
  b.addInput(a_in, ta);
  b.addOutput(ta, out);
  b.addInput(b_in, tb);
  b.addOutput(tb, out);
  b.addInput(seed, feeder);
  b.addOutput(feeder, b_in);
  auto net = b.freeze();
  Kernel k(net, {1.0, 1});
  Recorder rec(*net);
  k.addObserver(&rec);
  k.start();
  const auto out_ps = *net->findPlaceSlot(out, kDefaultSlot);
  EXPECT_EQ(k.marking(out_ps), 0);
  EXPECT_EQ(k.reserve(out_ps), 1);
  k.step();
  EXPECT_EQ(tokens(k, "Bin"), 1);  // B has its input now
  EXPECT_EQ(k.marking(out_ps), 0);
  EXPECT_FALSE(k.enabled(tb));     // but the room is promised to A
  k.step();
  k.step();  // A completes at step 3: the reserve becomes a token
  EXPECT_EQ(k.marking(out_ps), 1);
  EXPECT_EQ(k.reserve(out_ps), 0);
  EXPECT_FALSE(k.enabled(tb));
  EXPECT_TRUE(rec.startsOf("B").empty());
}

TEST(NetKernel, ReserveBlocksASecondWriterThatIsOtherwiseReady) {
  NetBuilder b;
  const auto in = b.addPlace("In");
  const auto out = b.addPlace("Out");
  b.setSlot(in, kDefaultSlot, kControl, kUnbounded, 2);
  b.setSlot(out, kDefaultSlot, kControl, 1, 0);
  const auto ta = b.addTransition("A", seconds(3));
  const auto tb = b.addTransition("B", seconds(3));
  b.addInput(in, ta);
  b.addOutput(ta, out);
  b.addInput(in, tb);
  b.addOutput(tb, out);
  Kernel k(b.freeze(), {1.0, 1});
  EXPECT_TRUE(k.enabled(ta));
  EXPECT_TRUE(k.enabled(tb));
  k.start();
  // A starts first (declaration order) and reserves Out; B, still having its input, loses
  EXPECT_TRUE(k.occurring(ta));
  EXPECT_FALSE(k.occurring(tb));
  EXPECT_FALSE(k.enabled(tb));
  EXPECT_EQ(tokens(k, "In"), 1);
}

TEST(NetKernel, SelfLoopOnAFullPlaceIsAllowed) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, 1, 1);
  const auto t = b.addTransition("T", seconds(2));
  b.addInput(p, t);
  b.addOutput(t, p);
  Kernel k(b.freeze(), {1.0, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  EXPECT_TRUE(k.enabled(t));  // it takes its input before it reserves its output
  k.start();
  for (int i = 0; i < 6; ++i) k.step();
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{0, 2, 4, 6}));
}

TEST(NetKernel, HigherPriorityWinsAConflict) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto low = b.addTransition("Low", seconds(1), 0);
  const auto high = b.addTransition("High", seconds(1), 5);  // declared later
  b.addInput(p, low);
  b.addInput(p, high);
  Kernel k(b.freeze(), {1.0, 1});
  k.start();
  EXPECT_TRUE(k.occurring(high));
  EXPECT_FALSE(k.occurring(low));
}

TEST(NetKernel, EqualPrioritiesGoByDeclarationOrderWhenEnabledTogether) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto first = b.addTransition("First");
  const auto second = b.addTransition("Second");
  b.addInput(p, second);
  b.addInput(p, first);
  Kernel k(b.freeze(), {1.0, 1});
  k.start();
  EXPECT_TRUE(k.occurring(first));
  EXPECT_FALSE(k.occurring(second));
}

TEST(NetKernel, FirstComeAmongEqualsEvenWhenDeclaredLater) {
  // Shared holds one token that two transitions want. Early is declared last but became
  // enabled one step before Late, so it goes first.
  //  - Early needs Shared and room on Gate (capacity 1, full). Opener empties Gate at time 0,
  //    during the firing phase, so Early becomes enabled then (it starts no earlier than step 1).
  //  - Late needs Shared and Feed, which Feeder fills at step 1.
  NetBuilder b;
  const auto shared = b.addPlace("Shared");
  const auto gate = b.addPlace("Gate");
  const auto feed = b.addPlace("Feed");
  const auto seed = b.addPlace("Seed");
  const auto sink = b.addPlace("Sink");
  b.setSlot(shared, kDefaultSlot, kControl, kUnbounded, 1);
  b.setSlot(gate, kDefaultSlot, kControl, 1, 1);
  b.setSlot(seed, kDefaultSlot, kControl, kUnbounded, 1);
  const auto late = b.addTransition("Late");
  const auto opener = b.addTransition("Opener", seconds(5));
  const auto feeder = b.addTransition("Feeder", seconds(1));
  const auto early = b.addTransition("Early");
  b.addInput(shared, late);
  b.addInput(feed, late);
  b.addInput(gate, opener);
  b.addOutput(opener, sink);
  b.addInput(seed, feeder);
  b.addOutput(feeder, feed);
  b.addInput(shared, early);
  b.addOutput(early, gate);
  Kernel k(b.freeze(), {1.0, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  EXPECT_TRUE(k.enabled(early));  // enabled at time 0, during firing: waits for the next step
  k.step();
  EXPECT_EQ(rec.startsOf("Early"), (std::vector<std::int64_t>{1}));
  EXPECT_TRUE(rec.startsOf("Late").empty());
}

// Ties (semantics: Ties): three transitions of one priority compete for one token; the winner
// gives it back one step later, so every step is a tie among the three.
std::shared_ptr<const Net> threeWayTie() {
  NetBuilder b;
  const auto pool = b.addPlace("pool");
  b.setSlot(pool, kDefaultSlot, kControl, kUnbounded, 1);
  for (const char* name : {"A", "B", "C"}) {
    const auto t = b.addTransition(name, seconds(1.0));
    b.addInput(pool, t);
    b.addOutput(t, pool);
  }
  return b.freeze();
}

/// Which transition started at each of `steps` steps (one start per step: one token).
std::string winners(bool random_ties, std::uint64_t seed, int steps) {
  KernelSettings settings{1.0, seed};
  settings.random_ties = random_ties;
  Kernel k(threeWayTie(), settings);
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  for (int i = 1; i < steps; ++i) k.step();
  std::string out(static_cast<std::size_t>(steps), '-');
  for (const char* name : {"A", "B", "C"}) {
    for (const auto step : rec.startsOf(name)) out[static_cast<std::size_t>(step)] = name[0];
  }
  return out;
}

TEST(NetKernel, TiesGoInDeclarationOrderUnlessRandom) {
  // in declaration order the first one always wins, whatever the seed
  EXPECT_EQ(winners(false, 1, 12), "AAAAAAAAAAAA");
  EXPECT_EQ(winners(false, 99, 12), "AAAAAAAAAAAA");
}

TEST(NetKernel, RandomTiesAreDrawnFromTheSeedAndReplayedFromIt) {
  const std::string first = winners(true, 7, 600);
  EXPECT_EQ(winners(true, 7, 600), first);  // the same seed: the same choices
  EXPECT_NE(winners(true, 8, 600), first);
  // each of the three wins about a third of the 600 ties (binomial: sd 11.5; 4.3 sd either
  // side; the seed is fixed, so the test cannot flake)
  for (const char c : {'A', 'B', 'C'}) {
    const auto wins = std::count(first.begin(), first.end(), c);
    EXPECT_GT(wins, 200 - 50) << c;
    EXPECT_LT(wins, 200 + 50) << c;
  }
}

TEST(NetKernel, RandomTiesKeepPriorityAndTheTimeEnabled) {
  // a higher priority still goes first, and so does one enabled in an earlier step
  NetBuilder b;
  const auto pool = b.addPlace("pool");
  b.setSlot(pool, kDefaultSlot, kControl, kUnbounded, 1);
  const auto low = b.addTransition("Low", seconds(1.0), 0);
  const auto high = b.addTransition("High", seconds(1.0), 5);
  for (const auto t : {low, high}) {
    b.addInput(pool, t);
    b.addOutput(t, pool);
  }
  KernelSettings settings{1.0, 3};
  settings.random_ties = true;
  Kernel k(b.freeze(), settings);
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  for (int i = 0; i < 20; ++i) k.step();
  EXPECT_TRUE(rec.startsOf("Low").empty());
  EXPECT_EQ(rec.startsOf("High").size(), 21U);  // steps 0 to 20
}

// Immediate transitions (semantics: Immediate transitions): duration 0 written.
Duration immediate() { return Duration{Duration::Law::Immediate, 0.0}; }

TEST(NetKernel, ImmediateTransitionsStartAndCompleteWithinTheFiringPhaseOneAfterAnother) {
  // P -> A (immediate) -> Q -> B (immediate) -> R -> C (1 s) -> S
  NetBuilder b;
  PlaceId p[5];
  const char* names[] = {"P", "Q", "R", "S", "T"};
  for (int i = 0; i < 5; ++i) {
    p[i] = b.addPlace(names[i]);
    b.setSlot(p[i], kDefaultSlot, kControl, kUnbounded, i == 0 ? 1 : 0);
  }
  const TransitionId ts[] = {b.addTransition("A", immediate()), b.addTransition("B", immediate()),
                             b.addTransition("C", seconds(1.0))};
  for (int i = 0; i < 3; ++i) {
    b.addInput(p[i], ts[i]);
    b.addOutput(ts[i], p[i + 1]);
  }
  Kernel k(b.freeze(), {0.1, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  // all at step 0: A and B came and went, and C, enabled by B, started in the same phase
  EXPECT_EQ(rec.startsOf("A"), (std::vector<std::int64_t>{0}));
  EXPECT_EQ(rec.startsOf("B"), (std::vector<std::int64_t>{0}));
  EXPECT_EQ(rec.startsOf("C"), (std::vector<std::int64_t>{0}));
  EXPECT_FALSE(k.occurring(ts[0]));
  EXPECT_FALSE(k.occurring(ts[1]));
  EXPECT_TRUE(k.occurring(ts[2]));
  EXPECT_EQ(tokens(k, "Q") + tokens(k, "R"), 0);
  for (int i = 0; i < 10; ++i) k.step();
  EXPECT_EQ(tokens(k, "S"), 1);
  EXPECT_EQ(k.steps(), 10);
}

TEST(NetKernel, AnImmediateTransitionFiresAgainWhileItIsEnabledAndPriorityComesFirst) {
  // three tokens: the immediate drain empties the place within the phase, before the
  // timed one of lower priority can take any; one of higher priority goes first
  NetBuilder b;
  const auto pool = b.addPlace("pool");
  const auto done = b.addPlace("done");
  b.setSlot(pool, kDefaultSlot, kControl, kUnbounded, 3);
  const auto drain = b.addTransition("Drain", immediate(), 1);
  const auto slow = b.addTransition("Slow", seconds(1.0), 0);
  for (const auto t : {drain, slow}) {
    b.addInput(pool, t);
    b.addOutput(t, done);
  }
  Kernel k(b.freeze(), {0.1, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  EXPECT_EQ(rec.startsOf("Drain"), (std::vector<std::int64_t>{0, 0, 0}));
  EXPECT_TRUE(rec.startsOf("Slow").empty());
  EXPECT_EQ(tokens(k, "done"), 3);
  EXPECT_TRUE(k.dead());
}

TEST(NetKernel, ImmediatesThatReEnableAProbableTransitionDoNotGiveItMoreDraws) {
  // U (p = 0.5) tests P; A takes P's token and B gives it back, both immediate: U is disabled
  // and enabled again within the phase, and still draws once (semantics: Probability)
  int started = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    NetBuilder b;
    const auto p = b.addPlace("P"), q = b.addPlace("Q"), x = b.addPlace("X"), r = b.addPlace("R"),
               out = b.addPlace("S");
    b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
    b.setSlot(q, kDefaultSlot, kControl, kUnbounded, 0);
    b.setSlot(x, kDefaultSlot, kControl, kUnbounded, 1);
    b.setSlot(r, kDefaultSlot, kControl, kUnbounded, 1);
    b.setSlot(out, kDefaultSlot, kControl, kUnbounded, 0);
    const auto u = b.addTransition("U", seconds(1.0), 1, 0.5);
    const auto ta = b.addTransition("A", immediate());
    const auto tb = b.addTransition("B", immediate());
    b.addInput(r, u);
    b.addInput(p, u, kDefaultSlot, 1, ArcKind::Test);
    b.addOutput(u, out);
    b.addInput(p, ta);
    b.addInput(x, ta);
    b.addOutput(ta, q);
    b.addInput(q, tb);
    b.addOutput(tb, p);
    Kernel k(b.freeze(), {0.1, seed});
    k.start();
    started += k.occurring(u) || tokens(k, "S") > 0 ? 1 : 0;
  }
  // half of 2000 (sd 22): not 1 - (1 - p)^2 = 75 %
  EXPECT_GT(started, 1000 - 110);
  EXPECT_LT(started, 1000 + 110);
}

TEST(NetKernel, ACycleOfImmediateTransitionsEndsTheStepAfterItsRoundsAndGoesOnInTheNext) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto there = b.addTransition("There", immediate());
  const auto back = b.addTransition("Back", immediate());
  b.addInput(p, there);
  b.addOutput(there, q);
  b.addInput(q, back);
  b.addOutput(back, p);
  Kernel k(b.freeze(), {0.1, 1});
  k.start();
  const auto first = k.startCount();
  EXPECT_EQ(first, 10009U);  // the phase's first pass and its 10,000 + 4 x 2 (transitions) rounds
  k.step();
  EXPECT_EQ(k.startCount(), 2 * first);
  EXPECT_EQ(tokens(k, "P") + tokens(k, "Q"), 1);
}

TEST(NetKernel, ImmediateTransitionsOfManyInstancesAllFireInTheirPhase) {
  // 20,000 instances of P -> I (immediate) -> Q: each I ends a round, and all of them fire at
  // time 0 (the rounds allowed grow with the net; a cycle of immediates is still cut)
  NetBuilder b;
  constexpr int kInstances = 20000;
  for (int i = 0; i < kInstances; ++i) {
    const auto p = b.addPlace("P" + std::to_string(i)), q = b.addPlace("Q" + std::to_string(i));
    b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
    b.setSlot(q, kDefaultSlot, kControl, kUnbounded, 0);
    const auto t = b.addTransition("I" + std::to_string(i), immediate(), i % 3);
    b.addInput(p, t);
    b.addOutput(t, q);
  }
  Kernel k(b.freeze(), {0.1, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  EXPECT_EQ(k.startCount(), static_cast<std::uint64_t>(kInstances));
  EXPECT_TRUE(k.dead());
  // by priority (i % 3, highest first), then declaration
  ASSERT_EQ(rec.starts.size(), static_cast<std::size_t>(kInstances));
  EXPECT_EQ(rec.starts[0].first, "I2");
  EXPECT_EQ(rec.starts[1].first, "I5");
  EXPECT_EQ(rec.starts.back().first, "I19998");
}

TEST(NetKernel, AtMostOneStartPerStepAndOneOccurrenceAtATime) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 5);
  const auto t = b.addTransition("T", seconds(0.25));
  b.addInput(p, t);
  b.addOutput(t, q);
  Kernel k(b.freeze(), {0.1, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  while (!k.dead()) k.step();
  // 0.25 s at dt 0.1 lasts ceil(2.5) = 3 steps; single server: one after the other
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{0, 3, 6, 9, 12}));
  EXPECT_EQ(tokens(k, "Q"), 5);
  EXPECT_EQ(k.steps(), 15);
}

/// Adds place `name`In (holding `initial`) -> transition `name` (lasting `lasts` seconds) ->
/// place `name`Out; returns the input place.
PlaceId addStage(NetBuilder& b, const std::string& name, std::int64_t initial, double lasts) {
  const auto in = b.addPlace(name + "In");
  b.setSlot(in, kDefaultSlot, kControl, kUnbounded, initial);
  const auto t = b.addTransition(name, seconds(lasts));
  b.addInput(in, t);
  b.addOutput(t, b.addPlace(name + "Out"));
  return in;
}

/// The "complete ..." events `rec` saw, but those of transitions whose name holds `except`.
std::vector<std::string> completions(const Recorder& rec, const std::string& except = "\n") {
  std::vector<std::string> out;
  for (const auto& e : rec.events) {
    if (e.rfind("complete ", 0) == 0 && e.find(except) == std::string::npos) out.push_back(e);
  }
  return out;
}

// Completions due in the same step come in the order the occurrences started, whether they
// waited long (beyond the kernel's near wheel of 256 steps, or a whole turn of its far one of
// 4,096) or a few steps.
TEST(NetKernel, OccurrencesEndingInOneStepCompleteInStartOrderHoweverLongTheyLasted) {
  NetBuilder b;
  // each chain: a wait from step 0, then the occurrence that ends at step 5000 (or 9096);
  // declared in the reverse of the order they start, so that neither order can stand in for
  // the other
  struct Chain {
    const char* name;
    double wait, lasts;
  };
  const Chain chains[] = {{"Later", 0, 9096}, {"Short", 4990, 10}, {"Near", 4800, 200}, {"Mid", 300, 4700},
                          {"Long", 0, 5000}};
  for (const Chain& c : chains) {
    const std::string name = c.name;
    const auto in = addStage(b, name, c.wait == 0 ? 1 : 0, c.lasts);
    if (c.wait > 0) {
      const auto start = b.addPlace(name + "Start");
      b.setSlot(start, kDefaultSlot, kControl, kUnbounded, 1);
      const auto wait = b.addTransition(name + "Wait", seconds(c.wait));
      b.addInput(start, wait);
      b.addOutput(wait, in);
    }
  }
  Kernel k(b.freeze(), {1.0, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  while (!k.dead()) k.step();
  const std::vector<std::string> order{"complete Long @5000", "complete Mid @5000", "complete Near @5000",
                                       "complete Short @5000", "complete Later @9096"};
  EXPECT_EQ(completions(rec, "Wait"), order);
  for (const Chain& c : chains) EXPECT_EQ(tokens(k, (std::string(c.name) + "Out").c_str()), 1) << c.name;
  EXPECT_EQ(k.steps(), 9096);
}

// The same at the near wheel's edge (255 and 256 steps from now), for occurrences the firing
// phase starts and ones the user starts between steps.
TEST(NetKernel, OccurrencesStartedByTheUserCompleteInStartOrderAtTheNearWheelsEdge) {
  NetBuilder b;
  const char* names[] = {"G", "F", "E", "D", "C", "B", "A"};
  const double lasts[] = {100, 300, 245, 246, 257, 256, 255};
  // A, B and C start in the first firing phase; the user starts the others
  for (int i = 0; i < 7; ++i) addStage(b, names[i], i >= 4 ? 1 : 0, lasts[i]);
  Kernel k(b.freeze(), {1.0, 1});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  auto fireNow = [&](const std::string& name) {
    const auto p = k.net().findPlace(name + "In");
    ASSERT_TRUE(p);
    ASSERT_EQ(k.setMarking(*k.net().findPlaceSlot(*p, kDefaultSlot), 1), "");
    ASSERT_EQ(k.fire(*k.net().findTransition(name)), "") << name;
  };
  while (k.steps() < 400) {
    k.step();
    if (k.steps() == 10) fireNow("D"), fireNow("F");  // end at 256 and 310
    if (k.steps() == 11) fireNow("E");                 // ends at 256
    if (k.steps() == 210) fireNow("G");                // ends at 310, after F
  }
  const std::vector<std::string> order{"complete A @255", "complete B @256", "complete D @256", "complete E @256",
                                       "complete C @257", "complete F @310", "complete G @310"};
  EXPECT_EQ(completions(rec), order);
}

TEST(NetKernel, EffectiveDurationIsWholeStepsAndAtLeastOne) {
  NetBuilder b;
  b.addPlace("P");
  Kernel k(b.freeze(), {0.1, 1});
  EXPECT_EQ(k.durationSteps(0.0), 1);
  EXPECT_EQ(k.durationSteps(0.05), 1);
  EXPECT_EQ(k.durationSteps(0.1), 1);
  EXPECT_EQ(k.durationSteps(0.3), 3);  // 0.3 / 0.1 is 2.9999999999999996 in doubles
  EXPECT_EQ(k.durationSteps(0.7), 7);  // and 7.000000000000001
  EXPECT_EQ(k.durationSteps(0.31), 4);
  EXPECT_EQ(k.durationSteps(1e300), std::int64_t{1} << 60);
}

TEST(NetKernel, ZeroDurationStillTakesOneStep) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto t = b.addTransition("T", seconds(0));
  b.addInput(p, t);
  b.addOutput(t, q);
  Kernel k(b.freeze(), {0.5, 1});
  k.start();
  EXPECT_EQ(tokens(k, "Q"), 0);
  k.step();
  EXPECT_EQ(tokens(k, "Q"), 1);
  EXPECT_DOUBLE_EQ(k.now(), 0.5);
}

TEST(NetKernel, ProbabilityDrawsFromTheSeededGenerator) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto t = b.addTransition("T", seconds(1), 0, 0.3);
  b.addInput(p, t);
  b.addOutput(t, p);
  Kernel k(b.freeze(), {1.0, 12345});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  for (int i = 0; i < 999; ++i) k.step();

  // replay: T is enabled in every firing phase it is not occurring in; each time one draw
  core::Random replay(12345);
  std::vector<std::int64_t> expected;
  std::int64_t busy_until = -1;
  for (std::int64_t step = 0; step < 1000; ++step) {
    if (step < busy_until) continue;
    if (replay.uniform01() < 0.3) {
      expected.push_back(step);
      busy_until = step + 1;
    }
  }
  EXPECT_EQ(rec.startsOf("T"), expected);
  // T is enabled in every step (one-step duration), so it starts in a share p of them
  const double n = static_cast<double>(expected.size());
  EXPECT_NEAR(n / 1000.0, 0.3, 5 * std::sqrt(0.3 * 0.7 / 1000));
}

TEST(NetKernel, NodeTokensKeepTheirIdentityAndOrder) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q1 = b.addPlace("Q1");
  const auto q2 = b.addPlace("Q2");
  constexpr SlotId d0 = 24;
  b.setNodes(p, d0, {"boxA", "boxB", "boxC", "boxD"});
  b.setSlot(q1, d0, SlotKind::Node, kUnbounded, 0);
  b.setSlot(q2, d0, SlotKind::Node, kUnbounded, 0);
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(p, t, d0, 2);
  b.addOutput(t, q1, d0, 1);
  b.addOutput(t, q2, d0, 1);
  auto net = b.freeze();
  Kernel k(net, {1.0, 1});
  Recorder rec(*net);
  k.addObserver(&rec);
  k.start();
  k.step();
  k.step();
  k.step();
  auto names = [&](PlaceId place) {
    std::vector<std::string> out;
    for (auto ref : k.nodes(*net->findPlaceSlot(place, d0))) {
      out.push_back(net->nodeNames()[ref]);
    }
    return out;
  };
  EXPECT_EQ(names(q1), (std::vector<std::string>{"boxA", "boxC"}));
  EXPECT_EQ(names(q2), (std::vector<std::string>{"boxB", "boxD"}));
  EXPECT_TRUE(names(p).empty());
  EXPECT_EQ(rec.events[1], "remove P.d0 x2 [0 1] @0");
  EXPECT_EQ(rec.events[3], "deposit Q1.d0 x1 [0] @1");
}

TEST(NetKernel, DrawnDurationsFollowTheirLaw) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto t = b.addTransition("T", Duration{Duration::Law::Uniform, 2.0, 4.0, {}});
  b.addInput(p, t);
  b.addOutput(t, p);
  Kernel k(b.freeze(), {0.01, 99});
  Recorder rec(k.net());
  k.addObserver(&rec);
  k.start();
  for (int i = 0; i < 300000; ++i) k.step();
  const auto starts = rec.startsOf("T");
  ASSERT_GT(starts.size(), 900u);
  double sum = 0;
  for (std::size_t i = 1; i < starts.size(); ++i) {
    const auto gap = starts[i] - starts[i - 1];
    EXPECT_GE(gap, 200);
    EXPECT_LE(gap, 400);
    sum += static_cast<double>(gap);
  }
  EXPECT_NEAR(sum / static_cast<double>(starts.size() - 1), 300.5, 5.0);  // mean of U(2,4) s, whole steps
}

TEST(NetKernel, DeadWhenNothingEnabledOrOccurring) {
  auto net = figure31();
  Kernel k(net, {1.0, 1});
  EXPECT_FALSE(k.dead());
  k.start();
  EXPECT_EQ(k.occurringCount(), 1u);
  k.step();
  k.step();
  EXPECT_TRUE(k.dead());
  EXPECT_EQ(k.enabledCount(), 0u);
}

TEST(SortKeys, SortsLargeUnsortedInputByRadix) {
  std::mt19937_64 gen(5);
  for (std::size_t n : {0u, 1u, 100u, 300u, 10000u}) {
    std::vector<std::uint64_t> keys(n), scratch;
    for (auto& k : keys) k = (gen() % 4) << 32 | (gen() % 1000000);
    auto expected = keys;
    std::sort(expected.begin(), expected.end());
    detail::sortKeys(keys, scratch);
    EXPECT_EQ(keys, expected) << n;
  }
}

// A ring of n places and n transitions (place i -> t_i -> place i+1), a token on every
// `every`-th place, each transition lasting `duration`.
std::shared_ptr<const Net> bigRing(std::uint32_t n, std::uint32_t every, Duration duration) {
  NetBuilder b;
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto p = b.addPlace("p" + std::to_string(i));
    b.setSlot(p, kDefaultSlot, kControl, kUnbounded, i % every == 0 ? 1 : 0);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto t = b.addTransition("t" + std::to_string(i), duration);
    b.addInput(static_cast<PlaceId>(i), t);
    b.addOutput(t, static_cast<PlaceId>((i + 1) % n));
  }
  return b.freeze();
}

// A net whose state passes 4 MiB fires with what it reads fetched ahead (the kernel's big-net
// path, which no smaller test reaches): the same firings as the rules give.
TEST(NetKernel, ABigNetFiresWhatItsRulesSay) {
  constexpr std::uint32_t n = 40000, every = 1000, steps = 2500;
  Kernel k(bigRing(n, every, seconds(0.01)), {0.01, 1});
  ASSERT_GE(k.memoryBytes(), std::size_t{4} << 20);
  k.start();
  for (std::uint32_t s = 0; s < steps; ++s) k.step();
  // every step, each token moves on by one transition: after `steps` steps, the token that
  // started on place j * every occurs in transition j * every + steps
  EXPECT_EQ(k.startCount(), std::uint64_t{n / every} * (steps + 1));
  EXPECT_EQ(k.occurringCount(), n / every);
  for (TransitionId t{0}; t < n; ++t) {
    const bool expected = (t + n - steps % n) % every == 0;
    ASSERT_EQ(k.occurring(t), expected) << "t" << t;
    if (expected) {
      ASSERT_EQ(k.startStep(t), steps) << "t" << t;
    }
  }
  for (PlaceSlotId ps{0}; ps < n; ++ps) ASSERT_EQ(k.marking(ps), 0);

  // drawn durations (their laws fetched ahead too): tokens kept, and the same run twice
  auto drawn = bigRing(n, every, Duration{Duration::Law::Uniform, 0.01, 0.05, {}});
  Kernel a(drawn, {0.01, 7}), c(drawn, {0.01, 7});
  a.start();
  c.start();
  for (std::uint32_t s = 0; s < steps; ++s) a.step(), c.step();
  std::uint32_t held = 0;
  for (TransitionId t{0}; t < n; ++t) {
    ASSERT_EQ(a.occurring(t), c.occurring(t)) << "t" << t;
    ASSERT_EQ(a.endStep(t), c.endStep(t)) << "t" << t;
    held += a.occurring(t) ? 1u : 0u;
  }
  for (PlaceSlotId ps{0}; ps < n; ++ps) held += static_cast<std::uint32_t>(a.marking(ps));
  EXPECT_EQ(held, n / every);
  EXPECT_EQ(a.startCount(), c.startCount());
  EXPECT_GT(a.startCount(), std::uint64_t{n / every} * steps / 5);
}

// --- readiness: what held a transition back, as the kernel last found it ---

/// Hooks whose guards all answer `open`; no other script does anything.
class GuardHooks : public ScriptHooks {
 public:
  bool guard(TransitionId) override {
    ++guards;
    return open;
  }
  bool eligible(TermId, NodeRef) override { return true; }
  void preFire(TransitionId) override {}
  void inFire(TransitionId) override {}
  void postFire(TransitionId) override {}
  void onDeposit(PlaceSlotId, const NodeRef*) override {}
  void onRemove(PlaceSlotId, const NodeRef*) override {}
  [[nodiscard]] bool halted() const override { return false; }
  bool open = false;
  int guards = 0;
};

// P (1 token) -> T -> Q, T guarded; C -> T a sensor condition when `condition`
std::shared_ptr<const Net> guardedNet(bool condition) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto q = b.addPlace("Q");
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(p, t);
  b.addOutput(t, q);
  ScriptSpec guard;
  guard.code = "open";
  b.setTransitionScript(t, ScriptKind::Guard, b.addScript(guard));
  if (condition) {
    const auto c = b.addPlace("C");
    ScriptSpec cond;
    cond.code = "C > 0";
    b.addCondition(c, t, kDefaultSlot, b.addScript(cond));
  }
  return b.freeze();
}

TEST(KernelReadiness, AGuardFalseHoldsBackATransitionWhoseMarkingSufficesUntilAPhaseFindsItTrue) {
  Kernel k(guardedNet(false), {1.0, 1});
  GuardHooks hooks;
  k.setHooks(&hooks);
  const TransitionId t = *k.net().findTransition("T");
  // its marking suffices: enabled by the counts, but no phase has tried its guard yet
  EXPECT_TRUE(k.enabled(t));
  EXPECT_EQ(k.readiness(t), Readiness::Untried);
  EXPECT_FALSE(heldBack(Readiness::Untried));
  k.start();
  EXPECT_EQ(k.readiness(t), Readiness::Guard);
  EXPECT_TRUE(heldBack(k.readiness(t)));
  EXPECT_EQ(k.readinessText(t), "guard false");
  // asking runs no script
  const int guards = hooks.guards;
  (void)k.readiness(t);
  (void)k.readinessText(t);
  EXPECT_EQ(hooks.guards, guards);
  // the guard turns true: the kernel's answer is the last phase's until the next one tries it
  hooks.open = true;
  EXPECT_EQ(k.readiness(t), Readiness::Guard);
  k.step();
  EXPECT_TRUE(k.occurring(t));
  EXPECT_EQ(k.readiness(t), Readiness::Occurring);
  EXPECT_EQ(k.readinessText(t), "occurring");
  // completed, P empty: its marking does not suffice
  k.step();
  EXPECT_EQ(k.readiness(t), Readiness::Tokens);
  EXPECT_FALSE(heldBack(k.readiness(t)));
  EXPECT_EQ(k.readinessText(t), "'P' a0 holds 0 of the 1 it needs");
  // a token put back between steps: a new enabling, untried until the next phase starts it
  ASSERT_EQ(k.setMarking(*k.net().findPlaceSlot(*k.net().findPlace("P"), kDefaultSlot), 1), "");
  EXPECT_EQ(k.readiness(t), Readiness::Untried);
  hooks.open = false;
  EXPECT_EQ(k.fire(t), "'T''s guard is false");
  EXPECT_EQ(k.readiness(t), Readiness::Guard);
}

TEST(KernelReadiness, AConditionFalseHoldsBackOnlyWhereTheMarkingSuffices) {
  Kernel k(guardedNet(true), {1.0, 1});
  GuardHooks hooks;
  hooks.open = true;
  k.setHooks(&hooks);
  const TransitionId t = *k.net().findTransition("T");
  TermId cond{0};
  for (TermId i{0}; i < k.net().terms().size(); ++i) {
    if (k.net().terms()[i].kind == TermKind::Condition) cond = i;
  }
  EXPECT_EQ(k.readiness(t), Readiness::Condition);
  EXPECT_TRUE(heldBack(Readiness::Condition));
  EXPECT_EQ(k.readinessText(t), "condition of arc 'C' -> 'T' false");
  // without P's token it is the marking that stops it
  ASSERT_EQ(k.setMarking(*k.net().findPlaceSlot(*k.net().findPlace("P"), kDefaultSlot), 0), "");
  EXPECT_EQ(k.readiness(t), Readiness::Tokens);
  ASSERT_EQ(k.setMarking(*k.net().findPlaceSlot(*k.net().findPlace("P"), kDefaultSlot), 1), "");
  k.setCondition(cond, true);
  EXPECT_EQ(k.readiness(t), Readiness::Untried);
  k.start();
  EXPECT_TRUE(k.occurring(t));
}

TEST(KernelReadiness, TransitionsNothingButTheirArcsCanHoldBackAreAbleWheneverEnabled) {
  Kernel k(figure31(), {1.0, 1});
  EXPECT_EQ(k.readiness(*k.net().findTransition("T1")), Readiness::Able);
  EXPECT_EQ(k.readinessText(*k.net().findTransition("T1")), "able to start");
  EXPECT_EQ(k.readiness(*k.net().findTransition("T2")), Readiness::Tokens);
}

TEST(KernelReadiness, ALostDrawHoldsBackUntilTheNextPhase) {
  NetBuilder b;
  const auto p = b.addPlace("P");
  b.setSlot(p, kDefaultSlot, kControl, kUnbounded, 1);
  const auto t = b.addTransition("T", seconds(1), 0, 1e-9);
  b.addInput(p, t);
  Kernel k(b.freeze(), {1.0, 1});
  EXPECT_EQ(k.readiness(t), Readiness::Untried);
  k.start();
  EXPECT_EQ(k.readiness(t), Readiness::Probability);
  EXPECT_EQ(k.readinessText(t), "lost its probability draw (p = 1e-09)");
}

}  // namespace
}  // namespace gdpn::net
