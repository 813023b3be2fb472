#include "gdpn/sensors/hub.h"

#include <algorithm>
#include <cmath>

#include "gdpn/scene/actions.h"

namespace gdpn::sensors {
namespace {

const scene::Node* bodyAbove(const scene::Node& n) {
  for (const scene::Node* p = n.parent(); p; p = p->parent()) {
    if (p->kind() == scene::NodeKind::Body) return p;
  }
  return nullptr;
}

/// The field a GradientSensor reads: the one its `field` names, or the scene's first.
const scene::Node* fieldOf(const scene::Scene& scene, const scene::Node& sensor) {
  const std::string& path = sensor.text(scene::field::GradientSensor::Field);
  if (!path.empty()) {
    const scene::Node* f = scene.find(path);
    return f && f->kind() == scene::NodeKind::GradientField ? f : nullptr;
  }
  const scene::Node* first = nullptr;
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (!first && n.kind() == scene::NodeKind::GradientField) first = &n;
  }, {}, scene::Templates::Skip);
  return first;
}

/// The field's vector at world point `p`: bilinear between grid points, held at the edges.
core::Vec3 sample(const scene::Node& field, core::Vec3 p) {
  const core::Vec3 q = field.world.inverse().apply(p);
  using F = scene::field::GradientField;
  const double w = field.number(F::Width), d = field.number(F::Depth);
  const auto nx = static_cast<std::size_t>(field.number(F::Nx)), ny = static_cast<std::size_t>(field.number(F::Ny));
  const auto& v = std::get<std::vector<double>>(field.value(F::Vectors));
  const double u = std::clamp((q.x + w / 2) / w, 0.0, 1.0) * static_cast<double>(nx - 1);
  const double t = std::clamp((q.y + d / 2) / d, 0.0, 1.0) * static_cast<double>(ny - 1);
  const auto i = std::min(static_cast<std::size_t>(u), nx - 2), j = std::min(static_cast<std::size_t>(t), ny - 2);
  const double fu = u - static_cast<double>(i), ft = t - static_cast<double>(j);
  auto at = [&](std::size_t a, std::size_t b, int c) { return v[(b * nx + a) * 2 + static_cast<std::size_t>(c)]; };
  core::Vec3 out;
  for (int c = 0; c < 2; ++c) {
    const double value = (1 - fu) * (1 - ft) * at(i, j, c) + fu * (1 - ft) * at(i + 1, j, c) +
                         (1 - fu) * ft * at(i, j + 1, c) + fu * ft * at(i + 1, j + 1, c);
    (c == 0 ? out.x : out.y) = value;
  }
  return field.world.rotation.rotate(out);
}

}  // namespace

bool Hub::check(const scene::Scene& scene, core::Diagnostics& diags) {
  bool ok = true;
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (n.kind() != scene::NodeKind::GradientSensor) return;
    if (!bodyAbove(n)) {
      diags.error(n.loc, "a GradientSensor samples the field where its body is, but '" + n.path() +
                             "' has no Body above it");
      ok = false;
    }
    if (!fieldOf(scene, n)) {
      diags.error(n.loc, "GradientSensor '" + n.path() + "' finds no GradientField to read" +
                             (n.text(scene::field::GradientSensor::Field).empty()
                                  ? ""
                                  : " at '" + n.text(scene::field::GradientSensor::Field) + "'"));
      ok = false;
    }
  }, {}, scene::Templates::Skip);
  return ok;
}

Hub::Hub(scene::Scene& scene, physics::World* world) : scene_(scene), world_(world) {
  scene::traverse(scene_.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (n.type().category == scene::Category::Sensor) entries_.push_back({&n, {}});
  }, {}, scene::Templates::Skip);
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.node->path() < b.node->path(); });
}

Hub::Entry* Hub::find(scene::NodeHandle h) {
  for (auto& e : entries_) {
    if (e.node->handle() == h) return &e;
  }
  return nullptr;
}

void Hub::push(InputEvent event) {
  // the events delivered are done with; among the pending, after those not later than it
  input_.erase(input_.begin(), input_.begin() + static_cast<std::ptrdiff_t>(next_input_));
  next_input_ = 0;
  const auto at = std::upper_bound(input_.begin(), input_.end(), event.t,
                                   [](double t, const InputEvent& e) { return t < e.t; });
  input_.insert(at, std::move(event));
}

bool Hub::mayChange() const {
  if (next_input_ < input_.size()) return true;
  return std::any_of(entries_.begin(), entries_.end(), [](const Entry& e) { return e.node->kind() == scene::NodeKind::TimeSensor; });
}

bool Hub::isSensor(scene::NodeHandle node) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.node->handle() == node; });
}

const Reading& Hub::reading(scene::NodeHandle sensor) const {
  static const Reading none;
  for (const auto& e : entries_) {
    if (e.node->handle() == sensor) return e.reading;
  }
  return none;
}

