#include "gdpn/sensors/hub.h"

#include <algorithm>
#include <cmath>

#include "gdpn/scene/actions.h"

namespace gdpn::sensors {

Hub::Hub(scene::Scene& scene, physics::World* world) : scene_(scene), world_(world) {
  scene::traverse(scene_.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (n.type().category == scene::Category::Sensor) entries_.push_back({&n, {}});
  });
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.node->path() < b.node->path(); });
}

Hub::Entry* Hub::find(scene::NodeHandle h) {
  for (auto& e : entries_) {
    if (e.node->handle() == h) return &e;
  }
  return nullptr;
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

const std::vector<Change>& Hub::update(double now) {
  changes_.clear();
  if (world_) world_->sense(felt_);
  index_.clear();
  for (std::size_t i = 0; i < felt_.size(); ++i) index_[felt_[i].first] = i;
  auto pathOf = [&](scene::NodeHandle h) {
    const scene::Node* n = scene_.resolve(h);
    return n ? n->path() : std::string();
  };
  for (auto& e : entries_) {
    Reading next = e.reading;
    const auto& type = e.node->type().name;
    if (type == "TimeSensor") {
      const double period = e.node->number("period"), offset = e.node->number("offset");
      const double ticks = now + 1e-9 < offset ? 0.0 : std::floor((now - offset) / period + 1e-9) + 1.0;
      next.active = ticks > e.reading.value;
      next.value = ticks;
    } else {
      auto at = index_.find(e.node->handle());
      if (at == index_.end()) continue;
      const auto& feel = felt_[at->second].second;
      next.items = feel.items;
      next.hit = feel.hit;
      next.value = type == "RangeFinder" ? feel.distance : static_cast<double>(next.items.size());
      next.active = type == "RangeFinder" ? next.hit != 0 : !next.items.empty();
    }
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
                         next.hit != e.reading.hit || (type == "TimeSensor" && next.active);
    e.reading = std::move(next);
    if (changed) changes_.push_back(std::move(change));
  }
  return changes_;
}

}  // namespace gdpn::sensors
