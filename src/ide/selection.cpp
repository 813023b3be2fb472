// Names of selection kinds, and whether a selection still names something of the model.

#include "gdpn/ide/selection.h"

#include <algorithm>

#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"

namespace gdpn::ide {

const char* selectionKindName(SelectionKind kind) {
  switch (kind) {
    case SelectionKind::None: return "none";
    case SelectionKind::Node: return "node";
    case SelectionKind::Place: return "place";
    case SelectionKind::Transition: return "transition";
    case SelectionKind::Instance: return "instance";
  }
  return "none";
}

bool namesSomething(const Document& doc, const Selection& selection) {
  const auto named = [](const auto& list, const std::string& name, auto key) {
    return std::any_of(list.begin(), list.end(), [&](const auto& x) { return key(x) == name; });
  };
  const auto by_name = [](const auto& x) -> const std::string& { return x.name; };
  const auto& net = doc.model().net;
  const auto at = selection.kind == SelectionKind::Node || selection.kind == SelectionKind::None
                      ? std::nullopt
                      : locateConstruct(net, selection.name);
  const auto* page = at ? findPage(net, at->page) : nullptr;
  switch (selection.kind) {
    case SelectionKind::None: return false;
    case SelectionKind::Node: return doc.scene() != nullptr && doc.scene()->find(selection.name) != nullptr;
    case SelectionKind::Place:
      return page != nullptr && (named(page->places, at->name, by_name) ||
                                 named(page->references, at->name, [](const auto& r) -> const std::string& { return r.place; }));
    case SelectionKind::Transition: return page != nullptr && named(page->transitions, at->name, by_name);
    case SelectionKind::Instance: return page != nullptr && named(page->instances, at->name, by_name);
  }
  return false;
}

}  // namespace gdpn::ide
