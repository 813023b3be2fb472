// The net view: the page (or instance) chosen, drawn by the diagram module's painter with the
// run's marking; zoom at the cursor, pan by dragging, fit; a click selects a construct, a
// double click on an instance goes into it. The mini view: the same page, fitted, in a small
// window over the world view.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

#include "../views.h"
#include "gdpn/diagram/net_state.h"
#include "gdpn/ide/net_edit.h"
#include "imgui_canvas.h"
#include "net_view_state.h"

namespace gdpn::ide {

/// The least height of the net view's names, pixels (docs/ide.md: 10 px at least on a 1600 x 900 window).
constexpr double kNetViewLabelPx = 10.0;
namespace {

/// Lays out the page the view shows again when the page or the document changed.
void ensureLayout(App& app, NetViewState& s) {
  const auto revision = app.document().revision();
  if (s.laid_out_path == s.path && s.laid_out_revision == revision) return;
  core::Diagnostics diags;
  s.view = diagram::findView(app.document().model().net, s.path, diags);
  s.layout = s.view.page ? diagram::layoutPage(*s.view.page, diags) : diagram::NetLayout{};
  s.index = std::make_unique<diagram::SpatialIndex>(s.layout);
  s.error = diags.hasErrors() ? diags.str() : "";
  if (s.laid_out_path != s.path) s.fit = true;
  s.laid_out_path = s.path;
  s.laid_out_revision = revision;
}

/// The qualified name of a laid-out construct in the frozen net ("" for arcs).
std::string qualified(const NetViewState& s, diagram::ItemRef item) {
  const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
  switch (item.kind) {
    case diagram::ItemKind::Place: return prefix + "/" + s.layout.places[item.index].name;
    case diagram::ItemKind::Transition: return prefix + "/" + s.layout.transitions[item.index].name;
    case diagram::ItemKind::Instance: return prefix + "/" + s.layout.instances[item.index].name;
    case diagram::ItemKind::Arc: return {};
  }
  return {};
}

/// The selection a click on `item` makes.
Selection selectionOf(const NetViewState& s, diagram::ItemRef item) {
  switch (item.kind) {
    case diagram::ItemKind::Place: return {SelectionKind::Place, qualified(s, item)};
    case diagram::ItemKind::Transition: return {SelectionKind::Transition, qualified(s, item)};
    case diagram::ItemKind::Instance: return {SelectionKind::Instance, qualified(s, item)};
    case diagram::ItemKind::Arc: return {};
  }
  return {};
}

/// The laid-out item the selection names on this page, if it is here.
std::optional<diagram::ItemRef> selectedItem(const NetViewState& s, const Selection& sel) {
  // the selection's page-local name, when it lies on this page: no string is built per item
  const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
  const std::string_view name(sel.name);
  if (!name.starts_with(prefix) || name.size() <= prefix.size() || name[prefix.size()] != '/') return std::nullopt;
  const std::string_view local = name.substr(prefix.size() + 1);
  auto find = [&](const auto& items, diagram::ItemKind kind) -> std::optional<diagram::ItemRef> {
    for (std::uint32_t i = 0; i < items.size(); ++i) {
      if (items[i].name == local) return diagram::ItemRef{kind, i};
    }
    return std::nullopt;
  };
  switch (sel.kind) {
    case SelectionKind::Place: return find(s.layout.places, diagram::ItemKind::Place);
    case SelectionKind::Transition: return find(s.layout.transitions, diagram::ItemKind::Transition);
    case SelectionKind::Instance: return find(s.layout.instances, diagram::ItemKind::Instance);
    case SelectionKind::None:
    case SelectionKind::Node: return std::nullopt;  // nothing of the net
  }
  return std::nullopt;  // no value of the enum
}

/// Pages of at most this many constructs report each one (positions, activity, tokens); the
/// report is made every frame, and a large page would cost a string per construct.
constexpr std::size_t kReportedItems = 500;

const char* activityName(diagram::Activity a) {
  switch (a) {
    case diagram::Activity::Idle: return "idle";
    case diagram::Activity::Enabled: return "enabled";
    case diagram::Activity::Waiting: return "waiting";
    case diagram::Activity::HeldBack: return "held back";
    case diagram::Activity::Occurring: return "occurring";
  }
  return "?";
}

/// The page choice: the model's pages, then its page types; "Up" leaves an instance.
void drawPageBar(App& app, NetViewState& s) {
  const auto& net = app.document().model().net;
  const std::string shown = s.path.empty() ? (net.pages.empty() ? std::string() : net.pages.front().name) : s.path;
  ImGui::SetNextItemWidth(std::min(260.0f, ImGui::GetContentRegionAvail().x * 0.5f));
  if (ImGui::BeginCombo("##page", shown.c_str())) {
    for (const auto& page : net.pages) {
      if (ImGui::Selectable(page.name.c_str(), page.name == shown)) s.path = page.name;
    }
    if (!net.page_types.empty()) ImGui::Separator();
    for (const auto& type : net.page_types) {
      const std::string label = type.name + "  (page type)";
      if (ImGui::Selectable(label.c_str(), type.name == shown)) s.path = type.name;
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  const auto slash = shown.rfind('/');
  ImGui::BeginDisabled(slash == std::string::npos);
  if (ImGui::Button("Up")) s.path = shown.substr(0, slash);
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Fit")) s.fit = true;
}

/// The free region of the current window as a canvas, taken by an invisible button (so the
/// window does not move under a drag), and the mouse in its pixels.
struct Region {
  ImVec2 origin;            // window pixels of its top-left corner
  int width = 1, height = 1;  // pixels
  diagram::Point mouse;     // the mouse, pixels from the corner
  bool hovered = false, active = false, activated = false;  // the region's button, as it was taken
};

Region regionHere(const char* id) {
  Region r;
  r.origin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  r.width = std::max(1, static_cast<int>(avail.x));
  r.height = std::max(1, static_cast<int>(avail.y));
  ImGui::InvisibleButton(id, {static_cast<float>(r.width), static_cast<float>(r.height)},
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle);
  r.hovered = ImGui::IsItemHovered();
  r.active = ImGui::IsItemActive();
  r.activated = ImGui::IsItemActivated();
  const ImGuiIO& io = ImGui::GetIO();
  r.mouse = {static_cast<double>(io.MousePos.x - r.origin.x), static_cast<double>(io.MousePos.y - r.origin.y)};
  return r;
}

/// The page's places whose marking holds node `path` as a token and its transitions holding it
/// while they occur (needs s.state and s.binding for the run).
std::vector<diagram::ItemRef> holdersOf(App& app, const NetViewState& s, const std::string& path) {
  std::vector<diagram::ItemRef> out;
  const auto& places = s.state->places;
  for (std::uint32_t i = 0; i < places.size(); ++i) {
    for (const auto& slot : places[i]) {
      if (std::find(slot.names.begin(), slot.names.end(), path) == slot.names.end()) continue;
      out.push_back({diagram::ItemKind::Place, i});
      break;
    }
  }
  const auto& sim = app.run().session()->simulation();
  for (std::uint32_t i = 0; i < s.binding.transitions.size(); ++i) {
    const auto t = s.binding.transitions[i];
    if (!t) continue;
    for (const auto& [slot, ref] : sim.kernel().held(*t)) {
      if (sim.nodeName(ref) != path) continue;
      out.push_back({diagram::ItemKind::Transition, i});
      break;
    }
  }
  return out;
}

/// Selects what a click (not the end of a drag) on the region's button hits, then paints the
/// page with the run's marking in `viewport` and frames the selection. Returns the item under
/// the mouse; writes what it drew into `report`.
std::optional<diagram::ItemRef> clickAndPaint(App& app, NetViewState& s, const Region& r,
                                              const diagram::Viewport& viewport, nlohmann::json& report) {
  const auto under = s.index->pick(viewport.toLayout(r.mouse), 4.0 / viewport.zoom);
  if (r.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).x == 0.0f &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).y == 0.0f) {
    if (under) app.document().select(selectionOf(s, *under));
    else app.document().select({});
    if (under && under->kind == diagram::ItemKind::Transition) app.toolbar.fire_target = qualified(s, *under);
  }
  // the run's marking, when there is a run of this model: the page's constructs found in its
  // net once, their state read again only after a step or a start (not for a pan or a zoom)
  std::optional<diagram::NetState>& state = s.state;
  if (auto* session = app.run().session()) {
    auto& sim = session->simulation();
    const net::Net* net = &sim.kernel().net();
    if (s.bound_net != net || s.bound_path != s.laid_out_path) {
      s.binding = diagram::bindPage(*net, s.view);
      s.bound_net = net;
      s.bound_path = s.laid_out_path;
      s.state_kernel = nullptr;
    }
    const auto& kernel = sim.kernel();
    const auto moved = static_cast<std::int64_t>(kernel.startCount()) + kernel.steps();  // a step or a start
    if (s.state_kernel != &kernel || s.state_steps != moved) {
      state = diagram::netStateOf(kernel, s.binding, [&](net::NodeRef ref) { return sim.nodeName(ref); });
      s.state_kernel = &kernel;
      s.state_steps = moved;
    }
  } else {
    state.reset();
    s.bound_net = nullptr;
  }
  // a selected node: the places and transitions that hold it as a token (found again after a
  // step or a start, or when another node is selected)
  const auto& selection = app.document().selection();
  const std::string node = selection.kind == SelectionKind::Node && state ? selection.name : std::string();
  if (node != s.holding_node || s.holding_steps != s.state_steps) {
    s.holding = node.empty() ? std::vector<diagram::ItemRef>{} : holdersOf(app, s, node);
    s.holding_node = node;
    s.holding_steps = s.state_steps;
  }
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImVec2 far{r.origin.x + static_cast<float>(r.width), r.origin.y + static_cast<float>(r.height)};
  list->PushClipRect(r.origin, far, true);
  ImGuiCanvas canvas(list, r.origin.x, r.origin.y, r.width, r.height, app.fonts.regular);
  const std::size_t drawn = diagram::paintNet(s.layout, *s.index, state ? &*state : nullptr, viewport, canvas);
  // the selection, and what holds a selected node: a frame around each in the highlight colour
  const auto frame = [&](diagram::ItemRef item, float thickness) {
    const diagram::Box& box = s.layout.boxOf(item);
    const diagram::Point lo = viewport.toScreen(box.min), hi = viewport.toScreen(box.max);
    list->AddRect({r.origin.x + static_cast<float>(lo.x) - 4, r.origin.y + static_cast<float>(lo.y) - 4},
                  {r.origin.x + static_cast<float>(hi.x) + 4, r.origin.y + static_cast<float>(hi.y) + 4},
                  IM_COL32(255, 170, 0, 255), 3.0f, 0, thickness);
  };
  if (const auto sel = selectedItem(s, selection)) frame(*sel, 2.0f);
  nlohmann::json holding = nlohmann::json::array();
  for (const auto item : s.holding) {
    frame(item, 2.0f);
    holding.push_back(qualified(s, item));
  }
  report["holding"] = holding;
  if (s.layout.places.empty() && s.layout.transitions.empty() && s.layout.instances.empty()) {
    constexpr const char* kHint = "An empty page: right-click to add a place or a transition";
    const ImVec2 size = ImGui::CalcTextSize(kHint);
    list->AddText({r.origin.x + (static_cast<float>(r.width) - size.x) / 2, r.origin.y + static_cast<float>(r.height) / 2},
                  IM_COL32(120, 120, 120, 255), kHint);
  }
  list->PopClipRect();
  if (under && r.hovered && under->kind != diagram::ItemKind::Arc) {
    std::string tip = qualified(s, *under);
    // a transition held back or waiting: what held it back, as the inspector says it
    const auto* session = app.run().session();
    if (under->kind == diagram::ItemKind::Transition && state && session != nullptr && under->index < s.binding.transitions.size()) {
      if (const auto t = s.binding.transitions[under->index]) {
        const auto& kernel = session->simulation().kernel();
        const net::Readiness ready = kernel.readiness(*t);
        if (net::heldBack(ready)) tip += "\nheld back: " + kernel.readinessText(*t);
        else if (ready == net::Readiness::Untried) tip += "\nwaiting: " + kernel.readinessText(*t);
      }
    }
    ImGui::SetTooltip("%s", tip.c_str());
  }
  report["drawn"] = drawn;
  report["zoom"] = viewport.zoom;
  // where the constructs stand in the window (for replay files and tests), on small pages
  if (s.layout.places.size() + s.layout.transitions.size() + s.layout.instances.size() <= kReportedItems) {
    nlohmann::json at_px = nlohmann::json::object();
    auto put = [&](diagram::ItemKind kind, std::size_t count) {
      for (std::uint32_t i = 0; i < count; ++i) {
        const diagram::Box& box = s.layout.boxOf({kind, i});
        const diagram::Point p = viewport.toScreen((box.min + box.max) * 0.5);
        at_px[qualified(s, {kind, i})] = {std::lround(static_cast<double>(r.origin.x) + p.x),
                                          std::lround(static_cast<double>(r.origin.y) + p.y)};
      }
    };
    put(diagram::ItemKind::Place, s.layout.places.size());
    put(diagram::ItemKind::Transition, s.layout.transitions.size());
    put(diagram::ItemKind::Instance, s.layout.instances.size());
    report["at"] = at_px;
  }
  // what each construct shows, on small pages (the report is made every frame)
  if (state && s.layout.places.size() + s.layout.transitions.size() <= kReportedItems) {
    nlohmann::json activity = nlohmann::json::object();
    for (std::uint32_t t = 0; t < s.layout.transitions.size() && t < state->transitions.size(); ++t) {
      activity[qualified(s, {diagram::ItemKind::Transition, t})] = activityName(state->transitions[t]);
    }
    report["activity"] = activity;
    nlohmann::json tokens = nlohmann::json::object();
    for (std::uint32_t p = 0; p < s.layout.places.size() && p < state->places.size(); ++p) {
      std::int64_t n = 0;
      for (const auto& slot : state->places[p]) n += slot.kind == net::SlotKind::Sensor ? 0 : slot.count;
      tokens[qualified(s, {diagram::ItemKind::Place, p})] = n;
    }
    report["tokens"] = tokens;
  }
  return under;
}

/// A layout point in editor units (`at:`), on a grid of a quarter unit (never -0: the file
/// would say `at: [0.75, -0]`).
net::EditorPos editorAt(diagram::Point p) {
  const auto snap = [](double v) { return std::round(v / diagram::kEditorUnit * 4.0) / 4.0 + 0.0; };
  return {snap(p.x), snap(p.y)};
}

/// The page the view edits: the page shown, or the page type of the instance shown.
const std::string& editedPage(const NetViewState& s) { return s.layout.page; }

/// "" when `e` was done, else the reason, which the status bar shows.
std::string perform(App& app, NetEdit e) {
  auto why = app.document().execute(std::make_unique<NetEditCommand>(std::move(e)));
  if (!why.empty()) app.message = why;
  return why;
}

/// A free name for a new construct: P1, P2, ... or T1, T2, ...
std::string freshName(const NetViewState& s, char letter) {
  for (std::size_t n = 1;; ++n) {
    const std::string name = letter + std::to_string(n);
    const auto used = [&](const auto& list) {
      return std::any_of(list.begin(), list.end(), [&](const auto& x) { return x.name == name; });
    };
    if (!used(s.layout.places) && !used(s.layout.transitions) && !used(s.layout.instances)) return name;
  }
}

/// The name of a place, transition or instance item ("" for an arc).
std::string localName(const NetViewState& s, diagram::ItemRef item) {
  switch (item.kind) {
    case diagram::ItemKind::Place: return s.layout.places[item.index].name;
    case diagram::ItemKind::Transition: return s.layout.transitions[item.index].name;
    case diagram::ItemKind::Instance: return s.layout.instances[item.index].name;
    case diagram::ItemKind::Arc: return {};
  }
  return {};
}

/// Editing by hand. A left drag on a place, transition or instance moves it, on a grid of a
/// quarter unit (one undo step). The right button opens a menu: on paper, a new place or
/// transition there; on a place or transition, rename, delete, or an arc from it (normal, test,
/// inhibitor) that a click on its other end finishes (Escape or a click on paper drops it).
/// Returns true while a drag moves a construct (the view does not pan then).
bool editGestures(App& app, NetViewState& s, const Region& r, const diagram::Viewport& viewport,
                  std::optional<diagram::ItemRef> under, nlohmann::json& report) {
  const diagram::Point mouse = viewport.toLayout(r.mouse);
  const bool node = under && under->kind != diagram::ItemKind::Arc;
  // a drag on a construct moves it
  if (r.activated && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && node && s.arc_from.empty()) {
    s.moving = localName(s, *under);
    ++app.inspector.drag_id;
  }
  if (!r.active) s.moving.clear();
  const bool moving = !s.moving.empty() && ImGui::IsMouseDragging(ImGuiMouseButton_Left);
  if (moving) {
    auto e = makeNetEdit(NetEditKind::Move, editedPage(s), s.moving);
    e.at = editorAt(mouse);
    e.drag = app.inspector.drag_id;
    if (s.layout.from_graphviz) {
      for (const auto& p : s.layout.places) e.pins.emplace_back(p.name, editorAt(p.centre));
      for (const auto& t : s.layout.transitions) e.pins.emplace_back(t.name, editorAt(t.centre));
      for (const auto& i : s.layout.instances) e.pins.emplace_back(i.name, editorAt(i.centre));
    }
    (void)perform(app, std::move(e));
  }
  // an arc begun: a click on its other end makes it
  if (!s.arc_from.empty()) {
    app.message = "click where the arc from " + s.arc_from + " ends (Escape: no arc)";
    const bool clicked = r.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
                         ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).x == 0.0f &&
                         ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).y == 0.0f;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      s.arc_from.clear();
      app.message.clear();
    } else if (clicked) {
      auto e = makeNetEdit(NetEditKind::AddArc, editedPage(s), s.arc_from);
      e.new_name = node ? localName(s, *under) : std::string();
      e.arc_kind = s.arc_kind;
      s.arc_from.clear();
      app.message.clear();
      if (node) (void)perform(app, std::move(e));
    }
  }
  // the menu
  if (r.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right)) {
    s.menu_item = node ? under : std::nullopt;
    s.menu_at = mouse;
    s.rename = node ? localName(s, *under) : std::string();
    ImGui::OpenPopup("##net_menu");
  }
  nlohmann::json items = nlohmann::json::object();
  const auto item = [&](const char* label) { return menuItem(label, items); };
  if (ImGui::BeginPopup("##net_menu")) {
    if (!s.menu_item) {
      // the new place or transition is selected: the contents view shows it
      const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
      const auto add = [&](NetEditKind kind, char letter, SelectionKind selected) {
        const auto name = freshName(s, letter);
        if (perform(app, makeNetEdit(kind, editedPage(s), name, {}, editorAt(s.menu_at))).empty()) {
          app.document().select({selected, prefix + "/" + name});
        }
      };
      if (item("Place here")) add(NetEditKind::AddPlace, 'P', SelectionKind::Place);
      if (item("Transition here")) add(NetEditKind::AddTransition, 'T', SelectionKind::Transition);
    } else if (s.menu_item->kind != diagram::ItemKind::Instance) {
      const std::string name = localName(s, *s.menu_item);
      ImGui::TextDisabled("%s %s", s.menu_item->kind == diagram::ItemKind::Place ? "place" : "transition", name.c_str());
      ImGui::SetNextItemWidth(140);
      // the name field takes the keyboard with its text selected: typing replaces it
      if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
      if (ImGui::InputText("name", &s.rename, ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll) &&
          s.rename != name) {
        if (perform(app, makeNetEdit(NetEditKind::Rename, editedPage(s), name, s.rename)).empty()) {
          // the selection follows the new name
          const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
          const bool place = s.menu_item->kind == diagram::ItemKind::Place;
          app.document().select({place ? SelectionKind::Place : SelectionKind::Transition, prefix + "/" + s.rename});
          ImGui::CloseCurrentPopup();
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("A new name, then Enter");
      if (item("Delete")) (void)perform(app, makeNetEdit(NetEditKind::Delete, editedPage(s), name));
      for (const auto& [label, kind] : {std::pair{"Arc from here", net::ArcKind::Normal},
                                        std::pair{"Test arc from here", net::ArcKind::Test},
                                        std::pair{"Inhibitor arc from here", net::ArcKind::Inhibitor}}) {
        if (item(label)) {
          s.arc_from = name;
          s.arc_kind = kind;
        }
      }
    }
    ImGui::EndPopup();
  }
  report["menu"] = items;
  report["moving"] = s.moving;
  report["arc_from"] = s.arc_from;
  return moving;
}

}  // namespace

