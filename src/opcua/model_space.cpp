// The model's namespace: its object, the named I/O, the parts' I/O, the net by page, the
// sensors and the parameters, each a node whose value is read from the run when asked.

#include "gdpn/opcua/model_space.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include "gdpn/core/text.h"
#include "gdpn/net/kernel.h"
#include "gdpn/model/part_run.h"
#include "gdpn/opcua/status.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/channel.h"

namespace gdpn::opcua {

namespace {

constexpr std::uint16_t kNs = 1;

NodeId sid(const std::string& text) { return NodeId::str(text, kNs); }

std::uint32_t dataTypeOf(model::IoDataType t) {
  switch (t) {
    case model::IoDataType::Boolean: return 1;
    case model::IoDataType::Int16: return 4;
    case model::IoDataType::UInt16: return 5;
    case model::IoDataType::Int32: return 6;
    case model::IoDataType::UInt32: return 7;
    case model::IoDataType::Float: return 10;
    case model::IoDataType::Double: return 11;
  }
  return 11;
}

/// `x` as a Variant of built-in type `type` (a number type or Boolean).
Variant numberAs(BuiltinType type, double x) {
  switch (type) {
    case BuiltinType::Boolean: return Variant::boolean(x != 0);
    case BuiltinType::SByte:
    case BuiltinType::Int16:
    case BuiltinType::Int32:
    case BuiltinType::Int64: return Variant::of(type, static_cast<std::int64_t>(std::llround(x)));
    case BuiltinType::Byte:
    case BuiltinType::UInt16:
    case BuiltinType::UInt32:
    case BuiltinType::UInt64: return Variant::of(type, static_cast<std::uint64_t>(std::max(0LL, std::llround(x))));
    case BuiltinType::Float:
    case BuiltinType::Double: return Variant::of(type, x);
    case BuiltinType::Null:
    case BuiltinType::String:
    case BuiltinType::DateTime:
    case BuiltinType::Guid:
    case BuiltinType::ByteString:
    case BuiltinType::XmlElement:
    case BuiltinType::NodeId:
    case BuiltinType::ExpandedNodeId:
    case BuiltinType::StatusCode:
    case BuiltinType::QualifiedName:
    case BuiltinType::LocalizedText:
    case BuiltinType::ExtensionObject:
    case BuiltinType::DataValue:
    case BuiltinType::Variant:
    case BuiltinType::DiagnosticInfo: break;
  }
  return Variant::dbl(x);
}

// the UNECE code of the units models write most, as OPC UA's EUInformation numbers it
std::int32_t uneceUnitId(const std::string& unit) {
  static const std::pair<const char*, const char*> codes[] = {
      {"mm", "MMT"}, {"m", "MTR"}, {"cm", "CMT"}, {"km", "KMT"}, {"s", "SEC"}, {"ms", "C26"}, {"min", "MIN"},
      {"h", "HUR"}, {"mm/s", "C16"}, {"m/s", "MTS"}, {"m/s^2", "MSK"}, {"N", "NEW"}, {"Nm", "NU"}, {"kg", "KGM"},
      {"g", "GRM"}, {"deg", "DD"}, {"rad", "C81"}, {"rad/s", "2A"}, {"deg/s", "E96"}, {"Hz", "HTZ"}, {"rpm", "RPM"},
      {"%", "P1"}, {"Pa", "PAL"}, {"bar", "BAR"}, {"l", "LTR"}, {"m3", "MTQ"}, {"m^3", "MTQ"}, {"l/s", "G51"},
      {"m3/s", "MQS"}, {"m^3/s", "MQS"}, {"A", "AMP"}, {"V", "VLT"}, {"W", "WTT"}, {"kW", "KWT"}, {"degC", "CEL"},
      {"K", "KEL"}};
  for (const auto& [u, code] : codes) {
    if (unit != u) continue;
    std::int32_t id = 0;
    for (const char* c = code; *c; ++c) id = (id << 8) | static_cast<unsigned char>(*c);
    return id;
  }
  return -1;
}

/// Adds the EngineeringUnits property of `unit` to variable `v`.
void engineeringUnits(AddressSpace& space, const NodeId& v, const std::string& unit) {
  if (unit.empty()) return;
  ExtensionObject eu{NodeId::num(id::kEUInformationEncoding), 1, {}};
  Encoder e(eu.body);
  e.string("http://www.opcfoundation.org/UA/units/un/cefact");
  e.i32(uneceUnitId(unit));
  e.localizedText({"", unit});
  e.localizedText({"", unit});
  space.addVariable(v, sid(v.text + "/EngineeringUnits"), 0, "EngineeringUnits", id::kEUInformation, true).value =
      Variant::of(BuiltinType::ExtensionObject, eu);
}

/// A method's InputArguments or OutputArguments property.
void arguments(AddressSpace& space, const NodeId& method, const char* which,
               const std::vector<std::tuple<const char*, std::uint32_t, const char*>>& args) {
  Variant list;
  list.type = BuiltinType::ExtensionObject;
  list.is_array = true;
  for (const auto& [name, type, help] : args) {
    ExtensionObject a{NodeId::num(id::kArgumentEncoding), 1, {}};
    Encoder e(a.body);
    e.string(name);
    e.nodeId(NodeId::num(type));
    e.i32(-1);
    e.length(0);
    e.localizedText({"", help});
    list.elements.push_back(Variant::of(BuiltinType::ExtensionObject, a));
  }
  Node& p = space.addVariable(method, sid(method.text + "/" + which), 0, which, id::kArgument, true);
  p.value_rank = 1;
  p.value = list;
}

std::string lastSegment(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The folder of page `page` (a qualified page name, "" for the net's top), made with its
/// parents as needed.
NodeId pageFolder(AddressSpace& space, const std::string& page) {
  if (page.empty()) return sid("net");
  const NodeId id = sid("page/" + page);
  if (space.find(id)) return id;
  const auto slash = page.rfind('/');
  const NodeId parent = pageFolder(space, slash == std::string::npos ? "" : page.substr(0, slash));
  space.addObject(parent, id, kNs, lastSegment(page));
  return id;
}

std::string pageOf(const std::string& qualified) {
  const auto slash = qualified.rfind('/');
  return slash == std::string::npos ? "" : qualified.substr(0, slash);
}

void addNet(AddressSpace& space, model::Simulation& sim) {
  const net::Net& net = sim.net();
  const net::Kernel& k = sim.kernel();
  const net::Colouring* colouring = net.colouring();
  for (const auto p : net.placeIds()) {
    const std::string name = net.placeName(p);
    const NodeId parent = pageFolder(space, pageOf(name));
    const NodeId id = sid("place/" + name);
    if (net.continuousPlace(p)) {
      Node& v = space.addVariable(parent, id, kNs, lastSegment(name), 11);
      v.read = [&k, p] { return Variant::dbl(k.amount(p)); };
      v.numeric = true;
      continue;
    }
    Node& v = space.addVariable(parent, id, kNs, lastSegment(name), 6);
    v.read = [&k, p] {
      return Variant::int32(static_cast<std::int32_t>(std::clamp<std::int64_t>(k.placeTokens(p), INT32_MIN, INT32_MAX)));
    };
    v.numeric = true;
    v.description = {"", "tokens on place " + name};
    if (!colouring) continue;
    // a value slot: one variable per value of a finite set, else the multiset as text
    for (const auto ps : net.placeSlotsOf(p)) {
      const auto set = colouring->setOf(ps);
      if (!set) continue;
      const auto values = colouring->colours.values(*set);
      if (!values.empty() && values.size() <= 64) {
        for (const auto& value : values) {
          const std::string text = colouring->colours.text(*set, value);
          Node& c = space.addVariable(id, sid("place/" + name + "/" + text), kNs, text, 6);
          c.read = [&k, ps, value] {
            const auto& m = k.values(ps);
            const auto it = m.find(value);
            return Variant::int32(static_cast<std::int32_t>(it == m.end() ? 0 : it->second));
          };
          c.numeric = true;
        }
      } else {
        Node& c = space.addVariable(id, sid("place/" + name + "/tokens"), kNs, "tokens", 12);
        c.read = [&k, ps, colouring, set] { return Variant::string(colouring->colours.text(*set, k.values(ps))); };
      }
    }
  }
  for (const auto t : net.transitionIds()) {
    if (net.continuous(t)) continue;
    const std::string name = net.transitionName(t);
    const NodeId id = sid("transition/" + name);
    Node& v = space.addVariable(pageFolder(space, pageOf(name)), id, kNs, lastSegment(name), 7);
    v.read = [&k, t] { return Variant::uint32(static_cast<std::uint32_t>(k.occurrences(t))); };
    v.numeric = true;
    v.description = {"", "occurrences of transition " + name + " running now"};
    space.addVariable(id, sid("transition/" + name + "/enabled"), kNs, "enabled", 1).read = [&k, t] {
      return Variant::boolean(k.enabled(t));
    };
  }
}

void addSensors(AddressSpace& space, model::Simulation& sim) {
  if (!sim.plant()) return;
  std::vector<const scene::Node*> stack{&sim.plant()->root()};
  while (!stack.empty()) {
    const scene::Node* n = stack.back();
    stack.pop_back();
    for (auto it = n->children().rbegin(); it != n->children().rend(); ++it) stack.push_back(it->get());
    const auto handle = n->handle();
    const sensors::Reading& r = sim.reading(handle);
    if (r.channels().empty()) continue;
    const std::string path = n->path();
    const NodeId id = sid("sensor/" + path);
    // the sensor's number: its first number channel, else whether it is active
    int first = -1;
    for (std::size_t c = 0; c < r.channels().size() && first < 0; ++c) {
      if (r.channels()[c].type == sensors::ChannelType::Number) first = static_cast<int>(c);
    }
    Node& v = space.addVariable(sid("sensors"), id, kNs, path, 11);
    v.read = [&sim, handle, first] {
      const sensors::Reading& now = sim.reading(handle);
      if (first >= 0 && static_cast<std::size_t>(first) < now.channels().size()) {
        return Variant::dbl(now.get<double>(static_cast<std::size_t>(first)));
      }
      return Variant::dbl(now.active ? 1.0 : 0.0);
    };
    v.numeric = true;
    if (first >= 0) engineeringUnits(space, id, std::string(r.channels()[static_cast<std::size_t>(first)].unit));
    space.addVariable(id, sid("sensor/" + path + "/active"), kNs, "active", 1).read = [&sim, handle] {
      return Variant::boolean(sim.reading(handle).active);
    };
    for (std::size_t c = 0; c < r.channels().size(); ++c) {
      const sensors::Channel& ch = r.channels()[c];
      const bool number = ch.type == sensors::ChannelType::Number;
      if (!number && ch.type != sensors::ChannelType::Flag) continue;
      const NodeId cid = sid("sensor/" + path + "/" + std::string(ch.name));
      Node& cv = space.addVariable(id, cid, kNs, std::string(ch.name), number ? 11 : 1);
      cv.description = {"", std::string(ch.help)};
      cv.numeric = number;
      cv.read = [&sim, handle, c, number] {
        const sensors::Reading& now = sim.reading(handle);
        if (c >= now.channels().size()) return number ? Variant::dbl(0) : Variant::boolean(false);
        return number ? Variant::dbl(now.get<double>(c)) : Variant::boolean(now.get<bool>(c));
      };
      if (number) engineeringUnits(space, cid, std::string(ch.unit));
    }
  }
}

StatusCode ioStatus(model::IoError e) {
  switch (e) {
    case model::IoError::None: return status::kGood;
    case model::IoError::IllegalFunction: return status::kBadNotWritable;
    case model::IoError::IllegalAddress: return status::kBadNotWritable;
    case model::IoError::IllegalValue: return status::kBadOutOfRange;
  }
  return status::kBadInternalError;
}

}  // namespace

std::string modelNamespace(const std::string& path) {
  std::string stem = path.empty() ? "model" : std::filesystem::path(path).filename().string();
  for (const char* suffix : {".gdpn.yaml", ".yaml", ".yml"}) {
    if (stem.ends_with(suffix)) {
      stem.resize(stem.size() - std::string_view(suffix).size());
      break;
    }
  }
  return "urn:gdpn:model:" + stem;
}

std::unique_ptr<AddressSpace> modelAddressSpace(model::Simulation& sim, model::IoMap* io, const std::string& client) {
  const std::string uri = modelNamespace(sim.model().path);
  const std::string stem = uri.substr(std::string_view("urn:gdpn:model:").size());
  auto space = std::make_unique<AddressSpace>(std::vector<std::string>{"http://opcfoundation.org/UA/", uri},
                                              "urn:gdpn:server", "gdpn", GDPN_VERSION);
  AddressSpace& s = *space;
  const NodeId model = sid("model");
  s.addObject(NodeId::num(id::kObjectsFolder), model, kNs, stem, id::kBaseObjectType);
  s.find(model)->description = {"", sim.model().description};
  net::Kernel& k = sim.kernel();
  {
    Node& t = s.addVariable(model, sid("time"), kNs, "Time", 11);
    t.read = [&k] { return Variant::dbl(k.now()); };
    t.description = {"", "model time"};
    t.numeric = true;
    engineeringUnits(s, sid("time"), "s");
    Node& n = s.addVariable(model, sid("steps"), kNs, "Steps", 9);
    n.read = [&k] { return Variant::of(BuiltinType::UInt64, static_cast<std::uint64_t>(k.steps())); };
    n.numeric = true;
  }
  {
    Node m;
    m.id = sid("step");
    m.node_class = NodeClass::Method;
    m.browse_name = {kNs, "Step"};
    m.display_name = {"", "Step"};
    m.description = {"", "takes Steps steps of the run (lockstep only) and answers with the model time"};
    m.executable = true;
    m.references.push_back({NodeId::num(id::kHasComponent), model, false});
    m.call = [&k](const std::vector<Variant>& in, std::vector<Variant>& out, std::vector<StatusCode>& in_results,
                  CallContext& ctx) -> StatusCode {
      if (in.empty()) return status::kBadArgumentsMissing;
      if (in.size() > 1) return status::kBadTooManyArguments;
      if (in[0].type != BuiltinType::UInt32 || in[0].is_array) {
        in_results = {status::kBadTypeMismatch};
        return status::kBadInvalidArgument;
      }
      if (!ctx.lockstep) return status::kBadInvalidState;
      ctx.wait_steps = static_cast<std::uint32_t>(std::get<std::uint64_t>(in[0].scalar));
      ctx.complete = [&k](std::vector<Variant>& outputs) { outputs = {Variant::dbl(k.now())}; };
      out.clear();
      return status::kGood;
    };
    s.add(std::move(m));
    arguments(s, sid("step"), "InputArguments", {{"Steps", 7, "steps of the run to take (each the model's dt)"}});
    arguments(s, sid("step"), "OutputArguments", {{"Time", 11, "the model time once they are taken (s)"}});
  }
  for (const auto& [folder, name] : {std::pair{"io", "IO"}, {"parts", "Parts"}, {"net", "Net"}, {"sensors", "Sensors"},
                                     {"params", "Parameters"}}) {
    s.addObject(model, sid(folder), kNs, name);
  }
  // the named I/O
  if (io) {
    for (std::size_t i = 0; i < io->points().size(); ++i) {
      const model::IoPoint& p = io->points()[i];
      const NodeId id = sid("io/" + p.name);
      const BuiltinType type = builtinOf(NodeId::num(dataTypeOf(p.type)));
      Node& v = s.addVariable(sid("io"), id, kNs, p.name, dataTypeOf(p.type));
      v.description = {"", p.what};
      v.numeric = p.type != model::IoDataType::Boolean;
      v.read = [io, i, type] { return numberAs(type, io->read(i)); };
      if (p.writable) {
        v.write = [io, i, &client](const Variant& value) {
          const auto x = value.number();
          return x ? ioStatus(io->write(i, *x, client)) : status::kBadTypeMismatch;
        };
      }
      engineeringUnits(s, id, p.unit);
    }
  }
  // the parts' I/O
  if (model::PartRun* parts = sim.parts()) {
    for (std::size_t i = 0; i < parts->instances().size(); ++i) {
      const auto& inst = parts->instances()[i];
      const NodeId folder = sid("part/" + inst.placed.name);
      s.addObject(sid("parts"), folder, kNs, inst.placed.name);
      for (const auto& io_spec : inst.spec->io) {
        const bool digital = io_spec.signal == model::IoSignal::Digital;
        const NodeId id = sid("part/" + inst.placed.name + "/" + io_spec.name);
        Node& v = s.addVariable(folder, id, kNs, io_spec.name, digital ? 1 : 11);
        v.description = {"", io_spec.description};
        v.numeric = !digital;
        const std::string name = io_spec.name;
        v.read = [parts, i, name, digital] {
          std::string why;
          const double x = parts->read(i, name, why).value_or(0.0);
          return digital ? Variant::boolean(x != 0) : Variant::dbl(x);
        };
        if (io_spec.direction == model::IoDirection::Output) {
          auto last = std::make_shared<std::optional<double>>();
          v.write = [parts, i, name, &sim, last, part = inst.placed.name](const Variant& value) {
            std::string why;
            const auto x = value.number();
            if (!x || !parts->write(i, name, *x, why)) return status::kBadOutOfRange;
            // traced as the io section's writes are: the changes
            if (*last != *x) {
              *last = *x;
              sim.note("io", "\"part\":\"" + part + "\",\"io\":\"" + name + "\",\"value\":" + core::formatDouble(*x));
            }
            return status::kGood;
          };
        }
        if (!digital) engineeringUnits(s, id, io_spec.unit);
      }
    }
  }
  addNet(s, sim);
  addSensors(s, sim);
  for (const auto& param : sim.model().params) {
    const NodeId id = sid("param/" + param.name);
    Node& v = s.addVariable(sid("params"), id, kNs, param.name, 11);
    v.value = Variant::dbl(param.value);
    v.description = {"", param.description};
    v.numeric = true;
    engineeringUnits(s, id, param.unit);
  }
  return space;
}

}  // namespace gdpn::opcua
