// A property of random nets: the kernel's incremental enabling (semantics.md, rules 1-4) and
// the successor generator of the analysis find the same transitions enabled in every
// marking, along random walks, over all reachable markings, and while the kernel runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <optional>
#include <set>
#include <sstream>

#include "gdpn/core/random.h"
#include "gdpn/net/analysis.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/kernel.h"
#include "net/detail/marking_store.h"

namespace gdpn::net {
namespace {

using Marking = std::vector<std::int64_t>;  // per place slot

constexpr SlotId kA0 = 0, kA1 = 1, kD0 = 24;
constexpr int kNets = 300;
constexpr std::uint64_t kSeed = 14;  // issue 14

/// A random net of 2-5 places and 1-4 transitions of one step each. Each place has control
/// slot a0, sometimes a1 and sometimes node slot d0, each with a capacity of 1-4 or none and
/// 0-3 initial tokens. Each (place, transition) pair gets no input arc, a normal, a test or an
/// inhibitor one (a normal one sometimes with a test or an inhibitor arc beside it), and
/// sometimes an output arc, on some of the place's slots, with weights 1-3 (self-loops
/// included). What a transition takes on d0 it puts out on d0, as compile() demands of node
/// slots; no two normal arcs join a place slot and a transition the same way, as compile()
/// demands.
std::shared_ptr<const Net> randomNet(core::Random& rng) {
  auto oneIn = [&](std::uint64_t n) { return rng.below(n) == 0; };
  auto weight = [&] { return static_cast<std::int32_t>(1 + rng.below(3)); };
  NetBuilder b;
  std::vector<std::vector<SlotId>> slots;  // per place
  int node_names = 0;
  const auto places = 2 + rng.below(4);
  for (std::uint64_t i = 0; i < places; ++i) {
    const PlaceId p = b.addPlace("P" + std::to_string(i));
    auto& own = slots.emplace_back(std::vector<SlotId>{kA0});
    if (oneIn(3)) own.push_back(kA1);
    if (oneIn(3)) own.push_back(kD0);
    for (SlotId s : own) {
      const std::int64_t capacity = oneIn(2) ? kUnbounded : static_cast<std::int64_t>(1 + rng.below(4));
      const auto most = static_cast<std::uint64_t>(std::min<std::int64_t>(capacity, 3));
      const auto initial = static_cast<std::int64_t>(rng.below(most + 1));
      b.setSlot(p, s, s == kD0 ? SlotKind::Node : SlotKind::Control, capacity, initial);
      if (s != kD0) continue;
      std::vector<std::string> names;
      for (std::int64_t k = 0; k < initial; ++k) names.push_back("n" + std::to_string(node_names++));
      b.setNodes(p, s, names);
    }
  }
  const auto transitions = 1 + rng.below(4);
  for (std::uint64_t i = 0; i < transitions; ++i) {
    const TransitionId t = b.addTransition("T" + std::to_string(i), Duration{Duration::Law::Fixed, 1.0, 0.0, {}});
    std::int32_t nodes_in = 0;
    std::vector<PlaceId> node_places;
    for (PlaceId p{0}; p < places; ++p) {
      const auto input = rng.below(6);  // 0, 1: none; 2, 5: normal; 3: test; 4: inhibitor
      const ArcKind kind = input == 3 ? ArcKind::Test : input == 4 ? ArcKind::Inhibitor : ArcKind::Normal;
      const bool output = oneIn(3);
      for (SlotId s : slots[p]) {
        if (s == kD0) node_places.push_back(p);
        if (input >= 2 && oneIn(2)) {
          const auto w = weight();
          b.addInput(p, t, s, w, kind);
          if (s == kD0 && kind == ArcKind::Normal) nodes_in += w;
          // beside a normal arc, sometimes a test or an inhibitor arc on the same slot
          if (kind == ArcKind::Normal && oneIn(4)) {
            b.addInput(p, t, s, weight(), oneIn(2) ? ArcKind::Test : ArcKind::Inhibitor);
          }
        }
        if (output && s != kD0 && oneIn(2)) b.addOutput(t, p, s, weight());
      }
    }
    if (nodes_in > 0) b.addOutput(t, node_places[rng.below(node_places.size())], kD0, nodes_in);
  }
  return b.freeze();
}

/// The net's arcs and capacities, for failure messages.
std::string describe(const Net& net) {
  std::ostringstream out;
  auto name = [&](PlaceSlotId ps) {
    const auto& s = net.placeSlots()[ps];
    return net.placeName(s.place) + "." + slotName(s.slot);
  };
  for (PlaceSlotId ps{0}; ps < net.placeSlots().size(); ++ps) {
    const auto& s = net.placeSlots()[ps];
    out << name(ps) << (s.kind == SlotKind::Node ? " node" : "") << " m0=" << s.initial;
    if (s.capacity != kUnbounded) out << " k=" << s.capacity;
    out << "\n";
  }
  const char* kinds[] = {"in", "test", "inhibitor", "out", "condition"};
  for (TransitionId t{0}; t < net.transitions().size(); ++t) {
    out << net.transitionName(t) << ":";
    for (const Term& term : net.termsOf(t)) {
      out << " " << kinds[static_cast<int>(term.kind)] << " " << name(term.place_slot) << "*" << term.weight;
    }
    out << "\n";
  }
  return out.str();
}

std::string str(const Marking& m) {
  std::string s = "[";
  for (std::size_t k = 0; k < m.size(); ++k) s += (k ? " " : "") + std::to_string(m[k]);
  return s + "]";
}

/// The successor generator of the analysis, on unpacked markings.
class Generator {
 public:
  explicit Generator(const Net& net)
      : net_(net),
        // 20 bits a count, none bounded: a count past them is caught, not carried on
        layout_(std::vector<std::uint32_t>(net.placeSlots().size(), 20), std::vector<bool>(net.placeSlots().size(), false),
                std::vector<bool>(net.placeSlots().size(), false)),
        firing_(net) {
    firing_.use(layout_);
  }

