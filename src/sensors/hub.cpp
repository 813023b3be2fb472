#include "gdpn/sensors/hub.h"

#include <algorithm>

#include "detail/sensor.h"
#include "gdpn/scene/actions.h"

namespace gdpn::sensors {

Hub::~Hub() = default;

bool Hub::check(const scene::Scene& scene, core::Diagnostics& diags, const std::string& model_dir) {
  bool ok = true;
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (const detail::KindDef* def = detail::kindDef(n.kind())) ok = def->check(scene, n, diags, model_dir) && ok;
  }, {}, scene::Templates::Skip);
  return ok;
}

Hub::Hub(scene::Scene& scene, physics::World* world, std::uint64_t seed)
    : scene_(scene), world_(world), seed_(seed) {
  // the World the physics takes: the first
  bool world_node = false;
  scene::traverse(scene_.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (n.kind() == scene::NodeKind::World && !world_node) {
      gravity_ = n.vec3(scene::field::World::Gravity);
      world_node = true;
    }
  }, {}, scene::Templates::Skip);
  enter(scene_.root());
}

void Hub::enter(scene::Node& top) {
  scene::traverse(top, [&](scene::Node& n, const scene::TraversalState&) {
    const detail::KindDef* def = detail::kindDef(n.kind());
    if (def == nullptr) return;
    Entry e;
    e.sensor = def->make(n, def->kind, seed_);
    e.reading = Reading(def->kind.channels);
    const auto at = entries_.emplace(Key{n.path(), n.handle()}, std::move(e)).first;
    entry_of_[n.handle()] = at;
    // the physics keeps what the sensors that ask for it read (contact and joint forces), and only that
    if (world_ && def->watch != nullptr) def->watch(*world_, n);
  }, {}, scene::Templates::Skip);
}

bool Hub::add(scene::Node& top, core::Diagnostics& diags) {
  bool ok = true;
  scene::traverse(top, [&](scene::Node& n, const scene::TraversalState&) {
    if (const detail::KindDef* def = detail::kindDef(n.kind())) ok = def->check(scene_, n, diags, model_dir_) && ok;
  }, {}, scene::Templates::Skip);
  if (ok) enter(top);
  return ok;
}

std::shared_ptr<const Image> Hub::image(scene::NodeHandle camera, std::string& why) {
  Entry* e = find(camera);
  if (!e) {
    why = "it is no camera";
    return nullptr;
  }
  detail::Context ctx{scene_, world_, gravity_, model_dir_, imager_.get(), last_now_, last_now_, {}, viewpoint_, nullptr};
  return e->sensor->picture(ctx, why);
}

std::shared_ptr<const Image> Hub::lastPicture(scene::NodeHandle camera) const {
  const auto at = entry_of_.find(camera);
  return at == entry_of_.end() ? nullptr : at->second->second.sensor->lastPicture();
}

Hub::Entry* Hub::find(scene::NodeHandle h) {
  const auto at = entry_of_.find(h);
  return at == entry_of_.end() ? nullptr : &at->second->second;
}

void Hub::forget(scene::Node& top) {
  scene::traverse(top, [&](scene::Node& n, const scene::TraversalState&) {
    const auto at = entry_of_.find(n.handle());
    if (at == entry_of_.end()) return;
    entries_.erase(at->second);
    entry_of_.erase(at);
  });
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
  return std::any_of(entries_.begin(), entries_.end(),
                     [](const auto& e) { return e.second.sensor->kind().sampling == Sampling::Clock; });
}

bool Hub::isSensor(scene::NodeHandle node) const { return entry_of_.count(node) > 0; }

const Reading& Hub::reading(scene::NodeHandle sensor) const {
  static const Reading none;
  const auto at = entry_of_.find(sensor);
  return at == entry_of_.end() ? none : at->second->second.reading;
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
  felt_of_.clear();
  for (auto& [sensor, feel] : felt_) felt_of_.emplace(sensor, std::move(feel));
  detail::Context ctx{scene_, world_, gravity_, model_dir_, imager_.get(), now, last_now_, due, viewpoint_, &felt_of_};
  auto pathOf = [&](scene::NodeHandle h) {
    const scene::Node* n = scene_.resolve(h);
    return n ? n->path() : std::string();
  };
  for (auto& [key, e] : entries_) {
    Reading next = e.reading;
    if (!e.sensor->read(ctx, e.reading, next)) continue;
    Change change;
    change.sensor = e.sensor->node().handle();
    // items are in path order on both sides: a merge finds who came and who went
    const auto& now_in = next.items();
    const auto& was_in = e.reading.items();
    for (auto h : now_in) {
      if (std::find(was_in.begin(), was_in.end(), h) == was_in.end()) change.entered.push_back(h);
    }
    for (auto h : was_in) {
      if (std::find(now_in.begin(), now_in.end(), h) == now_in.end()) change.exited.push_back(h);
    }
    std::sort(change.exited.begin(), change.exited.end(), [&](auto a, auto b) { return pathOf(a) < pathOf(b); });
    // a pulse (a tick, a sample) is no change by itself: what it measured is
    const bool changed = !change.entered.empty() || !change.exited.empty() || !next.sameValues(e.reading) ||
                         (next.active != e.reading.active && !e.sensor->kind().pulse());
    e.reading = std::move(next);
    if (changed) changes_.push_back(std::move(change));
  }
  last_now_ = now;
  return changes_;
}

}  // namespace gdpn::sensors
