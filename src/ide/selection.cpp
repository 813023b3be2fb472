// Names of selection kinds, and whether a selection still names something of the model.

#include "gdpn/ide/selection.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

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

std::vector<Selection> stillNamed(const Document& doc, std::vector<Selection> selections) {
  if (selections.size() < 8) {  // a few: one by one
    std::erase_if(selections, [&](const Selection& one) { return !namesSomething(doc, one); });
    return selections;
  }
  // per page: its places (and published references), transitions, instances and arcs, by kind and name
  std::unordered_map<std::string, std::unordered_set<std::string>> names;
  const auto& net = doc.model().net;
  const auto namesOf = [&](const std::string& page_name) -> const std::unordered_set<std::string>& {
    auto [it, fresh] = names.try_emplace(page_name);
    if (!fresh) return it->second;
    const auto* page = findPage(net, page_name);
    if (page == nullptr) return it->second;
    const auto key = [](SelectionKind kind, const std::string& name) { return char(static_cast<int>(kind) + '0') + name; };
    for (const auto& p : page->places) it->second.insert(key(SelectionKind::Place, p.name));
    for (const auto& r : page->references) it->second.insert(key(SelectionKind::Place, r.place));
    for (const auto& t : page->transitions) it->second.insert(key(SelectionKind::Transition, t.name));
    for (const auto& i : page->instances) it->second.insert(key(SelectionKind::Instance, i.name));
    for (const auto& a : page->arcs) it->second.insert(key(SelectionKind::Arc, arcName("", a.from, a.to, a.kind)));
    return it->second;
  };
  std::erase_if(selections, [&](const Selection& one) {
    switch (one.kind) {
      case SelectionKind::None: return true;
      case SelectionKind::Node: return !namesSomething(doc, one);
      case SelectionKind::Place:
      case SelectionKind::Transition:
      case SelectionKind::Instance:
      case SelectionKind::Arc: break;
    }
    const auto arc = one.kind == SelectionKind::Arc ? parseArcName(one.name) : std::nullopt;
    if (one.kind == SelectionKind::Arc && !arc) return true;
    const auto at = locateConstruct(net, arc ? arc->prefix + "/_" : one.name);
    if (!at) return true;
    const std::string local = arc ? arcName("", arc->from, arc->to, arc->kind) : at->name;
    return !namesOf(at->page).contains(char(static_cast<int>(one.kind) + '0') + local);
  });
  return selections;
}

}  // namespace gdpn::ide
