// The Python classes scripts see. Each holds a Ref to its engine and reads the kernel live.

#include "views.h"

#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "gdpn/core/math.h"
#include "gdpn/core/text.h"
#include "gdpn/scene/node_path.h"
#include "gdpn/scene/types.h"
#include "gdpn/sensors/sensor_kind.h"

namespace py = pybind11;

namespace gdpn::script::detail {
namespace {

struct TransitionView {
  Ref r;
  net::TransitionId t;
};
struct PlaceView {
  Ref r;
  net::PlaceId p;
};
struct SlotView {
  Ref r;
  bool of_transition;
  std::uint32_t owner;  // transition or place
  net::SlotId slot;
  [[nodiscard]] net::TransitionId transition() const { return net::TransitionId{owner}; }
  [[nodiscard]] net::PlaceId place() const { return net::PlaceId{owner}; }
};
struct NodeView {
  Ref r;
  net::NodeRef ref;
};
struct SimView {
  Ref r;
};
struct DataView {  // a node's user data
  Ref r;
  net::NodeRef ref;
};
struct ParamsView {  // sim.params
  py::dict values;
};
struct SensorView {
  Ref r;
  scene::NodeHandle sensor;
};
struct RandomView {
  Ref r;
};
struct PartView {  // sim.part(name): a part instance's I/O and parameters
  Ref r;
  std::size_t part;
};

struct UsesView {  // self.uses: the parts a control pattern's instance works with, by role
  Ref r;
  std::optional<std::size_t> owner;  // none: the construct belongs to no part's instance
  std::string construct;             // the construct asking, for messages
};

/// The roles of the control pattern instance the construct `name` belongs to.
py::object usesOf(Context& ctx, const std::string& name) {
  const auto& parts = ctx.parts();
  return py::cast(UsesView{refTo(ctx), parts.owner ? parts.owner(name) : std::nullopt, name});
}

/// The parameters of part or control pattern instance `part` as `sim.params` shows the model's.
py::object paramsOfPart(Context& ctx, std::size_t part) {
  py::dict values;
  for (const auto& p : ctx.parts().params(part)) {
    if (p.integer) values[py::str(p.name)] = py::int_(static_cast<long long>(p.value));
    else values[py::str(p.name)] = py::float_(p.value);
  }
  return makeParamsView(std::move(values));
}

/// The parameters of the part or control pattern instance the construct `name` belongs to
/// (none outside one).
py::object paramsOf(Context& ctx, const std::string& name) {
  const auto& parts = ctx.parts();
  const auto owner = parts.owner ? parts.owner(name) : std::nullopt;
  return owner ? paramsOfPart(ctx, *owner) : makeParamsView(py::dict());
}

/// The part view of the part the construct `name` belongs to or controls, or None.
py::object partOf(Context& ctx, const std::string& name) {
  const auto& parts = ctx.parts();
  if (!parts.of_construct) return py::none();
  const auto part = parts.of_construct(name);
  return part ? py::cast(PartView{refTo(ctx), *part}) : py::none();
}

/// The names of a part's I/O, joined for a message.
std::string ioList(const PartView& v) {
  std::string out;
  for (const auto& [name, digital] : v.r.get().parts().io(v.part)) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? std::string("none") : out;
}

std::string ownerName(const SlotView& s) {
  const auto& net = s.r.get().netRef();
  return s.of_transition ? "transition '" + net.transitionName(s.transition()) + "'"
                         : "place '" + net.placeName(s.place()) + "'";
}

/// The place slot of a place's slot view, if its place uses that slot.
std::optional<net::PlaceSlotId> placeSlot(const SlotView& s) {
  return s.r.get().netRef().findPlaceSlot(s.place(), s.slot);
}

/// The node tokens in a slot: a place's FIFO, or what a transition holds.
std::vector<net::NodeRef> tokensOf(const SlotView& s) {
  auto& ctx = s.r.get();
  if (!s.of_transition) {
    const auto ps = placeSlot(s);
    return ps ? ctx.kernelRef().nodes(*ps) : std::vector<net::NodeRef>{};
  }
  std::vector<net::NodeRef> out;
  for (const auto& [slot, node] : ctx.kernelRef().held(s.transition())) {
    if (slot == s.slot) out.push_back(node);
  }
  return out;
}

/// The path of the sensor a slot holds, or "": a place's sensor slot, or for a transition the
/// sensor slot of that name on a place its arcs touch (a sensor slot defines the slots of
/// the arcs and transitions around it).
const std::string& sensorOf(const SlotView& s) {
  static const std::string none;
  const auto& net = s.r.get().netRef();
  if (!s.of_transition) {
    const auto ps = placeSlot(s);
    return ps ? net.sensorPath(*ps) : none;
  }
  return sensorAround(net, s.transition(), s.slot);
}

/// The node of sensor view `v`; AttributeError when it is gone.
const scene::Node& sensorNode(const SensorView& v) {
  const scene::Scene* plant = v.r.get().plant();
  const scene::Node* n = plant ? plant->resolve(v.sensor) : nullptr;
  if (!n) throw py::attribute_error("the sensor is gone");
  return *n;
}

/// "a Region", "an Imu": node `n`'s type with its article, for messages.
std::string typeWithArticle(const scene::Node& n) {
  const std::string& name = n.type().name;
  const bool vowel = !name.empty() && std::string_view("AEIOU").find(name[0]) != std::string_view::npos;
  return (vowel ? "an " : "a ") + name;
}

/// What sensor view `v` reads now.
const sensors::Reading& readingOf(const SensorView& v) { return v.r.get().reading(v.sensor); }

/// The main number of sensor view `v` (0 where the sensor is gone).
double primaryOf(const SensorView& v) {
  const scene::Scene* plant = v.r.get().plant();
  const scene::Node* n = plant ? plant->resolve(v.sensor) : nullptr;
  const sensors::SensorKind* kind = n ? sensors::sensorKind(n->kind()) : nullptr;
  const auto& r = readingOf(v);
  return kind && kind->primary < r.channels().size() ? r.get<double>(kind->primary) : 0.0;
}

py::tuple tupleOf(core::Vec3 u) { return py::make_tuple(u.x, u.y, u.z); }

/// Channel `name` of sensor view `v` as Python: a float, a bool, an (x, y, z) tuple, a NumPy
/// array, a list of nodes, a node or None, a str, a list of str. Angular rates in the
/// model's angle unit per second. AttributeError, naming what it has, for a channel its kind
/// lacks.
py::object channelOf(const SensorView& v, const std::string& name) {
  const scene::Node& n = sensorNode(v);
  const auto& r = readingOf(v);
  const int i = r.find(name);
  if (i < 0) {
    std::string has = "active, value";
    for (const auto& c : r.channels()) has += ", " + std::string(c.name);
    throw py::attribute_error("sensor '" + n.path() + "' is " + typeWithArticle(n) + ": it has no '" + name +
                              "' (it has: " + has + ")");
  }
  const auto k = static_cast<std::size_t>(i);
  const sensors::Channel& c = r.channels()[k];
  const double scale = c.angular && v.r.get().angles() == scene::AngleUnit::Degrees ? core::degrees(1.0) : 1.0;
  switch (c.type) {
    case sensors::ChannelType::Number: return py::float_(r.get<double>(k) * scale);
    case sensors::ChannelType::Flag: return py::bool_(r.get<bool>(k));
    case sensors::ChannelType::Vector: return tupleOf(r.get<core::Vec3>(k) * scale);
    case sensors::ChannelType::Numbers: {
      const auto& x = r.get<std::vector<double>>(k);
      if (c.per_item) {
        // one per item, beside `items`: a list, as the items are
        py::list out;
        for (double f : x) out.append(f * scale);
        return out;
      }
      py::array_t<double> out(static_cast<py::ssize_t>(x.size()));
      auto at = out.mutable_unchecked<1>();
      for (std::size_t j = 0; j < x.size(); ++j) at(static_cast<py::ssize_t>(j)) = x[j] * scale;
      return out;
    }
    case sensors::ChannelType::Items: {
      py::list out;
      for (auto h : r.get<std::vector<scene::NodeHandle>>(k)) out.append(v.r.get().nodeView(h));
      return out;
    }
    case sensors::ChannelType::Node: {
      const auto h = r.get<scene::NodeHandle>(k);
      return h != 0 ? v.r.get().nodeView(h) : py::none();
    }
    case sensors::ChannelType::Text: return py::str(r.get<std::string>(k));
    case sensors::ChannelType::Texts: return py::cast(r.get<std::vector<std::string>>(k));
  }
  return py::none();
}

/// A camera's picture as a read-only NumPy array over the picture itself (no copy): height x
/// width x 3 bytes, or height x width metres (float32).
py::object pictureOf(const SensorView& v) {
  const scene::Node& n = sensorNode(v);
  if (const auto* kind = sensors::sensorKind(n.kind()); kind == nullptr || !kind->pictures) {
    throw py::attribute_error("sensor '" + n.path() + "' is " + typeWithArticle(n) + ": it has no 'image'");
  }
  std::string why;
  auto picture = v.r.get().image(v.sensor, why);
  if (!picture) throw std::runtime_error("camera '" + v.r.get().nodeName(v.sensor) + "' has no picture: " + why);
  auto* keep = new std::shared_ptr<const sensors::Image>(picture);
  py::capsule owner(keep, [](void* p) { delete static_cast<std::shared_ptr<const sensors::Image>*>(p); });
  const auto h = static_cast<py::ssize_t>(picture->height), w = static_cast<py::ssize_t>(picture->width);
  py::array out;
  if (!picture->depth.empty()) {
    out = py::array_t<float>({h, w}, picture->depth.data(), owner);
  } else {
    out = py::array_t<std::uint8_t>({h, w, py::ssize_t{3}}, picture->rgb.data(), owner);
  }
  out.attr("flags").attr("writeable") = false;
  return out;
}

py::object sensorView(const SlotView& s, const std::string& path) {
  const scene::Node* sensor = s.r.get().plant() ? s.r.get().plant()->find(path) : nullptr;
  if (!sensor) throw py::attribute_error("sensor '" + path + "' is not in the scene");
  return makeSensorView(s.r, sensor->handle());
}

/// The scene node of the page-type instance that construct `name` belongs to ("line/cellA/t":
/// the node "cellA", where the instance places its machine; nested instances give
/// "cellA/sub"); None for a construct of a top-level page or an instance without scene nodes.
/// Value `v` of set `set` as Python sees it: a bool, an int, a str (a string, or an enum's
/// constant by name), a tuple (a product), a SimpleNamespace (a record), None (dot).
py::object pythonValue(const net::Colours& colours, net::ColourId set, const net::Value& v) {
  const net::ColourSet& cs = colours.at(set);
  switch (cs.kind) {
    case net::ColourKind::Dot: return py::none();
    case net::ColourKind::Bool: return py::bool_(v.i != 0);
    case net::ColourKind::Integer: return py::int_(v.i);
    case net::ColourKind::Enum:
      return py::str(v.i >= 0 && static_cast<std::size_t>(v.i) < cs.constants.size() ? cs.constants[static_cast<std::size_t>(v.i)]
                                                                                      : std::string("?"));
    case net::ColourKind::String: return py::str(v.s);
    case net::ColourKind::Product: {
      py::tuple out(v.items.size());
      for (std::size_t k = 0; k < v.items.size() && k < cs.components.size(); ++k) {
        out[k] = pythonValue(colours, cs.components[k], v.items[k]);
      }
      return out;
    }
    case net::ColourKind::Record: {
      py::dict fields;
      for (std::size_t k = 0; k < v.items.size() && k < cs.components.size(); ++k) {
        fields[py::str(cs.fields[k])] = pythonValue(colours, cs.components[k], v.items[k]);
      }
      return py::module_::import("types").attr("SimpleNamespace")(**fields);
    }
  }
  return py::none();
}

/// The binding of transition `t`'s current occurrence as a SimpleNamespace of its variables,
/// or None when it has no variables or is not occurring.
py::object bindingOf(Context& ctx, net::TransitionId t) {
  const net::BoundOccurrence* b = ctx.kernelRef().binding(t);
  const net::Colouring* c = ctx.netRef().colouring();
  if (!b || !c || !c->of(t)) return py::none();
  const net::TransitionInscriptions& ti = *c->of(t);
  py::dict vars;
  for (std::size_t k = 0; k < b->binding.size() && k < ti.variables.size(); ++k) {
    vars[py::str(ti.variables[k])] = pythonValue(c->colours, ti.sets[k], b->binding[k]);
  }
  return py::module_::import("types").attr("SimpleNamespace")(**vars);
}

py::object instanceOf(Context& ctx, std::string_view name) {
  const auto first = name.find('/'), last = name.rfind('/');
  if (first == std::string_view::npos || first == last || !ctx.plant()) return py::none();
  const scene::Node* n = ctx.plant()->find(std::string(name.substr(first + 1, last - first - 1)));
  return n ? ctx.nodeView(n->handle()) : py::none();
}

/// The capacity of a place's slot: None when unbounded.
py::object capacityOf(const SlotView& s) {
  const auto ps = placeSlot(s);
  if (s.of_transition || !ps) throw py::attribute_error(ownerName(s) + " has no slot " + net::slotName(s.slot) + " with a capacity");
  const auto c = s.r.get().kernelRef().capacity(*ps);
  if (c == net::kUnbounded) return py::none();
  return py::int_(c);
}

/// Sets the capacity of a place's slot (None: unbounded); ValueError saying why not.
void setCapacity(const SlotView& s, const py::object& value) {
  const auto ps = placeSlot(s);
  if (s.of_transition || !ps) throw py::attribute_error(ownerName(s) + " has no slot " + net::slotName(s.slot) + " with a capacity");
  // a whole number or None; anything else says so, not pybind11's "Unable to cast"
  if (!value.is_none() && !py::isinstance<py::int_>(value)) {
    throw py::type_error("capacity of " + ownerName(s) + " slot " + net::slotName(s.slot) +
                         " expects a whole number or None, got " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                         py::repr(value).cast<std::string>());
  }
  const std::int64_t c = value.is_none() ? net::kUnbounded : value.cast<std::int64_t>();
  const std::string why = s.r.get().kernelRef().setCapacity(*ps, c);
  if (!why.empty()) {
    throw py::value_error("capacity of " + ownerName(s) + " slot " + net::slotName(s.slot) + ": " + why);
  }
}

/// The continuous place `v` is, in Fluid::places; AttributeError naming `what` for a place of tokens.
const net::FluidPlace& fluidPlace(const PlaceView& v, const char* what) {
  const net::Net& net = v.r.get().netRef();
  if (!net.continuousPlace(v.p)) {
    throw py::attribute_error("'" + net.placeName(v.p) + "' holds tokens, not an amount: it has no " + what +
                              " (a continuous place has; count tokens with len(place.a0))");
  }
  return net.fluid()->places[static_cast<std::size_t>(net.fluid()->of_place[v.p])];
}

/// Sets a continuous place's amount (Kernel::setAmount); TypeError for no number, ValueError
/// with the kernel's words when it refuses.
void setAmount(const PlaceView& v, const py::object& value) {
  const net::Net& net = v.r.get().netRef();
  (void)fluidPlace(v, "amount");
  if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
    throw py::type_error("amount of " + net.placeName(v.p) + " expects a number, got " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                         py::repr(value).cast<std::string>());
  }
  const std::string why = v.r.get().kernelRef().setAmount(v.p, value.cast<double>());
  if (!why.empty()) throw py::value_error("amount of " + net.placeName(v.p) + ": " + why);
}

bool isNodeSlot(const SlotView& s) {
  const auto& net = s.r.get().netRef();
  if (s.of_transition) return (net.transitions()[s.transition()].node_slot_mask >> s.slot) & 1u;
  const auto ps = placeSlot(s);
  return ps && net.placeSlots()[*ps].kind == net::SlotKind::Node;
}

std::int64_t count(const SlotView& s) {
  auto& ctx = s.r.get();
  if (isNodeSlot(s)) return static_cast<std::int64_t>(tokensOf(s).size());
  if (!s.of_transition) {
    const auto ps = placeSlot(s);
    return ps ? ctx.kernelRef().marking(*ps) : 0;
  }
  // control tokens a transition took: its normal inputs on this slot, while it occurs
  if (!ctx.kernelRef().occurring(s.transition())) return 0;
  std::int64_t n = 0;
  for (const auto& term : ctx.netRef().termsOf(s.transition())) {
    if (term.kind == net::TermKind::Input && ctx.netRef().placeSlots()[term.place_slot].slot == s.slot) {
      n += term.weight;
    }
  }
  return n;
}

/// The scene node behind a view; raises when there is no scene or it was deleted.
scene::Node& sceneNode(const NodeView& v) {
  scene::Node* n = v.r.get().sceneNode(v.ref);
  if (!n) throw py::value_error("node " + v.r.get().nodeName(v.ref) + " is not in the scene (deleted, or no scene)");
  return *n;
}

physics::World& world(const NodeView& v) {
  physics::World* w = v.r.get().physicsWorld();
  if (!w) throw py::value_error("the model has no physics");
  if (!w->isBody(sceneNode(v)) && sceneNode(v).kind() != scene::NodeKind::Joint) {
    // a node inside a body acts for that body; anything else is an error
    for (const scene::Node* p = sceneNode(v).parent(); p; p = p->parent()) {
      if (w->isBody(*p)) return *w;
    }
    throw py::value_error("node " + v.r.get().nodeName(v.ref) + " is not part of a body");
  }
  return *w;
}

/// The joint behind a view; raises when it is another kind of node.
const scene::Node& joint(const NodeView& v) {
  const scene::Node& n = sceneNode(v);
  if (n.kind() != scene::NodeKind::Joint) {
    throw py::value_error("node " + v.r.get().nodeName(v.ref) + " is a " + n.type().name + ", not a Joint");
  }
  return n;
}

/// A joint's position or rate on axis 1 (radians from the physics) in the units scripts use:
/// metres for a slider, else degrees or radians as the model's `angles` says.
double inScriptUnits(const Context& ctx, const scene::Node& joint, double x) {
  if (joint.choice<scene::JointKind>(scene::field::Joint::Kind) == scene::JointKind::Slider) return x;
  return ctx.angles() == scene::AngleUnit::Radians ? x : core::degrees(x);
}

py::object related(const NodeView& v, const scene::Node* n) {
  return n ? v.r.get().nodeView(n->handle()) : py::none();
}

core::Vec3 vec(const py::sequence& s) {
  if (py::len(s) != 3) throw py::value_error("expects three numbers (x, y, z)");
  return {s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()};
}

/// Three numbers for the physics method `method`: each finite and at most `bound` in size
/// (the units'), or a ValueError that names the method and the value.
core::Vec3 physicsVec(const py::sequence& s, const char* method, double bound, const char* unit) {
  const core::Vec3 u = vec(s);
  for (double x : {u.x, u.y, u.z}) {
    if (std::isfinite(x) && std::abs(x) <= bound) continue;
    char text[200];
    std::snprintf(text, sizeof text, "%s(%.6g, %.6g, %.6g): each number must be finite and at most %g %s", method,
                  u.x, u.y, u.z, bound, unit);
    throw py::value_error(text);
  }
  return u;
}

/// The index of field `name` of `n`'s type; raises AttributeError with a suggestion.
std::size_t fieldOf(const scene::Node& n, const std::string& name) {
  const int i = n.type().fieldIndex(name);
  if (i >= 0) return static_cast<std::size_t>(i);
  std::vector<std::string> names;
  for (const auto* f : n.type().fields) names.push_back(f->name);
  throw py::attribute_error("a " + n.type().name + " has no field '" + name + "'" + core::didYouMean(name, names));
}

/// A field's value for Python: bool, int, float, tuple or str.
py::object getField(const NodeView& v, const std::string& name) {
  const scene::Node& n = sceneNode(v);
  const std::size_t i = fieldOf(n, name);
  return std::visit(
      [](const auto& x) -> py::object {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::array<double, 3>>) return py::make_tuple(x[0], x[1], x[2]);
        else if constexpr (std::is_same_v<T, std::array<double, 4>>) return py::make_tuple(x[0], x[1], x[2], x[3]);
        else if constexpr (std::is_same_v<T, std::vector<double>>) return py::cast(x);
        else return py::cast(x);
      },
      scene::convertAngle(n, i, n.value(i), v.r.get().angles(), false));
}

