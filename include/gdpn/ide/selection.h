#pragma once
/// \file
/// The selection: what is chosen across every view of the IDE (a scene node, a place, a
/// transition, an arc or an instance of a page type). One thing is the current one, which the
/// inspector shows; the net view may hold more beside it (a rubber band, Shift-click). Views show
/// it and change it only through the document.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/net/spec.h"

namespace gdpn::ide {

/// What kind of thing is selected.
enum class SelectionKind : std::uint8_t {
  None,        ///< nothing
  Node,        ///< a scene node, by its path ("arm/turn/column")
  Place,       ///< a place, by its qualified name ("cellA/buffer")
  Transition,  ///< a transition, by its qualified name
  Instance,    ///< an instance of a page type, by its qualified name
  Arc,         ///< an arc, by arcName() ("line: infeed -> load_a", "line: busy -> start (inhibitor)")
};

/// "none", "node", "place", "transition", "instance", "arc".
[[nodiscard]] const char* selectionKindName(SelectionKind kind);

/// The one selected thing. Names rather than handles, so that a selection survives a reload
/// and a rebuilt run.
struct Selection {
  SelectionKind kind = SelectionKind::None;  ///< what is selected
  std::string name;                          ///< node path or qualified net name ("" for None)

  /// A selected scene node at `path`.
  static Selection node(std::string path) { return {SelectionKind::Node, std::move(path)}; }
  /// True when something is selected.
  [[nodiscard]] bool any() const { return kind != SelectionKind::None; }
  friend bool operator==(const Selection&, const Selection&) = default;
};

/// An arc's name in a selection: its page's prefix ("line", or "line/cellA" inside an
/// instance), ": ", then its source, " -> ", its target, and for a test or inhibitor arc its
/// kind in brackets: "line: infeed -> load_a", "line: cellA/exit -> transfer",
/// "line: busy -> start (inhibitor)".
[[nodiscard]] std::string arcName(const std::string& prefix, const std::string& from, const std::string& to,
                                  net::ArcKind kind);

/// An arc named by arcName(), taken apart.
struct ArcName {
  std::string prefix;  ///< the page's prefix ("line", "line/cellA")
  std::string from;    ///< the source, as the page writes it
  std::string to;      ///< the target
  net::ArcKind kind = net::ArcKind::Normal;  ///< normal, test or inhibitor
};

/// arcName() read back; nullopt when `name` is not one.
[[nodiscard]] std::optional<ArcName> parseArcName(const std::string& name);

class Document;

/// True when `selection` names something of `doc`'s model: a node of its scene, a place,
/// transition, arc or instance written on one of its pages (or in the page type of an instance
/// on the way). None names nothing.
[[nodiscard]] bool namesSomething(const Document& doc, const Selection& selection);

/// The entries of `selections` that name something of `doc`'s model (namesSomething()), in
/// their order; each page's names are gathered once, so that a page's worth costs its size.
[[nodiscard]] std::vector<Selection> stillNamed(const Document& doc, std::vector<Selection> selections);

}  // namespace gdpn::ide
