#pragma once
// Internal to the net module: state formulas evaluated on packed markings, for the queries'
// searches (reachability on the fly, CTL over the whole graph).

#include <algorithm>

#include "gdpn/net/query.h"
#include "marking_store.h"

namespace gdpn::net::detail {

/// Evaluates state formulas on packed markings.
class StateCheck {
 public:
  StateCheck(const Net& net, const Layout& layout) : layout_(layout), candidates_(net), firing_(net) {
    candidates_.use(layout_);
    firing_.use(layout_);
  }
  const Firing& firing() const { return firing_; }
  const Candidates& candidates() const { return candidates_; }

  /// The tokens `s` counts in `m`.
  std::int64_t sum(const TokenSum& s, const std::uint64_t* m) const {
    std::int64_t total = s.constant;
    for (PlaceSlotId k : s.slots) total += layout_.value(m, k);
    return total;
  }

  /// True when the state formula `f` holds in `m`.
  bool holds(const Formula& f, const std::uint64_t* m) {
    switch (f.kind) {
      case FormulaKind::True: return true;
      case FormulaKind::False: return false;
      case FormulaKind::Deadlock: {
        candidates_.find(m, scratch_);
        return std::none_of(scratch_.begin(), scratch_.end(), [&](TransitionId t) { return firing_.enabled(t, m); });
      }
      case FormulaKind::Fireable:
        return std::any_of(f.transitions.begin(), f.transitions.end(),
                           [&](TransitionId t) { return firing_.enabled(t, m); });
      case FormulaKind::Compare: {
        const std::int64_t a = sum(f.left, m), b = sum(f.right, m);
        switch (f.compare) {
          case Comparison::Less: return a < b;
          case Comparison::LessEqual: return a <= b;
          case Comparison::Equal: return a == b;
          case Comparison::NotEqual: return a != b;
          case Comparison::GreaterEqual: return a >= b;
          case Comparison::Greater: return a > b;
        }
        return false;
      }
      case FormulaKind::Not: return !holds(f.operands[0], m);
      case FormulaKind::And:
        return std::all_of(f.operands.begin(), f.operands.end(), [&](const Formula& o) { return holds(o, m); });
      case FormulaKind::Or:
        return std::any_of(f.operands.begin(), f.operands.end(), [&](const Formula& o) { return holds(o, m); });
      default: return false;  // not a state formula: never asked
    }
  }

 private:
  const Layout& layout_;
  Candidates candidates_;
  Firing firing_;
  std::vector<TransitionId> scratch_;
};

/// Field sizes for concrete markings: the bounds the invariants and the state equation give,
/// and 32 bits where there is none (a count past that stops the search).
inline Layout concreteLayout(const Plan& p) {
  std::vector<std::uint32_t> bits = p.bits;
  for (std::size_t k = 0; k < bits.size(); ++k) {
    if (p.omega[k]) bits[k] = kMaxBits;
  }
  return Layout(bits, std::vector<bool>(bits.size(), false));
}

}  // namespace gdpn::net::detail