/// What a field of kind `f` takes, for messages ("a number (kg)").
std::string expected(const scene::FieldDesc& f) {
  const std::string unit = f.unit.empty() ? "" : " (" + f.unit + ")";
  switch (f.kind) {
    case scene::FieldKind::Bool: return "True or False";
    case scene::FieldKind::Int: return "a whole number" + unit;
    case scene::FieldKind::Float: return "a number" + unit;
    case scene::FieldKind::Vec3: return "three numbers (x, y, z)" + unit;
    case scene::FieldKind::Color: return "a colour (r, g, b)";
    case scene::FieldKind::Rotation: return "(axis x, axis y, axis z, angle)";
    case scene::FieldKind::Enum: {
      std::string list;
      for (const auto& c : f.choices) list += (list.empty() ? "'" : ", '") + c + "'";
      return "one of " + list;
    }
    case scene::FieldKind::String:
    case scene::FieldKind::File: return "a string";
    case scene::FieldKind::FloatList: return "a list of numbers";
  }
  return "a value";
}

/// A Python value as field `f`'s kind (its syntax only); py::cast_error when it is not one.
scene::FieldValue fromPython(const scene::FieldDesc& f, const py::object& value) {
  const std::string& name = f.name;
  scene::FieldValue out;
  switch (f.kind) {
    case scene::FieldKind::Bool: out = value.cast<bool>(); break;
    case scene::FieldKind::Int: out = value.cast<std::int64_t>(); break;
    case scene::FieldKind::Float: out = value.cast<double>(); break;
    case scene::FieldKind::Vec3:
    case scene::FieldKind::Color: {
      const auto p = vec(value.cast<py::sequence>());
      out = std::array<double, 3>{p.x, p.y, p.z};
      break;
    }
    case scene::FieldKind::Rotation: {
      const auto s = value.cast<py::sequence>();
      if (py::len(s) != 4) throw py::value_error("'" + name + "' expects (axis x, axis y, axis z, angle)");
      out = std::array<double, 4>{s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>(), s[3].cast<double>()};
      break;
    }
    case scene::FieldKind::Enum:
    case scene::FieldKind::String:
    case scene::FieldKind::File: out = value.cast<std::string>(); break;
    case scene::FieldKind::FloatList: {
      std::vector<double> list;
      for (const auto& x : value.cast<py::sequence>()) list.push_back(x.cast<double>());
      out = std::move(list);
      break;
    }
  }
  return out;
}

