#pragma once
/// \file
/// The selection: one thing chosen across every view of the IDE (a scene node, a place, a
/// transition or an instance of a page type). Views show it and change it only through the
/// document.

#include <cstdint>
#include <string>

namespace gdpn::ide {

/// What kind of thing is selected.
enum class SelectionKind : std::uint8_t {
  None,        ///< nothing
  Node,        ///< a scene node, by its path ("arm/turn/column")
  Place,       ///< a place, by its qualified name ("cellA/buffer")
  Transition,  ///< a transition, by its qualified name
  Instance,    ///< an instance of a page type, by its qualified name
};

/// "none", "node", "place", "transition", "instance".
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

class Document;

/// True when `selection` names something of `doc`'s model: a node of its scene, a place,
/// transition or instance written on one of its pages (or in the page type of an instance on
/// the way). None names nothing.
[[nodiscard]] bool namesSomething(const Document& doc, const Selection& selection);

}  // namespace gdpn::ide
