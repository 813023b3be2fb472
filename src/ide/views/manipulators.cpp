// The manipulators over the world view (edit mode): arrows that move the selected Transform
// along an axis, rings that turn it about one, and the limits of a selected Joint, each drag
// one undoable step through SetFieldCommand, in snapped steps when snapping is on.

#include <imgui.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "../views.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/scene/fields.h"

namespace gdpn::ide {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kGrab = 8.0F;  // pixels from a handle that still grab it

/// A handle as drawn: its screen polyline and where the drag acts in the world.
struct HandleShape {
  Handle handle = Handle::None;
  std::vector<ImVec2> line;  // screen points (one: a point handle)
  ImU32 colour = 0;
  std::string field;                 // the field the drag edits
  core::Vec3 origin, axis, reference;  // world
  core::Vec3 parent_axis;            // moves and turns: the axis in the parent's frame
  ImVec2 grab;                       // where a replay grabs it
};

const std::array<ImU32, 3> kAxisColours = {IM_COL32(230, 60, 60, 255), IM_COL32(70, 200, 70, 255),
                                           IM_COL32(70, 120, 240, 255)};

/// The handles of the selected node: moves or turns for a Transform, limits for a Joint.
std::vector<HandleShape> handlesOf(App& app, scene::Node& node, const OrbitCamera& view, ImVec2 at, float w, float h) {
  std::vector<HandleShape> out;
  const auto screen = [&](const core::Vec3& p) -> std::optional<ImVec2> {
    const auto q = view.project(p, static_cast<double>(w), static_cast<double>(h));
    if (!q) return std::nullopt;
    return ImVec2{at.x + static_cast<float>((*q)[0]), at.y + static_cast<float>((*q)[1])};
  };
  // node.world is the frame the node is placed in (its parents'); its own frame adds its pose
  const core::Pose pose = node.framePose();
  const double size = 0.16 * (view.eye() - pose.position).length();
  const core::Quat parent = node.world.rotation;
  if (node.kind() == scene::NodeKind::Transform && app.tool != Tool::Select) {
    for (int i = 0; i < 3; ++i) {
      core::Vec3 e{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
      const core::Vec3 axis = app.local_axes ? pose.rotation.rotate(e) : e;
      HandleShape s;
      s.colour = kAxisColours[static_cast<std::size_t>(i)];
      s.origin = pose.position;
      s.axis = axis;
      s.reference = perpendicular(axis);
      s.parent_axis = parent.conjugate().rotate(axis);
      if (app.tool == Tool::Move) {
        s.handle = static_cast<Handle>(static_cast<int>(Handle::MoveX) + i);
        s.field = "translation";
        const auto a = screen(pose.position), b = screen(pose.position + axis * size);
        if (!a || !b) continue;
        s.line = {*a, *b};
        s.grab = *b;
      } else {
        s.handle = static_cast<Handle>(static_cast<int>(Handle::TurnX) + i);
        s.field = "rotation";
        const core::Vec3 side = axis.cross(s.reference);
        for (int k = 0; k <= 48; ++k) {
          const double t = 2 * kPi * k / 48;
          if (auto p = screen(pose.position + (s.reference * std::cos(t) + side * std::sin(t)) * size)) s.line.push_back(*p);
        }
        if (s.line.size() < 49) continue;
        s.grab = s.line[6];  // 45 degrees round
      }
      out.push_back(std::move(s));
    }
  }
  if (node.kind() == scene::NodeKind::Joint) {
    const auto kind = node.choice<scene::JointKind>(scene::field::Joint::Kind);
    const bool slider = kind == scene::JointKind::Slider, hinge = kind == scene::JointKind::Hinge;
    if (!slider && !hinge) return out;
    const core::Vec3 anchor = pose.apply(node.vec3(scene::field::Joint::Anchor));
    const core::Vec3 axis = pose.rotation.rotate(node.vec3(scene::field::Joint::Axis1)).normalized();
    const core::Vec3 reference = perpendicular(axis), side = axis.cross(reference);
    for (const auto& [handle, id, field] : {std::tuple{Handle::Lo1, scene::field::Joint::Lo1, "lo1"},
                                            std::tuple{Handle::Hi1, scene::field::Joint::Hi1, "hi1"}}) {
      const double v = node.number(id);
      if (!std::isfinite(v)) continue;
      const core::Vec3 p = slider ? anchor + axis * v
                                  : anchor + (reference * std::cos(v * kPi / 180) + side * std::sin(v * kPi / 180)) * size;
      const auto q = screen(p);
      if (!q) continue;
      HandleShape s;
      s.handle = handle;
      s.field = field;
      s.origin = anchor;
      s.axis = axis;
      s.reference = reference;
      s.colour = IM_COL32(255, 170, 0, 255);
      s.line = {*q};
      s.grab = *q;
      out.push_back(std::move(s));
    }
  }
  return out;
}

/// Distance in pixels from `p` to the polyline (or point) `line`.
float distanceTo(const std::vector<ImVec2>& line, ImVec2 p) {
  float best = 1e9F;
  const auto d2 = [](ImVec2 a, ImVec2 b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); };
  if (line.size() == 1) return std::sqrt(d2(line[0], p));
  for (std::size_t i = 1; i < line.size(); ++i) {
    const ImVec2 a = line[i - 1], b = line[i];
    const float len2 = d2(a, b);
    float t = len2 > 0 ? ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / len2 : 0.0F;
    t = std::fmax(0.0F, std::fmin(1.0F, t));
    best = std::fmin(best, std::sqrt(d2(p, {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t})));
  }
  return best;
}

/// Where the drag stands now, in the handle's measure: along the axis (m) or the angle (deg).
std::optional<double> measure(Handle h, const core::Ray& ray, const ManipulatorDrag& d, bool slider) {
  const bool along = h == Handle::MoveX || h == Handle::MoveY || h == Handle::MoveZ ||
                     ((h == Handle::Lo1 || h == Handle::Hi1) && slider);
  return along ? alongAxis(ray, d.origin, d.axis) : angleAbout(ray, d.origin, d.axis, d.reference);
}

bool isSlider(const scene::Node& node) {
  return node.kind() == scene::NodeKind::Joint &&
         node.choice<scene::JointKind>(scene::field::Joint::Kind) == scene::JointKind::Slider;
}

}  // namespace