/// Sets a field from Python, with the same checks as the model file.
void setField(const NodeView& v, const std::string& name, const py::object& value) {
  scene::Node& n = sceneNode(v);
  const std::size_t i = fieldOf(n, name);
  const scene::FieldDesc& f = *n.type().fields[i];
  // Python's value as the field's kind, then the field's own rules (as the model file has them)
  scene::FieldValue out;
  try {
    out = fromPython(f, value);
  } catch (const py::cast_error&) {
    throw py::type_error("'" + name + "' of a " + n.type().name + " expects " + expected(f) + ", got " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                         py::repr(value).cast<std::string>());
  }
  if (auto why = physics::assignField(n, i, std::move(out), v.r.get().angles(), v.r.get().physicsWorld()); !why.empty()) {
    throw py::value_error(why);
  }
}

/// The scene node behind a data view.
scene::Node& dataNode(const DataView& d) { return sceneNode(NodeView{d.r, d.ref}); }

/// A datum for Python: bool, int, float, str or a list of floats.
py::object datumToPython(const scene::FieldValue& v) {
  return std::visit([](const auto& x) -> py::object { return py::cast(x); }, v);
}

/// The datum `key` of a data view; KeyError naming the node and the data it has.
const scene::FieldValue& datumOf(const DataView& d, const std::string& key) {
  const scene::Node& n = dataNode(d);
  if (const auto* v = n.datum(key)) return *v;
  std::vector<std::string> names;
  for (const auto& kv : n.data) names.push_back(kv.first);
  std::string have;
  for (const auto& k : names) have += (have.empty() ? "" : ", ") + k;
  throw py::key_error("node " + d.r.get().nodeName(d.ref) + " has no datum '" + key + "'" +
                      core::didYouMean(key, names) + (names.empty() ? std::string("; it has no data") : "; it has " + have));
}

