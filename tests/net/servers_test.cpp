// Transitions with servers (semantics.md, Servers): several occurrences of one transition at
// once, each with its own start, end and tokens.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "gdpn/net/builder.h"
#include "gdpn/net/kernel.h"
#include "gdpn/net/stats.h"
#include "gdpn/net/timeline.h"
#include "support/recorder.h"

namespace gdpn::net {
namespace {

using testing::Recorder;

constexpr SlotId kD0 = 24;  // node slot d0

Duration seconds(double s) { return Duration{Duration::Law::Fixed, s, 0.0, {}}; }

std::int64_t tokens(const Kernel& k, const char* name) {
  const auto p = k.net().findPlace(name);
  const auto ps = p ? k.net().findPlaceSlot(*p, kDefaultSlot) : std::nullopt;
  return ps ? k.marking(*ps) : 0;
}

// P (`parts` tokens) -> T (`lasts`, default 2 s; `servers`; probability `p`) -> Q, at
// dt = 0.5 s a 2 s occurrence lasts 4 steps
std::shared_ptr<const Net> machine(std::uint32_t servers, std::int64_t parts = 5, Duration lasts = seconds(2.0),
                                   double p = 1.0) {
  NetBuilder b;
  const auto in = b.addPlace("P"), out = b.addPlace("Q");
  b.setSlot(in, kDefaultSlot, SlotKind::Control, kUnbounded, parts);
  b.setSlot(out, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
  const auto t = b.addTransition("T", lasts, 0, p);
  b.setServers(t, servers);
  b.addInput(in, t);
  b.addOutput(t, out);
  return b.freeze();
}

// per number of starts at time 0, in how many of 400 seeds the machine of 8 parts, p = 0.5,
// made them
std::map<std::uint64_t, int> startsAtTimeZero(Duration lasts, std::uint32_t servers) {
  std::map<std::uint64_t, int> starts;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    Kernel k(machine(servers, 8, lasts, 0.5), {1.0, seed});
    k.start();
    ++starts[k.startCount()];
  }
  return starts;
}

const Duration kImmediate{Duration::Law::Immediate, 0.0, 0.0, {}};

// S (`parts` tokens) -> Feed (`feed_s`) -> P -> T (`lasts`, `servers`) -> Q: a part comes
// every feed_s seconds. T is transition 1.
std::shared_ptr<const Net> fedStation(std::int64_t parts, double feed_s, Duration lasts, std::uint32_t servers) {
  NetBuilder b;
  const auto src = b.addPlace("S"), p = b.addPlace("P"), q = b.addPlace("Q");
  b.setSlot(src, kDefaultSlot, SlotKind::Control, kUnbounded, parts);
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
  b.setSlot(q, kDefaultSlot, SlotKind::Control, kUnbounded, 0);
  const auto feed = b.addTransition("Feed", seconds(feed_s));
  const auto t = b.addTransition("T", lasts);
  b.setServers(t, servers);
  b.addInput(src, feed);
  b.addOutput(feed, p);
  b.addInput(p, t);
  b.addOutput(t, q);
  return b.freeze();
}

/// Records each completion of transition `of` with the start step the kernel names for it.
struct Completions : NetObserver {
  explicit Completions(TransitionId t = TransitionId{0}) : of(t) {}
  void onComplete(TransitionId t, std::int64_t step, std::int64_t started) override {
    if (t == of) pairs.emplace_back(started, step);
  }
  TransitionId of;
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
};

TEST(Servers, NServersOverlap) {
  auto net = machine(2);
  Kernel k(net, {0.5, 1});
  Recorder rec(*net);
  Completions done;
  StatsCollector stats(*net);
  k.addObserver(&rec);
  k.addObserver(&done);
  k.addObserver(&stats);
  k.start();
  // two parts start at once; with both servers busy, the third waits though tokens are there
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{0, 0}));
  EXPECT_EQ(k.occurrences(TransitionId{0}), 2u);
  EXPECT_EQ(k.occurringCount(), 2u);
  EXPECT_TRUE(k.occurring(TransitionId{0}));
  EXPECT_FALSE(k.enabled(TransitionId{0}));
  EXPECT_EQ(tokens(k, "P"), 3);
  EXPECT_EQ(k.fire(TransitionId{0}), "'T' is occurring on all its 2 servers");
  while (!k.dead()) k.step();
  // 5 parts on 2 servers of 4 steps: batches at 0, 4 and 8, the last part alone
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{0, 0, 4, 4, 8}));
  EXPECT_EQ(done.pairs, (std::vector<std::pair<std::int64_t, std::int64_t>>{{0, 4}, {0, 4}, {4, 8}, {4, 8}, {8, 12}}));
  EXPECT_EQ(k.steps(), 12);
  EXPECT_EQ(tokens(k, "Q"), 5);
  stats.finish(k.steps());
  EXPECT_EQ(stats.transitions()[0].busy, 20);  // five occurrences of 4 steps, overlapping
}

