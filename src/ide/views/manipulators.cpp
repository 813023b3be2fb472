// The manipulators over the world view (edit mode): arrows that move the selected Transform
// along an axis, rings that turn it about one, the limits of a selected Joint, tabs that size a
// box (the dissertation's manipulator A), and a spot light's direction and cone (its E); each
// drag one undoable step through SetFieldCommand, in snapped steps when snapping is on.

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "../views.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/scene/actions.h"
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
  std::string name;                  // its key in the report
  ScaleTab tab{};                    // scale tabs: which one
  core::Vec3 point;                  // aims: a point of the drag's plane (world)
  core::Quat frame;                  // scale tabs: the box's rotation; aims: the light's parent's
  core::Vec3 scale{1, 1, 1};         // scale tabs: the scale of the box's parents
  bool round = false;                // drawn as a dot (else a point handle is a square)
  bool named = false;                // its label shown even when the pointer is elsewhere
};

/// A line drawn to explain the handles, not grabbed: a box's outline, a spot light's cone.
struct Guide {
  std::vector<ImVec2> line;  // screen points
  ImU32 colour = 0;
};

/// The handles of the selected node, the lines around them, and the point they act about.
struct Handles {
  std::vector<HandleShape> shapes;
  std::vector<Guide> guides;
  std::optional<core::Vec3> pivot;  // world
};

const std::array<ImU32, 3> kAxisColours = {IM_COL32(230, 60, 60, 255), IM_COL32(70, 200, 70, 255),
                                           IM_COL32(70, 120, 240, 255)};

