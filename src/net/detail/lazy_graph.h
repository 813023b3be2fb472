#pragma once
// Internal to the net module: the reachability graph made as a search asks for it, for the
// queries answered on the fly (CTL by local searches, LTL by the product searched depth
// first): a marking's successors are made the first time they are asked for and kept.

#include <cstdint>
#include <memory>
#include <vector>

#include "state_check.h"
#include "stubborn.h"

namespace gdpn::net::detail {

/// Thrown out of a search over a LazyGraph when a limit stops it (LazyGraph::stop() says
/// which): the answer is then unknown.
struct Stopped {};

/// The markings met so far (id 0 the initial one) and the edges of those expanded.
class LazyGraph {
 public:
  static constexpr std::uint64_t kNotYet = ~std::uint64_t{0};

  /// `atoms`: state formulas worked out once per marking as it is met (atom(k, s)).
  LazyGraph(const Net& net, const ExploreOptions& limits, std::vector<const Formula*> atoms = {})
      : states_(net, limits), limits_(limits), atoms_(std::move(atoms)) {
    if (!states_.ok()) {
      stop_ = ExploreStop::Overflow;
      return;
    }
    met(0);
  }

  /// False when the initial marking does not fit (stop() is Overflow; nothing may be used).
  bool ok() const { return states_.ok(); }
  /// Why a search stopped (Done while none has).
  ExploreStop stop() const { return stop_; }
  /// The markings met so far.
  std::size_t size() const { return first_.size(); }
  Store& store() { return states_.store(); }
  StateCheck& check() { return states_.check(); }

  /// The first of the edges of `s` (made now if they are not yet); throws Stopped when a
  /// limit stops the search.
  std::uint64_t first(StateId s) {
    if (first_[s] == kNotYet) expand(s);
    return first_[s];
  }
  /// One past the last edge of `s` (expanded).
  std::uint64_t end(StateId s) const { return first_[s] + count_[s]; }
  /// The number of edges of `s` (expanded).
  std::uint32_t degree(StateId s) const { return count_[s]; }
  /// The marking an edge leads to, and the transition that fires on it.
  StateId succ(std::uint64_t e) const { return succ_[e]; }
  TransitionId via(std::uint64_t e) const { return via_[e]; }
  /// Whether atom `k` holds in `s`.
  bool atom(std::size_t k, StateId s) const { return atom_[s * atoms_.size() + k] != 0; }

  /// From now on, a marking's edges are those of an ample set where one serves (LTL without
  /// next on the fly): the enabled members of a stubborn set (Stubborn::selectFrom) none of
  /// which is visible to the atoms, the smallest of those grown from the first few enabled
  /// transitions; all enabled transitions where none serves. The search must fully expand
  /// (expandFully) a marking whose ample edges close a cycle on its stack.
  void reduceFor(const Net& net) {
    stubborn_ = std::make_unique<Stubborn>(net, states_.store().layout());
    visible_ = stubborn_->visibleTo(atoms_);
  }
  /// Whether the edges of `s` (expanded) are an ample set short of all enabled transitions.
  bool reduced(StateId s) const { return s < reduced_.size() && reduced_[s] != 0; }
  /// Gives reduced `s` all its edges (a new list; the ample edges are among them).
  void expandFully(StateId s) {
    if (!reduced(s)) return;
    reduced_[s] = 0;
    edges(s, nullptr);
  }

  /// The markings the transitions `ts` lead to from `s` (those not enabled passed over),
  /// appended to `out`, met but not kept as edges of `s` (a search of its own over some of
  /// the edges: a stubborn set's); throws Stopped when a limit stops the search.
  void fireOnly(StateId s, const std::vector<TransitionId>& ts, std::vector<StateId>& out) {
    look();
    const bool fits = states_.fire(s, ts, [&](TransitionId, StateId w, bool added) {
      out.push_back(w);
      if (added) met(w);
      return true;
    });
    settle(fits);
  }

