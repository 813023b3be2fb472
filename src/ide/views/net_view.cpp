// The net view: the page (or instance) chosen, drawn by the diagram module's painter with the
// run's marking; zoom at the cursor, pan by dragging, fit; a click selects a construct, a
// double click on an instance goes into it. The mini view: the same page, fitted, in a small
// window over the world view.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "../action_run.h"
#include "../views.h"
#include "gdpn/diagram/net_state.h"
#include "gdpn/ide/net_edit.h"
#include "imgui_canvas.h"
#include "net_view_state.h"

namespace gdpn::ide {

/// The least height of the net view's names, pixels (docs/ide.md: 10 px at least on a 1600 x 900 window).
constexpr double kNetViewLabelPx = 10.0;

namespace {

/// The layout's spatial index and the overview's density (constructs per cell of a grid over
/// the page), made again after the layout changed.
void indexLayout(NetViewState& s) {
  s.index = std::make_unique<diagram::SpatialIndex>(s.layout);
  s.density.assign(static_cast<std::size_t>(kOverviewCols * kOverviewRows), 0);
  const diagram::Box& all = s.layout.bounds;
  const auto count = [&](const auto& items) {
    for (const auto& n : items) {
      const double fx = all.width() > 0 ? (n.centre.x - all.min.x) / all.width() : 0.5;
      const double fy = all.height() > 0 ? (n.centre.y - all.min.y) / all.height() : 0.5;
      const int cx = std::clamp(static_cast<int>(fx * kOverviewCols), 0, kOverviewCols - 1);
      const int cy = std::clamp(static_cast<int>(fy * kOverviewRows), 0, kOverviewRows - 1);
      ++s.density[static_cast<std::size_t>(cy * kOverviewCols + cx)];
    }
  };
  count(s.layout.places);
  count(s.layout.transitions);
  count(s.layout.instances);
}

}  // namespace

void ensureLayout(App& app, NetViewState& s) {
  const auto revision = app.document().revision();
  if (s.laid_out_path == s.path && s.laid_out_revision == revision) return;
  core::Diagnostics diags;
  s.view = diagram::findView(app.document().model().net, s.path, diags);
  s.layout = s.view.page ? diagram::layoutPage(*s.view.page, diags) : diagram::NetLayout{};
  s.error = diags.hasErrors() ? diags.str() : "";
  indexLayout(s);
  // laid out from the file's positions throughout: a move can be laid out again in place
  const auto placed = [](const auto& list) {
    return std::all_of(list.begin(), list.end(), [](const auto& x) { return x.position.has_value(); });
  };
  s.positioned = s.view.page != nullptr && placed(s.view.page->places) && placed(s.view.page->transitions) &&
                 placed(s.view.page->instances);
  // every item by the name a selection gives it
  s.by_name.clear();
  const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
  const auto put = [&](const auto& items, diagram::ItemKind kind) {
    for (std::uint32_t i = 0; i < items.size(); ++i) s.by_name.emplace(prefix + "/" + items[i].name, diagram::ItemRef{kind, i});
  };
  put(s.layout.places, diagram::ItemKind::Place);
  put(s.layout.transitions, diagram::ItemKind::Transition);
  put(s.layout.instances, diagram::ItemKind::Instance);
  if (s.view.page != nullptr) {
    for (std::uint32_t i = 0; i < s.layout.arcs.size(); ++i) {
      const auto& a = s.view.page->arcs[s.layout.arcs[i].spec_index];
      s.by_name.emplace(arcName(prefix, a.from, a.to, a.kind), diagram::ItemRef{diagram::ItemKind::Arc, i});
    }
  }
  if (s.laid_out_path != s.path) s.fit = true;
  // a view that showed the whole page keeps showing it when constructs added outgrow it: a part
  // placed from the palette lays its instance box out past the edge, where no one would look
  // for it (a construct moved past the edge, or a rename, moves no view)
  const std::size_t items = s.layout.places.size() + s.layout.transitions.size() + s.layout.instances.size();
  const bool added = s.laid_out_path == s.path && items > s.laid_out_items;
  s.laid_out_items = items;
  if (added && s.fitted && s.fitted_w > 0 && s.fitted_h > 0) {
    const diagram::Point lo = s.viewport.toLayout({0.0, 0.0});
    const diagram::Point hi = s.viewport.toLayout({static_cast<double>(s.fitted_w), static_cast<double>(s.fitted_h)});
    const diagram::Box& b = s.layout.bounds;
    if (b.min.x < lo.x || b.min.y < lo.y || b.max.x > hi.x || b.max.y > hi.y) s.fit = true;
  }
  s.laid_out_path = s.path;
  s.laid_out_revision = revision;
}

std::vector<std::pair<std::string, net::EditorPos>> pinsOf(const NetViewState& s) {
  std::vector<std::pair<std::string, net::EditorPos>> pins;
  if (s.positioned) return pins;
  for (const auto& p : s.layout.places) pins.emplace_back(p.name, editorAt(p.centre));
  for (const auto& t : s.layout.transitions) pins.emplace_back(t.name, editorAt(t.centre));
  for (const auto& i : s.layout.instances) pins.emplace_back(i.name, editorAt(i.centre));
  return pins;
}

const char* netToolName(NetTool tool) {
  switch (tool) {
    case NetTool::Select: return "select";
    case NetTool::Place: return "place";
    case NetTool::Transition: return "transition";
    case NetTool::Arc: return "arc";
  }
  return "select";
}

namespace {

/// The qualified name of a laid-out construct in the frozen net (an arc's: arcName()).
std::string qualified(const NetViewState& s, diagram::ItemRef item) {
  const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
  switch (item.kind) {
    case diagram::ItemKind::Place: return prefix + "/" + s.layout.places[item.index].name;
    case diagram::ItemKind::Transition: return prefix + "/" + s.layout.transitions[item.index].name;
    case diagram::ItemKind::Instance: return prefix + "/" + s.layout.instances[item.index].name;
    case diagram::ItemKind::Arc: {
      if (s.view.page == nullptr) return {};
      const auto& a = s.view.page->arcs[s.layout.arcs[item.index].spec_index];
      return arcName(prefix, a.from, a.to, a.kind);
    }
  }
  return {};
}

/// The kind of selection an item of `kind` makes.
SelectionKind selectionKindOf(diagram::ItemKind kind) {
  switch (kind) {
    case diagram::ItemKind::Place: return SelectionKind::Place;
    case diagram::ItemKind::Transition: return SelectionKind::Transition;
    case diagram::ItemKind::Instance: return SelectionKind::Instance;
    case diagram::ItemKind::Arc: return SelectionKind::Arc;
  }
  return SelectionKind::None;
}

/// The selection a click on `item` makes.
Selection selectionOf(const NetViewState& s, diagram::ItemRef item) { return {selectionKindOf(item.kind), qualified(s, item)}; }

/// The laid-out item the selection names on this page, if it is here.
std::optional<diagram::ItemRef> selectedItem(const NetViewState& s, const Selection& sel) {
  switch (sel.kind) {
    case SelectionKind::Place:
    case SelectionKind::Transition:
    case SelectionKind::Instance:
    case SelectionKind::Arc: {
      const auto it = s.by_name.find(sel.name);
      if (it == s.by_name.end()) return std::nullopt;
      // a name the page gives a construct of another kind is not this selection
      return selectionKindOf(it->second.kind) == sel.kind ? std::optional(it->second) : std::nullopt;
    }
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
void drawPageBar(App& app, NetViewState& s, nlohmann::json& tools) {
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
  // the tools: what a left click or drag on the paper does (keys S, P, T, A); on a row of
  // their own when the bar has no room for them
  const ImGuiStyle& style = ImGui::GetStyle();
  float strip = 0;
  for (const char* word : {"Select", "Place", "Transition", "Arc"}) strip += ImGui::CalcTextSize(word).x + style.FramePadding.x * 2 + 2;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + 16 + strip <= right) ImGui::SameLine(0, 16);
  for (const auto& [tool, id, word] : {std::tuple{NetTool::Select, ActionId::NetSelectTool, "Select"},
                                       std::tuple{NetTool::Place, ActionId::NetPlaceTool, "Place"},
                                       std::tuple{NetTool::Transition, ActionId::NetTransitionTool, "Transition"},
                                       std::tuple{NetTool::Arc, ActionId::NetArcTool, "Arc"}}) {
    const bool on = s.tool == tool;
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(word)) (void)performAction(app, id);
    if (on) ImGui::PopStyleColor();
    noteItem(word, tools);
    if (ImGui::IsItemHovered()) {
      const auto& a = info(id);
      ImGui::SetTooltip("%s (%s)", std::string(a.help).c_str(), std::string(a.keys).c_str());
    }
    ImGui::SameLine(0, 2);
  }
  ImGui::NewLine();
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

/// Selects what a click (not the end of a drag) on the region's button hits when `clicks`
/// (the mini view; the net view's own gestures select there), then paints the page with the
/// run's marking in `viewport` and frames the selection. Returns the item under the mouse;
/// writes what it drew into `report`.
std::optional<diagram::ItemRef> clickAndPaint(App& app, NetViewState& s, const Region& r,
                                              const diagram::Viewport& viewport, nlohmann::json& report, bool clicks) {
  const auto under = s.index->pick(viewport.toLayout(r.mouse), 4.0 / viewport.zoom);
  if (clicks && r.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
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
  // every selected item of this page: a frame, an arc drawn over in the highlight colour
  std::size_t framed = 0;
  const auto mark = [&](const Selection& one) {
    const auto item = selectedItem(s, one);
    if (!item) return;
    ++framed;
    if (item->kind != diagram::ItemKind::Arc) {
      frame(*item, one == selection ? 2.5f : 1.5f);
      return;
    }
    const auto& points = s.layout.arcs[item->index].points;
    for (std::size_t i = 1; i < points.size(); ++i) {
      const diagram::Point a = viewport.toScreen(points[i - 1]), b = viewport.toScreen(points[i]);
      list->AddLine({r.origin.x + static_cast<float>(a.x), r.origin.y + static_cast<float>(a.y)},
                    {r.origin.x + static_cast<float>(b.x), r.origin.y + static_cast<float>(b.y)}, IM_COL32(255, 170, 0, 110),
                    one == selection ? 6.0f : 5.0f);  // under the arc's own line, which shows through
    }
  };
  if (selection.any()) {
    mark(selection);
    for (const auto& one : app.document().alsoSelected()) mark(one);  // each frame: read in place
  }
  report["selected"] = framed;
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
    // a continuous place's amount of its capacity, a flow's rates
    if (under->kind == diagram::ItemKind::Place && under->index < s.layout.places.size()) {
      if (const auto& look = s.layout.places[under->index].fluid) {
        const bool live = state && under->index < state->amounts.size() && state->amounts[under->index];
        const double amount = live ? *state->amounts[under->index] : look->amount;
        tip += "\ncontinuous: " + diagram::amountText(amount, look->unit) +
               (look->capacity ? " of " + diagram::amountText(*look->capacity, look->unit) : std::string(", unbounded"));
      }
    }
    if (under->kind == diagram::ItemKind::Transition && session != nullptr && under->index < s.binding.transitions.size() &&
        under->index < s.layout.transitions.size() && s.layout.transitions[under->index].fluid) {
      if (const auto t = s.binding.transitions[under->index]) {
        const auto& kernel = session->simulation().kernel();
        const std::string& unit = s.layout.transitions[under->index].fluid->unit;
        tip += "\nflows at " + diagram::rateText(kernel.flowRate(*t), unit) + " (nominal " +
               diagram::rateText(kernel.nominalRate(*t), unit) + ")";
      }
    }
    // a coloured place's values, a coloured transition's binding while it occurs
    if (under->kind == diagram::ItemKind::Place && session != nullptr && under->index < s.binding.places.size()) {
      if (const auto p = s.binding.places[under->index]) tip += valuesTooltip(*session, *p);
    }
    if (under->kind == diagram::ItemKind::Transition && session != nullptr && under->index < s.binding.transitions.size()) {
      if (const auto t = s.binding.transitions[under->index]) {
        const auto& sim = session->simulation();
        const auto* c = sim.net().colouring();
        const auto* ti = c != nullptr ? c->of(*t) : nullptr;
        if (const auto* b = ti != nullptr ? sim.kernel().binding(*t) : nullptr) tip += "\noccurring in: " + bindingText(c->colours, *ti, b->binding);
      }
    }
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 35.0f);
    ImGui::TextUnformatted(tip.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
    report["tooltip"] = tip;
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
    // each arc's middle: the midpoint of its middle segment, where a click selects it
    nlohmann::json arc_px = nlohmann::json::object();
    for (std::uint32_t i = 0; i < s.layout.arcs.size(); ++i) {
      const auto& points = s.layout.arcs[i].points;
      const std::size_t k = (points.size() - 1) / 2;
      const diagram::Point p = viewport.toScreen((points[k] + points[k + 1]) * 0.5);
      arc_px[qualified(s, {diagram::ItemKind::Arc, i})] = {std::lround(static_cast<double>(r.origin.x) + p.x),
                                                           std::lround(static_cast<double>(r.origin.y) + p.y)};
    }
    report["arc_at"] = arc_px;
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
    // hybrid nets: the amounts drawn as levels and the rates written beside the flows
    nlohmann::json amounts = nlohmann::json::object(), rates = nlohmann::json::object();
    for (std::uint32_t p = 0; p < s.layout.places.size() && p < state->amounts.size(); ++p) {
      if (state->amounts[p]) amounts[qualified(s, {diagram::ItemKind::Place, p})] = *state->amounts[p];
    }
    for (std::uint32_t t = 0; t < s.layout.transitions.size() && t < state->flow_rates.size(); ++t) {
      if (state->flow_rates[t]) rates[qualified(s, {diagram::ItemKind::Transition, t})] = *state->flow_rates[t];
    }
    report["amounts"] = amounts;
    report["flow_rates"] = rates;
  }
  return under;
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

/// The places, transitions and instances of this page that are selected, with where each is
/// drawn now (editor units), in the page's order.
std::vector<std::pair<std::string, net::EditorPos>> selectedConstructs(App& app, const NetViewState& s) {
  std::vector<std::pair<std::string, net::EditorPos>> out;
  for (const auto& one : app.document().selections()) {
    const auto item = selectedItem(s, one);
    if (!item || item->kind == diagram::ItemKind::Arc) continue;
    // where the file puts it (so that every construct and bend of a group moves by the same
    // step, as a redo will), else where it is drawn
    std::optional<net::EditorPos> at;
    if (s.view.page != nullptr) {
      switch (item->kind) {
        case diagram::ItemKind::Place: at = s.view.page->places[item->index].position; break;
        case diagram::ItemKind::Transition: at = s.view.page->transitions[item->index].position; break;
        case diagram::ItemKind::Instance: at = s.view.page->instances[item->index].position; break;
        case diagram::ItemKind::Arc: break;
      }
    }
    const diagram::Box& box = s.layout.boxOf(*item);
    out.emplace_back(localName(s, *item), at ? *at : editorAt((box.min + box.max) * 0.5));
  }
  return out;
}

/// The items a rubber band from `a` to `b` (layout units) holds whole: places, transitions,
/// instances and arcs.
std::vector<diagram::ItemRef> inBand(const NetViewState& s, diagram::Point a, diagram::Point b) {
  return s.index->within({{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}});
}

/// The handles of the selected arc, when it is one of this page: each bend it follows (by its
/// index in `via`) and its label (-1), at layout points.
std::vector<std::pair<int, diagram::Point>> arcHandles(App& app, const NetViewState& s) {
  std::vector<std::pair<int, diagram::Point>> out;
  const auto& sel = app.document().selection();
  if (sel.kind != SelectionKind::Arc || app.document().selectedCount() != 1) return out;
  const auto item = selectedItem(s, sel);
  if (!item) return out;
  const auto& arc = s.layout.arcs[item->index];
  if (arc.follows_via) {
    for (std::size_t i = 1; i + 1 < arc.points.size(); ++i) out.emplace_back(static_cast<int>(i - 1), arc.points[i]);
  }
  if (!arc.inscription.empty()) out.emplace_back(-1, arc.label_at ? *arc.label_at : diagram::middleOf(arc.points));
  return out;
}

/// The selected arc's handle within 6 pixels of canvas point `px`, if any.
std::optional<std::pair<int, diagram::Point>> handleAt(App& app, const NetViewState& s, const diagram::Viewport& viewport,
                                                       diagram::Point px) {
  for (const auto& h : arcHandles(app, s)) {
    const diagram::Point d = viewport.toScreen(h.second) - px;
    // a bend within 6 pixels; the label within its text (about 12 by 8 pixels about its middle)
    if (h.first >= 0 ? d.x * d.x + d.y * d.y <= 36.0 : std::abs(d.x) <= 12.0 && std::abs(d.y) <= 8.0) return h;
  }
  return std::nullopt;
}

/// After an edit that moved `moved` (or bent an arc between them) alone: they and the arcs that
/// touch them laid out again in place, not the whole page (a drag on a large page). A page that
/// was not laid out from positions throughout (Graphviz's, or columns) is laid out whole.
void relaidOut(App& app, NetViewState& s, const std::vector<diagram::ItemRef>& moved) {
  if (!s.positioned || s.view.page == nullptr || s.laid_out_path != s.path) return;
  diagram::relayoutMoved(s.layout, *s.view.page, moved);
  indexLayout(s);
  s.laid_out_revision = app.document().revision();
}

/// Starts a drag of arc `item`'s bend `bend` (-1: its label; `fresh`: a new bend there).
void beginArcDrag(App& app, NetViewState& s, diagram::ItemRef item, int bend, bool fresh) {
  const auto& arc = s.layout.arcs[item.index];
  s.arc_drag = ArcDrag{item.index, s.view.page->arcs[arc.spec_index], bend, fresh};
  ++app.inspector.drag_id;
}

/// The arc being dragged with its bend or label at layout point `mouse`: one step for the
/// whole drag.
void dragArc(App& app, NetViewState& s, diagram::Point mouse) {
  const ArcDrag& d = *s.arc_drag;
  net::ArcSpec changed = d.spec;
  if (d.bend < 0) {
    changed.label_at = diagram::labelOffset(s.layout.arcs[d.arc], mouse);
    (*changed.label_at)[0] = std::round((*changed.label_at)[0] * 8.0) / 8.0 + 0.0;  // an eighth of a unit: a short file
    (*changed.label_at)[1] = std::round((*changed.label_at)[1] * 8.0) / 8.0 + 0.0;
  } else if (d.fresh) {
    changed.via.insert(changed.via.begin() + std::min<std::ptrdiff_t>(d.bend, static_cast<std::ptrdiff_t>(changed.via.size())), editorAt(mouse));
  } else if (static_cast<std::size_t>(d.bend) < changed.via.size()) {
    changed.via[static_cast<std::size_t>(d.bend)] = editorAt(mouse);
  }
  if (changed == d.spec) return;
  auto e = makeNetEdit(NetEditKind::SetArc, editedPage(s), d.spec.from, d.spec.to);
  e.arc_kind = d.spec.kind;
  e.arc = std::move(changed);
  e.drag = app.inspector.drag_id;
  if (perform(app, std::move(e)).empty()) relaidOut(app, s, {s.layout.arcs[d.arc].from, s.layout.arcs[d.arc].to});
}

/// Removes bend `bend` of the selected arc (a double-click on it).
void removeBend(App& app, NetViewState& s, int bend) {
  const auto item = selectedItem(s, app.document().selection());
  if (!item || bend < 0) return;
  net::ArcSpec changed = s.view.page->arcs[s.layout.arcs[item->index].spec_index];
  if (static_cast<std::size_t>(bend) >= changed.via.size()) return;
  auto e = makeNetEdit(NetEditKind::SetArc, editedPage(s), changed.from, changed.to);
  e.arc_kind = changed.kind;
  changed.via.erase(changed.via.begin() + bend);
  e.arc = std::move(changed);
  (void)perform(app, std::move(e));
}

/// A click that was not the end of a drag: the left button let go where it went down.
bool leftClicked(const Region& r) {
  return r.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
         ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).x == 0.0f &&
         ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).y == 0.0f;
}

/// Ends the arc begun at s.arc_from on `to`: an arc of the page, or, when one end is an
/// instance, a menu of its ports (the arc goes to or from `instance/place`).
void finishArc(App& app, NetViewState& s, const std::string& to) {
  const auto isInstance = [&](const std::string& name) {
    return std::any_of(s.layout.instances.begin(), s.layout.instances.end(), [&](const auto& i) { return i.name == name; });
  };
  if (isInstance(to) || isInstance(s.arc_from)) {
    s.port_into = isInstance(to);
    s.port_instance = s.port_into ? to : s.arc_from;
    s.port_other = s.port_into ? s.arc_from : to;
    return;
  }
  auto e = makeNetEdit(NetEditKind::AddArc, editedPage(s), s.arc_from, to);
  e.arc_kind = s.arc_kind;
  (void)perform(app, std::move(e));
}

/// Adds an instance of page type `type` at `at` (layout units), named for its type (cell1,
/// cell2, ...), and selects it.
void addInstanceAt(App& app, NetViewState& s, const std::string& type, diagram::Point at) {
  std::string name;
  for (int n = 1; name.empty(); ++n) {
    const std::string candidate = type + std::to_string(n);
    const auto used = [&](const auto& list) {
      return std::any_of(list.begin(), list.end(), [&](const auto& x) { return x.name == candidate; });
    };
    if (!used(s.layout.places) && !used(s.layout.transitions) && !used(s.layout.instances)) name = candidate;
  }
  if (perform(app, makeNetEdit(NetEditKind::AddInstance, editedPage(s), name, type, editorAt(at))).empty()) {
    const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
    app.document().select({SelectionKind::Instance, prefix + "/" + name});
  }
}

/// The context menu's items for the selection: the Edit and Net menus' actions that apply.
void netSelectionMenu(App& app, nlohmann::json& items) {
  actionItems(app,
              {ActionId::Cut, ActionId::Copy, ActionId::Delete, ActionId::ReverseArc, ActionId::AlignLeft, ActionId::AlignTop,
               ActionId::DistributeAcross, ActionId::DistributeDown, ActionId::PageTypeFromSelection, ActionId::OpenInstance},
              items);
}

/// Adds a place (`letter` P) or transition (T) at `at` (layout units) and selects it alone.
void addConstructAt(App& app, NetViewState& s, char letter, diagram::Point at) {
  const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
  const bool place = letter == 'P';
  const auto name = freshName(s, letter);
  const auto kind = place ? NetEditKind::AddPlace : NetEditKind::AddTransition;
  if (perform(app, makeNetEdit(kind, editedPage(s), name, {}, editorAt(at))).empty()) {
    app.document().select({place ? SelectionKind::Place : SelectionKind::Transition, prefix + "/" + name});
  }
}

/// The left button with the Select tool: a click selects (Shift or Ctrl: adds or takes away), a
/// drag on a selected construct moves the selection (one undo step), a drag on paper draws a
/// rubber band that selects what it holds whole, Alt+drag pans. Returns true while the
/// selection moves.
bool selectGestures(App& app, NetViewState& s, const Region& r, const diagram::Viewport& viewport, diagram::Point mouse,
                    std::optional<diagram::ItemRef> under) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool adds = io.KeyShift || io.KeyCtrl;
  auto& doc = app.document();
  const auto handle = r.hovered && s.view.page != nullptr ? handleAt(app, s, viewport, r.mouse) : std::nullopt;
  if (handle && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    removeBend(app, s, handle->first);  // a double-click on a bend takes it away
    s.arc_drag.reset();
    return false;
  }
  if (r.activated && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    s.panning = io.KeyAlt;
    s.toggling.reset();
    s.alone.reset();
    s.arc_drag.reset();
    if (s.panning) {
      // the view pans; nothing is selected
    } else if (handle && !adds) {
      // the selected arc's bend or label: dragged
      beginArcDrag(app, s, *selectedItem(s, doc.selection()), handle->first, false);
    } else if (under && under->kind == diagram::ItemKind::Arc && !adds && s.view.page != nullptr) {
      // an arc's path: selected, and a drag from there bends it
      doc.select(selectionOf(s, *under));
      const auto& arc = s.layout.arcs[under->index];
      const auto hit = diagram::nearestSegment(arc, mouse);
      beginArcDrag(app, s, *under, arc.follows_via ? static_cast<int>(hit.segment) : 0, true);
      if (!arc.follows_via) s.arc_drag->spec.via.clear();  // a straight (or Graphviz's) route: the new bend alone
    } else if (!under) {
      s.band_from = mouse;
      s.band_adds = adds;
    } else {
      const Selection one = selectionOf(s, *under);
      if (adds) s.toggling = under;
      else if (!doc.isSelected(one)) doc.select(one);
      else if (doc.selectedCount() > 1) s.alone = under;  // one of a group: alone, unless this becomes a drag
      if (under->kind == diagram::ItemKind::Transition && !adds) app.toolbar.fire_target = one.name;
      if (under->kind != diagram::ItemKind::Arc && !adds) {
        s.moving = localName(s, *under);
        s.moving_from = selectedConstructs(app, s);
        s.moving_origin = mouse;
        s.moved_by = {0, 0};
        ++app.inspector.drag_id;
      }
    }
  }
  const bool dragging = r.active && ImGui::IsMouseDragging(ImGuiMouseButton_Left);
  if (dragging) {
    s.toggling.reset();
    s.alone.reset();
  }
  if (s.arc_drag && dragging) {
    dragArc(app, s, mouse);
    return true;
  }
  // the selection follows the mouse, on a grid of a quarter unit, as one step
  bool moving = false;
  if (!s.moving.empty() && dragging && !s.moving_from.empty()) {
    moving = true;
    const auto by = editorAt(mouse - s.moving_origin);
    if (by != s.moved_by) {
      s.moved_by = by;
      auto e = makeNetEdit(NetEditKind::MoveMany, editedPage(s), {});
      e.moves.reserve(s.moving_from.size());
      for (const auto& [name, at] : s.moving_from) e.moves.emplace_back(name, net::EditorPos{at[0] + by[0], at[1] + by[1]});
      e.drag = app.inspector.drag_id;
      e.pins = pinsOf(s);
      if (perform(app, std::move(e)).empty()) {
        std::vector<diagram::ItemRef> moved;
        const std::string& prefix = s.view.prefix.empty() ? s.layout.page : s.view.prefix;
        for (const auto& [name, at] : s.moving_from) {
          if (const auto it = s.by_name.find(prefix + "/" + name); it != s.by_name.end()) moved.push_back(it->second);
        }
        relaidOut(app, s, moved);
      }
    }
  }
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    if (s.band_from) {
      const bool dragged = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).x != 0.0f ||
                           ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).y != 0.0f;
      if (dragged) {
        std::vector<Selection> chosen = s.band_adds ? doc.selections() : std::vector<Selection>{};
        for (const auto item : inBand(s, *s.band_from, mouse)) chosen.push_back(selectionOf(s, item));
        doc.selectAll(chosen);
        app.message = std::to_string(doc.selectedCount()) + " selected";
      } else if (!s.band_adds) {
        doc.select({});
      }
    }
    if (s.toggling && leftClicked(r)) doc.toggleSelected(selectionOf(s, *s.toggling));
    if (s.alone && leftClicked(r)) doc.select(selectionOf(s, *s.alone));
    s.band_from.reset();
    s.toggling.reset();
    s.alone.reset();
    s.moving.clear();
    s.moving_from.clear();
    s.panning = false;
    s.arc_drag.reset();
  }
  return moving;
}

