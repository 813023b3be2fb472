// Probes: one quantity of a run, resolved once and read on demand (signals, the I/O map).

#include "probe.h"

#include <algorithm>
#include <numbers>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/inscription.h"
#include "gdpn/net/kernel.h"
#include "gdpn/net/slot.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/fields.h"
#include "gdpn/scene/node_path.h"
#include "gdpn/sensors/sensor_kind.h"

namespace gdpn::model {

namespace {

/// A number or bool field a probe may read.
bool readable(const scene::FieldDesc& f) {
  return f.kind == scene::FieldKind::Float || f.kind == scene::FieldKind::Int || f.kind == scene::FieldKind::Bool;
}

/// The node at `path` that is simulated (not in a template); null and `why` otherwise.
const scene::Node* liveNode(const Simulation& sim, const std::string& path, std::string& why) {
  const scene::Node* node = sim.plant() ? sim.plant()->find(path) : nullptr;
  if (node == nullptr) {
    why = sim.plant() ? scene::noSceneNode(path) : "the model has no scene";
    return nullptr;
  }
  if (scene::inTemplate(*node)) {
    why = "'" + path + "' lies in a template, which is neither simulated nor sensed";
    return nullptr;
  }
  return node;
}

}  // namespace

double numberOf(const scene::FieldValue& v) {
  if (const auto* d = std::get_if<double>(&v)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
  return 0.0;
}

namespace {

/// What item `item` gives probe `p` (ItemDatum): its datum `p.key` as a number (a bool as 1 or
/// 0), else its number field of that name (a body's mass); with `p.match`, 1 when the datum
/// reads as that text. 0 when it has neither.
double itemValue(const scene::Node& item, const Probe& p) {
  for (const auto& [name, value] : item.data) {
    if (name != p.key) continue;
    if (p.match) return scene::datumText(value) == *p.match ? 1.0 : 0.0;
    return numberOf(value);
  }
  if (p.match) return 0.0;
  const int f = item.type().fieldIndex(p.key);
  return f < 0 ? 0.0 : numberOf(item.value(static_cast<std::size_t>(f)));
}

}  // namespace

std::optional<Probe> placeProbe(const Simulation& sim, const std::string& place, std::string& why) {
  const auto id = sim.net().findPlace(place);
  if (!id) {
    why = "no place '" + place + "' (names are qualified: page/place)";
    return std::nullopt;
  }
  Probe p;
  p.what = sim.net().continuousPlace(*id) ? Probe::What::Amount : Probe::What::Tokens;
  p.place = *id;
  return p;
}

bool countValue(const Simulation& sim, Probe& p, const std::string& text, const core::SourceLoc& at,
                const std::string& context, core::Diagnostics& diags) {
  const net::Net& net = sim.net();
  const net::Colouring* colouring = net.colouring();
  const std::string place = net.placeName(p.place);
  // the place's one value slot
  std::vector<net::PlaceSlotId> value_slots;
  for (const net::PlaceSlotId ps : net.placeSlotsOf(p.place)) {
    if (colouring != nullptr && colouring->setOf(ps)) value_slots.push_back(ps);
  }
  if (value_slots.size() != 1) {
    std::string names;
    for (const auto ps : value_slots) names += (names.empty() ? "" : ", ") + net::slotName(net.placeSlots()[ps].slot);
    diags.error(at, context + (value_slots.empty()
                                   ? "place '" + place + "' holds no values (it has no slot with a colour): 'value' " +
                                         "counts the tokens of one value of a value slot"
                                   : "place '" + place + "' has value slots " + names +
                                         ": 'value' counts on a place with one"));
    return false;
  }
  const net::PlaceSlotId ps = value_slots.front();
  const net::ColourId set = *colouring->setOf(ps);
  const net::Colours& colours = colouring->colours;
  // parsed and checked as one value of the slot's set, without variables; then evaluated
  core::Diagnostics found;
  std::optional<net::Expr> e = net::parseInscription(text, at, found);
  std::vector<std::uint32_t> used;
  const net::InscriptionScope scope{&colours, {}, {}};
  if (e && !found.hasErrors()) (void)net::checkInscription(*e, set, net::Expect::Single, scope, used, found);
  for (const auto& d : found.all()) {
    // a text with no line (a --signal argument's) is located as a whole
    const core::SourceLoc where = at.line > 0 ? d.loc : at;
    switch (d.severity) {
      case core::Severity::Error: diags.error(where, context + d.message); break;
      case core::Severity::Warning: diags.warning(where, context + d.message); break;
      case core::Severity::Note: diags.note(where, d.message); break;
    }
  }
  if (!e || found.hasErrors()) {
    if (found.hasErrors() && e) {
      diags.note(at, "place '" + place + "' holds values of " + colours.at(set).name);
    }
    return false;
  }
  const std::optional<net::Value> v = net::evaluate(*e, {}, colours);
  if (!v || !colours.contains(set, *v)) {
    const net::ColourSet& of = colours.at(set);
    const bool range = of.kind == net::ColourKind::Integer && of.range;
    diags.error(at, context + "'" + text + "' is no value of " + of.name +
                        (range ? " (" + std::to_string(of.lo) + ".." + std::to_string(of.hi) + ")" : std::string()) +
                        (v ? "" : " (it has none: a number outside a range, the successor of an enumeration's last "
                                  "constant, a division by zero)"));
    return false;
  }
  p.what = Probe::What::Count;
  p.slot = ps;
  p.value = *v;
  return true;
}

std::optional<Probe> nodeProbe(const Simulation& sim, const std::string& path, const std::string& quantity,
                               std::string& why) {
  const scene::Node* node = liveNode(sim, path, why);
  if (node == nullptr) return std::nullopt;
  Probe p;
  p.node = node->handle();
  const bool body = sim.physics() && sim.physics()->isBody(*node);
  const bool sensor = node->type().category == scene::Category::Sensor;
  const sensors::SensorKind* kind = sensors::sensorKind(node->kind());
  // a sensor's channel that gives numbers: one, a flag, or a vector's three (or one axis)
  const auto channelOf = [&](std::string_view name) -> int {
    if (kind == nullptr) return -1;
    for (std::size_t i = 0; i < kind->channels.size(); ++i) {
      const auto type = kind->channels[i].type;
      const bool numeric = type == sensors::ChannelType::Number || type == sensors::ChannelType::Flag ||
                           type == sensors::ChannelType::Vector;
      if (kind->channels[i].name == name && numeric) return static_cast<int>(i);
    }
    return -1;
  };
  std::string q = quantity;
  // position.x: one axis of a vector
  const bool of_items = q.starts_with("item.") || q.starts_with("items.");  // item.x is a datum, not an axis
  if (const auto dot = q.rfind('.'); !of_items && dot != std::string::npos && dot + 2 == q.size() && q[dot + 1] >= 'x' &&
                                     q[dot + 1] <= 'z') {
    p.axis = q[dot + 1] - 'x';
    q.resize(dot);
    const int c = channelOf(q);
    const bool vector = c >= 0 && kind->channels[static_cast<std::size_t>(c)].type == sensors::ChannelType::Vector;
    if (q != "position" && q != "velocity" && !vector) {
      why = "'." + quantity.substr(dot + 1) + "' picks an axis of position, velocity or a sensor's vector, not of '" + q + "'";
      return std::nullopt;
    }
  }
  if (const int c = channelOf(q); c >= 0 && q != "position" && q != "velocity") {
    // a sensor's own channel (a Gps's `position` is its node's, as for any node)
    p.what = Probe::What::Channel;
    p.field = static_cast<std::size_t>(c);
    p.vector = kind->channels[p.field].type == sensors::ChannelType::Vector;
    p.degrees = kind->channels[p.field].angular && sim.model().settings.angles == scene::AngleUnit::Degrees;
  } else if (q == "position") {
    p.what = Probe::What::Position;
  } else if (q == "velocity") {
    if (!body) {
      why = "'" + path + "' is no body the physics moves: it has no velocity";
      return std::nullopt;
    }
    p.what = Probe::What::Velocity;
  } else if (q == "angle" || q == "rate") {
    if (node->kind() != scene::NodeKind::Joint || !sim.physics()) {
      why = "'" + path + "' is no joint: it has no " + q;
      return std::nullopt;
    }
    p.what = q == "angle" ? Probe::What::JointAngle : Probe::What::JointRate;
    p.linear = node->choice<scene::JointKind>(scene::field::Joint::Kind) == scene::JointKind::Slider;
  } else if (of_items) {
    const bool items = kind != nullptr && std::any_of(kind->channels.begin(), kind->channels.end(), [](const auto& ch) {
                         return ch.type == sensors::ChannelType::Items;
                       });
    if (!items) {
      why = "'" + path + "' is no sensor of items: it has no " + q;
      return std::nullopt;
    }
    p.what = Probe::What::ItemDatum;
    p.all = q.starts_with("items.");
    p.key = q.substr(p.all ? 6 : 5);
    if (const auto eq = p.key.find('='); eq != std::string::npos) {
      p.match = p.key.substr(eq + 1);
      p.key.resize(eq);
    }
    if (!core::isIdentifier(p.key) || (p.match && (p.match->empty() || p.match->find('=') != std::string::npos))) {
      why = "'" + q + "' names no datum: write item.KEY, item.KEY=TEXT, items.KEY (item.colour_code, "
            "item.material=metal, items.mass)";
      return std::nullopt;
    }
  } else if (q == "reading" || q == "active") {
    if (!sensor) {
      why = "'" + path + "' is no sensor: it has no " + q;
      return std::nullopt;
    }
    p.what = q == "reading" ? Probe::What::Reading : Probe::What::Active;
  } else {
    const int i = node->type().fieldIndex(q);
    const auto* f = i >= 0 ? node->type().fields[static_cast<std::size_t>(i)] : nullptr;
    if (f == nullptr || !readable(*f)) {
      // what this node has: a position always, the others by its kind
      std::vector<std::string> known = {"position"};
      if (body) known.emplace_back("velocity");
      if (node->kind() == scene::NodeKind::Joint) known.insert(known.end(), {"angle", "rate"});
      if (sensor) known.insert(known.end(), {"reading", "active"});
      for (std::size_t k = 0; kind != nullptr && k < kind->channels.size(); ++k) {
        if (channelOf(kind->channels[k].name) == static_cast<int>(k)) known.emplace_back(kind->channels[k].name);
      }
      for (const auto& fd : node->type().fields) {
        if (readable(*fd)) known.push_back(fd->name);
      }
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      why = "a " + node->type().name + " has no number '" + q + "'" + core::didYouMean(q, known) + " (it has: " + list +
            ")";
      return std::nullopt;
    }
    p.what = Probe::What::Field;
    p.field = static_cast<std::size_t>(i);
  }
  return p;
}

std::optional<Probe> keyProbe(const Simulation& sim, const std::string& path, const std::string& key, std::string& why) {
  const scene::Node* node = liveNode(sim, path, why);
  if (node == nullptr) return std::nullopt;
  if (node->kind() != scene::NodeKind::KeyboardSensor) {
    why = "'" + path + "' is a " + node->type().name + ", not a KeyboardSensor: it hears no keys";
    return std::nullopt;
  }
  if (key.empty()) {
    why = "'key' names a key (a, space, left)";
    return std::nullopt;
  }
  Probe p;
  p.what = Probe::What::Key;
  p.node = node->handle();
  p.key = key;
  return p;
}

bool readProbe(const Simulation& sim, const Probe& p, double* out) {
  if (p.what == Probe::What::Tokens) {
    std::int64_t tokens = 0;
    for (const net::PlaceSlotId ps : sim.net().placeSlotsOf(p.place)) tokens += sim.kernel().marking(ps);
    *out = static_cast<double>(tokens);
    return true;
  }
  if (p.what == Probe::What::Amount) {
    *out = sim.kernel().amount(p.place);
    return true;
  }
  if (p.what == Probe::What::Count) {
    const net::Multiset& values = sim.kernel().values(p.slot);
    const auto it = values.find(p.value);
    *out = it == values.end() ? 0.0 : static_cast<double>(it->second);
    return true;
  }
  const scene::Node* node = sim.plant()->resolve(p.node);
  if (node == nullptr) return false;  // deleted: no value from now on
  const auto vector = [&](core::Vec3 v) {
    if (p.axis >= 0) {
      *out = p.axis == 0 ? v.x : p.axis == 1 ? v.y : v.z;
    } else {
      out[0] = v.x;
      out[1] = v.y;
      out[2] = v.z;
    }
  };
  switch (p.what) {
    case Probe::What::Tokens:
    case Probe::What::Count:
    case Probe::What::Amount: break;
    case Probe::What::Position: vector(node->framePose().position); break;
    case Probe::What::Velocity: vector(sim.physics()->velocity(*node)); break;
    case Probe::What::JointAngle:
    case Probe::What::JointRate: {
      const bool degrees = sim.model().settings.angles == scene::AngleUnit::Degrees;
      const double v = p.what == Probe::What::JointAngle ? sim.physics()->jointPosition(*node)
                                                         : sim.physics()->jointRate(*node);
      *out = !p.linear && degrees ? v * 180.0 / std::numbers::pi : v;
      break;
    }
    case Probe::What::Reading: {
      const auto& r = sim.reading(p.node);
      const sensors::SensorKind* kind = sensors::sensorKind(node->kind());
      *out = kind != nullptr && kind->primary < r.channels().size() ? r.get<double>(kind->primary) : 0.0;
      break;
    }
    case Probe::What::Channel: {
      const auto& r = sim.reading(p.node);
      if (p.field >= r.channels().size()) return false;
      const double scale = p.degrees ? 180.0 / std::numbers::pi : 1.0;
      if (const auto* x = std::get_if<double>(&r.value(p.field))) *out = *x * scale;
      else if (const auto* b = std::get_if<bool>(&r.value(p.field))) *out = *b ? 1.0 : 0.0;
      else if (const auto* v = std::get_if<core::Vec3>(&r.value(p.field))) vector(*v * scale);
      break;
    }
    case Probe::What::Active: *out = sim.reading(p.node).active ? 1.0 : 0.0; break;
    case Probe::What::Key: {
      const auto& r = sim.reading(p.node);
      const int k = r.find("keys");
      if (k < 0) return false;
      const auto& keys = r.get<std::vector<std::string>>(static_cast<std::size_t>(k));
      *out = std::find(keys.begin(), keys.end(), p.key) != keys.end() ? 1.0 : 0.0;
      break;
    }
    case Probe::What::ItemDatum: {
      *out = 0.0;
      const auto& r = sim.reading(p.node);
      for (std::size_t c = 0; c < r.channels().size(); ++c) {
        const auto* items = std::get_if<std::vector<scene::NodeHandle>>(&r.value(c));
        if (items == nullptr) continue;
        for (const auto h : *items) {
          if (const scene::Node* item = sim.plant()->resolve(h)) *out += itemValue(*item, p);
          if (!p.all) break;
        }
        break;
      }
      break;
    }
    case Probe::What::Field: {
      *out = numberOf(scene::convertAngle(*node, p.field, node->value(p.field), sim.model().settings.angles, false));
      break;
    }
  }
  return true;
}

}  // namespace gdpn::model