  Marking initial() const {
    Marking m;
    for (const auto& s : net_.placeSlots()) m.push_back(s.initial);
    return m;
  }
  /// Per transition: enabled in `m`.
  std::vector<bool> enabled(const Marking& m) const {
    const auto packed = pack(m);
    std::vector<bool> out;
    for (TransitionId t{0}; t < net_.transitions().size(); ++t) {
      out.push_back(firing_.enabled(t, packed.data()));
    }
    return out;
  }
  /// The marking after firing `t` in `m`; nullopt when `t` is not enabled or a count grows
  /// past what the packed markings hold.
  std::optional<Marking> fire(const Marking& m, TransitionId t) const {
    const auto packed = pack(m);
    std::vector<std::uint64_t> next(layout_.words());
    std::size_t field = 0;
    if (firing_.fire(t, packed.data(), next.data(), field) != detail::Fired::Ok) return std::nullopt;
    Marking out(m.size());
    layout_.unpack(next.data(), out.data());
    return out;
  }

 private:
  std::vector<std::uint64_t> pack(const Marking& m) const {
    std::vector<std::uint64_t> packed(layout_.words());
    std::size_t bad = 0;
    EXPECT_TRUE(layout_.pack(m.data(), packed.data(), bad)) << str(m);
    return packed;
  }
  const Net& net_;
  detail::Layout layout_;
  detail::Firing firing_;
};

/// Per transition: the kernel says it is enabled.
std::vector<bool> kernelEnabled(const Kernel& k) {
  std::vector<bool> out;
  for (TransitionId t{0}; t < k.net().transitions().size(); ++t) out.push_back(k.enabled(t));
  return out;
}

Marking kernelMarking(const Kernel& k) {
  Marking m;
  for (PlaceSlotId ps{0}; ps < k.net().placeSlots().size(); ++ps) m.push_back(k.marking(ps));
  return m;
}

/// Brings `k` (nothing occurring) to `m` the way scripts would: counts set on control slots;
/// on node slots the first tokens deleted, or fresh ones (numbered from `fresh`) added.
void moveKernelTo(Kernel& k, const Marking& m, NodeRef& fresh) {
  for (PlaceSlotId ps{0}; ps < m.size(); ++ps) {
    if (k.net().placeSlots()[ps].kind == SlotKind::Control) {
      ASSERT_EQ(k.setMarking(ps, m[ps]), "") << ps;
      continue;
    }
    const auto nodes = k.nodes(ps);
    if (static_cast<std::int64_t>(nodes.size()) > m[ps]) {
      const std::set<NodeRef> gone(nodes.begin(), nodes.end() - static_cast<std::ptrdiff_t>(m[ps]));
      k.dropNodes([&](NodeRef r) { return gone.count(r) > 0; });
    }
    while (k.marking(ps) < m[ps]) ASSERT_EQ(k.addNode(ps, fresh++), "") << ps;
  }
}

/// Compares the two in marking `m` (the kernel's); names the net and the marking on failure.
void expectSameEnabled(const Kernel& k, const Generator& g, int net_index) {
  const Marking m = kernelMarking(k);
  ASSERT_EQ(k.occurringCount(), 0u);
  EXPECT_EQ(kernelEnabled(k), g.enabled(m)) << "net " << net_index << " in " << str(m) << ":\n" << describe(k.net());
}

TEST(EnablingProperty, KernelAndAnalysisAgreeAlongRandomWalks) {
  core::Random rng(kSeed);
  for (int i = 0; i < kNets && !HasFailure(); ++i) {
    const auto net = randomNet(rng);
    const Generator g(*net);
    Kernel k(net, {1.0, 1});
    NodeRef fresh = 1000;
    for (int walk = 0; walk < 3; ++walk) {
      Marking m = g.initial();
      for (int step = 0; step < 30 && !HasFailure(); ++step) {
        moveKernelTo(k, m, fresh);
        expectSameEnabled(k, g, i);
        std::vector<TransitionId> can;
        const auto enabled = g.enabled(m);
        for (TransitionId t{0}; t < enabled.size(); ++t) {
          if (enabled[t]) can.push_back(t);
        }
        if (can.empty()) break;
        const auto next = g.fire(m, can[rng.below(can.size())]);
        if (!next) break;
        m = *next;
      }
    }
  }
}

TEST(EnablingProperty, KernelAndAnalysisAgreeInEveryReachableMarking) {
  // breadth first over the reachable markings (up to 500); when that is all of them, the
  // analysis must count as many
  core::Random rng(kSeed + 1);
  int complete = 0;
  for (int i = 0; i < kNets && !HasFailure(); ++i) {
    const auto net = randomNet(rng);
    const Generator g(*net);
    Kernel k(net, {1.0, 1});
    NodeRef fresh = 1000;
    std::set<Marking> seen{g.initial()};
    std::deque<Marking> queue{g.initial()};
    bool cut = false;
    while (!queue.empty() && !HasFailure()) {
      const Marking m = queue.front();
      queue.pop_front();
      moveKernelTo(k, m, fresh);
      expectSameEnabled(k, g, i);
      for (TransitionId t{0}; t < net->transitions().size(); ++t) {
        const auto next = g.fire(m, t);
        if (!next || seen.count(*next)) continue;
        if (seen.size() >= 500) {
          cut = true;
          continue;
        }
        seen.insert(*next);
        queue.push_back(*next);
      }
    }
    if (cut) continue;
    ++complete;
    const StateSpace s = explore(*net);
    EXPECT_TRUE(s.bounded) << "net " << i << ":\n" << describe(*net);
    EXPECT_EQ(s.states, seen.size()) << "net " << i << ":\n" << describe(*net);
  }
  EXPECT_GT(complete, kNets / 2);  // most random nets are small enough to see whole
}

TEST(EnablingProperty, KernelAndAnalysisAgreeWhileTheKernelFiresOnItsOwn) {
  // one-step transitions: after the completions of a step nothing occurs, and the marking
  // the kernel's own starts and completions made is compared before the next firing phase
  core::Random rng(kSeed + 2);
  for (int i = 0; i < kNets && !HasFailure(); ++i) {
    const auto net = randomNet(rng);
    const Generator g(*net);
    Kernel k(net, {1.0, 1});
    expectSameEnabled(k, g, i);
    k.start();
    for (int step = 0; step < 30 && !HasFailure(); ++step) {
      k.beginStep();
      k.completeOccurrences();
      expectSameEnabled(k, g, i);
      k.fireEnabled();
    }
  }
}

}  // namespace
}  // namespace gdpn::net
