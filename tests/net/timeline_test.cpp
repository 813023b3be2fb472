// The timeline the HTML report plots: occurrences with their start and completion, and each
// place's tokens over steps, within a budget of records.

#include "gdpn/net/timeline.h"

#include <gtest/gtest.h>

#include "gdpn/net/builder.h"
#include "gdpn/net/kernel.h"

namespace gdpn::net {
namespace {

using Change = Timeline::Change;

// P (5 tokens) -> T (0.25 s, 3 steps of 0.1 s) -> Q: five occurrences one after the other
std::shared_ptr<const Net> drain() {
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setSlot(p, kDefaultSlot, SlotKind::Control, kUnbounded, 5);
  const auto t = b.addTransition("T", Duration{Duration::Law::Fixed, 0.25, 0.0, {}});
  b.addInput(p, t);
  b.addOutput(t, q);
  return b.freeze();
}

TEST(Timeline, KeepsEachOccurrenceAndEachPlacesTokensStepByStep) {
  Kernel k(drain(), {0.1, 1});
  Timeline tl(k.net());
  k.addObserver(&tl);
  k.start();
  while (!k.dead()) k.step();
  ASSERT_EQ(tl.occurrences().size(), 5U);
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& o = tl.occurrences()[i];
    EXPECT_EQ(o.transition, 0U);
    EXPECT_EQ(o.start, static_cast<std::int64_t>(3 * i));
    EXPECT_EQ(o.end, static_cast<std::int64_t>(3 * i + 3));
  }
  const auto p = *k.net().findPlace("P");
  const auto q = *k.net().findPlace("Q");
  // P: 5 at step 0, then one fewer at each start (the first start is at step 0 itself)
  EXPECT_EQ(tl.places()[p], (std::vector<Change>{{0, 4}, {3, 3}, {6, 2}, {9, 1}, {12, 0}}));
  EXPECT_EQ(tl.places()[q], (std::vector<Change>{{0, 0}, {3, 1}, {6, 2}, {9, 3}, {12, 4}, {15, 5}}));
  EXPECT_EQ(tl.cutAt(), -1);
  EXPECT_EQ(tl.dropped(), 0);
}

TEST(Timeline, StopsKeepingWhenItsBudgetIsSpentAndSaysFromWhen) {
  Kernel k(drain(), {0.1, 1});
  Timeline tl(k.net(), 4);  // four records: the first start, P's and Q's first changes, ...
  k.addObserver(&tl);
  k.start();
  while (!k.dead()) k.step();
  std::size_t kept = tl.occurrences().size();
  for (const auto& changes : tl.places()) kept += changes.size() - 1;  // the initial tokens are free
  EXPECT_EQ(kept, 4U);
  EXPECT_GT(tl.cutAt(), 0);
  // five starts, four changes on P after step 0's (merged into it), five on Q
  EXPECT_EQ(tl.dropped() + 4, 5 + 4 + 5);
  // an occurrence kept still gets its completion
  EXPECT_EQ(tl.occurrences().front().end, 3);
}

}  // namespace
}  // namespace gdpn::net
