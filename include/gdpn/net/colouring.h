#pragma once
/// \file
/// What a frozen net knows of its value tokens (semantics: *Value tokens*): the colour sets,
/// the set and initial values of each value slot, and per coloured transition its variables,
/// condition and arc inscriptions, each tied to the arc term it refines.

#include <cstdint>
#include <vector>

#include "gdpn/net/colour.h"
#include "gdpn/net/id.h"
#include "gdpn/net/inscription.h"

namespace gdpn::net {

/// The value tokens of a net. A net without value slots and conditions has none
/// (Net::colouring() is null).
struct Colouring {
  Colours colours;                              ///< the built-in and declared colour sets
  std::vector<std::string> variables;           ///< every declared variable, by name
  std::vector<ColourId> variable_sets;          ///< and its set
  std::vector<std::int32_t> slot_set;           ///< per place slot: the set of a value slot, -1 for other slots
  std::vector<Multiset> initial;                ///< per place slot: the initial values (empty for other slots)
  std::vector<std::int32_t> of_transition;      ///< per transition: its entry in `transitions`, -1 when it has none
  std::vector<TransitionInscriptions> transitions;  ///< per coloured transition: variables, condition, arcs
  std::vector<std::vector<TermId>> arc_terms;   ///< per coloured transition: the term of each of its arcs
  std::vector<TransitionId> transition_ids;     ///< per coloured transition: which transition it is
  /// True when every inscription of a normal, test or output arc moves the same number of
  /// tokens under every binding: the arc terms' weights are then exact, and what counts alone
  /// shows of the net (P-invariants, bounds of counts) holds for it.
  bool counts_exact = true;

  /// The inscriptions of `t`, or null when it has none.
  [[nodiscard]] const TransitionInscriptions* of(TransitionId t) const {
    const auto i = of_transition.empty() ? -1 : of_transition[t];
    return i < 0 ? nullptr : &transitions[static_cast<std::size_t>(i)];
  }
  /// The set of place slot `ps` when it is a value slot.
  [[nodiscard]] std::optional<ColourId> setOf(PlaceSlotId ps) const {
    const auto s = slot_set.empty() ? -1 : slot_set[ps];
    return s < 0 ? std::nullopt : std::optional<ColourId>(static_cast<ColourId>(s));
  }
};

}  // namespace gdpn::net
