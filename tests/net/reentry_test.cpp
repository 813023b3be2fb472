// Scripts that re-enter the kernel from inside a hook (delete a node, add a token, set a
// marking) while the kernel is in the middle of a start or a completion: every hook call is
// still made, and the kernel stays consistent.

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

#include "gdpn/net/builder.h"
#include "gdpn/net/kernel.h"
#include "support/recorder.h"

namespace gdpn::net {
namespace {

using testing::Recorder;

constexpr SlotId kD0 = 24;  // "d0", a node slot

Duration seconds(double s) { return Duration{Duration::Law::Fixed, s, 0.0, {}}; }

/// A script for a construct: its text does not matter, the hooks below stand in for it.
ScriptSpec pass() {
  ScriptSpec script;
  script.code = "pass";
  return script;
}

/// Records every hook call as text ("on_remove P.d0 #1", "pre_fire T") and runs the action
/// given for a call the first time it is made; the action re-enters the kernel.
class ReentrantHooks : public ScriptHooks {
 public:
  explicit ReentrantHooks(const Net& net) : net_(net) {}
  bool guard(TransitionId t) override {
    record("guard " + net_.transitionName(t));
    return true;
  }
  bool eligible(TermId, NodeRef) override { return true; }
  void preFire(TransitionId t) override { record("pre_fire " + net_.transitionName(t)); }
  void inFire(TransitionId t) override { record("in_fire " + net_.transitionName(t)); }
  void postFire(TransitionId t) override { record("post_fire " + net_.transitionName(t)); }
  void onDeposit(PlaceSlotId ps, const NodeRef* token) override { record("on_deposit " + where(ps, token)); }
  void onRemove(PlaceSlotId ps, const NodeRef* token) override { record("on_remove " + where(ps, token)); }
  [[nodiscard]] bool halted() const override { return false; }

  /// Runs `action` when the call `text` is first made.
  void when(const std::string& text, std::function<void()> action) { actions_[text] = std::move(action); }

  std::vector<std::string> calls;