  /// Memory held, bytes (with what the caller keeps per marking: alsoPerMarking).
  std::uint64_t bytes() const {
    return states_.bytes() + first_.capacity() * (12 + per_marking_) + succ_.capacity() * 8 + atom_.capacity();
  }
  /// Counts `bytes` more per marking met: tables the caller keeps beside the graph.
  void alsoPerMarking(std::uint64_t bytes) { per_marking_ = bytes; }

 private:
  void met(StateId s) {
    first_.push_back(kNotYet);
    count_.push_back(0);
    if (atoms_.empty()) return;
    const std::uint64_t* m = states_.store().load(s, here_);
    for (const Formula* f : atoms_) atom_.push_back(states_.check().holds(*f, m) ? 1 : 0);
  }

  void expand(StateId s) {
    if (!stubborn_) {
      edges(s, nullptr);
      return;
    }
    // an ample set: the smallest invisible stubborn set grown from one of the first enabled
    // transitions
    const std::uint64_t* m = states_.store().load(s, here_);
    states_.check().candidates().find(m, states_.check().firing(), enabled_);
    std::erase_if(enabled_, [&](TransitionId t) { return !states_.check().firing().enabled(t, m); });
    ample_.clear();
    std::size_t tries = 0;
    for (TransitionId seed : enabled_) {
      if (visible_[seed]) continue;
      if (stubborn_->selectFrom(seed, m, visible_, set_) && (ample_.empty() || set_.size() < ample_.size())) {
        ample_.swap(set_);
        if (ample_.size() == 1) break;
      }
      if (++tries == 4) break;
    }
    const bool reduce = !ample_.empty() && ample_.size() < enabled_.size();
    if (reduced_.size() < first_.size()) reduced_.resize(first_.size(), 0);
    reduced_[s] = reduce ? 1 : 0;
    edges(s, reduce ? &ample_ : nullptr);
  }

  // before markings are made: the limits looked at now and then; throws Stopped past one
  void look() {
    if (stop_ == ExploreStop::Done && (++expansions_ & 0x3ff) == 0) stop_ = passedLimit(limits_, bytes());
    if (stop_ != ExploreStop::Done) throw Stopped{};
  }
  // after: a count past its field, or too many markings, stops the search
  void settle(bool fits) {
    if (!fits) stop_ = ExploreStop::Overflow;
    if (states_.store().size() > std::min<std::uint64_t>(limits_.max_states, 0xfffffff0u)) {
      stop_ = ExploreStop::MaxStates;
    }
    if (stop_ != ExploreStop::Done) throw Stopped{};
  }

  // the edges of `s`, made now: those of `only` (all where null)
  void edges(StateId s, const std::vector<TransitionId>* only) {
    look();
    const std::uint64_t at = succ_.size();
    auto each = [&](TransitionId t, StateId w, bool added) {
      succ_.push_back(w);
      via_.push_back(t);
      if (added) met(w);
      return true;
    };
    settle(only ? states_.fire(s, *only, each) : states_.successors(s, each));
    first_[s] = at;
    count_[s] = static_cast<std::uint32_t>(succ_.size() - at);
  }

  ConcreteStates states_;
  const ExploreOptions& limits_;
  std::vector<const Formula*> atoms_;
  ExploreStop stop_ = ExploreStop::Done;
  std::uint64_t expansions_ = 0;
  std::uint64_t per_marking_ = 0;
  std::vector<std::uint64_t> first_;  // per marking: its first edge, kNotYet until expanded
  std::vector<std::uint32_t> count_;  // per marking: its edges
  std::vector<StateId> succ_;
  std::vector<TransitionId> via_;
  std::vector<std::uint8_t> atom_;  // per marking, per atom
  std::vector<std::uint64_t> here_;
  // the ample sets (reduceFor)
  std::unique_ptr<Stubborn> stubborn_;
  std::vector<bool> visible_;
  std::vector<std::uint8_t> reduced_;  // per marking: its edges are an ample set short of all
  std::vector<TransitionId> enabled_, ample_, set_;
};

}  // namespace gdpn::net::detail
