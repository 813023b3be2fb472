#include "gdpn/sensors/hub.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "gdpn/core/text.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/sensor_rules.h"
#include "gdpn/scene/terrain.h"

namespace gdpn::sensors {
namespace {

using scene::NodeKind;
namespace F = scene::field;

/// A sensor's noise: standard deviation, bias and resolution, in its reading's units.
struct Noise {
  double sd = 0, bias = 0, resolution = 0;
  [[nodiscard]] bool none() const { return sd == 0 && bias == 0 && resolution == 0; }
};

/// The noise fields, which each type declares in a row from its `noise`.
template <scene::FieldId Id>
Noise noiseFields(const scene::Node& n, Id noise) {
  const auto at = [&](int k) { return n.number(static_cast<Id>(static_cast<int>(noise) + k)); };
  return {at(0), at(1), at(2)};
}

Noise noiseOf(const scene::Node& n) {
  switch (n.kind()) {
    case NodeKind::RangeFinder: return noiseFields(n, F::RangeFinder::Noise);
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera: return noiseFields(n, F::ColorCamera::Noise);
    case NodeKind::LaserScan: return noiseFields(n, F::LaserScan::Noise);
    case NodeKind::Imu: return noiseFields(n, F::Imu::Noise);
    case NodeKind::Gps: return noiseFields(n, F::Gps::Noise);
    case NodeKind::Contact: return noiseFields(n, F::Contact::Noise);
    case NodeKind::ForceTorque: return noiseFields(n, F::ForceTorque::Noise);
    default: return {};
  }
}

/// A sampled sensor's rate, Hz (0: every step).
double rateOf(const scene::Node& n) {
  switch (n.kind()) {
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera: return n.number(F::ColorCamera::Rate);
    case NodeKind::LaserScan: return n.number(F::LaserScan::Rate);
    case NodeKind::Imu: return n.number(F::Imu::Rate);
    case NodeKind::Gps: return n.number(F::Gps::Rate);
    case NodeKind::Contact: return n.number(F::Contact::Rate);
    case NodeKind::ForceTorque: return n.number(F::ForceTorque::Rate);
    default: return 0;
  }
}

/// The directions of a LaserScan's rays in its frame: from min_angle to max_angle about +z,
/// evenly, the last left out when the fan is a whole turn (it would repeat the first).
std::vector<core::Vec3> fanOf(const scene::Node& n) {
  const auto count = static_cast<std::size_t>(n.number(F::LaserScan::Count));
  const double lo = n.number(F::LaserScan::MinAngle), hi = n.number(F::LaserScan::MaxAngle);
  const bool turn = std::abs(std::abs(hi - lo) - 360.0) < 1e-9;
  const double step = count < 2 ? 0.0 : (hi - lo) / static_cast<double>(turn ? count : count - 1);
  std::vector<core::Vec3> dirs(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double a = core::radians(lo + step * static_cast<double>(i));
    dirs[i] = {std::cos(a), std::sin(a), 0};
  }
  return dirs;
}

/// The Terrain a geodetic Gps reads: the one its `terrain` names, or the scene's first.
const scene::Node* terrainOf(const scene::Scene& scene, const scene::Node& gps) {
  const std::string& path = gps.text(F::Gps::Terrain);
  if (!path.empty()) {
    const scene::Node* t = scene.find(path);
    return t && t->kind() == NodeKind::Terrain ? t : nullptr;
  }
  const scene::Node* first = nullptr;
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (!first && n.kind() == NodeKind::Terrain) first = &n;
  }, {}, scene::Templates::Skip);
  return first;
}

std::unique_ptr<scene::Geodesy> geodesyOf(const scene::Node& terrain, const std::string& dir, std::string& why) {
  const std::string& file = terrain.text(F::Terrain::File);
  const std::string path = file.empty() || file[0] == '/' ? file : dir + "/" + file;
  return scene::Geodesy::open(path, terrain.number(F::Terrain::Width), terrain.number(F::Terrain::Depth), why);
}

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

bool sampled(NodeKind kind) {
  switch (kind) {
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera:
    case NodeKind::LaserScan:
    case NodeKind::Imu:
    case NodeKind::Gps:
    case NodeKind::Contact:
    case NodeKind::ForceTorque: return true;
    default: return false;
  }
}

Hub::~Hub() = default;