bool drawManipulators(App& app, scene::Scene& scene, const OrbitCamera& view, ImVec2 at, float w, float h,
                      nlohmann::json& report) {
  auto& drag = app.manipulating;
  const auto& sel = app.document().selection();
  scene::Node* node = sel.kind == SelectionKind::Node && app.run().mode() == RunMode::Edit ? scene.find(sel.name) : nullptr;
  report["tool"] = app.tool == Tool::Move ? "move" : app.tool == Tool::Turn ? "turn" : "select";
  if (node == nullptr) {
    drag = {};
    return false;
  }
  const auto shapes = handlesOf(app, *node, view, at, w, h);
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const auto ray = view.ray(static_cast<double>(mouse.x - at.x), static_cast<double>(mouse.y - at.y), static_cast<double>(w),
                            static_cast<double>(h));
  const bool slider = isSlider(*node);

  // a press on a handle starts a drag (the world view's button was just pressed)
  if (drag.handle == Handle::None && ImGui::IsItemActivated() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const HandleShape* best = nullptr;
    float nearest = kGrab;
    for (const auto& s : shapes) {
      const float d = distanceTo(s.line, mouse);
      if (d < nearest) {
        nearest = d;
        best = &s;
      }
    }
    if (best != nullptr) {
      drag.handle = best->handle;
      drag.path = sel.name;
      drag.field = best->field;
      drag.origin = best->origin;
      drag.axis = best->axis;
      drag.reference = best->reference;
      drag.parent_axis = best->parent_axis;
      drag.value = node->value(static_cast<std::size_t>(node->type().fieldIndex(best->field)));
      drag.start = measure(drag.handle, ray, drag, slider).value_or(0.0);
      drag.id = ++app.drag_id;
    }
  }
  bool took = drag.handle != Handle::None;
  if (took && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    if (const auto now = measure(drag.handle, ray, drag, slider)) {
      std::optional<scene::FieldValue> value;
      switch (drag.handle) {
        case Handle::MoveX:
        case Handle::MoveY:
        case Handle::MoveZ: {
          const double d = app.snap ? snapTo(*now - drag.start, app.move_step) : *now - drag.start;
          // the move along the axis goes in whole steps; the translation is in the parent's frame
          auto t = std::get<std::array<double, 3>>(drag.value);
          t[0] += drag.parent_axis.x * d;
          t[1] += drag.parent_axis.y * d;
          t[2] += drag.parent_axis.z * d;
          value = t;
          break;
        }
        case Handle::TurnX:
        case Handle::TurnY:
        case Handle::TurnZ: {
          double d = std::remainder(*now - drag.start, 360.0);
          if (app.snap) d = snapTo(d, app.turn_step);
          value = turned(std::get<std::array<double, 4>>(drag.value), drag.parent_axis, d);
          break;
        }
        case Handle::Lo1:
        case Handle::Hi1: value = app.snap ? snapTo(*now, slider ? app.move_step : app.turn_step) : *now; break;
        case Handle::None: break;
      }
      if (value && *value != node->value(static_cast<std::size_t>(node->type().fieldIndex(drag.field)))) {
        const auto why = app.document().execute(std::make_unique<SetFieldCommand>(drag.path, drag.field, *value, drag.id));
        app.inspector_error = why;
        if (!why.empty()) app.message = why;
      }
    }
  } else if (took) {
    // released: the drag is one step
    app.document().history().seal();
    drag = {};
  }

  // the handles, over the picture; a joint's range as a line between its limits
  ImDrawList* list = ImGui::GetWindowDrawList();
  if (shapes.size() == 2 && shapes[0].line.size() == 1 && shapes[1].line.size() == 1) {
    list->AddLine(shapes[0].line[0], shapes[1].line[0], IM_COL32(255, 170, 0, 200), 2.0F);
  }
  nlohmann::json grabs = nlohmann::json::object();
  for (const auto& s : shapes) {
    const bool hot = s.handle == drag.handle || (drag.handle == Handle::None && distanceTo(s.line, mouse) < kGrab);
    const float thick = hot ? 4.0F : 2.5F;
    if (s.line.size() == 1) {
      // a limit: a square with its name (outlined, legible on a light ground and a dark one)
      const ImVec2 p = s.line[0];
      list->AddRectFilled({p.x - 5, p.y - 5}, {p.x + 5, p.y + 5}, s.colour);
      list->AddRect({p.x - 5, p.y - 5}, {p.x + 5, p.y + 5}, IM_COL32(40, 30, 0, 255));
      const auto label = s.field + (hot ? " (drag)" : "");
      list->AddText({p.x + 8, p.y - 6}, IM_COL32(20, 20, 20, 255), label.c_str());
      list->AddText({p.x + 7, p.y - 7}, s.colour, label.c_str());
    } else {
      list->AddPolyline(s.line.data(), static_cast<int>(s.line.size()), s.colour, 0, thick);
      if (s.line.size() == 2) list->AddCircleFilled(s.line[1], hot ? 6.0F : 4.5F, s.colour);
    }
    grabs[handleName(s.handle)] = {std::lround(s.grab.x), std::lround(s.grab.y)};
  }
  report["handles"] = grabs;
  // the point the handles act about, where a replay can drag one back to
  if (!shapes.empty()) {
    if (const auto q = view.project(shapes.front().origin, static_cast<double>(w), static_cast<double>(h))) {
      report["pivot"] = {std::lround(at.x + static_cast<float>((*q)[0])), std::lround(at.y + static_cast<float>((*q)[1]))};
    }
  }
  report["manipulating"] = handleName(drag.handle);
  return took;
}

}  // namespace gdpn::ide
