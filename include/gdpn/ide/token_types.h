#pragma once
/// \file
/// The dissertation's type propagation: which node types each node slot can hold, found by
/// following the node tokens of the initial marking along the arcs, slot by slot; where two
/// types meet in one slot; and scripts that read a field no such node has, flagged before a
/// run. Also the scripts along a token's path. No ImGui: the contents view shows these.

#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/net/spec.h"
#include "gdpn/scene/types.h"

namespace gdpn::ide {

/// A construct's slot: "page/name" and the slot.
using SlotKey = std::pair<std::string, net::SlotId>;

/// What the propagation found on the pages of a net.
struct TokenTypes {
  /// The node types (their names, sorted) each place's and transition's node slot can hold.
  std::map<SlotKey, std::set<std::string>> types;
  /// A slot that two or more node types reach, and the transitions that bring them.
  struct Conflict {
    SlotKey slot;                   ///< the place slot
    std::set<std::string> types;    ///< the types that meet there
    std::vector<std::string> from;  ///< "page/transition" that deposit into it
  };
  std::vector<Conflict> conflicts;  ///< in page and declaration order
  /// A script that reads a field the slot's node type does not have.
  struct UnknownField {
    std::string construct;  ///< "page/name"
    std::string script;     ///< its kind ("pre_fire", "on_deposit (b0)")
    int line = 0;           ///< the line of the script's text, 1 its first
    std::string use;        ///< what it reads ("self.b0.vel9")
    std::string message;    ///< "a Joint has no field or method 'vel9'"
  };
  std::vector<UnknownField> unknown;  ///< in page and declaration order
};

/// The node type of the node at `path` on page `page` (a page type's paths are its own scene's);
/// null when there is none.
using NodeTypeOf = std::function<const scene::NodeType*(const std::string& page, const std::string& path)>;

/// Propagates the node types of `net`'s initial node tokens along its arcs, page by page
/// (pages and page types; an arc to a link is not followed), and checks the scripts.
TokenTypes propagateTokenTypes(const net::NetSpec& net, const NodeTypeOf& typeOf);

/// The places and transitions of `page` that the tokens of slot `slot` of place `place` can
/// reach along its arcs (the place first), in the order found: whose scripts touch them.
std::vector<std::string> tokenPath(const net::PageSpec& page, const std::string& place, net::SlotId slot);

}  // namespace gdpn::ide