/// Removes datum `key`; KeyError as datumOf() when there is none.
void eraseDatum(const DataView& d, const std::string& key) {
  (void)datumOf(d, key);
  dataNode(d).eraseDatum(key);
}

/// The names of a node's data, in order.
py::list dataKeys(const DataView& d) {
  py::list out;
  for (const auto& kv : dataNode(d).data) out.append(py::str(kv.first));
  return out;
}

/// Sets datum `key` from Python: a bool, an int, a finite float, a str or a sequence of numbers.
void setDatum(const DataView& d, const std::string& key, const py::object& value) {
  scene::Node& n = dataNode(d);
  if (!core::isIdentifier(key)) {
    throw py::key_error("datum name '" + key + "' is not an identifier (letters, digits and '_')");
  }
  const auto bad = [&]() {
    return py::type_error("datum '" + key + "' of node " + d.r.get().nodeName(d.ref) +
                          " is a bool, an int, a finite float, a str or a list of numbers, got " +
                          py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                          py::repr(value).cast<std::string>());
  };
  if (py::isinstance<py::bool_>(value)) {
    n.setDatum(key, value.cast<bool>());
  } else if (py::isinstance<py::int_>(value)) {
    try {
      n.setDatum(key, value.cast<std::int64_t>());
    } catch (const py::cast_error&) {
      throw bad();
    }
  } else if (py::isinstance<py::float_>(value)) {
    const double x = value.cast<double>();
    if (!std::isfinite(x)) throw bad();
    n.setDatum(key, x);
  } else if (py::isinstance<py::str>(value)) {
    n.setDatum(key, value.cast<std::string>());
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::vector<double> list;
    for (const auto& x : value.cast<py::sequence>()) {
      if (py::isinstance<py::bool_>(x) || !(py::isinstance<py::int_>(x) || py::isinstance<py::float_>(x))) throw bad();
      list.push_back(x.cast<double>());
      if (!std::isfinite(list.back())) throw bad();
    }
    n.setDatum(key, std::move(list));
  } else {
    throw bad();
  }
}

py::object slotAttr(Ref r, bool of_transition, std::uint32_t owner, const std::string& name) {
  const auto slot = net::parseSlot(name);
  if (!slot) throw py::attribute_error("no attribute '" + name + "' (slots are a0 ... d7)");
  return py::cast(SlotView{std::move(r), of_transition, owner, *slot});
}

/// The node a script passes where a node is expected: a node, on_enter's `item`, or a slot
/// holding exactly one node token (the dissertation's `self.b2.attach(self.d0)`); TypeError
/// otherwise.
NodeView asNode(const py::object& o, const char* method) {
  if (py::isinstance<NodeView>(o)) return o.cast<NodeView>();
  // on_enter's `item` stands for the node that entered
  if (py::hasattr(o, "node") && py::isinstance<NodeView>(o.attr("node"))) return o.attr("node").cast<NodeView>();
  if (py::isinstance<SlotView>(o)) {
    const auto& s = o.cast<const SlotView&>();
    const auto tokens = tokensOf(s);
    if (tokens.size() == 1) return NodeView{s.r, tokens.front()};
    throw py::type_error(std::string(method) + "(): " + ownerName(s) + " slot " + net::slotName(s.slot) + " holds " +
                         std::to_string(tokens.size()) + " node tokens; pass one node (" + net::slotName(s.slot) +
                         "[0], say)");
  }
  throw py::type_error(std::string(method) + "() expects a node or a slot holding one, got " +
                       py::str(py::type::of(o).attr("__name__")).cast<std::string>());
}

/// What a node stands for in attach and detach: a joint the body it moves (its child Body, as
/// the dissertation's effector), any other node itself.
const scene::Node& movedBy(const scene::Node& n) {
  if (n.kind() != scene::NodeKind::Joint) return n;
  for (const auto& c : n.children()) {
    if (c->kind() == scene::NodeKind::Body) return *c;
  }
  return n;
}

/// A vector given as one sequence (x, y, z) or as three numbers, checked as physicsVec does.
core::Vec3 vectorArgs(const py::args& args, const char* method, double bound, const char* unit) {
  if (args.size() == 1) return physicsVec(args[0].cast<py::sequence>(), method, bound, unit);
  if (args.size() == 3) return physicsVec(py::make_tuple(args[0], args[1], args[2]), method, bound, unit);
  throw py::type_error(std::string(method) + "() takes (x, y, z) or three numbers, got " +
                       std::to_string(args.size()) + " arguments");
}

/// A physics method of a node that takes one vector.
struct VectorMethod {
  const char* name;
  const char* doc;
  double bound;       ///< the largest size of a component
  const char* unit;
  void (physics::World::*apply)(const scene::Node&, core::Vec3);
};

/// gdpn's names, and the dissertation's (camelCase, three numbers or one sequence alike). The
/// dissertation's setForce is ODE's dBodySetForce: a force for the next step only.
const VectorMethod kVectorMethods[] = {
    {"set_velocity", "sets its body's linear velocity, m/s", physics::kMaxSpeed, "m/s", &physics::World::setVelocity},
    {"setVelocity", "the dissertation's set_velocity", physics::kMaxSpeed, "m/s", &physics::World::setVelocity},
    {"set_force", "a force on its body, N, world frame, applied every step until changed", physics::kMaxForce, "N",
     &physics::World::setForce},
    {"add_force", "a force on its body, N, world frame, for the next step only", physics::kMaxForce, "N",
     &physics::World::addForce},
    {"addForce", "the dissertation's add_force", physics::kMaxForce, "N", &physics::World::addForce},
    {"setForce", "the dissertation's setForce: a force on its body, N, world frame, for the next step only",
     physics::kMaxForce, "N", &physics::World::addForce},
    {"set_torque", "a torque on its body, N m, world frame, applied every step until changed", physics::kMaxForce,
     "N m", &physics::World::setTorque},
};