/// Editing by hand. With the Select tool, selectGestures(); with the Place or Transition tool a
/// click on paper adds one there; with the Arc tool a drag (or a click, then a click) from a
/// place to a transition or back adds an arc. The right button opens a menu: on paper, a new
/// place or transition there; on a place or transition, rename, delete, or an arc from it
/// (normal, test, inhibitor) that a click on its other end finishes (Escape or a click on
/// paper drops it); on an arc, reverse or delete it. Returns true while a drag moves constructs
/// (the view does not pan then).
bool editGestures(App& app, NetViewState& s, const Region& r, const diagram::Viewport& viewport,
                  std::optional<diagram::ItemRef> under, nlohmann::json& report) {
  const diagram::Point mouse = viewport.toLayout(r.mouse);
  const bool node = under && under->kind != diagram::ItemKind::Arc;
  bool moving = false;
  nlohmann::json items = nlohmann::json::object();  // the menus' items, for replays
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)) && !ImGui::GetIO().WantTextInput) {
    // Escape drops what is under way and goes back to selecting
    s.arc_from.clear();
    s.band_from.reset();
    s.tool = NetTool::Select;
    app.message.clear();
  }
  switch (s.overview_hot ? NetTool::Select : s.tool) {
    case NetTool::Select:
      if (s.overview_hot) break;  // the overview takes the left button
      if (s.arc_from.empty()) moving = selectGestures(app, s, r, viewport, mouse, under);
      break;
    case NetTool::Place:
    case NetTool::Transition:
      if (leftClicked(r) && !under) addConstructAt(app, s, s.tool == NetTool::Place ? 'P' : 'T', mouse);
      else if (leftClicked(r) && under) app.document().select(selectionOf(s, *under));
      break;
    case NetTool::Arc:
      // a drag from one end: the arc starts where the button went down
      if (r.activated && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && node && s.arc_from.empty()) {
        s.arc_from = localName(s, *under);
        s.arc_kind = net::ArcKind::Normal;
        s.moving = "\x01arc";  // the drag draws the arc, it pans nothing
      }
      if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !s.arc_from.empty() && !leftClicked(r)) {
        // let go after a drag: on a construct the arc is made, elsewhere dropped
        if (node && localName(s, *under) != s.arc_from) finishArc(app, s, localName(s, *under));
        s.arc_from.clear();
        app.message.clear();
      }
      if (!r.active) s.moving.clear();
      moving = !s.arc_from.empty();
      break;
  }
  // an arc begun: a click on its other end makes it
  if (!s.arc_from.empty()) {
    app.message = "click where the arc from " + s.arc_from + " ends (Escape: no arc)";
    if (leftClicked(r) && !(node && localName(s, *under) == s.arc_from)) {
      app.message.clear();
      if (node) finishArc(app, s, localName(s, *under));
      s.arc_from.clear();
    }
  }
  // an arc to or from an instance: which of its ports
  if (!s.port_instance.empty() && !s.port_open) {
    ImGui::OpenPopup("##ports");
    s.port_open = true;
  }
  if (ImGui::BeginPopup("##ports")) {
    const auto& net = app.document().model().net;
    const net::PageSpec* type = nullptr;
    if (const auto* page = findPage(net, editedPage(s))) {
      for (const auto& i : page->instances) {
        if (i.name == s.port_instance) type = findPage(net, i.type);
      }
    }
    ImGui::TextDisabled("%s which port of %s?", s.port_into ? "into" : "out of", s.port_instance.c_str());
    if (type != nullptr) {
      for (const auto& ref : type->references) {
        if (!menuItem(ref.place.c_str(), items)) continue;
        const std::string link = s.port_instance + "/" + ref.place;
        auto e = makeNetEdit(NetEditKind::AddArc, editedPage(s), s.port_into ? s.port_other : link,
                             s.port_into ? link : s.port_other);
        e.arc_kind = s.arc_kind;
        (void)perform(app, std::move(e));
      }
    }
    if (type == nullptr || type->references.empty()) ImGui::TextDisabled("(it publishes no places)");
    ImGui::EndPopup();
  } else if (s.port_open) {
    s.port_instance.clear();  // the menu closed
    s.port_open = false;
  }
  // the menu
  if (r.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right)) {
    s.menu_item = under;
    s.menu_at = mouse;
    s.rename = node ? localName(s, *under) : std::string();
    // a right-click on something not selected selects it alone (the menu is about it)
    if (under && !app.document().isSelected(selectionOf(s, *under))) app.document().select(selectionOf(s, *under));
    ImGui::OpenPopup("##net_menu");
  }
  const auto item = [&](const char* label) { return menuItem(label, items); };
  if (ImGui::BeginPopup("##net_menu")) {
    if (!s.menu_item) {
      if (item("Place here")) addConstructAt(app, s, 'P', s.menu_at);
      if (item("Transition here")) addConstructAt(app, s, 'T', s.menu_at);
      const auto& types = app.document().model().net.page_types;
      if (!types.empty() && beginMenu("Instance here", items)) {
        for (const auto& type : types) {
          if (type.name == editedPage(s) || !menuItem(type.name.c_str(), items)) continue;
          addInstanceAt(app, s, type.name, s.menu_at);
        }
        ImGui::EndMenu();
      }
      if (app.document().selectedCount() > 0) {
        ImGui::Separator();
        netSelectionMenu(app, items);
      }
    } else if (s.menu_item->kind == diagram::ItemKind::Arc) {
      ImGui::TextDisabled("%s", qualified(s, *s.menu_item).c_str());
      netSelectionMenu(app, items);
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
      for (const auto& [label, kind] : {std::pair{"Arc from here", net::ArcKind::Normal},
                                        std::pair{"Test arc from here", net::ArcKind::Test},
                                        std::pair{"Inhibitor arc from here", net::ArcKind::Inhibitor}}) {
        if (item(label)) {
          s.arc_from = name;
          s.arc_kind = kind;
        }
      }
      ImGui::Separator();
      netSelectionMenu(app, items);
    } else {
      ImGui::TextDisabled("instance %s", localName(s, *s.menu_item).c_str());
      if (item("Open Its Page")) s.path = (s.path.empty() ? s.layout.page : s.path) + "/" + localName(s, *s.menu_item);
      netSelectionMenu(app, items);
    }
    ImGui::EndPopup();
  }
  report["menu"] = items;
  report["moving"] = s.moving == "\x01arc" ? std::string() : s.moving;
  report["arc_from"] = s.arc_from;
  report["tool"] = netToolName(s.tool);
  report["band"] = s.band_from.has_value();
  return moving;
}

