// The tree view: the scene tree (node tokens and sensors in bold, a colour per category) and
// the net's places and transitions; a click selects.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "../views.h"
#include "gdpn/diagram/layout.h"
#include "gdpn/ide/scene_edit.h"

namespace gdpn::ide {

namespace {

/// A colour per category of node (shape, material, body, joint, sensor, light, camera).
ImVec4 colourOf(scene::NodeKind kind) {
  using K = scene::NodeKind;
  switch (kind) {
    case K::Group:
    case K::Transform: return {0.85F, 0.86F, 0.88F, 1.0F};
    case K::Material:
    case K::Fog: return {0.95F, 0.62F, 0.30F, 1.0F};
    case K::Light: return {0.98F, 0.88F, 0.35F, 1.0F};
    case K::Camera: return {0.55F, 0.80F, 0.98F, 1.0F};
    case K::Cube:
    case K::Sphere:
    case K::Cylinder:
    case K::Cone:
    case K::Plane:
    case K::Mesh:
    case K::Terrain: return {0.60F, 0.88F, 0.55F, 1.0F};
    case K::World:
    case K::Body:
    case K::Conveyor:
    case K::GradientField: return {0.85F, 0.60F, 0.95F, 1.0F};
    case K::Joint: return {0.95F, 0.50F, 0.60F, 1.0F};
    case K::Region:
    case K::RangeFinder:
    case K::GradientSensor:
    case K::KeyboardSensor:
    case K::MouseSensor:
    case K::ColorCamera:
    case K::DepthCamera:
    case K::LaserScan:
    case K::Imu:
    case K::Gps:
    case K::Contact:
    case K::ForceTorque:
    case K::TimeSensor: return {0.40F, 0.92F, 0.90F, 1.0F};
  }
  return {1, 1, 1, 1};
}

struct TreeState {
  App& app;
  std::set<std::string> tokens;  // paths of the nodes that are node tokens
  std::string selected;          // the selected node's path
  nlohmann::json bold = nlohmann::json::array();
  int shown = 0;
  nlohmann::json rows = nlohmann::json::object();  // where the first rows stand, by path
  std::optional<SceneEdit> request;  // an edit asked for in a menu, made once the tree is drawn
  bool import = false;               // the import menu asked for its files, read once the tree is drawn
  nlohmann::json menu = nlohmann::json::object();  // the open menu's items, where they stand
  nlohmann::json menu_at = nlohmann::json::object();  // the Scene header, where it stands
};

/// The menu "Import meshes": mesh files (';' between them) read through the importers.
void importMenu(TreeState& st) {
  if (!beginMenu("Import meshes", st.menu)) return;
  ImGui::TextDisabled("Mesh files (obj, stl, 3ds, gltf, dae, ply, wrl, iv), ';' between them:");
  ImGui::SetNextItemWidth(360);
  const bool entered = ImGui::InputText("##files", &st.app.tree.import_files, ImGuiInputTextFlags_EnterReturnsTrue);
  noteItem("files", st.menu);
  if (menuItem("Import", st.menu) || entered) {
    st.import = true;  // once the tree is drawn
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndMenu();
}

/// The menu "Add": a node of any type under `parent` ("" the root).
void addMenu(TreeState& st, const scene::Scene& s, const std::string& parent) {
  if (!beginMenu("Add", st.menu)) return;
  for (const scene::NodeType* type : s.types().all()) {
    ImGui::PushStyleColor(ImGuiCol_Text, colourOf(type->kind));
    if (menuItem(type->name.c_str(), st.menu)) st.request = SceneEdit{SceneEditKind::Add, parent, type->name, {}, false, {}};
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered() && !type->doc.empty()) ImGui::SetTooltip("%s", type->doc.c_str());
  }
  ImGui::EndMenu();
}

/// A node's menu (right click): its name, Add, Duplicate, Delete. The model is edited only as
/// edited, not while a run is shown.
void nodeMenu(TreeState& st, const scene::Scene& s, const scene::Node& node, const std::string& path) {
  if (!ImGui::BeginPopupContextItem()) return;
  App& app = st.app;
  if (app.run().mode() != RunMode::Edit) {
    ImGui::TextDisabled("The run's plant: Reset to edit the model");
  } else {
    ImGui::TextDisabled("%s %s", node.type().name.c_str(), path.c_str());
    ImGui::SetNextItemWidth(160);
    // the name field takes the keyboard with its text selected: typing replaces it
    if (ImGui::IsWindowAppearing()) {
      app.tree.rename = node.name();
      ImGui::SetKeyboardFocusHere();
    }
    if (ImGui::InputText("name", &app.tree.rename, ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll) &&
        app.tree.rename != node.name()) {
      st.request = SceneEdit{SceneEditKind::Rename, path, {}, app.tree.rename, false, {}};
      ImGui::CloseCurrentPopup();
    }
    if (node.type().has_children) {
      addMenu(st, s, path);
      importMenu(st);
    }
    if (menuItem("Duplicate", st.menu)) st.request = SceneEdit{SceneEditKind::Duplicate, path, {}, {}, false, {}};
    const auto uses = usesOf(app.document().model().net, path);
    if (uses.empty()) {
      if (menuItem("Delete", st.menu)) st.request = SceneEdit{SceneEditKind::Delete, path, {}, {}, false, {}};
    } else {
      if (menuItem("Delete, and from the marking", st.menu)) st.request = SceneEdit{SceneEditKind::Delete, path, {}, {}, true, {}};
      if (ImGui::IsItemHovered()) {
        std::string list;
        for (const auto& u : uses) list += "\n  " + u;
        ImGui::SetTooltip("The net holds it:%s", list.c_str());
      }
    }
  }
  ImGui::EndPopup();
}

/// A row (or the Scene heading, `parent` "") that takes a node dragged from the tree: the node
/// moves under it (edit mode only).
void dropTarget(TreeState& st, const std::string& parent) {
  if (st.app.run().mode() != RunMode::Edit || !ImGui::BeginDragDropTarget()) return;
  if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kNodePayload)) {
    const std::string dragged(static_cast<const char*>(payload->Data), static_cast<std::size_t>(payload->DataSize));
    if (dragged != parent) st.request = SceneEdit{SceneEditKind::Reparent, dragged, {}, parent, false, {}};
  }
  ImGui::EndDragDropTarget();
}