/// Registers `gdpn_script.Node`: node tokens: fields as attributes, the physics' methods.
void registerNodeView(py::module_& m) {
  py::class_<NodeView> node_class(m, "Node", "A node token: a reference to a scene node, with its fields as attributes");
  // the physics methods that take a vector, under gdpn's names and the dissertation's
  for (const auto& method : kVectorMethods) {
    auto call = [method](const NodeView& v, const py::args& args) {
      (world(v).*method.apply)(sceneNode(v), vectorArgs(args, method.name, method.bound, method.unit));
    };
    node_class.def(method.name, call, method.doc);
  }
  node_class.def_property_readonly("name", [](const NodeView& v) { return v.r.get().nodeName(v.ref); },
                             "the node's path")
      .def_property_readonly("ref", [](const NodeView& v) { return v.ref; }, "the node's handle")
      .def_property_readonly("type", [](const NodeView& v) { return sceneNode(v).type().name; },
                             "its node type's name ('Body', 'Cube')")
      .def_property_readonly("data", [](const NodeView& v) { return DataView{v.r, v.ref}; },
                             "its user data, declared in the model (`data: {kind: red}`) or set here: "
                             "node.data['kind'] or node.data.kind")
      .def_property_readonly("template", [](const NodeView& v) { return sceneNode(v).is_template; },
                             "True for a template: kept to be spawned, neither simulated nor drawn")
      .def_property_readonly("parent", [](const NodeView& v) { return related(v, sceneNode(v).parent()); },
                             "the node above it, or None")
      .def_property_readonly("prev", [](const NodeView& v) { return related(v, sceneNode(v).prev()); },
                             "the sibling before it, or None")
      .def_property_readonly("next", [](const NodeView& v) { return related(v, sceneNode(v).next()); },
                             "the sibling after it, or None")
      .def_property_readonly("children",
                             [](const NodeView& v) {
                               py::list out;
                               for (const auto& c : sceneNode(v).children()) out.append(related(v, c.get()));
                               return out;
                             },
                             "the nodes below it, in order")
      .def("find", [](const NodeView& v, const std::string& path) { return related(v, sceneNode(v).find(path)); },
           py::arg("path"), "the node at a path below this one ('..' goes up), or None")
      .def_property_readonly("position",
                             [](const NodeView& v) {
                               const auto p = sceneNode(v).framePose().position;
                               return py::make_tuple(p.x, p.y, p.z);
                             },
                             "world position, m: a Transform's own translation included (where its children stand)")
      .def_property_readonly("rotation",
                             [](const NodeView& v) {
                               const auto q = sceneNode(v).framePose().rotation;
                               return py::make_tuple(q.w, q.x, q.y, q.z);
                             },
                             "world orientation as a quaternion (w, x, y, z)")
      .def_property_readonly("velocity",
                             [](const NodeView& v) {
                               const auto u = world(v).velocity(sceneNode(v));
                               return py::make_tuple(u.x, u.y, u.z);
                             },
                             "its body's linear velocity, m/s")
      .def("attach", [](const NodeView& v, const py::object& other) {
             return world(v).attach(movedBy(sceneNode(v)), movedBy(sceneNode(asNode(other, "attach"))));
           }, py::arg("other"), "joins this node's body to the other's (a node, or a slot holding one) with a fixed joint; "
              "False if already joined")
      .def("detach", [](const NodeView& v, const py::object& other) {
             return world(v).detach(movedBy(sceneNode(v)), movedBy(sceneNode(asNode(other, "detach"))));
           }, py::arg("other"), "breaks the joint attach() made; False if there is none")
      .def_property_readonly("angle",
                             [](const NodeView& v) {
                               const auto& n = joint(v);
                               return inScriptUnits(v.r.get(), n, world(v).jointPosition(n));
                             },
                             "a joint's position on axis 1: degrees (radians with `angles: radians`), or metres for a slider")
      .def_property_readonly("rate",
                             [](const NodeView& v) {
                               const auto& n = joint(v);
                               return inScriptUnits(v.r.get(), n, world(v).jointRate(n));
                             },
                             "a joint's rate on axis 1: deg/s (rad/s with `angles: radians`), or m/s for a slider")
      .def("spawn",
           [](const NodeView& v, const py::object& templ, const py::object& at) {
             auto& ctx = v.r.get();
             const scene::Node* source = nullptr;
             if (py::isinstance<NodeView>(templ) || py::isinstance<SlotView>(templ)) {
               source = &sceneNode(asNode(templ, "spawn"));
             } else if (ctx.plant()) {
               source = ctx.plant()->find(templ.cast<std::string>());
             }
             if (!source) throw py::value_error("no template node " + py::str(templ).cast<std::string>());
             std::optional<core::Vec3> where;
             if (!at.is_none()) where = physicsVec(at.cast<py::sequence>(), "spawn", physics::kMaxDistance, "m");
             std::string why;
             scene::Node* made = ctx.spawn(*source, sceneNode(v), where, why);
             if (!made) throw py::value_error("cannot spawn " + source->path() + ": " + why);
             return ctx.nodeView(made->handle());
           },
           py::arg("template"), py::arg("at") = py::none(),
           "copies a template node (a node or a path) as a child of this node, at a world position if given; "
           "returns the copy")
      .def("delete", [](const NodeView& v) { v.r.get().erase(sceneNode(v)); },
           "deletes this node and its subtree; tokens that hold them leave the net")
      .def("__getattr__", [](const NodeView& v, const std::string& name) { return getField(v, name); })
      .def("__setattr__", [](const NodeView& v, const std::string& name, const py::object& value) {
        setField(v, name, value);
      })
      .def("__eq__",
           [](const NodeView& a, const py::object& b) -> py::object {
             // another kind of object: Python asks it next (on_enter's `item` compares as its node)
             if (!py::isinstance<NodeView>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(a.ref == b.cast<const NodeView&>().ref);
           })
      .def("__hash__", [](const NodeView& v) { return std::hash<net::NodeRef>{}(v.ref); })
      .def("__repr__", [](const NodeView& v) { return "<node " + v.r.get().nodeName(v.ref) + ">"; });
}

/// Registers `gdpn_script.Data`: a node's user data.
void registerDataView(py::module_& m) {
  py::class_<DataView>(m, "Data", "A node's user data: names to bool, int, float, str or a list of numbers")
      .def("__getitem__", [](const DataView& d, const std::string& key) { return datumToPython(datumOf(d, key)); })
      .def("__setitem__", &setDatum)
      .def("__delitem__", &eraseDatum)
      .def("__contains__", [](const DataView& d, const std::string& key) { return dataNode(d).datum(key) != nullptr; })
      .def("__len__", [](const DataView& d) { return dataNode(d).data.size(); })
      .def("__iter__", [](const DataView& d) { return py::iter(dataKeys(d)); })
      .def("keys", &dataKeys, "the data's names")
      .def("items",
           [](const DataView& d) {
             py::list out;
             for (const auto& [k, v] : dataNode(d).data) out.append(py::make_tuple(k, datumToPython(v)));
             return out;
           },
           "(name, value) pairs")
      .def("get",
           [](const DataView& d, const std::string& key, const py::object& otherwise) -> py::object {
             const auto* v = dataNode(d).datum(key);
             return v ? datumToPython(*v) : otherwise;
           },
           py::arg("key"), py::arg("default") = py::none(), "the datum called key, or default when there is none")
      .def("__getattr__",
           [](const DataView& d, const std::string& key) {
             try {
               return datumToPython(datumOf(d, key));
             } catch (const py::key_error& e) {
               throw py::attribute_error(e.what());
             }
           })
      .def("__setattr__", &setDatum)
      .def("__delattr__",
           [](const DataView& d, const std::string& key) {
             try {
               eraseDatum(d, key);
             } catch (const py::key_error& e) {
               throw py::attribute_error(e.what());
             }
           })
      .def("__repr__", [](const DataView& d) {
        py::dict out;
        for (const auto& [k, v] : dataNode(d).data) out[py::str(k)] = datumToPython(v);
        return py::repr(out).cast<std::string>();
      });
}

/// Registers `gdpn_script.Slot`: a place's or transition's slot.
void registerSlotView(py::module_& m) {
  py::class_<SlotView>(m, "Slot", "One slot of a place or transition")
      .def("get", &count, "tokens in the slot (a count; for a node slot, how many nodes)")
      .def("set",
           [](const SlotView& s, std::int64_t n) {
             if (s.of_transition) throw py::type_error("a transition's slots are read-only");
             const auto ps = placeSlot(s);
             if (!ps) throw py::attribute_error(ownerName(s) + " has no slot " + net::slotName(s.slot));
             const std::string why = s.r.get().kernelRef().setMarking(*ps, n);
             if (!why.empty()) throw py::value_error(ownerName(s) + " slot " + net::slotName(s.slot) + ": " + why);
           },
           py::arg("n"), "sets a control slot's count (places only)")
      .def("add",
           [](const SlotView& s, const py::object& what) {
             const NodeView node = asNode(what, "add");
             if (s.of_transition) throw py::type_error("add node tokens to a place's slot");
             const auto ps = placeSlot(s);
             if (!ps) throw py::attribute_error(ownerName(s) + " has no slot " + net::slotName(s.slot));
             const std::string why = s.r.get().kernelRef().addNode(*ps, node.ref);
             if (!why.empty()) throw py::value_error(ownerName(s) + " slot " + net::slotName(s.slot) + ": " + why);
           },
           py::arg("node"), "puts a node token at the end of a place's node slot (a spawned node, say)")
      .def("__len__",
           [](const SlotView& s) -> std::int64_t {
             if (const auto& path = sensorOf(s); !path.empty()) return static_cast<std::int64_t>(py::len(sensorView(s, path)));
             return count(s);
           })
      .def("__contains__",
           [](const SlotView& s, const py::object& node) -> bool {
             if (const auto& path = sensorOf(s); !path.empty()) return sensorView(s, path).contains(node);
             const auto tokens = tokensOf(s);
             return py::isinstance<NodeView>(node) &&
                    std::find(tokens.begin(), tokens.end(), node.cast<const NodeView&>().ref) != tokens.end();
           })
      .def("__getitem__",
           [](const SlotView& s, std::int64_t i) {
             const auto tokens = tokensOf(s);
             const auto n = static_cast<std::int64_t>(tokens.size());
             if (i < 0) i += n;
             if (i < 0 || i >= n) {
               throw py::index_error(ownerName(s) + " slot " + net::slotName(s.slot) + " holds " + std::to_string(n) +
                                     " node token" + (n == 1 ? "" : "s") + ": no [" + std::to_string(i < 0 ? i - n : i) +
                                     "]");
             }
             return s.r.get().nodeView(tokens[static_cast<std::size_t>(i)]);
           })
      .def("__iter__",
           [](const SlotView& s) {
             py::list out;
             for (auto ref : tokensOf(s)) out.append(s.r.get().nodeView(ref));
             return py::iter(out);
           })
      .def("__getattr__",
           [](const SlotView& s, const std::string& name) -> py::object {
             if (const auto& path = sensorOf(s); !path.empty()) return sensorView(s, path).attr(name.c_str());
             const auto tokens = tokensOf(s);
             if (tokens.empty()) {
               throw py::attribute_error(ownerName(s) + " slot " + net::slotName(s.slot) +
                                         " holds no node token to read '" + name + "' from");
             }
             return s.r.get().nodeView(tokens.front()).attr(name.c_str());
           })
      .def_property_readonly("capacity", &capacityOf, "a place's slot's capacity, tokens; None when unbounded")
      .def("__setattr__",
           [](const SlotView& s, const std::string& name, const py::object& value) {
             if (name == "capacity") return setCapacity(s, value);
             const auto tokens = tokensOf(s);
             if (tokens.empty()) {
               throw py::attribute_error(ownerName(s) + " slot " + net::slotName(s.slot) +
                                         " holds no node token to set '" + name + "' on");
             }
             py::setattr(s.r.get().nodeView(tokens.front()), name.c_str(), value);
           })
      .def("__repr__", [](const SlotView& s) {
        return "<slot " + net::slotName(s.slot) + " of " + ownerName(s) + ": " + std::to_string(count(s)) + ">";
      });
}

/// Registers `gdpn_script.Sensor`: a sensor's reading: its kind's channels.
void registerSensorView(py::module_& m) {
  py::class_<SensorView> sensor(m, "Sensor", "What a sensor reports now: `active`, `value` and its kind's channels");
  sensor
      .def_property_readonly("items",
                             [](const SensorView& v) {
                               py::list out;
                               for (auto h : readingOf(v).items()) out.append(v.r.get().nodeView(h));
                               return out;
                             },
                             "what it senses (a Region's contents, a Contact's touches): bodies or static shapes "
                             "in path order; empty for kinds that sense no items")
      .def_property_readonly("value", [](const SensorView& v) { return primaryOf(v); },
                             "its main number: a Region's count, a RangeFinder's distance (m), a TimeSensor's "
                             "ticks, a Contact's total force (N); each kind's is listed in docs/format.md")
      .def_property_readonly("active", [](const SensorView& v) { return readingOf(v).active; },
                             "something inside, something seen, a key heard, a click, or a tick or sample now")
      .def_property_readonly("image", &pictureOf,
                             "a ColorCamera's picture (height x width x 3 bytes, NumPy) or a DepthCamera's "
                             "(height x width metres), rendered when first read after a sample, of the scene as it stands then; read-only")
      .def("__len__", [](const SensorView& v) { return readingOf(v).items().size(); })
      .def("__contains__",
           [](const SensorView& v, const NodeView& n) {
             const auto& items = readingOf(v).items();
             return std::find(items.begin(), items.end(), n.ref) != items.end();
           })
      .def("__repr__", [](const SensorView& v) { return "<sensor " + v.r.get().nodeName(v.sensor) + ">"; });
  // every channel of every kind, read by name: the kinds' own descriptions, not a list here
  std::map<std::string, std::string, std::less<>> channel_docs;
  for (const sensors::SensorKind* kind : sensors::sensorKinds()) {
    const scene::NodeType* type = scene::builtinTypes().find(kind->node_kind);
    for (const auto& c : kind->channels) {
      if (c.name == "items") continue;  // above, for every kind
      auto& doc = channel_docs[std::string(c.name)];
      doc += (doc.empty() ? "" : "; ") + (type ? type->name : std::string("?")) + ": " + std::string(c.help) +
             (c.unit.empty() ? "" : ", " + std::string(c.angular ? "deg/s (rad/s with angles: radians)" : c.unit));
    }
  }
  for (const auto& [name, doc] : channel_docs) {
    sensor.def_property_readonly(name.c_str(), [name = name](const SensorView& v) { return channelOf(v, name); }, doc.c_str());
  }
}

/// Registers `gdpn_script.Transition`: a transition.
void registerTransitionView(py::module_& m) {
  py::class_<TransitionView>(m, "Transition", "A transition, as its scripts see it")
      .def_property_readonly("name", [](const TransitionView& v) { return v.r.get().netRef().transitionName(v.t); },
                             "its qualified name (main/cell/work)")
      .def_property_readonly("elapsed",
                             [](const TransitionView& v) {
                               auto& k = v.r.get().kernelRef();
                               if (!k.occurring(v.t)) return 0.0;
                               return static_cast<double>(k.steps() - k.startStep(v.t)) * k.dt();
                             },
                             "seconds since the occurrence started")
      .def_property_readonly("progress",
                             [](const TransitionView& v) {
                               auto& k = v.r.get().kernelRef();
                               if (!k.occurring(v.t)) return 0.0;
                               const auto whole = k.endStep(v.t) - k.startStep(v.t);
                               if (whole <= 0) return 1.0;  // an immediate occurrence: done as it starts
                               return static_cast<double>(k.steps() - k.startStep(v.t)) / static_cast<double>(whole);
                             },
                             "share of the occurrence done, in (0, 1] during in_fire")
      .def_property_readonly("binding", [](const TransitionView& v) { return bindingOf(v.r.get(), v.t); },
                             "the values of its variables in the occurrence running (`self.binding.x`), or None "
                             "when it has none (value tokens: semantics.md)")
      .def_property_readonly("occurrences",
                             [](const TransitionView& v) { return v.r.get().kernelRef().occurrences(v.t); },
                             "how many of its occurrences run now (more than 1 only with servers)")
      .def_property_readonly("servers",
                             [](const TransitionView& v) -> py::object {
                               const auto n = v.r.get().kernelRef().servers(v.t);
                               return n == net::kUnlimitedServers ? py::object(py::none()) : py::object(py::int_(n));
                             },
                             "occurrences it may have at once, or None for unlimited")
      .def_property_readonly("start_time",
                             [](const TransitionView& v) {
                               auto& k = v.r.get().kernelRef();
                               return static_cast<double>(k.startStep(v.t)) * k.dt();
                             },
                             "seconds; when the current or last occurrence started")
      .def_property_readonly(
          "instance", [](const TransitionView& v) { return instanceOf(v.r.get(), v.r.get().netRef().transitionName(v.t)); },
          "the scene node of its page type's instance (the Transform that places the instance's "
          "machine), or None on a top-level page")
      .def_property_readonly(
          "part", [](const TransitionView& v) { return partOf(v.r.get(), v.r.get().netRef().transitionName(v.t)); },
          "the part its instance is, or controls (a control pattern's), or None")
      .def_property_readonly(
          "uses", [](const TransitionView& v) { return usesOf(v.r.get(), v.r.get().netRef().transitionName(v.t)); },
          "a control pattern's: the parts its instance works with, by role (`self.uses.eye`; None: left unfilled)")
      .def_property_readonly(
          "params", [](const TransitionView& v) { return paramsOf(v.r.get(), v.r.get().netRef().transitionName(v.t)); },
          "the parameters of the part or control pattern instance it belongs to")
      .def("__getattr__", [](const TransitionView& v, const std::string& name) { return slotAttr(v.r, true, v.t, name); })
      .def("__repr__", [](const TransitionView& v) {
        return "<transition " + v.r.get().netRef().transitionName(v.t) + ">";
      });
}

/// Registers `gdpn_script.Place`: a place.
void registerPlaceView(py::module_& m) {
  py::class_<PlaceView>(m, "Place", "A place, as scripts see it")
      .def_property_readonly("name", [](const PlaceView& v) { return v.r.get().netRef().placeName(v.p); },
                             "its qualified name (main/cell/buffer)")
      .def_property(
          "capacity",
          [](const PlaceView& v) -> py::object {
            if (!v.r.get().netRef().continuousPlace(v.p)) {
              return capacityOf(SlotView{v.r, false, v.p, net::kDefaultSlot});
            }
            const double c = fluidPlace(v, "capacity").capacity;
            return c == net::kNoBound ? py::none() : py::object(py::float_(c));
          },
          [](const PlaceView& v, const py::object& c) {
            if (v.r.get().netRef().continuousPlace(v.p)) {
              throw py::attribute_error("capacity of " + v.r.get().netRef().placeName(v.p) +
                                        " is the model's (a continuous place's is read-only)");
            }
            setCapacity(SlotView{v.r, false, v.p, net::kDefaultSlot}, c);
          },
          "the capacity of slot a0, tokens; None when unbounded; settable when the model gives one (a continuous "
          "place's: in its unit, read-only)")
      .def_property(
          "amount",
          [](const PlaceView& v) {
            (void)fluidPlace(v, "amount");
            return v.r.get().kernelRef().amount(v.p);
          },
          &setAmount,
          "a continuous place's amount, in its unit; settable (not below 0, nor above its capacity less the room "
          "promised)")
      .def_property_readonly(
          "unit", [](const PlaceView& v) { return fluidPlace(v, "unit").unit; },
          "a continuous place's unit (L, kg; '' when the model gives none)")
      .def_property_readonly(
          "part", [](const PlaceView& v) { return partOf(v.r.get(), v.r.get().netRef().placeName(v.p)); },
          "the part its instance is, or controls (a control pattern's), or None")
      .def_property_readonly(
          "uses", [](const PlaceView& v) { return usesOf(v.r.get(), v.r.get().netRef().placeName(v.p)); },
          "a control pattern's: the parts its instance works with, by role (`self.uses.eye`; None: left unfilled)")
      .def_property_readonly(
          "params", [](const PlaceView& v) { return paramsOf(v.r.get(), v.r.get().netRef().placeName(v.p)); },
          "the parameters of the part or control pattern instance it belongs to")
      .def_property_readonly(
          "instance", [](const PlaceView& v) { return instanceOf(v.r.get(), v.r.get().netRef().placeName(v.p)); },
          "the scene node of its page type's instance, or None on a top-level page")
      .def("__getattr__",
           [](const PlaceView& v, const std::string& name) {
             // a property that raised AttributeError lands here: a place of tokens has no amount
             if (name == "amount" || name == "unit") (void)fluidPlace(v, name.c_str());
             return slotAttr(v.r, false, v.p, name);
           })
      .def("__repr__", [](const PlaceView& v) { return "<place " + v.r.get().netRef().placeName(v.p) + ">"; });
}

/// Registers `gdpn_script.Random`: the seeded random generator.
void registerRandomView(py::module_& m) {
  py::class_<RandomView>(m, "Random", "The model's seeded random generator")
      .def("random", [](const RandomView& v) { return v.r.get().kernelRef().random().uniform01(); },
           "a float in [0, 1)")
      .def("uniform", [](const RandomView& v, double a, double b) { return v.r.get().kernelRef().random().uniform(a, b); },
           py::arg("a"), py::arg("b"), "a float in [a, b)")
      .def("normal", [](const RandomView& v, double mu, double sigma) {
             return v.r.get().kernelRef().random().normal(mu, sigma);
           }, py::arg("mu") = 0.0, py::arg("sigma") = 1.0, "a float from the normal law of mean mu and deviation sigma")
      .def("exponential", [](const RandomView& v, double mean) { return v.r.get().kernelRef().random().exponential(mean); },
           py::arg("mean"), "a float from the exponential law of that mean")
      .def("randint",
           [](const RandomView& v, std::int64_t a, std::int64_t b) {
             if (b < a) throw py::value_error("randint(a, b) needs a <= b");
             const auto span = static_cast<std::uint64_t>(b - a) + 1;
             return a + static_cast<std::int64_t>(v.r.get().kernelRef().random().below(span));
           },
           py::arg("a"), py::arg("b"), "an integer in [a, b]")
      .def("choice", [](const RandomView& v, const py::sequence& seq) {
        const auto n = py::len(seq);
        if (n == 0) throw py::index_error("choice from an empty sequence");
        return seq[v.r.get().kernelRef().random().below(n)];
      }, py::arg("seq"), "one item of the sequence, each as likely");
}

/// Registers `gdpn_script.Params`: the model's parameters.
void registerParamsView(py::module_& m) {
  py::class_<ParamsView>(m, "Params", "The model's parameters (its params section, as this run set them); read-only")
      .def("__getattr__",
           [](const ParamsView& v, const std::string& name) -> py::object {
             if (!v.values.contains(name)) {
               std::string known;
               for (const auto& k : v.values) known += (known.empty() ? "" : ", ") + py::str(k.first).cast<std::string>();
               throw py::attribute_error("no parameter '" + name + "' (the model declares " +
                                         (known.empty() ? std::string("none") : known) + ")");
             }
             return v.values[py::str(name)];
           })
      .def("__getitem__",
           [](const ParamsView& v, const std::string& name) -> py::object {
             if (!v.values.contains(name)) throw py::key_error("no parameter '" + name + "'");
             return v.values[py::str(name)];
           })
      .def("__contains__", [](const ParamsView& v, const std::string& name) { return v.values.contains(name); })
      .def("__iter__", [](const ParamsView& v) { return py::iter(v.values); })
      .def("__len__", [](const ParamsView& v) { return py::len(v.values); })
      .def("items", [](const ParamsView& v) { return v.values.attr("items")(); }, "(name, value) pairs of every parameter")
      .def("__repr__", [](const ParamsView& v) { return "<sim.params " + py::repr(v.values).cast<std::string>() + ">"; });
}

/// Registers `gdpn_script.Uses`: a control pattern instance's roles, each a part (or None).
void registerUsesView(py::module_& m) {
  py::class_<UsesView>(m, "Uses", "The parts a control pattern's instance works with, by role, as attributes")
      .def("__getattr__",
           [](const UsesView& v, const std::string& role) -> py::object {
             const auto& parts = v.r.get().parts();
             if (!v.owner) {
               throw py::attribute_error("'" + v.construct + "' belongs to no control pattern's instance: it uses no parts");
             }
             std::string roles;
             for (const auto& [name, part] : parts.uses(*v.owner)) {
               if (name == role) return part ? py::cast(PartView{v.r, *part}) : py::object(py::none());
               roles += (roles.empty() ? "" : ", ") + name;
             }
             throw py::attribute_error("'" + parts.name(*v.owner) + "' has no role '" + role + "' (it has: " +
                                       (roles.empty() ? std::string("none") : roles) + ")");
           })
      .def("__dir__", [](const UsesView& v) {
        py::list out;
        if (!v.owner) return out;
        for (const auto& [name, part] : v.r.get().parts().uses(*v.owner)) out.append(name);
        return out;
      })
      .def("__repr__", [](const UsesView& v) {
        const auto& parts = v.r.get().parts();
        if (!v.owner) return "<uses of " + v.construct + ": none>";
        std::string out = "<uses of " + parts.name(*v.owner);
        const char* sep = ": ";
        for (const auto& [name, part] : parts.uses(*v.owner)) {
          out += sep + name + "=" + (part ? parts.name(*part) : std::string("None"));
          sep = ", ";
        }
        return out + ">";
      });
}

/// Registers `gdpn_script.Part`: a part instance, its I/O as attributes.
void registerPartView(py::module_& m) {
  py::class_<PartView>(m, "Part", "A part instance: its inputs and outputs as attributes, its parameters as `params`")
      .def_property_readonly("name", [](const PartView& v) { return v.r.get().parts().name(v.part); },
                             "its qualified name (main/pusher1)")
      .def_property_readonly("io", [](const PartView& v) {
        py::list out;
        for (const auto& [name, digital] : v.r.get().parts().io(v.part)) out.append(name);
        return out;
      }, "the names of its inputs and outputs")
      .def_property_readonly("params", [](const PartView& v) { return paramsOfPart(v.r.get(), v.part); },
                             "its parameters as this instance has them")
      .def_property_readonly("node", [](const PartView& v) -> py::object {
        const auto h = v.r.get().parts().frame(v.part);
        return h != 0 ? v.r.get().nodeView(h) : py::none();
      }, "the Transform that holds its machine, or None")
      .def("__getattr__",
           [](const PartView& v, const std::string& name) -> py::object {
             const auto& parts = v.r.get().parts();
             for (const auto& [io, digital] : parts.io(v.part)) {
               if (io != name) continue;
               std::string why;
               const auto value = parts.read(v.part, name, why);
               if (!value) throw py::value_error(why);
               if (digital) return py::bool_(*value != 0.0);
               return py::float_(*value);
             }
             throw py::attribute_error("part '" + parts.name(v.part) + "' has no I/O '" + name + "' (it has: " +
                                       ioList(v) + ")");
           })
      .def("__setattr__",
           [](const PartView& v, const std::string& name, const py::object& value) {
             const auto& parts = v.r.get().parts();
             double x = 0.0;
             if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
               x = value.cast<double>();
             } else {
               throw py::type_error("I/O '" + name + "' of part '" + parts.name(v.part) +
                                    "' takes a bool or a number, got " +
                                    py::str(py::type::of(value).attr("__name__")).cast<std::string>());
             }
             std::string why;
             bool known = false;
             for (const auto& [io, digital] : parts.io(v.part)) known = known || io == name;
             if (!known) {
               throw py::attribute_error("part '" + parts.name(v.part) + "' has no I/O '" + name + "' (it has: " +
                                         ioList(v) + ")");
             }
             if (!parts.write(v.part, name, x, why)) throw py::value_error(why);
           })
      .def("__repr__", [](const PartView& v) {
        const auto& parts = v.r.get().parts();
        std::string out = "<part " + parts.name(v.part);
        const char* sep = ": ";
        for (const auto& [io, digital] : parts.io(v.part)) {
          std::string why;
          const auto value = parts.read(v.part, io, why);
          out += sep + io + "=" + (!value ? "?" : digital ? (*value != 0 ? "True" : "False") : core::formatDouble(*value));
          sep = ", ";
        }
        return out + ">";
      });
}

