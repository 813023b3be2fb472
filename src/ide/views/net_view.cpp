// The net view: the page (or instance) chosen, drawn by the diagram module's painter with the
// run's marking; zoom at the cursor, pan by dragging, fit; a click selects a construct, a
// double click on an instance goes into it. The mini view: the same page, fitted, in a small
// window over the world view.

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "../views.h"
#include "gdpn/diagram/net_state.h"
#include "imgui_canvas.h"
#include "net_view_state.h"

namespace gdpn::ide {
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
    default: return std::nullopt;
  }
}

/// Pages of at most this many constructs report each one (positions, activity, tokens); the
/// report is made every frame, and a large page would cost a string per construct.
constexpr std::size_t kReportedItems = 500;

const char* activityName(diagram::Activity a) {
  switch (a) {
    case diagram::Activity::Idle: return "idle";
    case diagram::Activity::Enabled: return "enabled";
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
};

Region regionHere(const char* id) {
  Region r;
  r.origin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  r.width = std::max(1, static_cast<int>(avail.x));
  r.height = std::max(1, static_cast<int>(avail.y));
  ImGui::InvisibleButton(id, {static_cast<float>(r.width), static_cast<float>(r.height)},
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle);
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
    if (t < 0) continue;
    for (const auto& [slot, ref] : sim.kernel().held(static_cast<net::TransitionId>(t))) {
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
  if (ImGui::IsItemHovered() && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).x == 0.0f &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f).y == 0.0f) {
    if (under) app.document().select(selectionOf(s, *under));
    else app.document().select({});
    if (under && under->kind == diagram::ItemKind::Transition) app.fire_target = qualified(s, *under);
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
  list->PopClipRect();
  if (under && ImGui::IsItemHovered() && under->kind != diagram::ItemKind::Arc) {
    ImGui::SetTooltip("%s", qualified(s, *under).c_str());
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

}  // namespace

void drawNetView(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##net", at, "Net view");
  NetViewState& s = app.netView();
  drawPageBar(app, s);
  ensureLayout(app, s);
  report = {{"path", s.path}, {"page", s.layout.page}, {"places", s.layout.places.size()},
            {"transitions", s.layout.transitions.size()}};
  if (!s.error.empty()) {
    ImGui::TextWrapped("%s", s.error.c_str());
    report["error"] = s.error;
    endPanel();
    return;
  }
  const Region r = regionHere("##netcanvas");
  if (s.fit) {
    s.viewport = diagram::fitViewport(s.layout, r.width, r.height);
    s.fit = false;
  }
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    s.viewport = s.viewport.zoomedAbout(r.mouse, std::pow(1.15, static_cast<double>(io.MouseWheel)));
  }
  if (ImGui::IsItemActive() &&
      (ImGui::IsMouseDragging(ImGuiMouseButton_Left) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))) {
    s.viewport = s.viewport.panned({static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y)});
  }
  const auto under = clickAndPaint(app, s, r, s.viewport, report);
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && under &&
      under->kind == diagram::ItemKind::Instance) {
    s.path = (s.path.empty() ? s.layout.page : s.path) + "/" + s.layout.instances[under->index].name;
  }
  endPanel();
}

void drawMiniView(App& app, const Rect& world, nlohmann::json& report) {
  report = {{"shown", app.show_mini}};
  if (!app.show_mini) return;
  NetViewState& s = app.netView();
  ensureLayout(app, s);
  const float w = std::max(160.0f, world.w * 0.45f), h = std::max(90.0f, world.h * 0.32f);
  ImGui::SetNextWindowPos({world.x + world.w - w - 8, world.y + world.h - h - 8}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize({w, h}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.92f);
  const bool open = ImGui::Begin("Mini view", &app.show_mini,
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                     ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoFocusOnAppearing);
  if (open && s.error.empty()) {
    const Region r = regionHere("##minicanvas");
    clickAndPaint(app, s, r, diagram::fitViewport(s.layout, r.width, r.height, 6.0), report);
  }
  ImGui::End();
}

}  // namespace gdpn::ide
