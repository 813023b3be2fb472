// The Edit and Net menus' actions on the net view's selection.

#include "net_actions.h"

#include <algorithm>
#include <map>
#include <set>

#include "app.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/page_from_selection.h"
#include "gdpn/session/breakpoint_syntax.h"
#include "views/net_view_state.h"

namespace gdpn::ide {

namespace {

/// The prefix of the net view's qualified names.
const std::string& prefixOf(const NetViewState& s) { return s.view.prefix.empty() ? s.layout.page : s.view.prefix; }

/// "" when `e` was done, else the reason (the status bar shows it).
std::string perform(App& app, NetEdit e) {
  auto why = app.document().execute(std::make_unique<NetEditCommand>(std::move(e)));
  if (!why.empty()) app.message = why;
  return why;
}

/// The name a place, transition or instance item has on its page.
const std::string& nameOf(const NetViewState& s, diagram::ItemRef item) {
  switch (item.kind) {
    case diagram::ItemKind::Place: return s.layout.places[item.index].name;
    case diagram::ItemKind::Transition: return s.layout.transitions[item.index].name;
    case diagram::ItemKind::Instance: return s.layout.instances[item.index].name;
    case diagram::ItemKind::Arc: break;
  }
  static const std::string none;
  return none;
}

}  // namespace

PageSelection netSelection(App& app) {
  NetViewState& s = app.netView();
  ensureLayout(app, s);
  PageSelection out;
  out.page = s.layout.page;
  out.prefix = prefixOf(s);
  if (s.view.page == nullptr) return out;
  for (const auto& one : app.document().selections()) {
    if (one.kind == SelectionKind::None || one.kind == SelectionKind::Node) continue;
    const auto it = s.by_name.find(one.name);
    if (it == s.by_name.end()) continue;
    const diagram::ItemRef item = it->second;
    if (item.kind == diagram::ItemKind::Arc) {
      out.arcs.push_back(s.view.page->arcs[s.layout.arcs[item.index].spec_index]);
    } else {
      const diagram::Box& box = s.layout.boxOf(item);
      out.constructs.emplace_back(nameOf(s, item), editorAt((box.min + box.max) * 0.5));
    }
  }
  return out;
}

void selectAllOnPage(App& app) {
  NetViewState& s = app.netView();
  ensureLayout(app, s);
  std::vector<Selection> all;
  const std::string& prefix = prefixOf(s);
  for (const auto& p : s.layout.places) all.push_back({SelectionKind::Place, prefix + "/" + p.name});
  for (const auto& t : s.layout.transitions) all.push_back({SelectionKind::Transition, prefix + "/" + t.name});
  for (const auto& i : s.layout.instances) all.push_back({SelectionKind::Instance, prefix + "/" + i.name});
  if (s.view.page != nullptr) {
    for (const auto& a : s.layout.arcs) {
      const auto& spec = s.view.page->arcs[a.spec_index];
      all.push_back({SelectionKind::Arc, arcName(prefix, spec.from, spec.to, spec.kind)});
    }
  }
  app.document().selectAll(all);
  app.message = std::to_string(app.document().selectedCount()) + " selected on " + prefix;
}

std::string deleteNetSelection(App& app) {
  const PageSelection sel = netSelection(app);
  if (sel.empty()) return "nothing of the net view's page is selected";
  auto e = makeNetEdit(NetEditKind::DeleteMany, sel.page, {});
  for (const auto& [name, at] : sel.constructs) e.names.push_back(name);
  e.arcs = sel.arcs;
  const auto count = e.names.size() + e.arcs.size();
  if (auto why = perform(app, std::move(e)); !why.empty()) return why;
  app.document().select({});
  app.message = count == 1 ? "deleted " + (sel.constructs.empty() ? std::string("an arc") : sel.prefix + "/" + sel.constructs.front().first)
                           : "deleted " + std::to_string(count) + " items of " + sel.prefix;
  return {};
}

net::PageSpec copyNetSelection(App& app) {
  const PageSelection sel = netSelection(app);
  net::PageSpec fragment;
  const auto* page = findPage(app.document().model().net, sel.page);
  if (page == nullptr || sel.empty()) return fragment;
  fragment.name = sel.page;
  std::set<std::string> names;
  for (const auto& [name, at] : sel.constructs) names.insert(name);
  for (const auto& p : page->places) {
    if (names.contains(p.name)) fragment.places.push_back(p);
  }
  for (const auto& t : page->transitions) {
    if (names.contains(t.name)) fragment.transitions.push_back(t);
  }
  // the arcs among them (a selected arc comes along only with both its ends)
  for (const auto& a : page->arcs) {
    if (names.contains(a.from) && names.contains(a.to)) fragment.arcs.push_back(a);
  }
  return fragment;
}

std::string reverseSelectedArc(App& app) {
  const PageSelection sel = netSelection(app);
  if (sel.arcs.size() != 1 || !sel.constructs.empty()) return "select one arc to reverse";
  const net::ArcSpec& was = sel.arcs.front();
  auto e = makeNetEdit(NetEditKind::SetArc, sel.page, was.from, was.to);
  e.arc_kind = was.kind;
  net::ArcSpec turned = was;
  std::swap(turned.from, turned.to);
  std::reverse(turned.via.begin(), turned.via.end());  // the same route, run the other way
  e.arc = turned;
  if (auto why = perform(app, std::move(e)); !why.empty()) return why;
  app.document().select({SelectionKind::Arc, arcName(sel.prefix, turned.from, turned.to, turned.kind)});
  app.message = "reversed: " + turned.from + " -> " + turned.to;
  return {};
}

std::string pageTypeFromSelection(App& app) {
  const PageSelection sel = netSelection(app);
  PageFromSelection request;
  request.page = sel.page;
  for (const auto& [name, at] : sel.constructs) request.names.push_back(name);
  if (request.names.empty()) return "select the places and transitions to make a page type of";
  // the first free names: page type subnet1 (subnet2, ...) and its instance of the same name
  const auto& net = app.document().model().net;
  const auto* page = findPage(net, sel.page);
  for (int n = 1; request.type.empty(); ++n) {
    const std::string name = "subnet" + std::to_string(n);
    const bool type_taken = findPage(net, name) != nullptr;
    const bool on_page = page != nullptr && (std::any_of(page->places.begin(), page->places.end(), [&](const auto& x) { return x.name == name; }) ||
                                             std::any_of(page->transitions.begin(), page->transitions.end(), [&](const auto& x) { return x.name == name; }) ||
                                             std::any_of(page->instances.begin(), page->instances.end(), [&](const auto& x) { return x.name == name; }));
    if (!type_taken && !on_page) request.type = request.instance = name;
  }
  auto command = std::make_unique<PageFromSelectionCommand>(request);
  const auto* made = command.get();  // kept on the undo stack when it succeeds
  const std::string why = app.document().execute(std::move(command));
  if (!why.empty()) return why;
  // the run's breakpoints follow the names that moved
  for (const auto& description : app.run().breakpoints()) {
    auto bp = session::parseBreakpoint(description);
    if (!bp) continue;
    const std::string moved = followName(made->result(), bp.value().target);
    if (moved == bp.value().target) continue;
    (void)app.run().removeBreakpoint(description);
    bp.value().target = moved;
    (void)app.run().addBreakpoint(std::move(bp.value()));
  }
  std::string note = "made page type " + request.type + " (instance " + sel.prefix + "/" + request.instance + ")";
  if (!made->result().pulled_in.empty()) {
    note += "; places taken in with it as ports:";
    for (const auto& p : made->result().pulled_in) note += " " + p;
  }
  app.message = note;
  return {};
}

void openSelectedInstance(App& app) {
  const auto& sel = app.document().selection();
  if (sel.kind != SelectionKind::Instance) return;
  app.netView().path = sel.name;  // an instance's qualified name is the view's path into it
  app.message = "showing " + sel.name + " (Up: back)";
}

std::string arrangeNetSelection(App& app, Arrange how) {
  PageSelection sel = netSelection(app);
  if (sel.constructs.size() < 2) return "select two or more places, transitions or instances";
  const bool across = how == Arrange::Left || how == Arrange::Across;  // x is set (else y)
  const std::size_t axis = across ? 0 : 1;
  auto& items = sel.constructs;
  std::stable_sort(items.begin(), items.end(), [&](const auto& a, const auto& b) { return a.second[axis] < b.second[axis]; });
  const double first = items.front().second[axis], last = items.back().second[axis];
  auto e = makeNetEdit(NetEditKind::MoveMany, sel.page, {});
  for (std::size_t i = 0; i < items.size(); ++i) {
    net::EditorPos at = items[i].second;
    switch (how) {
      case Arrange::Left:
      case Arrange::Top: at[axis] = first; break;
      case Arrange::Across:
      case Arrange::Down: {
        // on the quarter-unit grid the view's moves use
        const double exact = first + (last - first) * static_cast<double>(i) / static_cast<double>(items.size() - 1);
        at[axis] = std::round(exact * 4.0) / 4.0 + 0.0;
        break;
      }
    }
    e.moves.emplace_back(items[i].first, at);
  }
  e.pins = pinsOf(app.netView());
  if (auto why = perform(app, std::move(e)); !why.empty()) return why;
  app.message = "arranged " + std::to_string(items.size()) + " items";
  return {};
}

}  // namespace gdpn::ide