/// Registers `gdpn_script.Sim`: the running simulation.
void registerSimView(py::module_& m) {
  py::class_<SimView>(m, "Sim", "The running simulation")
      .def_property_readonly("time", [](const SimView& v) { return v.r.get().kernelRef().now(); }, "seconds")
      .def_property_readonly("dt", [](const SimView& v) { return v.r.get().kernelRef().dt(); }, "seconds")
      .def_property_readonly("step", [](const SimView& v) { return v.r.get().kernelRef().steps(); },
                             "steps taken since the start")
      .def_property_readonly("random", [](const SimView& v) { return RandomView{v.r}; },
                             "the model's seeded random generator")
      .def_property_readonly("params", [](const SimView& v) { return v.r.get().params(); },
                             "the model's parameters: sim.params.belt_speed")
      .def("log",
           [](const SimView& v, const py::args& args) {
             std::string text;
             for (const auto& a : args) text += (text.empty() ? "" : " ") + py::str(a).cast<std::string>();
             v.r.get().log(text);
           },
           "writes a line to the trace and to stderr")
      .def("stop", [](const SimView& v, const std::string& reason) { v.r.get().stop(reason); },
           py::arg("reason") = "stopped by a script", "ends the run after this step")
      .def("place",
           [](const SimView& v, const std::string& name) {
             const auto p = v.r.get().netRef().findPlace(name);
             if (!p) throw py::key_error("no place '" + name + "'");
             return v.r.get().placeView(*p);
           },
           py::arg("name"), "a place by its qualified name (main/belt)")
      .def("node",
           [](const SimView& v, const std::string& path) -> py::object {
             auto& ctx = v.r.get();
             const scene::Node* n = ctx.plant() ? ctx.plant()->find(path) : nullptr;
             if (!n) throw py::key_error(scene::noSceneNode(path));
             return ctx.nodeView(n->handle());
           },
           py::arg("path"), "the scene node at a path")
      .def("part",
           [](const SimView& v, const std::string& name) -> py::object {
             const auto& parts = v.r.get().parts();
             std::string why = "no part '" + name + "' (the model has none)";
             const auto part = parts.find ? parts.find(name, why) : std::nullopt;
             if (!part) throw py::key_error(why);
             return py::cast(PartView{v.r, *part});
           },
           py::arg("name"), "a part instance by name: its I/O as attributes (sim.part('pusher1').front_limit)")
      .def("transition", [](const SimView& v, const std::string& name) {
        const auto t = v.r.get().netRef().findTransition(name);
        if (!t) throw py::key_error("no transition '" + name + "'");
        return v.r.get().transitionView(*t);
      }, py::arg("name"), "a transition by its qualified name (main/push)");
}

}  // namespace