/// Where the overview goes: the view's lower right corner, in the page's proportions; none
/// while the whole page is in view.
std::optional<diagram::Box> overviewBox(const NetViewState& s, const Region& r, const diagram::Viewport& viewport) {
  const diagram::Box& all = s.layout.bounds;
  const diagram::Box seen = viewport.visible(r.width, r.height);
  const bool whole = seen.min.x <= all.min.x && seen.min.y <= all.min.y && seen.max.x >= all.max.x && seen.max.y >= all.max.y;
  if (whole || all.width() <= 0 || all.height() <= 0 || r.width < 320 || r.height < 240) return std::nullopt;
  const double w = std::min(200.0, r.width * 0.3), scale = std::min(w / all.width(), (r.height * 0.3) / all.height());
  const double bw = all.width() * scale, bh = all.height() * scale;
  const diagram::Point hi{static_cast<double>(r.width) - 10, static_cast<double>(r.height) - 10};
  return diagram::Box{{hi.x - bw, hi.y - bh}, hi};
}

/// The overview of a page larger than the view: where its constructs lie, shaded by how many,
/// and the part the view shows framed; a click or drag in it brings the view there. True
/// while it takes the mouse.
bool drawOverview(NetViewState& s, const Region& r, nlohmann::json& report) {
  const auto box = overviewBox(s, r, s.viewport);
  report["overview"] = box.has_value();
  if (!box) return false;
  // its corners in window pixels, for replays and tests
  const double ox = static_cast<double>(r.origin.x), oy = static_cast<double>(r.origin.y);
  report["overview_box"] = {std::lround(ox + box->min.x), std::lround(oy + box->min.y), std::lround(ox + box->max.x),
                            std::lround(oy + box->max.y)};
  ImDrawList* list = ImGui::GetWindowDrawList();
  const auto px = [&](diagram::Point p) { return ImVec2{r.origin.x + static_cast<float>(p.x), r.origin.y + static_cast<float>(p.y)}; };
  list->AddRectFilled(px(box->min - diagram::Point{3, 3}), px(box->max + diagram::Point{3, 3}), IM_COL32(250, 250, 250, 235), 3.0f);
  list->AddRect(px(box->min - diagram::Point{3, 3}), px(box->max + diagram::Point{3, 3}), IM_COL32(150, 150, 150, 255), 3.0f);
  const double cw = box->width() / kOverviewCols, ch = box->height() / kOverviewRows;
  const std::uint32_t most = std::max<std::uint32_t>(1, *std::max_element(s.density.begin(), s.density.end()));
  for (int y = 0; y < kOverviewRows; ++y) {
    for (int x = 0; x < kOverviewCols; ++x) {
      const auto n = s.density[static_cast<std::size_t>(y * kOverviewCols + x)];
      if (n == 0) continue;
      const int shade = 200 - static_cast<int>(140.0 * std::sqrt(static_cast<double>(n) / most));
      const diagram::Point lo{box->min.x + x * cw, box->min.y + y * ch};
      list->AddRectFilled(px(lo), px(lo + diagram::Point{cw, ch}), IM_COL32(shade, shade, shade + 20, 255));
    }
  }
  // the part in view
  const diagram::Box& all = s.layout.bounds;
  const double scale = box->width() / all.width();
  const diagram::Box seen = s.viewport.visible(r.width, r.height);
  const auto onBox = [&](diagram::Point p) {
    return diagram::Point{std::clamp(box->min.x + (p.x - all.min.x) * scale, box->min.x, box->max.x),
                          std::clamp(box->min.y + (p.y - all.min.y) * scale, box->min.y, box->max.y)};
  };
  list->AddRect(px(onBox(seen.min)), px(onBox(seen.max)), IM_COL32(255, 140, 0, 255), 0.0f, 0, 2.0f);
  // a click or drag there centres the view on that point of the page
  const bool inside = r.hovered && r.mouse.x >= box->min.x && r.mouse.y >= box->min.y && r.mouse.x <= box->max.x && r.mouse.y <= box->max.y;
  if (inside && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) s.overview_drag = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) s.overview_drag = false;
  if (s.overview_drag) {
    const diagram::Point q{all.min.x + (std::clamp(r.mouse.x, box->min.x, box->max.x) - box->min.x) / scale,
                           all.min.y + (std::clamp(r.mouse.y, box->min.y, box->max.y) - box->min.y) / scale};
    const diagram::Point centre{r.width / 2.0, r.height / 2.0};
    s.viewport = s.viewport.panned(centre - s.viewport.toScreen(q));
    s.fitted = false;
  }
  return inside || s.overview_drag;
}

