#pragma once
// Internal to the net module: state formulas evaluated on packed markings, for the queries'
// searches (reachability on the fly, CTL over the whole graph).

#include <algorithm>
#include <chrono>
#include <memory>

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
    // queries see concrete markings (no ω), fields of at most 32 bits and constants of at most
    // 2^60 in magnitude: the sum cannot overflow
    for (PlaceSlotId k : s.slots) total += layout_.value(m, k);
    return total;
  }

  /// True when the state formula `f` holds in `m`.
  bool holds(const Formula& f, const std::uint64_t* m) {
    switch (f.kind) {
      case FormulaKind::True: return true;
      case FormulaKind::False: return false;
      case FormulaKind::Deadlock: {
        candidates_.find(m, firing_, scratch_);
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
      case FormulaKind::All:
      case FormulaKind::Bound:
      case FormulaKind::Exists:
      case FormulaKind::Future:
      case FormulaKind::Globally:
      case FormulaKind::Next:
      case FormulaKind::Until: return false;  // not a state formula: never asked
    }
    return false;  // no value of the enum
  }

 private:
  const Layout& layout_;
  Candidates candidates_;
  Firing firing_;
  std::vector<TransitionId> scratch_;
};

/// The limit of `limits` passed now, memory against `bytes` held and the deadline, or Done.
inline ExploreStop passedLimit(const ExploreOptions& limits, std::uint64_t bytes) {
  if (limits.max_bytes != 0 && bytes > limits.max_bytes) return ExploreStop::MaxMemory;
  if (limits.deadline && std::chrono::steady_clock::now() >= *limits.deadline) return ExploreStop::TimeLimit;
  return ExploreStop::Done;
}

/// The concrete markings of a net met so far (no ω: fields sized by the invariants' and the
/// state equation's bounds, 32 bits where there is none), id 0 the initial one, and their
/// successors: what the queries' breadth-first searches share.
class ConcreteStates {
 public:
  ConcreteStates(const Net& net, const ExploreOptions& limits) {
    const Plan p = plan(net, limits);
    if (p.overflow) return;
    std::vector<std::uint32_t> bits = p.bits;
    for (std::size_t k = 0; k < bits.size(); ++k) {
      if (p.omega[k]) bits[k] = kMaxBits;
    }
    std::vector<bool> bounded = p.omega;
    bounded.flip();
    store_ = std::make_unique<Store>(Layout(bits, std::vector<bool>(bits.size(), false), bounded));
    check_ = std::make_unique<StateCheck>(net, store_->layout());
    next_.resize(store_->words());
    std::size_t bad = 0;
    store_->layout().pack(p.m0.data(), next_.data(), bad);
    bool added = false;
    store_->insert(next_.data(), store_->hash(next_.data()), added);
  }
  /// False when the initial marking does not fit the fields (then nothing else may be used).
  bool ok() const { return store_ != nullptr; }
  Store& store() { return *store_; }
  std::unique_ptr<Store> releaseStore() { return std::move(store_); }
  StateCheck& check() { return *check_; }
  /// Memory the markings hold, bytes.
  std::uint64_t bytes() const { return store_->bytes(); }

  /// Calls `f(t, w, added)` for each transition t enabled in state `s`, w being the id of its
  /// successor (`added`: new to the store), until f returns false. False when a count did not
  /// fit its field (the search must stop: Overflow).
  template <class F>
  bool successors(StateId s, F f) {
    const std::uint64_t* m = store_->load(s, here_);
    check_->candidates().find(m, check_->firing(), candidates_);
    return fireFrom(m, candidates_, f);
  }

  /// The same for the transitions `ts` only (those not enabled are passed over).
  template <class F>
  bool fire(StateId s, const std::vector<TransitionId>& ts, F f) {
    return fireFrom(store_->load(s, here_), ts, f);
  }

 private:
  /// fire() from the packed marking `m` of the state.
  template <class F>
  bool fireFrom(const std::uint64_t* m, const std::vector<TransitionId>& ts, F f) {
    for (TransitionId t : ts) {
      std::size_t field = 0;
      const Fired fired = check_->firing().fire(t, m, next_.data(), field);
      if (fired == Fired::NotEnabled) continue;
      if (fired == Fired::TooBig) return false;
      bool added = false;
      const StateId w = store_->insert(next_.data(), store_->hash(next_.data()), added);
      if (!f(t, w, added)) break;
    }
    return true;
  }

  std::unique_ptr<Store> store_;
  std::unique_ptr<StateCheck> check_;
  std::vector<std::uint64_t> next_;
  std::vector<std::uint64_t> here_;  // the marking of the state whose successors are made
  std::vector<TransitionId> candidates_;
};

}  // namespace gdpn::net::detail