 private:
  void record(const std::string& text) {
    calls.push_back(text);
    auto it = actions_.find(text);
    if (it == actions_.end()) return;
    const auto action = std::move(it->second);
    actions_.erase(it);
    action();
  }
  std::string where(PlaceSlotId ps, const NodeRef* token) const {
    const auto& s = net_.placeSlots()[ps];
    return net_.placeName(s.place) + "." + slotName(s.slot) + (token ? " #" + std::to_string(*token) : "");
  }
  const Net& net_;
  std::map<std::string, std::function<void()>> actions_;
};

/// A kernel over `net` (steps of 1 s) with recording hooks and an event recorder.
struct Harness {
  explicit Harness(std::shared_ptr<const Net> frozen)
      : net(std::move(frozen)), kernel(net, {1.0, 1}), hooks(*net), recorder(*net) {
    kernel.setHooks(&hooks);
    kernel.addObserver(&recorder);
  }
  std::shared_ptr<const Net> net;
  Kernel kernel;
  ReentrantHooks hooks;
  Recorder recorder;
};

PlaceSlotId slotOf(const Kernel& k, const char* place, SlotId slot = kDefaultSlot) {
  const auto p = k.net().findPlace(place);
  const auto ps = p ? k.net().findPlaceSlot(*p, slot) : std::nullopt;
  if (!ps) ADD_FAILURE() << "no place " << place << " with that slot";
  return ps.value_or(PlaceSlotId{0});
}

std::vector<NodeRef> nodesOf(const Kernel& k, const char* place) { return k.nodes(slotOf(k, place, kD0)); }

std::vector<NodeRef> heldBy(const Kernel& k, TransitionId t) {
  std::vector<NodeRef> out;
  for (const auto& [slot, node] : k.held(t)) out.push_back(node);
  return out;
}

std::function<bool(NodeRef)> oneOf(std::set<NodeRef> refs) {
  return [refs = std::move(refs)](NodeRef r) { return refs.count(r) > 0; };
}

/// The kernel's bookkeeping against its own state: no marking or reserve below zero, none
/// beyond its capacity, node slots holding as many nodes as their marking, and each
/// transition enabled exactly when rules 1-4 of semantics.md hold.
void expectConsistent(const Kernel& k) {
  const Net& net = k.net();
  for (PlaceSlotId ps{0}; ps < net.placeSlots().size(); ++ps) {
    const auto& slot = net.placeSlots()[ps];
    EXPECT_GE(k.marking(ps), 0) << ps;
    EXPECT_GE(k.reserve(ps), 0) << ps;
    if (slot.capacity != kUnbounded) {
      EXPECT_LE(k.marking(ps) + k.reserve(ps), slot.capacity) << ps;
    }
    if (slot.kind == SlotKind::Node) {
      EXPECT_EQ(static_cast<std::int64_t>(k.nodes(ps).size()), k.marking(ps)) << ps;
    }
  }
  std::size_t enabled = 0;
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    bool ok = !k.occurring(t);
    for (const Term& term : net.termsOf(t)) {
      const std::int64_t m = k.marking(term.place_slot), cap = net.placeSlots()[term.place_slot].capacity;
      switch (term.kind) {
        case TermKind::Input:
        case TermKind::Test: ok = ok && m >= term.weight; break;
        case TermKind::Inhibitor: ok = ok && m < term.weight; break;
        case TermKind::Output:
          ok = ok && (cap == kUnbounded || cap - (m - term.take) - k.reserve(term.place_slot) >= term.weight);
          break;
        case TermKind::Condition: ok = false; break;
      }
    }
    EXPECT_EQ(k.enabled(t), ok) << net.transitionName(t);
    enabled += ok ? 1 : 0;
  }
  EXPECT_EQ(k.enabledCount(), enabled);
}

TEST(KernelReentry, DeletingATakenNodeInOnRemoveLeavesTheOtherTokensTheirCalls) {
  // the defect: deleting a node made its tokens leave re-entrantly, which cleared the buffer
  // the start was walking, so #1 and #2 never got their on_remove
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setNodes(p, kD0, {"n0", "n1", "n2"});
  b.setSlot(q, kD0, SlotKind::Node, kUnbounded, 0);
  b.setSlotScript(p, kD0, ScriptKind::OnRemove, b.addScript(pass()));
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(p, t, kD0, 3);
  b.addOutput(t, q, kD0, 3);
  Harness h(b.freeze());
  auto& k = h.kernel;
  auto& hooks = h.hooks;
  auto& rec = h.recorder;
  std::size_t dropped = 0;
  hooks.when("on_remove P.d0 #0", [&] { dropped = k.dropNodes(oneOf({0})); });

  k.start();
  EXPECT_EQ(dropped, 1u);  // the node was inside T
  EXPECT_EQ(hooks.calls, (std::vector<std::string>{"on_remove P.d0 #0", "on_remove P.d0 #1", "on_remove P.d0 #2"}));
  EXPECT_EQ(heldBy(k, t), (std::vector<NodeRef>{1, 2}));
  expectConsistent(k);
  k.step();
  EXPECT_EQ(nodesOf(k, "Q"), (std::vector<NodeRef>{1, 2}));
  expectConsistent(k);
  EXPECT_EQ(rec.events, (std::vector<std::string>{"start T @0", "remove P.d0 x3 [0 1 2] @0", "complete T @1",
                                                  "deposit Q.d0 x2 [1 2] @1"}));
}

TEST(KernelReentry, DeletingSeveralNodesInOnRemoveMeetsAStartThatTookAllItsInputs) {
  // while T's removal from P is reported, a script deletes three nodes at once: one still on
  // P, one T has just taken from R, one still on R. T had taken R's tokens before any script
  // ran, so it neither takes a deleted node nor runs short
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto r = b.addPlace("R");
  const auto q = b.addPlace("Q");
  const auto s = b.addPlace("S");
  b.setNodes(p, kD0, {"n0", "n1"});
  b.setNodes(r, kD0, {"n2", "n3", "n4"});
  b.setSlot(q, kD0, SlotKind::Node, kUnbounded, 0);
  b.setSlot(s, kD0, SlotKind::Node, kUnbounded, 0);
  const auto script = b.addScript(pass());
  b.setSlotScript(p, kD0, ScriptKind::OnRemove, script);
  b.setSlotScript(r, kD0, ScriptKind::OnRemove, script);
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(p, t, kD0, 1);
  b.addInput(r, t, kD0, 2);
  b.addOutput(t, q, kD0, 1);
  b.addOutput(t, s, kD0, 2);
  Harness h(b.freeze());
  auto& k = h.kernel;
  auto& hooks = h.hooks;
  auto& rec = h.recorder;
  std::size_t dropped = 0;
  hooks.when("on_remove P.d0 #0", [&] {
    dropped = k.dropNodes(oneOf({1, 2, 4}));
    expectConsistent(k);
  });

  k.start();
  EXPECT_EQ(dropped, 3u);
  EXPECT_EQ(hooks.calls, (std::vector<std::string>{"on_remove P.d0 #0", "on_remove R.d0 #2", "on_remove R.d0 #3"}));
  EXPECT_TRUE(nodesOf(k, "P").empty());
  EXPECT_TRUE(nodesOf(k, "R").empty());
  EXPECT_EQ(heldBy(k, t), (std::vector<NodeRef>{0, 3}));
  expectConsistent(k);
  k.step();
  EXPECT_EQ(nodesOf(k, "Q"), (std::vector<NodeRef>{0}));
  EXPECT_EQ(nodesOf(k, "S"), (std::vector<NodeRef>{3}));
  expectConsistent(k);
  EXPECT_EQ(rec.events, (std::vector<std::string>{"start T @0", "remove P.d0 x1 [0] @0", "remove R.d0 x2 [2 3] @0",
                                                  "remove P.d0 x1 [1] @0", "remove R.d0 x1 [4] @0", "complete T @1",
                                                  "deposit Q.d0 x1 [0] @1", "deposit S.d0 x1 [3] @1"}));
}

TEST(KernelReentry, SettingMarkingsInOnRemoveCannotUndoATakeOrOverfillAnOutput) {
  // T takes 2 from A (on_remove) and 2 from B, and will put 1 on C (capacity 3). The first
  // on_remove empties B (3 tokens at once) and fills C: B's take and C's reserve are already
  // made, so B does not go below zero and C refuses what would break m + r <= k
  NetBuilder b;
  const auto a = b.addPlace("A");
  const auto bp = b.addPlace("B");
  const auto c = b.addPlace("C");
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 2);
  b.setSlot(bp, kDefaultSlot, SlotKind::Control, kUnbounded, 5);
  b.setSlot(c, kDefaultSlot, SlotKind::Control, 3, 0);
  b.setSlotScript(a, kDefaultSlot, ScriptKind::OnRemove, b.addScript(pass()));
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(a, t, kDefaultSlot, 2);
  b.addInput(bp, t, kDefaultSlot, 2);
  b.addOutput(t, c);
  Harness h(b.freeze());
  auto& k = h.kernel;
  auto& hooks = h.hooks;
  auto& rec = h.recorder;
  std::vector<std::string> why;
  hooks.when("on_remove A.a0", [&] {
    why.push_back(k.setMarking(slotOf(k, "B"), 0));
    why.push_back(k.setMarking(slotOf(k, "C"), 3));
    why.push_back(k.setMarking(slotOf(k, "C"), 2));
  });