TEST(Servers, OneServerIsTheDefaultAndKeepsOneOccurrenceAtATime) {
  auto net = machine(1);
  Kernel k(net, {0.5, 1});
  Recorder rec(*net);
  k.addObserver(&rec);
  k.start();
  while (!k.dead()) k.step();
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{0, 4, 8, 12, 16}));
  EXPECT_EQ(k.fire(TransitionId{0}), "'T' is not enabled: 'P' a0 holds 0 of the 1 it needs");
}

TEST(Servers, UnlimitedServersStartEveryEnabledOccurrenceInOnePhase) {
  auto net = machine(kUnlimitedServers, 1000);
  Kernel k(net, {0.5, 1});
  Recorder rec(*net);
  Completions done;
  k.addObserver(&rec);
  k.addObserver(&done);
  k.start();
  EXPECT_EQ(rec.startsOf("T").size(), 1000u);
  EXPECT_EQ(k.occurrences(TransitionId{0}), 1000u);
  EXPECT_EQ(k.startStep(TransitionId{0}), 0);
  EXPECT_EQ(k.endStep(TransitionId{0}), 4);
  // the transition is not enabled because its inputs ran out, not for want of a server
  EXPECT_EQ(k.fire(TransitionId{0}), "'T' is not enabled: 'P' a0 holds 0 of the 1 it needs");
  for (int i = 0; i < 4; ++i) k.step();
  EXPECT_EQ(done.pairs.size(), 1000u);
  EXPECT_EQ(tokens(k, "Q"), 1000);
  EXPECT_TRUE(k.dead());
  EXPECT_FALSE(k.occurring(TransitionId{0}));
}

TEST(Servers, AFreeServerStartsWhenItsTokenArrivesWhileOthersOccur) {
  // a feeder puts one part in P per step; T (4 steps, 3 servers) takes each as it comes
  auto net = fedStation(6, 0.5, seconds(2.0), 3);
  Kernel k(net, {0.5, 1});
  Recorder rec(*net);
  k.addObserver(&rec);
  k.start();
  while (!k.dead()) k.step();
  // parts arrive at steps 1 to 6; the fourth, come at 4, waits for the first server, free at 5
  EXPECT_EQ(rec.startsOf("T"), (std::vector<std::int64_t>{1, 2, 3, 5, 6, 7}));
  EXPECT_EQ(tokens(k, "Q"), 6);
}

TEST(Servers, EachOccurrenceKeepsItsOwnNodeTokensAndCompletesOnItsOwnTime) {
  // a feeder moves one box per step from P to Q; T, with unlimited servers and a drawn
  // duration, takes each box as it comes: later boxes may finish first
  NetBuilder b;
  const auto p = b.addPlace("P"), q = b.addPlace("Q"), r = b.addPlace("R");
  std::vector<std::string> boxes;
  for (int i = 0; i < 12; ++i) boxes.push_back("box" + std::to_string(i));
  b.setNodes(p, kD0, boxes);
  b.setSlot(q, kD0, SlotKind::Node, kUnbounded, 0);
  b.setSlot(r, kD0, SlotKind::Node, kUnbounded, 0);
  const auto feed = b.addTransition("Feed", seconds(0.1));
  const auto t = b.addTransition("T", Duration{Duration::Law::Uniform, 0.1, 2.0, {}});
  b.setServers(t, kUnlimitedServers);
  b.addInput(p, feed, kD0);
  b.addOutput(feed, q, kD0);
  b.addInput(q, t, kD0);
  b.addOutput(t, r, kD0);
  auto net = b.freeze();

  // per start step, the box taken; per completion, the box put out and the start it names
  struct Boxes : NetObserver {
    explicit Boxes(TransitionId t) : watched(t) {}
    void onStart(TransitionId t, std::int64_t step) override { starting = t == watched ? step : -1; }
    void onComplete(TransitionId t, std::int64_t, std::int64_t started) override {
      completing = t == watched ? started : -1;
      if (completing >= 0) order.push_back(started);
    }
    void onRemove(PlaceSlotId, std::int64_t, std::span<const NodeRef> nodes, std::int64_t) override {
      if (starting >= 0) taken[starting] = nodes[0];
      starting = -1;
    }
    void onDeposit(PlaceSlotId, std::int64_t, std::span<const NodeRef> nodes, std::int64_t) override {
      if (completing >= 0) given.emplace_back(completing, nodes[0]);
      completing = -1;
    }
    TransitionId watched;
    std::int64_t starting = -1, completing = -1;
    std::map<std::int64_t, NodeRef> taken;
    std::vector<std::pair<std::int64_t, NodeRef>> given;
    std::vector<std::int64_t> order;  // start steps, in the order of completion
  } seen(t);
  Kernel k(net, {0.1, 7});
  k.addObserver(&seen);
  k.start();
  std::size_t most = 0;
  while (!k.dead()) {
    k.step();
    most = std::max(most, k.occurrences(t));
  }
  ASSERT_EQ(seen.taken.size(), 12u);
  ASSERT_EQ(seen.given.size(), 12u);
  for (const auto& [started, box] : seen.given) EXPECT_EQ(seen.taken.at(started), box) << "started at " << started;
  EXPECT_GT(most, 1u);
  // the seed draws durations under which some occurrence overtakes an earlier one
  EXPECT_FALSE(std::is_sorted(seen.order.begin(), seen.order.end()));
  EXPECT_EQ(k.nodes(*net->findPlaceSlot(r, kD0)).size(), 12u);
}

