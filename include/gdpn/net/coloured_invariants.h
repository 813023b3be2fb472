#pragma once
/// \file
/// P-invariants of a coloured net found on the net itself, without unfolding it (semantics:
/// *Invariants of a coloured net*): invariants over counts (a weight per place slot for every
/// value: `|Think| + |Eat| = 5`), and families of invariants over a finite colour set D, one
/// per value x of D, that count the tokens whose value (or one component of it) is x or a
/// successor of x in a cyclic set (`Think(x) + Eat(x) = 1 for every x in Philo`). Found where
/// the inscriptions allow it exactly; a place whose inscriptions do not is left out, never
/// guessed. Not all invariants of the unfolded net are listed: those that are no such family
/// are not.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/net/invariants.h"
#include "gdpn/net/net.h"

namespace gdpn::net {

/// What a term of a coloured invariant counts of its place slot's tokens.
enum class Projection : std::uint8_t {
  Count,      ///< every token, whatever its value (and the tokens of a slot without values)
  Value,      ///< the tokens whose value is x shifted by `offset` (the slot's set is the family's)
  Component,  ///< the tokens whose component `component` is x shifted by `offset` (a product or record)
};

/// One term of a coloured invariant: `weight` times what `projection` counts on `place_slot`.
struct ColouredTerm {
  PlaceSlotId place_slot{0u};                  ///< the place slot counted
  Projection projection = Projection::Count;  ///< which of its tokens count
  std::uint32_t component = 0;                ///< Component: which component (a record's in field order), from 0
  /// Value, Component: the value counted is the `offset`-th successor of x (in a cyclic set,
  /// from 0 to |D|-1: `succ(x)` is 1, `pred(x)` is |D|-1); 0 elsewhere.
  std::int64_t offset = 0;
  std::int64_t weight = 1;  ///< > 0
  friend auto operator<=>(const ColouredTerm&, const ColouredTerm&) = default;
};

/// A P-invariant of a coloured net, or a family of them (one per value x of `over`): the
/// weighted sum of its terms is the same in every reachable marking.
struct ColouredInvariant {
  std::optional<ColourId> over;     ///< the set D of x; none for an invariant over counts (all terms Count)
  std::vector<ColouredTerm> terms;  ///< sorted
  /// The weighted sum in the initial marking (and so in every reachable one): per value x of
  /// `over`, in the set's order; one number for an invariant over counts.
  std::vector<std::int64_t> tokens;
};

/// Limits of colouredInvariants().
struct ColouredInvariantOptions {
  InvariantOptions limits{};  ///< of each Farkas computation (candidate rows, memory, deadline)
  /// Sets of more values are not taken as a family's D (each value is an equation per binding).
  std::int64_t most_values = 64;
  /// A set D is not taken where the transitions' bindings of their variables of D, together,
  /// number more than this.
  std::size_t most_bindings = 100'000;
};

/// What colouredInvariants() found.
struct ColouredInvariants {
  std::vector<ColouredInvariant> invariants;  ///< those over counts first, then the families by set
  bool complete = true;                       ///< false when a limit stopped a computation
  ExploreStop stop = ExploreStop::Done;       ///< the first limit that did
  /// What was left out and why, one line each ("over Philo: 'forks' is left out: ...").
  std::vector<std::string> notes;
};

/// The P-invariants of coloured net `net` over counts and over each finite colour set of 2 to
/// options.most_values values that a value slot's set is or has as a component and some
/// transition has a variable of (see the file comment). A net without value tokens gets its
/// P-invariants over counts.
ColouredInvariants colouredInvariants(const Net& net, const ColouredInvariantOptions& options = {});

/// The weight invariant `inv` gives a token on place slot `ps` of value `value` (null for a
/// slot without values), for the member x = the `x`-th value of inv.over (ignored for an
/// invariant over counts).
std::int64_t colouredWeight(const Net& net, const ColouredInvariant& inv, std::size_t x, PlaceSlotId ps,
                            const Value* value);

/// `inv` as a CPN Tools user reads it: `|main/thinking| + |main/eating| = 5` over counts;
/// `main/thinking(x) + main/eating(x) + main/eating(pred(x)) = 1 for every x in Phil` for a
/// family (a component: `P(x, _)`, a record's field: `P{f = x}`; a sum that differs by x lists
/// the values: `= 1 for x = a; 0 for every other x in D`).
std::string colouredInvariantText(const Net& net, const ColouredInvariant& inv);

}  // namespace gdpn::net