  k.start();
  EXPECT_EQ(hooks.calls, (std::vector<std::string>{"on_remove A.a0", "on_remove A.a0"}));
  EXPECT_EQ(why, (std::vector<std::string>{"", "no room: capacity 3, reserved 1", ""}));
  EXPECT_EQ(k.marking(slotOf(k, "A")), 0);
  EXPECT_EQ(k.marking(slotOf(k, "B")), 0);
  EXPECT_EQ(k.marking(slotOf(k, "C")), 2);
  EXPECT_EQ(k.reserve(slotOf(k, "C")), 1);
  expectConsistent(k);
  k.step();
  EXPECT_EQ(k.marking(slotOf(k, "C")), 3);
  expectConsistent(k);
  EXPECT_EQ(rec.events, (std::vector<std::string>{"start T @0", "remove A.a0 x2 @0", "remove B.a0 x2 @0",
                                                  "remove B.a0 x3 @0", "deposit C.a0 x2 @0", "complete T @1",
                                                  "deposit C.a0 x1 @1"}));
}

TEST(KernelReentry, PreInAndPostFireMayAddAndDeleteTokens) {
  // T (2 steps) moves two nodes from P to Q (capacity 3). pre_fire adds a node to P and
  // deletes one T holds; in_fire adds a node to Q, and is refused a second for T's reserve;
  // post_fire deletes that node again and adds one to P. T completes with the one node it
  // still holds and starts again at once on what P now holds
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto q = b.addPlace("Q");
  b.setNodes(p, kD0, {"n0", "n1", "n2"});
  b.setSlot(q, kD0, SlotKind::Node, 3, 0);
  const auto t = b.addTransition("T", seconds(2));
  const auto script = b.addScript(pass());
  for (ScriptKind which : {ScriptKind::PreFire, ScriptKind::InFire, ScriptKind::PostFire}) b.setTransitionScript(t, which, script);
  b.addInput(p, t, kD0, 2);
  b.addOutput(t, q, kD0, 2);
  Harness h(b.freeze());
  auto& k = h.kernel;
  auto& hooks = h.hooks;
  const PlaceSlotId ps = slotOf(k, "P", kD0), qs = slotOf(k, "Q", kD0);
  std::vector<std::string> why;
  std::size_t dropped = 0;
  hooks.when("pre_fire T", [&] {
    why.push_back(k.addNode(ps, 10));
    dropped += k.dropNodes(oneOf({0}));
  });
  hooks.when("in_fire T", [&] {
    why.push_back(k.addNode(qs, 11));
    why.push_back(k.addNode(qs, 12));
  });
  hooks.when("post_fire T", [&] {
    dropped += k.dropNodes(oneOf({11}));
    why.push_back(k.addNode(ps, 13));
  });

  k.start();
  EXPECT_EQ(nodesOf(k, "P"), (std::vector<NodeRef>{2, 10}));
  EXPECT_EQ(heldBy(k, t), (std::vector<NodeRef>{1}));
  expectConsistent(k);
  k.step();
  EXPECT_EQ(nodesOf(k, "Q"), (std::vector<NodeRef>{11}));
  expectConsistent(k);
  k.step();
  EXPECT_EQ(hooks.calls,
            (std::vector<std::string>{"pre_fire T", "in_fire T", "in_fire T", "post_fire T", "pre_fire T"}));
  EXPECT_EQ(why, (std::vector<std::string>{"", "", "no room: capacity 3, reserved 2", ""}));
  EXPECT_EQ(dropped, 2u);
  EXPECT_EQ(nodesOf(k, "Q"), (std::vector<NodeRef>{1}));
  EXPECT_EQ(nodesOf(k, "P"), (std::vector<NodeRef>{13}));
  EXPECT_EQ(heldBy(k, t), (std::vector<NodeRef>{2, 10}));
  expectConsistent(k);
}