/// A part instance's machine: one row, the part, edited through its parameters (inspector).
void drawPart(TreeState& st, const std::string& path, const PartInstanceAt& at) {
  const auto* inst = instanceAt(st.app.document().model(), at);
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (path == st.selected) flags |= ImGuiTreeNodeFlags_Selected;
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{0.98F, 0.78F, 0.45F, 1.0F});
  ImGui::TreeNodeEx(path.c_str(), flags, "Part  %s", at.name.c_str());
  ImGui::PopStyleColor();
  if (st.shown < 200) noteItem(path, st.rows);
  ++st.shown;
  if (path == st.selected && st.app.tree.reveal) ImGui::SetScrollHereY();
  if (ImGui::IsItemHovered() && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) st.app.document().select(Selection::node(path));
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) st.app.frameSelection();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Part %s (%s): its parameters, I/O and control are in the inspector", at.name.c_str(),
                      inst != nullptr ? inst->type.c_str() : "?");
  }
}

void drawNode(TreeState& st, scene::Node& node) {
  const auto path = node.path();
  if (const auto part = partAtPath(st.app, path)) {
    drawPart(st, path, *part);
    return;
  }
  const bool is_token = st.tokens.count(path) > 0;
  const bool is_sensor = node.type().category == scene::Category::Sensor;
  const bool leaf = node.children().empty();
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (leaf) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
  if (path == st.selected) flags |= ImGuiTreeNodeFlags_Selected;
  // open the parents of a selection made elsewhere
  if (st.app.tree.reveal && !st.selected.empty() && st.selected.starts_with(path + "/")) {
    ImGui::SetNextItemOpen(true);
  }
  const auto label = node.type().name + (node.name().empty() ? std::string() : "  " + node.name()) +
                     (node.is_template ? "  (template)" : "");
  if (is_token || is_sensor) {
    ImGui::PushFont(st.app.fonts.bold);
    st.bold.push_back(path);
  }
  ImGui::PushStyleColor(ImGuiCol_Text, colourOf(node.kind()));
  const bool open = ImGui::TreeNodeEx(path.c_str(), flags, "%s", label.c_str());
  ImGui::PopStyleColor();
  if (is_token || is_sensor) ImGui::PopFont();
  // dragged onto a slot of the contents view, a node becomes a token there
  if (ImGui::BeginDragDropSource()) {
    ImGui::SetDragDropPayload(kNodePayload, path.data(), path.size());
    ImGui::Text("%s", path.c_str());
    ImGui::EndDragDropSource();
  }
  // dropped onto another row, a node moves under it
  dropTarget(st, path);
  if (const auto* s = st.app.shownScene()) nodeMenu(st, *s, node, path);
  if (st.shown < 200) noteItem(path, st.rows);
  ++st.shown;
  if (path == st.selected && st.app.tree.reveal) ImGui::SetScrollHereY();
  // selected when the button comes up without a drag (a drag carries the node elsewhere)
  if (ImGui::IsItemHovered() && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Left).x == 0.0F && ImGui::GetMouseDragDelta(ImGuiMouseButton_Left).y == 0.0F) {
    st.app.document().select(Selection::node(path));
  }
  // a double click also frames it in the world view
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) st.app.frameSelection();
  if (ImGui::IsItemHovered() && !node.type().doc.empty()) ImGui::SetTooltip("%s", node.type().doc.c_str());
  if (!leaf && open) {
    for (const auto& child : node.children()) drawNode(st, *child);
    ImGui::TreePop();
  }
}

}  // namespace