bool Hub::check(const scene::Scene& scene, core::Diagnostics& diags, const std::string& model_dir) {
  bool ok = true;
  auto fail = [&](const core::SourceLoc& loc, const std::string& message) {
    diags.error(loc, message);
    ok = false;
  };
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    switch (n.kind()) {
      case NodeKind::Imu:
      case NodeKind::Contact:
        if (!bodyAbove(n)) {
          fail(n.loc, std::string(n.kind() == NodeKind::Imu ? "an Imu feels the motion of" : "a Contact feels what touches") +
                          " its body, but '" + n.path() + "' has no Body above it");
        }
        return;
      case NodeKind::ForceTorque:
        if (!n.parent() || n.parent()->kind() != NodeKind::Joint) {
          fail(n.loc, "a ForceTorque reads the joint it sits in, but the parent of '" + n.path() + "' is no Joint");
        }
        return;
      case NodeKind::ColorCamera:
      case NodeKind::DepthCamera:
      case NodeKind::LaserScan:
        if (const auto rule = scene::sensorRule(n, scene::kAsItIs, {}); !rule.message.empty()) {
          const auto& at = n.field_locs[rule.field].line ? n.field_locs[rule.field] : n.loc;
          const bool laser = n.kind() == NodeKind::LaserScan;  // "laser scan 'x' has ...", "camera 'x': far ..."
          fail(at, (laser ? "laser scan '" : "camera '") + n.path() + (laser ? "' " : "': ") + rule.message);
        }
        return;
      case NodeKind::Gps: {
        if (n.choice<scene::GpsFrame>(F::Gps::Frame) != scene::GpsFrame::Geodetic) return;
        const scene::Node* t = terrainOf(scene, n);
        const auto& at = n.fieldLoc(F::Gps::Frame).line ? n.fieldLoc(F::Gps::Frame) : n.loc;
        std::string why;
        if (!t) {
          fail(at, "a geodetic Gps needs a georeferenced Terrain, but '" + n.path() + "' finds no Terrain" +
                       (n.text(F::Gps::Terrain).empty() ? "" : " at '" + n.text(F::Gps::Terrain) + "'"));
        } else if (!geodesyOf(*t, model_dir, why)) {
          fail(at, "a geodetic Gps needs a georeferenced Terrain, but the file of '" + t->path() + "' cannot give latitudes: " + why);
        }
        return;
      }
      default: break;
    }
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

Hub::Hub(scene::Scene& scene, physics::World* world, std::uint64_t seed) : scene_(scene), world_(world) {
  bool world_node = false;
  scene::traverse(scene_.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (n.type().category == scene::Category::Sensor) {
      Entry e;
      e.node = &n;
      e.noise.reseed(seed ^ core::fnv1a(n.path()));
      entries_.push_back(std::move(e));
    }
    // the World the physics takes: the first
    if (n.kind() == NodeKind::World && !world_node) {
      gravity_ = n.vec3(F::World::Gravity);
      world_node = true;
    }
  }, {}, scene::Templates::Skip);
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.node->path() < b.node->path(); });
  for (std::size_t i = 0; i < entries_.size(); ++i) entry_of_[entries_[i].node->handle()] = i;
  if (!world_) return;
  // the physics keeps the forces that contact and force-torque sensors read, and only those
  for (const auto& e : entries_) {
    if (e.node->kind() == NodeKind::Contact) world_->watchContacts(*e.node);
    if (e.node->kind() == NodeKind::ForceTorque && e.node->parent()) world_->watchJoint(*e.node->parent());
  }
}

void Hub::track(Entry& e, double now) {
  // the velocity of the Imu's point on its body, differenced over the step
  const scene::Node* body = bodyAbove(*e.node);
  core::Vec3 v, w;
  if (world_ && body && world_->isBody(*body)) {
    v = world_->pointVelocity(*body, e.node->world.position);
    w = world_->angularVelocity(*body);
  }
  const double dt = now - last_now_;
  e.acceleration = e.moved && dt > 0 ? (v - e.velocity) * (1.0 / dt) : core::Vec3{};
  // the change of velocity over the step belongs to the middle of the step: seen in the
  // frame the sensor had then (on a turntable, the chord's direction)
  const core::Quat now_rot = e.node->world.rotation;
  const core::Quat last = e.moved ? e.rotation : now_rot;
  const double sign = last.w * now_rot.w + last.x * now_rot.x + last.y * now_rot.y + last.z * now_rot.z < 0 ? -1.0 : 1.0;
  core::Quat mid{last.w + sign * now_rot.w, last.x + sign * now_rot.x, last.y + sign * now_rot.y, last.z + sign * now_rot.z};
  const double norm = std::sqrt(mid.w * mid.w + mid.x * mid.x + mid.y * mid.y + mid.z * mid.z);
  e.middle = norm > 0 ? core::Quat{mid.w / norm, mid.x / norm, mid.y / norm, mid.z / norm} : now_rot;
  e.rotation = now_rot;
  e.velocity = v;
  e.spin = w;
  e.moved = true;
}