/// The box's own axis `i` (0, 1, 2) in the world.
core::Vec3 axisOf(const core::Quat& rotation, std::size_t i) {
  return rotation.rotate({i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
}

/// Whether `node` is a box the scale tool sizes: a Cube, or a Region of shape box.
/// The Body a joint moves, as the physics finds it: the first Body below the joint (Transforms
/// may place it) that is no template and not inside another Body; null when there is none.
const scene::Node* jointBody(const scene::Node& joint) {
  std::vector<const scene::Node*> todo;
  for (auto it = joint.children().rbegin(); it != joint.children().rend(); ++it) todo.push_back(it->get());
  while (!todo.empty()) {
    const scene::Node* c = todo.back();
    todo.pop_back();
    if (c->is_template) continue;
    if (c->kind() == scene::NodeKind::Body) return c;
    for (auto it = c->children().rbegin(); it != c->children().rend(); ++it) todo.push_back(it->get());
  }
  return nullptr;
}

bool isBox(const scene::Node& node) {
  return node.kind() == scene::NodeKind::Cube ||
         (node.kind() == scene::NodeKind::Region &&
          node.choice<scene::RegionShape>(scene::field::Region::Shape) == scene::RegionShape::Box);
}

/// A box's edge lengths (m, before the scale above it).
core::Vec3 boxSize(const scene::Node& node) {
  return node.kind() == scene::NodeKind::Cube ? node.vec3(scene::field::Cube::Size) : node.vec3(scene::field::Region::Size);
}

/// `x` in metres or degrees as a label shows it ("0.8", "1.25").
std::string shortNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

/// The label of a scale tab: the axes it scales and their lengths ("+x+y: 0.8 x 1.2 m").
std::string tabLabel(const ScaleTab& tab, const core::Vec3& size) {
  const std::array<double, 3> s = {size.x, size.y, size.z};
  std::string lengths;
  for (std::size_t i = 0; i < 3; ++i) {
    if (tab[i] != 0) lengths += (lengths.empty() ? "" : " x ") + shortNumber(s[i]);
  }
  return scaleTabName(tab).substr(6) + ": " + lengths + " m";
}

/// The handles of the selected node: moves or turns for a Transform, limits for a Joint, tabs
/// for a box, direction and cone for a spot light.
Handles handlesOf(App& app, scene::Node& node, const OrbitCamera& view, ImVec2 at, float w, float h) {
  Handles handles;
  auto& out = handles.shapes;
  const auto screen = [&](const core::Vec3& p) -> std::optional<ImVec2> {
    const auto q = view.project(p, static_cast<double>(w), static_cast<double>(h));
    if (!q) return std::nullopt;
    return ImVec2{at.x + static_cast<float>((*q)[0]), at.y + static_cast<float>((*q)[1])};
  };
  // node.world is the frame the node is placed in (its parents'); its own frame adds its pose
  const core::Pose pose = node.framePose();
  const double size = 0.16 * (view.eye() - pose.position).length();
  const core::Quat parent = node.world.rotation;
  const core::Vec3 forward = (view.target - view.eye()).normalized();
  if (node.kind() == scene::NodeKind::Transform && (app.world.tool == Tool::Move || app.world.tool == Tool::Turn)) {
    handles.pivot = pose.position;
    for (int i = 0; i < 3; ++i) {
      core::Vec3 e{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
      const core::Vec3 axis = app.world.local_axes ? pose.rotation.rotate(e) : e;
      HandleShape s;
      s.colour = kAxisColours[static_cast<std::size_t>(i)];
      s.origin = pose.position;
      s.axis = axis;
      s.reference = perpendicular(axis);
      s.parent_axis = parent.conjugate().rotate(axis);
      if (app.world.tool == Tool::Move) {
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
    if (!slider && !hinge) return handles;
    // a hinge turns about its anchor; a slider has none (the physics ignores it): its limits
    // are offsets of its body from where the body stands now, so they are drawn from there
    const auto* body = slider ? jointBody(node) : nullptr;
    const core::Vec3 anchor = body != nullptr ? body->framePose().position : pose.apply(node.vec3(scene::field::Joint::Anchor));
    handles.pivot = anchor;
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
      s.named = true;
      out.push_back(std::move(s));
    }
  }
  // a box: its outline, and a tab on each face and edge the view can drag (the box's own axes)
  if (isBox(node) && app.world.tool == Tool::Scale) {
    const core::Vec3 half = boxSize(node).times(node.world_scale) * 0.5;
    const auto corner = [&](double x, double y, double z) { return pose.apply({x * half.x, y * half.y, z * half.z}); };
    handles.pivot = pose.position;
    for (std::size_t a = 0; a < 3; ++a) {
      // the four edges along axis a, at the corners (u, v) of the other two
      for (const auto& [u, v] : {std::pair{-1.0, -1.0}, std::pair{-1.0, 1.0}, std::pair{1.0, -1.0}, std::pair{1.0, 1.0}}) {
        std::array<double, 3> from{}, to{};
        from[a] = -1.0;
        to[a] = 1.0;
        from[(a + 1) % 3] = to[(a + 1) % 3] = u;
        from[(a + 2) % 3] = to[(a + 2) % 3] = v;
        const auto q0 = screen(corner(from[0], from[1], from[2])), q1 = screen(corner(to[0], to[1], to[2]));
        if (q0 && q1) handles.guides.push_back({{*q0, *q1}, IM_COL32(250, 250, 250, 230)});
      }
    }
    for (const auto& tab : scaleTabs()) {
      if (!scaleTabShown(tab, pose.rotation, forward)) continue;
      const auto q = screen(corner(tab[0], tab[1], tab[2]));
      if (!q) continue;
      HandleShape s;
      s.handle = Handle::Scale;
      s.tab = tab;
      s.name = scaleTabName(tab);
      s.field = "size";
      s.origin = corner(tab[0], tab[1], tab[2]);
      s.frame = pose.rotation;
      s.scale = node.world_scale;
      // a face tab is dragged along its axis, an edge tab in the plane of its two axes
      const int axes = (tab[0] != 0) + (tab[1] != 0) + (tab[2] != 0);
      for (std::size_t i = 0; i < 3; ++i) {
        if ((axes == 1) == (tab[i] != 0)) s.axis = axisOf(pose.rotation, i);
        if (axes == 1 && tab[i] != 0) s.colour = kAxisColours[i];
      }
      if (axes == 2) s.colour = IM_COL32(245, 245, 245, 255);
      s.line = {*q};
      s.grab = *q;
      out.push_back(std::move(s));
    }
  }
  // a spot light: the beam's axis ending in the aim handle, the cone's outline with its handle
  if (node.kind() == scene::NodeKind::Light && app.world.tool == Tool::Aim &&
      node.choice<scene::LightKind>(scene::field::Light::Kind) == scene::LightKind::Spot) {
    const core::Vec3 apex = node.world.apply(node.vec3(scene::field::Light::Location));
    const core::Vec3 axis = node.world.rotation.rotate(node.vec3(scene::field::Light::Direction)).normalized();
    if (axis.length() == 0) return handles;
    handles.pivot = apex;
    const double reach = 0.2 * (view.eye() - apex).length();  // the cone's slant, m
    const double cutoff = node.number(scene::field::Light::Cutoff) * kPi / 180;
    const core::Vec3 side = coneSide(axis, forward), other = axis.cross(side);
    const auto a = screen(apex), tip = screen(apex + axis * (1.4 * reach));
    const auto rim = [&](double t) {
      return apex + (axis * std::cos(cutoff) + (side * std::cos(t) + other * std::sin(t)) * std::sin(cutoff)) * reach;
    };
    Guide ring{{}, IM_COL32(255, 220, 90, 230)};
    for (int k = 0; k <= 48; ++k) {
      if (const auto p = screen(rim(2 * kPi * k / 48))) ring.line.push_back(*p);
    }
    if (ring.line.size() == 49) handles.guides.push_back(std::move(ring));
    for (const double t : {0.0, kPi}) {
      if (const auto p = screen(rim(t)); a && p) handles.guides.push_back({{*a, *p}, IM_COL32(255, 220, 90, 230)});
    }
    if (a && tip) {
      handles.guides.push_back({{*a, *tip}, IM_COL32(255, 220, 90, 255)});
      HandleShape s;
      s.handle = Handle::Aim;
      s.name = handleName(Handle::Aim);
      s.field = "direction";
      s.origin = apex;
      s.axis = forward;  // dragged in the plane through the handle facing the view
      s.point = apex + axis * (1.4 * reach);
      s.frame = node.world.rotation;
      s.colour = IM_COL32(255, 210, 40, 255);
      s.line = {*tip};
      s.grab = *tip;
      s.round = true;
      s.named = true;
      out.push_back(std::move(s));
    }
    if (const auto q = screen(rim(0))) {
      HandleShape s;
      s.handle = Handle::Cone;
      s.name = handleName(Handle::Cone);
      s.field = "cutoff";
      s.origin = apex;
      s.axis = axis;
      s.reference = side;
      s.colour = IM_COL32(255, 150, 0, 255);
      s.line = {*q};
      s.grab = *q;
      s.named = true;
      out.push_back(std::move(s));
    }
  }
  for (auto& s : out) {
    if (s.name.empty()) s.name = handleName(s.handle);
  }
  return handles;
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

/// Where a scale tab's drag stands now (world, m): on the line along a face tab's axis, in
/// the plane of an edge tab's two axes.
std::optional<core::Vec3> tabPoint(const core::Ray& ray, const ManipulatorDrag& d) {
  const int axes = (d.tab[0] != 0) + (d.tab[1] != 0) + (d.tab[2] != 0);
  if (axes == 2) return onPlane(ray, d.origin, d.axis);
  const auto t = alongAxis(ray, d.origin, d.axis);
  if (!t) return std::nullopt;
  return d.origin + d.axis * *t;
}

/// The name of the tool in the report.
const char* toolName(Tool tool) {
  switch (tool) {
    case Tool::Select: return "select";
    case Tool::Move: return "move";
    case Tool::Turn: return "turn";
    case Tool::Scale: return "scale";
    case Tool::Aim: return "aim";
  }
  return "";
}

/// Whether handle `s` is the one dragged in `d`.
bool dragged(const HandleShape& s, const ManipulatorDrag& d) {
  return s.handle == d.handle && (s.handle != Handle::Scale || s.tab == d.tab);
}

/// `text` at `p` with a dark shadow, legible on a light ground and a dark one.
void outlinedText(ImDrawList* list, ImVec2 p, ImU32 colour, const std::string& text) {
  list->AddText({p.x + 1, p.y + 1}, IM_COL32(20, 20, 20, 255), text.c_str());
  list->AddText(p, colour, text.c_str());
}

bool isSlider(const scene::Node& node) {
  return node.kind() == scene::NodeKind::Joint &&
         node.choice<scene::JointKind>(scene::field::Joint::Kind) == scene::JointKind::Slider;
}

}  // namespace

bool drawManipulators(App& app, scene::Scene& scene, const OrbitCamera& view, ImVec2 at, float w, float h,
                      nlohmann::json& report) {
  auto& drag = app.world.manipulating;
  const auto& sel = app.document().selection();
  scene::Node* node = sel.kind == SelectionKind::Node && app.run().mode() == RunMode::Edit ? scene.find(sel.name) : nullptr;
  report["tool"] = toolName(app.world.tool);
  if (node == nullptr) {
    drag = {};
    return false;
  }
  const auto handles = handlesOf(app, *node, view, at, w, h);
  const auto& shapes = handles.shapes;
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
      drag.point = best->point;
      drag.frame = best->frame;
      drag.scale = best->scale;
      drag.tab = best->tab;
      drag.value = node->value(static_cast<std::size_t>(node->type().fieldIndex(best->field)));
      if (drag.handle == Handle::Scale) {
        drag.point = tabPoint(ray, drag).value_or(drag.origin);
      } else if (drag.handle != Handle::Aim && drag.handle != Handle::Cone) {
        drag.start = measure(drag.handle, ray, drag, slider).value_or(0.0);
      }
      drag.id = ++app.inspector.drag_id;
    }
  }
  bool took = drag.handle != Handle::None;
  if (took && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    // a spot's handles set absolute values: a press alone (no move yet) changes nothing
    const bool moved = ImGui::GetIO().MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] >= 1.0F;
    const auto now = drag.handle == Handle::Scale || drag.handle == Handle::Aim || drag.handle == Handle::Cone
                         ? std::optional<double>{0.0}
                         : measure(drag.handle, ray, drag, slider);
    if (now) {
      std::optional<scene::FieldValue> value;
      switch (drag.handle) {
        case Handle::MoveX:
        case Handle::MoveY:
        case Handle::MoveZ: {
          const double d = app.world.snap ? snapTo(*now - drag.start, app.world.move_step) : *now - drag.start;
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
          if (app.world.snap) d = snapTo(d, app.world.turn_step);
          value = turned(std::get<std::array<double, 4>>(drag.value), drag.parent_axis, d);
          break;
        }
        case Handle::Lo1:
        case Handle::Hi1: value = app.world.snap ? snapTo(*now, slider ? app.world.move_step : app.world.turn_step) : *now; break;
        case Handle::Scale: {
          // the move since the press, along the box's own axes
          if (const auto p = tabPoint(ray, drag)) {
            const core::Vec3 moved_by = drag.frame.conjugate().rotate(*p - drag.point);
            value = scaledSize(std::get<std::array<double, 3>>(drag.value), drag.tab, moved_by, drag.scale,
                               app.world.snap ? app.world.move_step : 0.0);
          }
          break;
        }
        case Handle::Aim: {
          // toward the shape under the pointer, else toward the pointer in the dot's plane facing
          // the view; written in the light's parent's frame
          const auto hit = scene::pick(scene.root(), ray);
          const auto toward = !moved                 ? std::nullopt
                              : hit.shape != nullptr ? aimToward(drag.origin, ray.origin + ray.direction * hit.distance)
                                                     : aimAt(ray, drag.origin, drag.point, drag.axis);
          if (toward) {
            core::Vec3 d = drag.frame.conjugate().rotate(*toward);
            d = app.world.snap ? snapDirection(d, app.world.turn_step) : d.normalized();
            value = std::array<double, 3>{d.x, d.y, d.z};
          }
          break;
        }
        case Handle::Cone: {
          if (const auto angle = moved ? coneAngle(ray, drag.origin, drag.axis, drag.reference) : std::nullopt) {
            value = std::clamp(app.world.snap ? snapTo(*angle, app.world.turn_step) : *angle, 0.0, 90.0);
          }
          break;
        }
        case Handle::None: break;
      }
      if (value && *value != node->value(static_cast<std::size_t>(node->type().fieldIndex(drag.field)))) {
        const auto why = app.document().execute(manipulatorCommand(app, drag.path, drag.field, *value, drag.id));
        app.inspector.error = why;
        if (!why.empty()) app.message = why;
      }
    }
  } else if (took) {
    // released: the drag is one step
    app.document().history().seal();
    drag = {};
  }

  // the lines around the handles, then the handles over the picture; a joint's range as a line
  // between its limits
  ImDrawList* list = ImGui::GetWindowDrawList();
  for (const auto& g : handles.guides) {
    list->AddPolyline(g.line.data(), static_cast<int>(g.line.size()), IM_COL32(20, 20, 20, 150), 0, 3.0F);
    list->AddPolyline(g.line.data(), static_cast<int>(g.line.size()), g.colour, 0, 1.5F);
  }
  if (shapes.size() == 2 && shapes[0].handle == Handle::Lo1 && shapes[1].handle == Handle::Hi1) {
    list->AddLine(shapes[0].line[0], shapes[1].line[0], IM_COL32(255, 170, 0, 200), 2.0F);
  }
  nlohmann::json grabs = nlohmann::json::object();
  const HandleShape* hot_shape = nullptr;
  for (const auto& s : shapes) {
    const bool hot = dragged(s, drag) || (drag.handle == Handle::None && distanceTo(s.line, mouse) < kGrab);
    if (hot) hot_shape = &s;
    const float thick = hot ? 4.0F : 2.5F;
    if (s.line.size() == 1) {
      // a point handle: a dot or a square (outlined, legible on a light ground and a dark one)
      const ImVec2 p = s.line[0];
      const float r = hot ? 7.0F : 5.0F;
      if (s.round) {
        list->AddCircleFilled(p, r + 1, s.colour);
        list->AddCircle(p, r + 1, IM_COL32(40, 30, 0, 255), 0, 1.5F);
      } else {
        list->AddRectFilled({p.x - r, p.y - r}, {p.x + r, p.y + r}, s.colour);
        list->AddRect({p.x - r, p.y - r}, {p.x + r, p.y + r}, IM_COL32(40, 30, 0, 255), 0, 0, 1.5F);
      }
    } else {
      list->AddPolyline(s.line.data(), static_cast<int>(s.line.size()), s.colour, 0, thick);
      if (s.line.size() == 2) list->AddCircleFilled(s.line[1], hot ? 6.0F : 4.5F, s.colour);
    }
    grabs[s.name] = {std::lround(s.grab.x), std::lround(s.grab.y)};
  }
  // the labels: a limit's, a spot's always; a scale tab's while it is under the pointer or dragged
  for (const auto& s : shapes) {
    const bool hot = &s == hot_shape;
    if (!s.named && !hot) continue;
    std::string label;
    switch (s.handle) {
      case Handle::Scale: label = tabLabel(s.tab, boxSize(*node)); break;
      case Handle::Aim: label = "direction"; break;
      case Handle::Cone: label = "cone " + shortNumber(node->number(scene::field::Light::Cutoff)) + " deg"; break;
      case Handle::Lo1:
      case Handle::Hi1: label = s.field; break;
      case Handle::None:
      case Handle::MoveX:
      case Handle::MoveY:
      case Handle::MoveZ:
      case Handle::TurnX:
      case Handle::TurnY:
      case Handle::TurnZ: break;
    }
    if (label.empty()) continue;
    if (hot) label += " (drag)";
    const ImVec2 p = s.line[0];
    outlinedText(list, {p.x + 9, p.y - 7}, s.colour, label);
  }
  report["handles"] = grabs;
  // the point the handles act about, where a replay can drag one back to
  if (handles.pivot) {
    if (const auto q = view.project(*handles.pivot, static_cast<double>(w), static_cast<double>(h))) {
      report["pivot"] = {std::lround(at.x + static_cast<float>((*q)[0])), std::lround(at.y + static_cast<float>((*q)[1]))};
    }
  }
  report["manipulating"] = drag.handle == Handle::Scale ? scaleTabName(drag.tab) : handleName(drag.handle);
  return took;
}

}  // namespace gdpn::ide