TEST(KernelReentry, OnDepositMayDeleteTokensStillToBeDepositedAndEmptyItsPlace) {
  // T deposits one node on Q, one on S and 3 control tokens on C, each with on_deposit. Q's
  // script deletes the node headed for S; C's first on_deposit empties C (3 tokens at once)
  // and the other two calls are still made
  NetBuilder b;
  const auto p = b.addPlace("P");
  const auto a = b.addPlace("A");
  const auto q = b.addPlace("Q");
  const auto s = b.addPlace("S");
  const auto c = b.addPlace("C");
  b.setNodes(p, kD0, {"n0", "n1"});
  b.setSlot(a, kDefaultSlot, SlotKind::Control, kUnbounded, 3);
  b.setSlot(q, kD0, SlotKind::Node, kUnbounded, 0);
  b.setSlot(s, kD0, SlotKind::Node, kUnbounded, 0);
  b.setSlot(c, kDefaultSlot, SlotKind::Control, 3, 0);
  const auto script = b.addScript(pass());
  b.setSlotScript(q, kD0, ScriptKind::OnDeposit, script);
  b.setSlotScript(s, kD0, ScriptKind::OnDeposit, script);
  b.setSlotScript(c, kDefaultSlot, ScriptKind::OnDeposit, script);
  const auto t = b.addTransition("T", seconds(1));
  b.addInput(p, t, kD0, 2);
  b.addInput(a, t, kDefaultSlot, 3);
  b.addOutput(t, q, kD0, 1);
  b.addOutput(t, s, kD0, 1);
  b.addOutput(t, c, kDefaultSlot, 3);
  Harness h(b.freeze());
  auto& k = h.kernel;
  auto& hooks = h.hooks;
  auto& rec = h.recorder;
  std::size_t dropped = 0;
  std::string why = "not called";
  hooks.when("on_deposit Q.d0 #0", [&] { dropped = k.dropNodes(oneOf({1})); });
  hooks.when("on_deposit C.a0", [&] {
    why = k.setMarking(slotOf(k, "C"), 0);
    expectConsistent(k);
  });

  k.start();
  k.step();
  EXPECT_EQ(dropped, 1u);
  EXPECT_EQ(why, "");
  EXPECT_EQ(hooks.calls, (std::vector<std::string>{"on_deposit Q.d0 #0", "on_deposit C.a0", "on_deposit C.a0",
                                                   "on_deposit C.a0"}));
  EXPECT_EQ(nodesOf(k, "Q"), (std::vector<NodeRef>{0}));
  EXPECT_TRUE(nodesOf(k, "S").empty());
  EXPECT_EQ(k.marking(slotOf(k, "C")), 0);
  EXPECT_FALSE(k.occurring(t));
  expectConsistent(k);
  EXPECT_EQ(rec.events, (std::vector<std::string>{"start T @0", "remove P.d0 x2 [0 1] @0", "remove A.a0 x3 @0",
                                                  "complete T @1", "deposit Q.d0 x1 [0] @1", "deposit S.d0 x0 @1",
                                                  "deposit C.a0 x3 @1", "remove C.a0 x3 @1"}));
}

}  // namespace
}  // namespace gdpn::net