void drawTreeView(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##tree", at, "Tree view");
  TreeState st{app, {}, {}, nlohmann::json::array(), 0, nlohmann::json::object(), std::nullopt, false,
               nlohmann::json::object(), nlohmann::json::object()};
  const auto& sel = app.document().selection();
  if (sel.kind == SelectionKind::Node) st.selected = sel.name;
  auto* session = app.run().session();
  if (session != nullptr) {
    for (const auto& name : session->simulation().net().nodeNames()) st.tokens.insert(name);
  }

  // the scene
  ImGui::BeginChild("##tree_scroll", {0, 0}, false);
  auto* s = app.shownScene();
  if (s == nullptr) {
    ImGui::TextDisabled("(the model has no scene)");
  } else {
    const bool open = ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen);
    noteItem("header", st.menu_at);
    dropTarget(st, "");
    if (app.run().mode() == RunMode::Edit && ImGui::BeginPopupContextItem("##scene_menu")) {
      addMenu(st, *s, "");
      importMenu(st);
      ImGui::EndPopup();
    }
    if (open) {
      for (const auto& child : s->root().children()) drawNode(st, *child);
      if (s->root().children().empty()) ImGui::TextDisabled("Empty: right-click Scene to add a node");
    }
  }

  // the net's places and transitions (the net view shows them later)
  int places = 0, transitions = 0;
  if (session != nullptr && ImGui::CollapsingHeader("Net")) {
    // the instances of page types, as written
    for (const auto& page : app.document().model().net.pages) {
      for (const auto& inst : page.instances) {
        const auto name = page.name + "/" + inst.name;
        const auto label = "instance  " + name + "  (" + inst.type + ")";
        if (ImGui::Selectable(label.c_str(), sel.kind == SelectionKind::Instance && sel.name == name)) {
          app.document().select({SelectionKind::Instance, name});
        }
      }
    }
    const auto& net = session->simulation().net();
    const auto& kernel = session->simulation().kernel();
    for (std::size_t i = 0; i < net.places().size(); ++i) {
      const auto id = static_cast<net::PlaceId>(i);
      const auto name = net.placeName(id);
      // a continuous place: its amount with its unit (hybrid nets)
      const auto* fluid = net.fluid();
      const auto count = net.continuousPlace(id)
                             ? diagram::amountText(kernel.amount(id), fluid->places[static_cast<std::size_t>(fluid->of_place[id])].unit)
                             : std::to_string(kernel.placeTokens(id));
      const auto label = "place  " + name + "  (" + count + ")";
      const bool is_sel = sel.kind == SelectionKind::Place && sel.name == name;
      if (ImGui::Selectable(label.c_str(), is_sel)) app.document().select({SelectionKind::Place, name});
      ++places;
    }
    for (std::size_t i = 0; i < net.transitions().size(); ++i) {
      const auto id = static_cast<net::TransitionId>(i);
      const auto name = net.transitionName(id);
      // the kernel's answer, as the net view draws it: enabled only when able to start
      const net::Readiness ready = kernel.readiness(id);
      const bool able = ready == net::Readiness::Able, held = net::heldBack(ready);
      const char* state = kernel.occurring(id) ? "occurring" : able ? "enabled" : held ? "held back" : "";
      const bool flowing = net.continuous(id) && kernel.flowRate(id) != 0.0;  // a flow never fires
      if (net.continuous(id)) state = flowing ? "flowing" : "";
      const auto label = "transition  " + name + (*state != '\0' ? std::string("  [") + state + "]" : "");
      const bool is_sel = sel.kind == SelectionKind::Transition && sel.name == name;
      ImGui::PushStyleColor(ImGuiCol_Text, kernel.occurring(id) ? ImVec4{1.0F, 0.45F, 0.4F, 1}
                                           : able || flowing     ? ImVec4{0.45F, 0.95F, 0.45F, 1}
                                           : held               ? ImVec4{0.95F, 0.70F, 0.10F, 1}
                                                                : ImGui::GetStyleColorVec4(ImGuiCol_Text));
      if (ImGui::Selectable(label.c_str(), is_sel)) {
        app.document().select({SelectionKind::Transition, name});
        app.toolbar.fire_target = name;
      }
      ImGui::PopStyleColor();
      ++transitions;
    }
  }
  ImGui::EndChild();
  endPanel();
  app.tree.reveal = false;
  // the edit a menu asked for, now that nothing iterates the tree
  if (st.import) app.importMeshes(app.tree.import_files);
  if (st.request) {
    auto command = std::make_unique<SceneEditCommand>(*st.request);
    const auto* edit = command.get();  // kept on the undo stack when it succeeds
    const auto why = app.document().execute(std::move(command));
    const std::string made = why.empty() ? edit->made() : std::string();
    app.message = why;
    if (why.empty() && st.request->kind == SceneEditKind::Delete) app.document().select({});
    // the node added, copied or renamed is selected, and the tree opens to it
    if (why.empty() && !made.empty()) {
      app.document().select(Selection::node(made));
      app.tree.reveal = true;
    }
  }
  report = {{"nodes_shown", st.shown},
            {"bold", st.bold},
            {"selected", st.selected},
            {"places_shown", places},
            {"transitions_shown", transitions},
            {"menu", st.menu},
            {"rows", st.rows},
            {"scene", st.menu_at["header"]}};
}

}  // namespace gdpn::ide