/// Draws over the page what a gesture under way shows: a rubber band, an arc being drawn.
void paintGestures(App& app, const NetViewState& s, const Region& r, const diagram::Viewport& viewport) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  const auto px = [&](diagram::Point p) { return ImVec2{r.origin.x + static_cast<float>(p.x), r.origin.y + static_cast<float>(p.y)}; };
  // the selected arc's handles: a square on each bend, a diamond on its label
  if (s.view.page != nullptr) {
    for (const auto& [bend, at] : arcHandles(app, s)) {
      const ImVec2 c = px(viewport.toScreen(at));
      if (bend >= 0) {
        list->AddRectFilled({c.x - 4, c.y - 4}, {c.x + 4, c.y + 4}, IM_COL32(255, 255, 255, 255));
        list->AddRect({c.x - 4, c.y - 4}, {c.x + 4, c.y + 4}, IM_COL32(255, 140, 0, 255), 0.0f, 0, 1.5f);
      } else {
        // the label: framed, so that the text stays readable (a drag on it moves it)
        const auto item = selectedItem(s, app.document().selection());
        const std::string& text = item ? s.layout.arcs[item->index].inscription : std::string();
        const ImVec2 size = ImGui::CalcTextSize(text.c_str());
        const float hw = std::max(8.0f, size.x * 0.5f + 4), hh = std::max(7.0f, size.y * 0.5f + 1);
        list->AddRect({c.x - hw, c.y - hh}, {c.x + hw, c.y + hh}, IM_COL32(255, 140, 0, 255), 3.0f, 0, 1.5f);
      }
    }
  }
  if (s.band_from) {
    const diagram::Point a = viewport.toScreen(*s.band_from);
    const diagram::Point lo{std::min(a.x, r.mouse.x), std::min(a.y, r.mouse.y)}, hi{std::max(a.x, r.mouse.x), std::max(a.y, r.mouse.y)};
    list->AddRectFilled(px(lo), px(hi), IM_COL32(60, 120, 220, 40));
    list->AddRect(px(lo), px(hi), IM_COL32(60, 120, 220, 220), 0.0f, 0, 1.0f);
    // what letting go would select: its places, transitions and instances framed
    for (const auto item : inBand(s, *s.band_from, viewport.toLayout(r.mouse))) {
      if (item.kind == diagram::ItemKind::Arc) continue;
      const diagram::Box& box = s.layout.boxOf(item);
      list->AddRect(px(viewport.toScreen(box.min) - diagram::Point{3, 3}), px(viewport.toScreen(box.max) + diagram::Point{3, 3}),
                    IM_COL32(60, 120, 220, 255), 2.0f, 0, 1.5f);
    }
  }
  if (!s.arc_from.empty()) {
    const auto it = s.by_name.find((s.view.prefix.empty() ? s.layout.page : s.view.prefix) + "/" + s.arc_from);
    if (it == s.by_name.end()) return;
    const diagram::Box& box = s.layout.boxOf(it->second);
    list->AddLine(px(viewport.toScreen((box.min + box.max) * 0.5)), px(r.mouse), IM_COL32(40, 90, 200, 255), 2.0f);
  }
}

}  // namespace