void Hub::addNoise(Entry& e, double* x, std::size_t n) {
  const Noise noise = noiseOf(*e.node);
  if (noise.none()) return;
  for (std::size_t i = 0; i < n; ++i) {
    double v = x[i] + noise.bias;
    if (noise.sd > 0) v += e.noise.normal(0.0, noise.sd);
    if (noise.resolution > 0) v = std::round(v / noise.resolution) * noise.resolution;
    x[i] = v;
  }
}

void Hub::measure(Entry& e, Reading& next) {
  const scene::Node& n = *e.node;
  const core::Quat to_local = n.world.rotation.conjugate();
  switch (n.kind()) {
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera:
      next.value = static_cast<double>(e.samples);
      e.image.reset();  // rendered when read
      return;
    case NodeKind::LaserScan: {
      auto dirs = fanOf(n);
      for (auto& d : dirs) d = n.world.rotation.rotate(d);
      std::vector<scene::NodeHandle> hits;
      const double length = n.number(F::LaserScan::Length);
      if (world_) {
        world_->castRays(n, n.choice<scene::Scope>(F::LaserScan::Scope), n.world.position, dirs, length, next.values, hits);
      } else {
        next.values.assign(dirs.size(), length);
      }
      addNoise(e, next.values.data(), next.values.size());
      next.value = next.values.empty() ? length : *std::min_element(next.values.begin(), next.values.end());
      return;
    }
    case NodeKind::Imu: {
      // what an accelerometer feels: its acceleration less gravity; both in its frame
      double x[6] = {};
      const core::Vec3 a = e.middle.conjugate().rotate(e.acceleration - gravity_), w = to_local.rotate(e.spin);
      x[0] = a.x, x[1] = a.y, x[2] = a.z;
      x[3] = core::degrees(w.x), x[4] = core::degrees(w.y), x[5] = core::degrees(w.z);
      addNoise(e, x, 6);
      next.linear = {x[0], x[1], x[2]};
      next.angular = {core::radians(x[3]), core::radians(x[4]), core::radians(x[5])};
      next.value = static_cast<double>(e.samples);
      return;
    }
    case NodeKind::Gps: {
      core::Vec3 p = n.world.position;
      const bool geodetic = n.choice<scene::GpsFrame>(F::Gps::Frame) == scene::GpsFrame::Geodetic;
      const scene::Geodesy* geodesy = nullptr;
      if (geodetic) {
        // its Terrain, found once (a path, or the first Terrain), resolved each sample
        if (e.terrain == 0) {
          const scene::Node* t = terrainOf(scene_, n);
          e.terrain = t ? t->handle() : 0;
        }
        if (const scene::Node* t = e.terrain ? scene_.resolve(e.terrain) : nullptr) {
          auto [at, fresh] = geodesies_.try_emplace(e.terrain);
          std::string why;
          if (fresh) at->second = geodesyOf(*t, model_dir_, why);
          geodesy = at->second.get();
          p = t->world.inverse().apply(p);
        }
      }
      double x[3] = {p.x, p.y, p.z};
      addNoise(e, x, 3);
      next.linear = {x[0], x[1], x[2]};
      // where the Terrain is gone (or its file no longer gives a georeference) the position
      // has no latitude: NaN, not metres read as degrees
      double lat = 0, lon = 0;
      if (geodetic && !(geodesy && geodesy->toGeodetic(x[0], x[1], lat, lon))) lat = lon = std::nan("");
      if (geodetic) next.linear = {lat, lon, x[2]};
      next.value = static_cast<double>(e.samples);
      return;
    }
    case NodeKind::Contact: {
      next.items.clear();
      next.values.clear();
      if (world_) {
        for (const auto& t : world_->touches(n)) {
          next.items.push_back(t.other);
          next.values.push_back(t.normal_force);
        }
      }
      addNoise(e, next.values.data(), next.values.size());
      next.value = 0;
      for (double f : next.values) next.value += f;
      return;
    }
    case NodeKind::ForceTorque: {
      core::Vec3 f, t;
      if (world_ && n.parent()) world_->jointWrench(*n.parent(), n.world.position, f, t);
      f = to_local.rotate(f);
      t = to_local.rotate(t);
      double x[6] = {f.x, f.y, f.z, t.x, t.y, t.z};
      addNoise(e, x, 6);
      next.linear = {x[0], x[1], x[2]};
      next.angular = {x[3], x[4], x[5]};
      next.value = next.linear.length();
      return;
    }
    default: return;
  }
}

