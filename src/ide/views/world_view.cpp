// The world view: the plant through the renderer into an offscreen texture shown as an image;
// orbit (left drag), pan (right or middle drag), zoom (wheel), pick (click), standard views,
// the scene's cameras; keys and, during a run, clicks go to the keyboard and mouse sensors.

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../detail/keys.h"
#include "../detail/world_texture.h"
#include "../views.h"
#include "palette_state.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/actions.h"

namespace gdpn::ide {

namespace {

/// The highlighted nodes: the selected node, or the node tokens of a selected place.
std::vector<scene::NodeHandle> highlighted(App& app, scene::Scene& s) {
  const auto& sel = app.document().selection();
  if (sel.kind == SelectionKind::Node) {
    const auto* node = s.find(sel.name);
    if (node != nullptr) return {node->handle()};
    return {};
  }
  auto* session = app.run().session();
  if (sel.kind != SelectionKind::Place || session == nullptr) return {};
  const auto& sim = session->simulation();
  const auto p = sim.net().findPlace(sel.name);
  if (!p) return {};
  const auto& place = sim.net().places()[*p];
  // the run's tokens are nodes of the run's plant; before a run, the model's scene is shown:
  // the same nodes found there by path
  const bool same = &s == sim.plant();
  std::vector<scene::NodeHandle> out;
  for (net::PlaceSlotId ps{place.slots_begin}; ps < place.slots_end; ++ps) {
    for (const auto h : sim.kernel().nodes(ps)) {
      if (same) {
        out.push_back(h);
      } else if (const auto* token = sim.plant()->resolve(h)) {
        if (const auto* node = s.find(token->path())) out.push_back(node->handle());
      }
    }
  }
  return out;
}

/// The world view's own row: frame, standard views, the scene's cameras, overlays.
void drawViewBar(App& app, scene::Scene* s) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextColored({0.62F, 0.72F, 0.86F, 1.0F}, "World view");
  ImGui::SameLine(0, 12);
  if (ImGui::Button("Frame")) app.frameSelection();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Frame the selection (the whole scene when none)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  if (ImGui::BeginCombo("##views", "view", ImGuiComboFlags_HeightLarge)) {
    for (auto v : {StandardView::Front, StandardView::Back, StandardView::Left, StandardView::Right, StandardView::Top,
                   StandardView::Iso}) {
      if (ImGui::Selectable(standardViewName(v))) {
        app.world.orbit.look(v);
        app.world.camera_node.clear();
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Standard views");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  if (ImGui::BeginCombo("##camera", app.world.camera_node.empty() ? "free camera" : app.world.camera_node.c_str())) {
    if (ImGui::Selectable("free camera", app.world.camera_node.empty())) app.world.camera_node.clear();
    if (s != nullptr) {
      scene::traverse(s->root(), [&](scene::Node& n, const scene::TraversalState&) {
        if (n.kind() != scene::NodeKind::Camera) return;
        const auto path = n.path();
        if (ImGui::Selectable(path.c_str(), path == app.world.camera_node)) app.world.camera_node = path;
      }, {}, scene::Templates::Skip);
    }
    ImGui::EndCombo();
  }
  // the manipulator of the selected node, and its steps
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  const char* tools[] = {"select", "move", "turn", "scale", "aim"};
  if (ImGui::BeginCombo("##tool", tools[static_cast<int>(app.world.tool)], ImGuiComboFlags_HeightLarge)) {
    for (int i = 0; i < 5; ++i) {
      if (ImGui::Selectable(tools[i], static_cast<int>(app.world.tool) == i)) app.world.tool = static_cast<Tool>(i);
    }
    ImGui::Separator();
    ImGui::Checkbox("snap", &app.world.snap);
    ImGui::SetNextItemWidth(70);
    ImGui::InputDouble("m a step", &app.world.move_step, 0, 0, "%g");
    ImGui::SetNextItemWidth(70);
    ImGui::InputDouble("degrees a step", &app.world.turn_step, 0, 0, "%g");
    app.world.move_step = std::clamp(app.world.move_step, 1e-6, 1e6);
    app.world.turn_step = std::clamp(app.world.turn_step, 1e-6, 360.0);
    ImGui::Checkbox("the node's own axes", &app.world.local_axes);
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("What a drag on the selected node's handles does: move along or turn about an axis; scale a box "
                      "(a Cube, a box Region) by the tabs on its faces and edges; aim a spot light and size its cone (a "
                      "joint's limits always have handles)");
  }
  // what to show: one list, so that the row fits a narrow view
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  if (ImGui::BeginCombo("##show", "show", ImGuiComboFlags_HeightLarge)) {
    ImGui::Checkbox("sensor volumes", &app.world.show_sensors);
    ImGui::Checkbox("joint axes", &app.world.show_joints);
    ImGui::Checkbox("contacts", &app.world.show_contacts);
    ImGui::Checkbox("shadows", &app.world.show_shadows);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Off makes each frame about a third cheaper on a software renderer");
    ImGui::Checkbox("ground grid", &app.world.show_grid);
    ImGui::Checkbox("mini view", &app.world.show_mini);
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Overlays: sensors, joints, contacts; shadows, grid; the mini view");
}

/// The App::show_* switches as bits, for WorldKey.
unsigned shownBits(const App& app) {
  return (app.world.show_sensors ? 1U : 0U) | (app.world.show_joints ? 2U : 0U) | (app.world.show_contacts ? 4U : 0U) |
         (app.world.show_shadows ? 8U : 0U) | (app.world.show_grid ? 16U : 0U);
}

}  // namespace

void drawWorldView(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##world", at, nullptr);
  auto* s = app.shownScene();
  drawViewBar(app, s);
  const auto size = ImGui::GetContentRegionAvail();
  const int w = std::max(16, static_cast<int>(size.x));
  const int h = std::max(16, static_cast<int>(size.y));
  const auto origin = ImGui::GetCursorScreenPos();
  report = {{"size", {w, h}},
            {"camera", app.world.camera_node.empty() ? "free" : app.world.camera_node},
            {"origin", {origin.x, origin.y}},
            {"center", {std::floor(origin.x + static_cast<float>(w) / 2), std::floor(origin.y + static_cast<float>(h) / 2)}}};
  if (s == nullptr || !app.world.renderer) {
    ImGui::TextDisabled("(nothing to draw)");
    endPanel();
    return;
  }
  if (app.run().mode() == RunMode::Edit) scene::updateTransforms(s->root());

  // the camera: a Camera node of the scene, or the orbit camera the mouse moves
  render::Camera camera = app.world.orbit.camera();
  if (!app.world.camera_node.empty()) {
    const auto* node = s->find(app.world.camera_node);
    if (node != nullptr && node->kind() == scene::NodeKind::Camera) camera = render::cameraOf(*node, app.run().time());
  }

  // draw the plant into the texture and show it (at a lower resolution while a slow renderer
  // runs the model: App::worldScale)
  const double scale = app.worldScale();
  const int rw = std::max(16, static_cast<int>(std::lround(w * scale)));
  const int rh = std::max(16, static_cast<int>(std::lround(h * scale)));
  render::DrawOptions options;
  options.width = rw;
  options.height = rh;
  options.sensors = app.world.show_sensors;
  options.shadows = app.world.show_shadows;
  options.joints = app.world.show_joints;
  options.grid = app.world.show_grid;
  options.selection = highlighted(app, *s);
  // contact points are recorded by the run's physics only while they are shown
  physics::World* physics = app.run().session() != nullptr && app.run().mode() != RunMode::Edit
                                ? app.run().session()->simulation().physics()
                                : nullptr;
  if (physics != nullptr) {
    physics->recordContacts(app.world.show_contacts);
    for (const auto& c : physics->contacts()) options.contacts.push_back({c.position, c.normal});
    // the parts' markings: a conveyor's arrows move with the run's time, a visible Region
    // shows when it holds something
    const auto& sim = app.run().session()->simulation();
    options.time = app.run().time();
    options.active = [&sim](const scene::Node& n) { return sim.reading(n.handle()).active; };
  }
  // a part dragged from the palette: the scene with its ghost where it would land, outlined
  const auto ghost = paletteGhost(app, OrbitCamera::from(camera), origin, static_cast<float>(w), static_cast<float>(h));
  if (ghost.scene != nullptr) options.selection = ghost.selection;
  // draw only when something seen changed: the run, the model, the camera, the selection
  WorldKey seen{app.run().steps(), app.run().mode(), app.document().sceneRevision(), camera.eye, camera.target,
                camera.fov, options.selection, rw, rh, shownBits(app), app.run().session(), app.palette().generation};
  if (!(seen == app.world.key) || app.world.stats.draw_calls == 0) {
    // four samples a pixel against jagged edges; none in a lowered picture, already soft
    app.world.texture->begin(rw, rh, scale < 1 ? 1 : 4);
    app.world.stats = app.world.renderer->draw(ghost.scene != nullptr ? *ghost.scene : *s, camera, options);
    app.world.texture->end();
    app.world.key = std::move(seen);
  }
  const auto& stats = app.world.stats;
  ImGui::Image(reinterpret_cast<ImTextureID>(app.world.texture->texture()), {static_cast<float>(w), static_cast<float>(h)},
               {0, 1}, {1, 0});
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton("##world_input", {static_cast<float>(w), static_cast<float>(h)},
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  const bool active = ImGui::IsItemActive();
  // a part dropped from the palette is placed where its ghost stands
  app.world.shown = OrbitCamera::from(camera);
  paletteDrop(app, app.world.shown, origin, static_cast<float>(w), static_cast<float>(h), report);
  auto& io = ImGui::GetIO();
  const auto take_camera = [&] {
    // moving the view leaves a scene camera for the orbit camera at the same place
    if (!app.world.camera_node.empty()) {
      app.world.orbit = OrbitCamera::from(camera);
      app.world.camera_node.clear();
    }
  };

  // the manipulators of the selected node: a drag that starts on a handle edits the node
  const bool manipulating =
      drawManipulators(app, *s, OrbitCamera::from(camera), origin, static_cast<float>(w), static_cast<float>(h), report);

  // orbit, pan, zoom
  if (active && !manipulating && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
      take_camera();
      app.world.orbit.orbit(static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y));
    } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle)) {
      take_camera();
      app.world.orbit.pan(static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y), h);
    }
  }
  if (hovered && io.MouseWheel != 0) {
    take_camera();
    app.world.orbit.zoom(static_cast<double>(io.MouseWheel));
  }

  // a click (no drag): during a run (going or paused) the run gets it as an input event, and a
  // click that a mouse sensor counts operates the plant; any other click picks a shape
  if (hovered && !manipulating && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 16) {
    const auto ray = OrbitCamera::from(camera).ray(static_cast<double>(io.MousePos.x - origin.x),
                                                   static_cast<double>(io.MousePos.y - origin.y), w, h);
    // in a run the world view shows the run's plant, where the run's own pick is the view's
    const auto target = app.run().click(ray);
    std::vector<std::string> felt;
    for (const auto* sensor : target.sensors) felt.push_back(sensor->path());
    const auto hit = app.run().mode() == RunMode::Edit ? scene::pick(s->root(), ray) : target.hit;
    // a click a sensor counts keeps the selection (the run's status line names the sensor)
    if (felt.empty() && hit.shape != nullptr) {
      // a part's shape picks the part
      const auto picked = partPathOf(app, hit.shape->path());
      app.selectNode(picked);
      app.message = "picked " + picked;
    } else if (felt.empty()) {
      app.document().select({});
    }
    report["picked"] = hit.shape != nullptr ? hit.shape->path() : "";
    app.world.clicked = std::move(felt);
  }

  // keys typed over the world view go to the keyboard sensors, with where the viewer is
  auto& was_down = app.world.key_was_down;
  auto& last_eye = app.world.last_eye;
  if (hovered && (camera.eye - last_eye).length() > 1e-9) {
    sensors::InputEvent view;
    view.t = app.run().time();
    view.kind = sensors::InputEvent::Kind::Viewpoint;
    view.position = camera.eye;
    app.run().push(view);
    last_eye = camera.eye;
  }
  for (const auto& [code, name] : sensorKeys()) {
    const bool down = io.KeysDown[code];
    if (down != was_down[static_cast<std::size_t>(code)] && (hovered || !down) && !io.WantTextInput) {
      sensors::InputEvent key;
      key.t = app.run().time();
      key.kind = sensors::InputEvent::Kind::Key;
      key.key = name;
      key.down = down;
      app.run().push(key);
      if (down) app.world.pressed_keys.push_back(name);
    }
    was_down[static_cast<std::size_t>(code)] = down;
  }
  endPanel();

  const auto eye = camera.eye;
  report["eye"] = {eye.x, eye.y, eye.z};
  report["target"] = {camera.target.x, camera.target.y, camera.target.z};
  report["triangles"] = stats.triangles;
  report["highlighted"] = !options.selection.empty();
  report["highlighted_nodes"] = options.selection.size();
  report["keys"] = app.world.pressed_keys;
  report["clicked"] = app.world.clicked;
  report["sensors"] = app.world.show_sensors;
  report["joints"] = app.world.show_joints;
  report["contacts"] = options.contacts.size();
  report["shadows"] = app.world.show_shadows;
  report["grid"] = app.world.show_grid;
  report["scale"] = scale;
}

}  // namespace gdpn::ide