void drawNetView(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##net", at, "Net view");
  NetViewState& s = app.netView();
  nlohmann::json tools = nlohmann::json::object();
  drawPageBar(app, s, tools);
  ensureLayout(app, s);
  report = {{"path", s.path}, {"page", s.layout.page}, {"places", s.layout.places.size()},
            {"transitions", s.layout.transitions.size()}, {"arcs", s.layout.arcs.size()}, {"tools", tools}};
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
  // the overview of a large page takes the mouse over it
  const auto overview = overviewBox(s, r, s.viewport);
  const bool over_overview = s.overview_drag || (overview && r.mouse.x >= overview->min.x && r.mouse.y >= overview->min.y &&
                                                 r.mouse.x <= overview->max.x && r.mouse.y <= overview->max.y);
  s.overview_hot = over_overview;
  const bool moving = editGestures(app, s, r, s.viewport, over_overview ? std::nullopt : pointed, report);
  ensureLayout(app, s);  // an edit a menu or a gesture made: the page as it is now (nothing when unchanged)
  // the middle button pans, as does a left drag with Alt, or on paper with a tool that adds
  const bool left_pans = s.panning || (s.tool != NetTool::Select && s.arc_from.empty() && !moving);
  if (r.active && !moving && s.moving.empty() && !s.band_from && !over_overview &&
      ((left_pans && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))) {
    s.viewport = s.viewport.panned({static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y)});
    s.fitted = false;
  }
  auto shown = s.viewport;
  shown.min_label_px = kNetViewLabelPx;  // names a user can read where there is room for them
  const auto under = clickAndPaint(app, s, r, shown, report, false);
  paintGestures(app, s, r, shown);
  // the selected arc's handles, for replays and tests: "bend 0", ..., "label"
  nlohmann::json handles = nlohmann::json::object();
  if (s.view.page != nullptr) {
    for (const auto& [bend, spot] : arcHandles(app, s)) {
      const diagram::Point p = shown.toScreen(spot);
      handles[bend < 0 ? std::string("label") : "bend " + std::to_string(bend)] = {
          std::lround(static_cast<double>(r.origin.x) + p.x), std::lround(static_cast<double>(r.origin.y) + p.y)};
    }
  }
  report["handles"] = handles;
  (void)drawOverview(s, r, report);
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
    clickAndPaint(app, s, r, diagram::fitViewport(s.layout, r.width, r.height, 6.0), report, true);
  }
  ImGui::End();
}

}  // namespace gdpn::ide