void drawNetView(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##net", at, "Net view");
  NetViewState& s = app.netView();
  drawPageBar(app, s);
  ensureLayout(app, s);
  report = {{"path", s.path}, {"page", s.layout.page}, {"places", s.layout.places.size()},
            {"transitions", s.layout.transitions.size()}, {"arcs", s.layout.arcs.size()}};
  // a model with no page yet (a new, empty file) has an empty net, which is no error
  if (s.path.empty() && app.document().model().net.pages.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("No net yet: a part dropped into the world view starts page main.");
    ImGui::PopTextWrapPos();
    report["empty"] = true;
    endPanel();
    return;
  }
  if (!s.error.empty()) {
    ImGui::TextWrapped("%s", s.error.c_str());
    report["error"] = s.error;
    endPanel();
    return;
  }
  const Region r = regionHere("##netcanvas");
  // fitted again when asked, and when the canvas changed size (a splitter, the view filling the
  // window) while it showed the fit
  if (s.fit || (s.fitted && (r.width != s.fitted_w || r.height != s.fitted_h))) {
    s.viewport = diagram::fitViewport(s.layout, r.width, r.height);
    s.fit = false;
    s.fitted = true;
    s.fitted_w = r.width;
    s.fitted_h = r.height;
  }
  const ImGuiIO& io = ImGui::GetIO();
  if (r.hovered && io.MouseWheel != 0.0f) {
    s.viewport = s.viewport.zoomedAbout(r.mouse, std::pow(1.15, static_cast<double>(io.MouseWheel)));
    s.fitted = false;
  }
  // what is under the mouse as the frame begins: a drag that starts on a construct moves it
  const auto pointed = s.index->pick(s.viewport.toLayout(r.mouse), 4.0 / s.viewport.zoom);
  const bool moving = editGestures(app, s, r, s.viewport, pointed, report);
  if (r.active && !moving && s.moving.empty() &&
      (ImGui::IsMouseDragging(ImGuiMouseButton_Left) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))) {
    s.viewport = s.viewport.panned({static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y)});
    s.fitted = false;
  }
  auto shown = s.viewport;
  shown.min_label_px = kNetViewLabelPx;  // names a user can read where there is room for them
  const auto under = clickAndPaint(app, s, r, shown, report);
  report["label_px"] = diagram::labelPx(shown);
  if (r.hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && under &&
      under->kind == diagram::ItemKind::Instance) {
    s.path = (s.path.empty() ? s.layout.page : s.path) + "/" + s.layout.instances[under->index].name;
  }
  endPanel();
}

void drawMiniView(App& app, const Rect& world, nlohmann::json& report) {
  report = {{"shown", app.world.show_mini}};
  if (!app.world.show_mini) return;
  NetViewState& s = app.netView();
  ensureLayout(app, s);
  const float w = std::max(160.0f, world.w * 0.45f), h = std::max(90.0f, world.h * 0.32f);
  ImGui::SetNextWindowPos({world.x + world.w - w - 8, world.y + world.h - h - 8}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize({w, h}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.92f);
  const bool open = ImGui::Begin("Mini view", &app.world.show_mini,
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                     ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoFocusOnAppearing);
  if (open && s.error.empty()) {
    const Region r = regionHere("##minicanvas");
    clickAndPaint(app, s, r, diagram::fitViewport(s.layout, r.width, r.height, 6.0), report);
  }
  ImGui::End();
}

}  // namespace gdpn::ide
