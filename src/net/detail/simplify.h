#pragma once
// Internal to the net module: formulas made simpler before they are answered, by what holds
// in every reachable marking (the state equation's bounds and refutations) and by identities
// of CTL (semantics: docs/queries.md, "What is answered").

#include <chrono>
#include <map>
#include <optional>

#include "gdpn/net/query.h"

namespace gdpn::net::detail {

/// Simplifies formulas of one net, keeping what it has worked out (the state equation's bound
/// of each sum) for the next.
class Simplifier {
 public:
  /// Nothing is worked out past `deadline` (the formula is then simplified less).
  Simplifier(const Net& net, std::optional<std::chrono::steady_clock::time_point> deadline)
      : net_(net), deadline_(deadline) {}

  /// `f` with the same value in the initial marking: a state subformula that the state
  /// equation shows to hold in no reachable marking made false (in every one, true); a
  /// comparison whose sums' bounds decide it made constant; then constants folded (`EF
  /// false` = false, `p and false` = false, `E [p U true]` = true, ...) and repeated
  /// operators merged (`EF EF p` = `EF p`, `AG AG p` = `AG p`). `changed` counts the
  /// subformulas replaced.
  Formula simplified(const Formula& f, std::size_t& changed);

 private:
  // the bound of `s` from the state equation, -1 where none
  std::int64_t most(const TokenSum& s);
  // true, false, or nullopt: what a comparison is in every reachable marking, by bounds
  std::optional<bool> decide(const Formula& compare);
  // true, false, or nullopt: what a state formula is in every reachable marking
  std::optional<bool> constant(const Formula& f);
  bool late() const { return deadline_ && std::chrono::steady_clock::now() >= *deadline_; }

  const Net& net_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  std::map<std::vector<PlaceSlotId>, std::int64_t> most_;
};

}  // namespace gdpn::net::detail
