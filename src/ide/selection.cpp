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
    case SelectionKind::Arc: return "arc";
  }
  return "none";
}

std::string arcName(const std::string& prefix, const std::string& from, const std::string& to, net::ArcKind kind) {
  std::string out = prefix + ": " + from + " -> " + to;
  if (kind != net::ArcKind::Normal) out += std::string(" (") + net::arcKindName(kind) + ")";
  return out;
}

std::optional<ArcName> parseArcName(const std::string& name) {
  const auto colon = name.find(": ");
  const auto arrow = name.find(" -> ");
  if (colon == std::string::npos || arrow == std::string::npos || colon == 0 || arrow < colon + 3) return std::nullopt;
  ArcName out;
  out.prefix = name.substr(0, colon);
  out.from = name.substr(colon + 2, arrow - colon - 2);
  out.to = name.substr(arrow + 4);
  for (const net::ArcKind kind : {net::ArcKind::Test, net::ArcKind::Inhibitor}) {
    const std::string suffix = std::string(" (") + net::arcKindName(kind) + ")";
    if (out.to.size() > suffix.size() && out.to.ends_with(suffix)) {
      out.to.resize(out.to.size() - suffix.size());
      out.kind = kind;
    }
  }
  if (out.to.empty() || out.to.find(' ') != std::string::npos || out.from.find(' ') != std::string::npos) return std::nullopt;
  return out;
}

bool namesSomething(const Document& doc, const Selection& selection) {
  const auto named = [](const auto& list, const std::string& name, auto key) {
    return std::any_of(list.begin(), list.end(), [&](const auto& x) { return key(x) == name; });
  };
  const auto by_name = [](const auto& x) -> const std::string& { return x.name; };
  const auto& net = doc.model().net;
  const auto arc = selection.kind == SelectionKind::Arc ? parseArcName(selection.name) : std::nullopt;
  const auto at = selection.kind == SelectionKind::Node || selection.kind == SelectionKind::None
                      ? std::nullopt
                      : locateConstruct(net, arc ? arc->prefix + "/_" : selection.name);  // an arc: its page
  const auto* page = at ? findPage(net, at->page) : nullptr;
  switch (selection.kind) {
    case SelectionKind::None: return false;
    case SelectionKind::Node: return doc.scene() != nullptr && doc.scene()->find(selection.name) != nullptr;
    case SelectionKind::Place:
      return page != nullptr && (named(page->places, at->name, by_name) ||
                                 named(page->references, at->name, [](const auto& r) -> const std::string& { return r.place; }));
    case SelectionKind::Transition: return page != nullptr && named(page->transitions, at->name, by_name);
    case SelectionKind::Instance: return page != nullptr && named(page->instances, at->name, by_name);
    case SelectionKind::Arc:
      return page != nullptr && arc &&
             std::any_of(page->arcs.begin(), page->arcs.end(), [&](const net::ArcSpec& a) {
               return a.from == arc->from && a.to == arc->to && a.kind == arc->kind;
             });
  }
  return false;
}

}  // namespace gdpn::ide