bool Hub::read(const Entry& e, double now, const std::vector<const InputEvent*>& due, Reading& next) const {
  switch (e.node->kind()) {
    case scene::NodeKind::KeyboardSensor: {
      // it hears keys while the viewer is inside its parent's box
      const scene::Node* parent = e.node->parent();
      const core::Aabb box = parent ? scene::boundingBox(*parent) : core::Aabb{};
      const auto& v = viewpoint_ ? *viewpoint_ : core::Vec3{};
      next.active = viewpoint_ && !box.empty() && v.x >= box.lo.x && v.x <= box.hi.x && v.y >= box.lo.y &&
                    v.y <= box.hi.y && v.z >= box.lo.z && v.z <= box.hi.z;
      bool heard = false;
      for (const auto* ev : due) {
        if (ev->kind != InputEvent::Kind::Key || !next.active) continue;
        heard = true;
        next.key = ev->key;
        next.down = ev->down;
        auto it = std::find(next.keys.begin(), next.keys.end(), ev->key);
        if (ev->down && it == next.keys.end()) next.keys.push_back(ev->key);
        if (!ev->down && it != next.keys.end()) next.keys.erase(it);
        next.value += 1;
      }
      return heard || next.active != e.reading.active;
    }
    case scene::NodeKind::MouseSensor: {
      // a click counts when its ray's first hit lies in the parent's subtree
      bool clicked = false;
      for (const auto* ev : due) {
        if (ev->kind != InputEvent::Kind::Click) continue;
        const scene::Pick hit = scene::pick(scene_.root(), ev->ray);
        for (const scene::Node* n = hit.shape; n && !clicked; n = n->parent()) {
          if (n == e.node->parent()) {
            clicked = true;
            next.hit = hit.shape->handle();
            next.value += 1;
          }
        }
      }
      next.active = clicked;
      return clicked || e.reading.active;
    }
    case scene::NodeKind::GradientSensor: {
      const scene::Node* body = bodyAbove(*e.node);
      const scene::Node* field = fieldOf(scene_, *e.node);
      if (!body || !field) return false;
      next.vector = sample(*field, body->world.position);
      next.value = next.vector.length();
      next.active = true;
      return true;
    }
    case scene::NodeKind::TimeSensor: {
      const double period = e.node->number(scene::field::TimeSensor::Period);
      const double offset = e.node->number(scene::field::TimeSensor::Offset);
      const double ticks = now + 1e-9 < offset ? 0.0 : std::floor((now - offset) / period + 1e-9) + 1.0;
      next.active = ticks > e.reading.value;
      next.value = ticks;
      return true;
    }
    case scene::NodeKind::Region:
    case scene::NodeKind::RangeFinder: {
      // felt through the physics
      auto at = index_.find(e.node->handle());
      if (at == index_.end()) return false;
      const auto& feel = felt_[at->second].second;
      const bool range = e.node->kind() == scene::NodeKind::RangeFinder;
      next.items = feel.items;
      next.hit = feel.hit;
      next.value = range ? feel.distance : static_cast<double>(next.items.size());
      next.active = range ? next.hit != 0 : !next.items.empty();
      return true;
    }
    case scene::NodeKind::Group:
    case scene::NodeKind::Transform:
    case scene::NodeKind::Material:
    case scene::NodeKind::Light:
    case scene::NodeKind::Camera:
    case scene::NodeKind::Fog:
    case scene::NodeKind::Cube:
    case scene::NodeKind::Sphere:
    case scene::NodeKind::Cylinder:
    case scene::NodeKind::Cone:
    case scene::NodeKind::Plane:
    case scene::NodeKind::Mesh:
    case scene::NodeKind::Terrain:
    case scene::NodeKind::World:
    case scene::NodeKind::Body:
    case scene::NodeKind::Joint:
    case scene::NodeKind::Conveyor:
    case scene::NodeKind::GradientField: return false;  // not sensors
  }
  return false;
}

const std::vector<Change>& Hub::update(double now) {
  changes_.clear();
  // the input due now: viewpoint moves, key events, clicks
  std::vector<const InputEvent*> due;
  while (next_input_ < input_.size() && input_[next_input_].t <= now + 1e-9) due.push_back(&input_[next_input_++]);
  for (const auto* ev : due) {
    if (ev->kind == InputEvent::Kind::Viewpoint) viewpoint_ = ev->position;
  }
  if (!viewpoint_) {
    // the viewer starts at the scene's first camera
    scene::traverse(scene_.root(), [&](scene::Node& n, const scene::TraversalState& st) {
      if (!viewpoint_ && n.kind() == scene::NodeKind::Camera) {
        viewpoint_ = st.pose.apply(n.vec3(scene::field::Camera::Position));
      }
    }, {}, scene::Templates::Skip);
  }
  if (world_) world_->sense(felt_);
  index_.clear();
  for (std::size_t i = 0; i < felt_.size(); ++i) index_[felt_[i].first] = i;
  auto pathOf = [&](scene::NodeHandle h) {
    const scene::Node* n = scene_.resolve(h);
    return n ? n->path() : std::string();
  };
  for (auto& e : entries_) {
    Reading next = e.reading;
    const scene::NodeKind kind = e.node->kind();
    if (!read(e, now, due, next)) continue;
    Change change;
    change.sensor = e.node->handle();
    // items are in path order on both sides: a merge finds who came and who went
    for (auto h : next.items) {
      if (std::find(e.reading.items.begin(), e.reading.items.end(), h) == e.reading.items.end()) {
        change.entered.push_back(h);
      }
    }
    for (auto h : e.reading.items) {
      if (std::find(next.items.begin(), next.items.end(), h) == next.items.end()) change.exited.push_back(h);
    }
    std::sort(change.exited.begin(), change.exited.end(),
              [&](auto a, auto b) { return pathOf(a) < pathOf(b); });
    const bool changed = !change.entered.empty() || !change.exited.empty() || next.value != e.reading.value ||
                         next.hit != e.reading.hit || !(next.vector == e.reading.vector) ||
                         (next.active != e.reading.active && kind != scene::NodeKind::TimeSensor) ||
                         (kind == scene::NodeKind::TimeSensor && next.active);
    e.reading = std::move(next);
    if (changed) changes_.push_back(std::move(change));
  }
  return changes_;
}

}  // namespace gdpn::sensors