std::shared_ptr<const Image> Hub::image(scene::NodeHandle camera, std::string& why) {
  Entry* e = find(camera);
  if (!e || (e->node->kind() != NodeKind::ColorCamera && e->node->kind() != NodeKind::DepthCamera)) {
    why = "it is no camera";
    return nullptr;
  }
  if (e->image) return e->image;
  if (!imager_) {
    why = "this run renders no camera pictures";
    return nullptr;
  }
  auto picture = std::make_shared<Image>();
  if (!imager_->render(scene_, *e->node, *picture, why)) return nullptr;
  const Noise noise = noiseOf(*e->node);
  if (!noise.none()) {
    if (e->node->kind() == NodeKind::DepthCamera) {
      std::vector<double> d(picture->depth.begin(), picture->depth.end());
      addNoise(*e, d.data(), d.size());
      for (std::size_t i = 0; i < d.size(); ++i) picture->depth[i] = static_cast<float>(d[i]);
    } else {
      std::vector<double> c(picture->rgb.begin(), picture->rgb.end());
      addNoise(*e, c.data(), c.size());
      for (std::size_t i = 0; i < c.size(); ++i) picture->rgb[i] = static_cast<std::uint8_t>(std::clamp(std::round(c[i]), 0.0, 255.0));
    }
  }
  e->image = std::move(picture);
  e->last = e->image;
  return e->image;
}

std::shared_ptr<const Image> Hub::lastPicture(scene::NodeHandle camera) const {
  const auto at = entry_of_.find(camera);
  return at == entry_of_.end() ? nullptr : entries_[at->second].last;
}

Hub::Entry* Hub::find(scene::NodeHandle h) {
  const auto at = entry_of_.find(h);
  return at == entry_of_.end() ? nullptr : &entries_[at->second];
}

void Hub::forget(scene::Node& top) {
  std::unordered_set<scene::NodeHandle> gone;
  scene::traverse(top, [&](scene::Node& n, const scene::TraversalState&) { gone.insert(n.handle()); });
  const auto before = entries_.size();
  std::erase_if(entries_, [&](const Entry& e) { return gone.count(e.node->handle()) > 0; });
  std::erase_if(geodesies_, [&](const auto& g) { return gone.count(g.first) > 0; });
  if (entries_.size() == before) return;
  entry_of_.clear();
  for (std::size_t i = 0; i < entries_.size(); ++i) entry_of_[entries_[i].node->handle()] = i;
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

bool Hub::isSensor(scene::NodeHandle node) const { return entry_of_.count(node) > 0; }

const Reading& Hub::reading(scene::NodeHandle sensor) const {
  static const Reading none;
  const auto at = entry_of_.find(sensor);
  return at == entry_of_.end() ? none : entries_[at->second].reading;
}

bool Hub::read(Entry& e, double now, const std::vector<const InputEvent*>& due, Reading& next) {
  switch (e.node->kind()) {
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera:
    case NodeKind::LaserScan:
    case NodeKind::Imu:
    case NodeKind::Gps:
    case NodeKind::Contact:
    case NodeKind::ForceTorque: {
      if (e.node->kind() == NodeKind::Imu) track(e, now);
      // a sample at 0, 1/rate, 2/rate, ... s (every step at rate 0)
      const double rate = rateOf(*e.node);
      const auto due_samples = rate > 0 ? static_cast<std::uint64_t>(std::floor(now * rate + 1e-9)) + 1 : e.samples + 1;
      next.active = due_samples > e.samples;
      if (!next.active) return e.reading.active;
      e.samples = due_samples;
      measure(e, next);
      return true;
    }
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
      if (range) addNoise(e, &next.value, 1);
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
                         next.values != e.reading.values || !(next.linear == e.reading.linear) ||
                         !(next.angular == e.reading.angular) ||
                         (next.active != e.reading.active && kind != scene::NodeKind::TimeSensor && !sampled(kind)) ||
                         (kind == scene::NodeKind::TimeSensor && next.active);
    e.reading = std::move(next);
    if (changed) changes_.push_back(std::move(change));
  }
  last_now_ = now;
  return changes_;
}

}  // namespace gdpn::sensors
