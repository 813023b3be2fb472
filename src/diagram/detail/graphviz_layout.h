#pragma once
// Graphviz's `dot` as a layout engine: nodes of given sizes and edges in, centres and edge
// polylines out (layout units, y down). Internal to the diagram module.

#include <optional>
#include <string>
#include <vector>

#include "gdpn/diagram/geometry.h"

namespace gdpn::diagram::detail {

/// A node to place: its size, layout units, and whether it is drawn round.
struct GvNode {
  double width = 0.0;   // layout units
  double height = 0.0;  // layout units
  bool round = false;   // a circle (places) rather than a box
};

/// An edge between two nodes (indices into the node list).
struct GvEdge {
  std::size_t from = 0;
  std::size_t to = 0;
};

/// What dot made of the graph: node centres and one polyline per edge (layout units, y down,
/// the top-left of the drawing at 0, 0).
struct GvResult {
  std::vector<Point> centres;
  std::vector<std::vector<Point>> edges;
};

/// Runs dot (rankdir LR, ranks `rank_gap` layout units apart) on the graph; nullopt with
/// `why` when Graphviz fails.
std::optional<GvResult> dotLayout(const std::vector<GvNode>& nodes, const std::vector<GvEdge>& edges, double rank_gap,
                                  std::string& why);

}  // namespace gdpn::diagram::detail