const std::string& sensorAround(const net::Net& net, net::TransitionId t, net::SlotId slot) {
  static const std::string none;
  // a slot the transition's own arcs carry tokens in is its own
  for (const auto& term : net.termsOf(t)) {
    if (net.placeSlots()[term.place_slot].slot == slot && net.sensorPath(term.place_slot).empty()) return none;
  }
  for (const auto& term : net.termsOf(t)) {
    const auto ps = net.findPlaceSlot(net.placeSlots()[term.place_slot].place, slot);
    if (!ps) continue;
    if (const auto& path = net.sensorPath(*ps); !path.empty()) return path;
  }
  return none;
}

Context& Ref::get() const {
  if (!alive || !*alive) throw std::runtime_error("this view's model is gone");
  return *ctx;
}

void registerViews() {
  static bool done = false;
  if (done) return;
  done = true;
  py::module_ m = py::module_::import("types").attr("ModuleType")("gdpn_script");
  py::module_::import("sys").attr("modules")["gdpn_script"] = m;
  // on_enter/on_exit's `item`: the dissertation's list of the geometries in the region, the
  // ones of what entered (or left) first; attributes read that node (`item.name`)
  py::exec(R"(
class Geometries(list):
    """The geometries in a region, those of the node that entered or left first.
    Attributes read that node: item.name, item.velocity; item[0] is its first geometry."""
    __slots__ = ("node",)

    def __getattr__(self, name):
        return getattr(object.__getattribute__(self, "node"), name)

    # it stands for its node: equal to it, hashed like it, printed like it
    def __eq__(self, other):
        return self.node == (other.node if isinstance(other, Geometries) else other)

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash(self.node)

    def __repr__(self):
        return repr(self.node)
)",
           m.attr("__dict__"));

  registerNodeView(m);
  registerDataView(m);
  registerSlotView(m);
  registerSensorView(m);
  registerTransitionView(m);
  registerPlaceView(m);
  registerRandomView(m);
  registerParamsView(m);
  registerPartView(m);
  registerUsesView(m);
  registerSimView(m);
}

py::object makeTransitionView(Ref r, net::TransitionId t) { return py::cast(TransitionView{std::move(r), t}); }
py::object makePlaceView(Ref r, net::PlaceId p) { return py::cast(PlaceView{std::move(r), p}); }
py::object makeNodeView(Ref r, net::NodeRef ref) { return py::cast(NodeView{std::move(r), ref}); }
py::object makeSimView(Ref r) { return py::cast(SimView{std::move(r)}); }
py::object makeSensorView(Ref r, scene::NodeHandle sensor) { return py::cast(SensorView{std::move(r), sensor}); }
py::object makeParamsView(py::dict values) { return py::cast(ParamsView{std::move(values)}); }

}  // namespace gdpn::script::detail
