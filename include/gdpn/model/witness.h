#pragma once
/// \file
/// Witnesses: the firing sequence that shows a query's answer, written by `gdpn analyze
/// --witness` as JSON and read back by `gdpn run --replay` to play it in simulation.

#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/analysis.h"
#include "gdpn/net/kernel.h"

namespace gdpn::model {

/// A witness read back: the transitions to fire, in order, and the marking they reach.
struct Witness {
  std::string query;                          ///< the formula it shows, as text
  std::vector<net::TransitionId> path;        ///< from the initial marking to `marking`
  std::vector<net::TransitionId> cycle;       ///< a lasso's loop, fired once after `path` (back to `marking`)
  bool lasso = false;                         ///< an infinite path: `path`, then `cycle` forever
  std::vector<std::pair<std::string, std::int64_t>> marking;  ///< tokens per place (places not named hold none)
};

/// Reads a witness file written by witnessJson (model/analysis.h) for `net`; mistakes (not JSON, a transition or
/// place the net does not have, a missing key) go to `diags` as `file:line:col: error: ...`.
std::optional<Witness> loadWitness(const net::Net& net, const std::string& file, core::Diagnostics& diags);

/// Compares the marking of `kernel` with the witness' marking: "" when they agree, or which
/// place holds what against what the witness says.
std::string witnessMismatch(const net::Net& net, const net::Kernel& kernel, const Witness& witness);

}  // namespace gdpn::model