TEST(Servers, TheTimelinePairsEachCompletionWithItsOwnStart) {
  // durations drawn per occurrence: the Gantt bars must keep each occurrence's own length
  auto net = fedStation(20, 0.1, Duration{Duration::Law::Uniform, 0.1, 3.0, {}}, 4);
  const TransitionId t{1};
  Kernel k(net, {0.1, 3});
  Timeline timeline(*net);
  Completions done(t);
  k.addObserver(&timeline);
  k.addObserver(&done);
  k.start();
  while (!k.dead()) k.step();
  std::multiset<std::pair<std::int64_t, std::int64_t>> bars, truth(done.pairs.begin(), done.pairs.end());
  for (const auto& o : timeline.occurrences()) {
    if (o.transition == t) bars.emplace(o.start, o.end);
  }
  EXPECT_EQ(bars, truth);
  EXPECT_EQ(bars.size(), 20u);
}

TEST(Servers, AProbableTransitionDrawsForEachFurtherServer) {
  // 8 tokens, 8 servers, p = 0.5: each start in the turn draws, and the first loss ends it
  auto started_at_once = startsAtTimeZero(seconds(10.0), 8);
  // geometric: none in about half the runs, exactly one in about a quarter
  EXPECT_NEAR(started_at_once[0] / 400.0, 0.5, 0.1);
  EXPECT_NEAR(started_at_once[1] / 400.0, 0.25, 0.08);
  EXPECT_GT(started_at_once[3], 0);
}

TEST(Servers, AnImmediateTransitionWithServersDrainsItsPlaceWithinThePhase) {
  Kernel k(machine(kUnlimitedServers, 5, kImmediate), {1.0, 1});
  k.start();
  EXPECT_EQ(tokens(k, "Q"), 5);
  EXPECT_EQ(k.startCount(), 5u);
  EXPECT_TRUE(k.dead());
}

TEST(Servers, AnImmediateProbableTransitionWithServersDrawsForEachStartOfItsTurn) {
  // immediate, unlimited servers, p = 0.5, 8 tokens: each start completes at once and the
  // turn goes on with a new draw, so the starts in the phase are geometric, not at most one
  auto starts = startsAtTimeZero(kImmediate, kUnlimitedServers);
  EXPECT_NEAR(starts[0] / 400.0, 0.5, 0.1);
  EXPECT_NEAR(starts[1] / 400.0, 0.25, 0.08);
  EXPECT_GT(starts[3], 0);
}

TEST(Servers, AnOccurrenceSpanningStepsWithTheNetOffIsPairedWithItsStart) {
  // the IDE's plant-only steps: the net is off, occurrences pause; the timeline and the
  // figures still pair each completion with the step its start was seen at
  for (const std::uint32_t servers : {1u, 2u}) {
    auto net = machine(servers, 2);
    Kernel k(net, {0.5, 1});
    Timeline timeline(*net);
    StatsCollector stats(*net);
    k.addObserver(&timeline);
    k.addObserver(&stats);
    k.start();
    k.step();
    for (int i = 0; i < 3; ++i) k.idleStep();
    while (!k.dead()) k.step();
    for (const auto& o : timeline.occurrences()) EXPECT_GE(o.end, 0) << servers << " servers";
    EXPECT_EQ(timeline.occurrences().front().start, 0);
    EXPECT_EQ(timeline.occurrences().front().end, 7);  // 4 steps with the net on, 3 off
    stats.finish(k.steps());
    EXPECT_EQ(stats.transitions()[0].busy, servers == 1 ? 7 + 4 : 7 + 7) << servers << " servers";
  }
}

}  // namespace
}  // namespace gdpn::net
