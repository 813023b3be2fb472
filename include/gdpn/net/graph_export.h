#pragma once
/// \file
/// The reachability graph written out for other tools: Graphviz DOT (markings as node labels,
/// transitions on the edges) and the Aldebaran format of CADP and mCRL2 (`.aut`).

#include <ostream>

#include "gdpn/net/analysis.h"

namespace gdpn::net {

/// A file format for the reachability graph.
enum class GraphFormat : std::uint8_t {
  Dot,        ///< `digraph`: node `s<i>` labelled with the places holding tokens, edges with transitions
  Aldebaran,  ///< `des (0, edges, states)` then `(from, "transition", to)` per edge; state 0 the initial one
};

/// Stores the reachability graph of `net` under `limits` (states numbered breadth first from
/// the initial marking, 0) and writes it to `out` in `format`. Returns Done, or the limit
/// that stopped the graph (then nothing is written).
ExploreStop writeStateGraph(const Net& net, GraphFormat format, std::ostream& out, const ExploreOptions& limits = {});

}  // namespace gdpn::net
