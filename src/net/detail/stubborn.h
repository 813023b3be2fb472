#pragma once
// Internal to the net module: stubborn sets for reachability (Valmari; Kristensen, Schmidt
// and Valmari's question-guided form), the partial-order reduction of the queries' searches
// on the fly.

#include <cstdint>
#include <vector>

#include "marking_store.h"
#include "state_check.h"

namespace gdpn::net::detail {

/// Chooses, in a marking where a state formula does not hold yet, the transitions whose
/// firing keeps every marking where it holds reachable: the enabled members of a stubborn
/// set that holds an up-set of the formula (transitions of which one must fire before the
/// formula can hold). A disabled member stays disabled until another member fires (it waits
/// for a place that only members change); an enabled member neither disables nor is
/// disabled by a transition outside the set. So the first member on any path to the formula
/// can fire first, and a breadth-first search over the chosen transitions finds the formula
/// wherever the full search would (the path it finds is shortest among the chosen ones).
class Stubborn {
 public:
  Stubborn(const Net& net, const Layout& layout);

  /// The enabled transitions of a stubborn set for `target` in `m` (where `target` fails),
  /// in increasing order, into `out`. Empty when `target` cannot hold after `m`.
  void select(const Formula& target, const std::uint64_t* m, StateCheck& check, std::vector<TransitionId>& out);

  /// The enabled members of a stubborn set grown from `seed` (enabled in `m`), in increasing
  /// order, into `out`; each of them is a key transition (nothing outside the set disables
  /// it). False when one of them is `visible` (per transition): the set then does not serve
  /// LTL without next.
  bool selectFrom(TransitionId seed, const std::uint64_t* m, const std::vector<bool>& visible,
                  std::vector<TransitionId>& out);

  /// Per transition: whether firing it can change the value of one of the state formulas
  /// `atoms` (it changes the tokens of a place slot that one of them reads: a sum's, or one
  /// that a transition of a fireable depends on; with `deadlock`, of any slot).
  std::vector<bool> visibleTo(const std::vector<const Formula*>& atoms) const;

 private:
  // a transition's requirement on one place slot: lo <= tokens <= hi
  struct Need {
    std::uint32_t slot;
    std::int64_t lo, hi;
  };
  // the transitions of a list per place slot (compressed rows)
  struct Rows {
    std::vector<std::uint32_t> begin;
    std::vector<TransitionId> items;
    std::span<const TransitionId> of(std::size_t k) const { return {items.data() + begin[k], begin[k + 1] - begin[k]}; }
  };
  static Rows rows(std::size_t slots, std::vector<std::vector<TransitionId>>& lists);

  bool holds(const Need& n, const std::uint64_t* m) const;
  bool enabled(TransitionId t, const std::uint64_t* m) const;
  // the transitions that can make `n` hold where it fails
  std::span<const TransitionId> fixers(const Need& n, const std::uint64_t* m) const;
  // into the set: the fixers of the failing need of disabled `t` that has the fewest
  void addScapegoat(TransitionId t, const std::uint64_t* m);
  // into the set: the transitions that can disable enabled `t`
  void addDisablers(TransitionId t);
  // into the set: an up-set of `f` (positive) or of `not f`, which fails in `m`
  void addUpSet(const Formula& f, bool positive, const std::uint64_t* m, StateCheck& check);
  // into the set: the transitions that can raise (or lower) the value of `left - right`
  void addMovers(const TokenSum& left, const TokenSum& right, bool raise);
  void add(TransitionId t);
  // a new set, empty
  void start();
  // closes the set grown so far and puts its enabled members into `out`
  void close(const std::uint64_t* m, std::vector<TransitionId>& out);
  void add(std::span<const TransitionId> ts) {
    for (TransitionId t : ts) add(t);
  }

  const Layout& layout_;
  std::vector<std::uint32_t> need_begin_;  // per transition: its needs in needs_ from here
  std::vector<Need> needs_;
  std::vector<std::uint32_t> change_begin_;  // per transition: the slots it changes, with the sign
  std::vector<std::pair<std::uint32_t, std::int64_t>> changes_;
  Rows raisers_, lowerers_;  // per slot: the transitions that add to it, take from it (net)
  Rows floors_, ceilings_;   // per slot: the transitions that need at least, at most some tokens there
  std::vector<std::uint32_t> stamp_;  // per transition: == epoch_ when in the set
  std::uint32_t epoch_ = 0;
  std::vector<TransitionId> work_;
};

}  // namespace gdpn::net::detail
