#pragma once
/// \file
/// Unfolding a coloured net (semantics: *Value tokens*) into a place/transition net that the
/// analysis reads: a place per value of each value slot, a transition per binding of each
/// coloured transition.

#include <cstddef>
#include <optional>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/name_expansion.h"
#include "gdpn/net/spec.h"

namespace gdpn::net {

/// The most bindings unfold() makes of one transition, and places of one value slot, unless
/// told otherwise.
inline constexpr std::size_t kMostUnfoldedBindings = 100'000;

/// A coloured net unfolded.
struct Unfolding {
  /// The place/transition net: every value slot of a place P becomes a place `P_v` per value v
  /// of its set (holding the tokens of that value; `P` itself stays only where it has other
  /// slots); every coloured transition T a transition `T_b` per binding b (its variables'
  /// values) whose condition holds and whose arcs all have values, with arcs of the
  /// multiplicities the binding gives. Uncoloured places, transitions and arcs, and every
  /// attribute but the colours (durations, scripts ...), are as they were.
  NetSpec net;
  /// Each coloured place and transition (top-level pages' constructs, qualified "page/name")
  /// -> the qualified names of what it became: what a query about it means.
  NameExpansion names;
};

/// True when `spec` has anything coloured: a colour set, a variable, a value slot, an arc
/// inscription or a condition.
bool coloured(const NetSpec& spec);

/// Unfolds `spec` (see Unfolding). Refused, with a located error in `diags`: an inscription
/// that does not parse or type-check, a value slot of a set that is not finite or has more
/// than `most_bindings` values, a transition
/// with more than `most_bindings` bindings (or a variable of a set that is not finite), a
/// coloured construct of a page type, an arc on a value slot without an inscription.
std::optional<Unfolding> unfold(const NetSpec& spec, core::Diagnostics& diags,
                                std::size_t most_bindings = kMostUnfoldedBindings);

}  // namespace gdpn::net
