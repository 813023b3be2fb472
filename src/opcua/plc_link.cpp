// The plant as a PLC's OPC UA client: the io section's points linked to the PLC's nodes,
// checked once when connecting, then exchanged between steps without waiting.

#include "gdpn/opcua/plc_link.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "gdpn/opcua/address_space.h"
#include "gdpn/opcua/status.h"

namespace gdpn::opcua {

namespace plc_detail {

/// The publishing interval asked of the PLC (ms): a PLC scans about this often.
inline constexpr double kPublishingMs = 10;

/// The values a built-in type holds: integers from `min` to `max`, or any number.
struct TypeRange {
  bool integer = false;
  double min = 0, max = 0;
};

TypeRange rangeOf(BuiltinType type) {
  // by the type's number, SByte (2) to UInt64 (9)
  static const TypeRange kIntegers[] = {
      {true, -128.0, 127.0},   {true, 0.0, 255.0},        {true, -32768.0, 32767.0},
      {true, 0.0, 65535.0},    {true, -2147483648.0, 2147483647.0}, {true, 0.0, 4294967295.0},
      {true, -9223372036854775808.0, 9223372036854775807.0}, {true, 0.0, 18446744073709551615.0}};
  const auto n = static_cast<std::size_t>(type);
  return n >= 2 && n <= 9 ? kIntegers[n - 2] : TypeRange{};
}

bool mappable(BuiltinType type) {
  return static_cast<std::uint8_t>(type) >= static_cast<std::uint8_t>(BuiltinType::Boolean) &&
         static_cast<std::uint8_t>(type) <= static_cast<std::uint8_t>(BuiltinType::Double);
}

const char* builtinName(BuiltinType type) {
  static const char* const kNames[] = {"Boolean", "SByte", "Byte",  "Int16",  "UInt16", "Int32",
                                       "UInt32",  "Int64", "UInt64", "Float", "Double"};
  return mappable(type) ? kNames[static_cast<std::size_t>(type) - 1] : "no Boolean or number";
}

/// `value` as a scalar of `type` (held within an integer type's range, rounded).
Variant variantOf(BuiltinType type, double value) {
  if (type == BuiltinType::Boolean) return Variant::boolean(value != 0);
  if (type == BuiltinType::Float || type == BuiltinType::Double) return Variant::of(type, value);
  const TypeRange r = rangeOf(type);
  const double held = std::isnan(value) ? 0.0 : std::clamp(std::round(value), r.min, r.max);
  if (r.min < 0) {
    const double top = 9223372036854775807.0;  // 2^63: beyond int64's range
    return Variant::of(type, held >= top ? std::numeric_limits<std::int64_t>::max() : static_cast<std::int64_t>(held));
  }
  const double top = 18446744073709551615.0;  // 2^64
  return Variant::of(type, held >= top ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(held));
}

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace plc_detail


bool typeHolds(BuiltinType from, BuiltinType to) {
  if (from == BuiltinType::Boolean || to == BuiltinType::Boolean) return from == to;
  if (!plc_detail::mappable(from) || !plc_detail::mappable(to)) return false;
  const plc_detail::TypeRange f = plc_detail::rangeOf(from), t = plc_detail::rangeOf(to);
  if (f.integer && t.integer) return t.min <= f.min && f.max <= t.max;
  if (f.integer) {  // into Float or Double: the integers it holds exactly
    const double exact = to == BuiltinType::Float ? 16777216.0 : 9007199254740992.0;
    return -exact <= f.min && f.max <= exact;
  }
  if (t.integer) return false;
  return from == to || to == BuiltinType::Double;
}

BuiltinType builtinOfPoint(model::IoDataType type) {
  switch (type) {
    case model::IoDataType::Boolean: return BuiltinType::Boolean;
    case model::IoDataType::Int16: return BuiltinType::Int16;
    case model::IoDataType::UInt16: return BuiltinType::UInt16;
    case model::IoDataType::Int32: return BuiltinType::Int32;
    case model::IoDataType::UInt32: return BuiltinType::UInt32;
    case model::IoDataType::Float: return BuiltinType::Float;
    case model::IoDataType::Double: return BuiltinType::Double;
  }
  return BuiltinType::Null;
}

PlcLink::~PlcLink() { close(); }

std::unique_ptr<PlcLink> PlcLink::connect(const std::string& url, model::IoMap& io, const std::string& model_path,
                                          core::Diagnostics& diags, std::string& why, const ClientOptions& options) {
  // the points linked, their nodes parsed
  const auto& points = io.points();
  std::vector<Linked> ins, outs;
  std::map<NodeId, std::size_t> taken;  // node -> the point linked to it
  const std::size_t errors = diags.errorCount();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const model::IoPoint& p = points[i];
    if (p.plc_node.empty()) continue;
    std::string bad;
    const auto node = NodeId::parse(p.plc_node, bad);
    if (!node) {
      diags.error(p.plc_node_loc, "opcua: " + bad);
      continue;
    }
    const auto [at, fresh] = taken.emplace(*node, i);
    if (!fresh) {
      diags.error(p.plc_node_loc, "opcua: the PLC's node " + node->str() + " is linked to '" + points[at->second].name + "' already");
      continue;
    }
    Linked l;
    l.point = i;
    l.node = *node;
    (p.writable ? outs : ins).push_back(std::move(l));
  }
  if (diags.errorCount() > errors) return nullptr;
  if (ins.empty() && outs.empty()) {
    diags.error({model_path, 0, 0},
                "--opcua-client: no io entry is linked to a node of the PLC (give the entries `opcua: NODEID`)");
    return nullptr;
  }

  auto client = Client::connect(url, options, why);
  if (!client) return nullptr;
  auto link = std::unique_ptr<PlcLink>(new PlcLink(io, std::move(client)));

  // each node's data type, access level and value
  std::vector<Linked*> all;
  for (auto& l : ins) all.push_back(&l);
  for (auto& l : outs) all.push_back(&l);
  std::vector<ReadItem> items;
  for (const Linked* l : all) {
    items.push_back({l->node, static_cast<std::uint32_t>(AttributeId::DataType)});
    items.push_back({l->node, static_cast<std::uint32_t>(AttributeId::AccessLevel)});
    items.push_back({l->node, static_cast<std::uint32_t>(AttributeId::Value)});
  }
  std::vector<DataValue> values;
  if (!link->client_->read(items, values, why)) {
    why = "the PLC at " + url + ": " + why;
    return nullptr;
  }
  link->stats_.reads += items.size();
  std::vector<std::pair<std::size_t, double>> initial;  // actuators' values now
  for (std::size_t k = 0; k < all.size(); ++k) {
    Linked& l = *all[k];
    const model::IoPoint& p = points[l.point];
    const DataValue& type = values[3 * k];
    const DataValue& access = values[3 * k + 1];
    const DataValue& value = values[3 * k + 2];
    const std::string node = l.node.str();
    const StatusCode type_status = type.status.value_or(status::kGood);
    if (type_status == status::kBadNodeIdUnknown) {
      diags.error(p.plc_node_loc, "opcua: the PLC at " + url + " has no node " + node);
      continue;
    }
    if (status::isBad(type_status) || !type.value || type.value->type != BuiltinType::NodeId) {
      diags.error(p.plc_node_loc, "opcua: the PLC's node " + node + " has no data type (" + status::name(type_status) + "): is it a variable?");
      continue;
    }
    l.plc_type = builtinOf(std::get<NodeId>(type.value->scalar));
    const BuiltinType mine = builtinOfPoint(p.type);
    const char* point_type = model::ioDataTypeName(p.type);
    if (!plc_detail::mappable(l.plc_type)) {
      diags.error(p.plc_node_loc, "opcua: the PLC's node " + node + " is of data type " + std::get<NodeId>(type.value->scalar).str() +
                                      ", which is no Boolean or number");
      continue;
    }
    if (p.writable && !typeHolds(l.plc_type, mine)) {
      diags.error(p.plc_node_loc, "opcua: the PLC's node " + node + " is " + plc_detail::builtinName(l.plc_type) + ": '" + p.name + "' (" +
                                      point_type + ") cannot take each of its values");
      continue;
    }
    if (!p.writable && !typeHolds(mine, l.plc_type)) {
      diags.error(p.plc_node_loc, "opcua: the PLC's node " + node + " is " + plc_detail::builtinName(l.plc_type) + ": it cannot take each value of '" +
                                      p.name + "' (" + point_type + ")");
      continue;
    }
    if (!status::isBad(access.status.value_or(status::kGood)) && access.value) {
      const auto bits = static_cast<std::uint32_t>(access.value->number().value_or(0));
      if (!p.writable && (bits & 2u) == 0) {
        diags.error(p.plc_node_loc, "opcua: the PLC will not let its node " + node + " be written (the plant writes '" + p.name + "' to it)");
        continue;
      }
      if (p.writable && (bits & 1u) == 0) {
        diags.error(p.plc_node_loc, "opcua: the PLC will not let its node " + node + " be read (it drives '" + p.name + "')");
        continue;
      }
    }
    if (value.value && value.value->is_array) {
      diags.error(p.plc_node_loc, "opcua: the PLC's node " + node + " holds an array, not one value");
      continue;
    }
    if (p.writable && !status::isBad(value.status.value_or(status::kGood)) && value.value && value.value->number()) {
      initial.emplace_back(k - ins.size(), *value.value->number());
    }
  }
  if (diags.errorCount() > errors) return nullptr;
  link->inputs_ = std::move(ins);
  link->outputs_ = std::move(outs);

  // the PLC's outputs as they are now, then as they change
  for (const auto& [k, v] : initial) {
    if (!link->apply(link->outputs_[k], v, why)) return nullptr;
  }
  if (!link->outputs_.empty()) {
    std::uint32_t subscription = 0;
    std::vector<MonitorItem> watch;
    for (std::size_t k = 0; k < link->outputs_.size(); ++k) {
      watch.push_back({link->outputs_[k].node, static_cast<std::uint32_t>(k), plc_detail::kPublishingMs});
    }
    std::vector<StatusCode> results;
    if (!link->client_->subscribe(plc_detail::kPublishingMs, subscription, why) || !link->client_->monitor(subscription, watch, results, why)) {
      why = "the PLC at " + url + ": " + why;
      return nullptr;
    }
    for (std::size_t k = 0; k < results.size(); ++k) {
      if (status::isBad(results[k])) {
        diags.error(points[link->outputs_[k].point].plc_node_loc,
                    "opcua: the PLC will not let its node " + link->outputs_[k].node.str() + " be watched: " + status::name(results[k]));
      }
    }
    if (diags.errorCount() > errors) return nullptr;
  }
  return link;
}

bool PlcLink::apply(Linked& out, double value, std::string& why) {
  const model::IoPoint& p = io_.points()[out.point];
  switch (io_.write(out.point, value, "plc")) {
    case model::IoError::None:
      out.last = value;
      ++stats_.applied;
      return true;
    case model::IoError::IllegalFunction:
    case model::IoError::IllegalAddress:
      why = "'" + p.name + "' cannot be written (the PLC's node " + out.node.str() + " drives it)";
      return false;
    case model::IoError::IllegalValue: break;
  }
  why = "the PLC's node " + out.node.str() + " sent " + plc_detail::number(value) + ", which '" + p.name + "' (" + model::ioDataTypeName(p.type) +
        ") refuses";
  return false;
}

bool PlcLink::exchange(std::string& why) {
  if (!client_) {
    why = "the link to the PLC is closed";
    return false;
  }
  if (!client_->poll(0, why)) return false;
  // the newest value of each PLC output, applied
  for (auto& change : client_->takeChanges()) {
    ++stats_.notifications;
    if (change.handle >= outputs_.size() || !change.value.value) continue;
    if (status::isBad(change.value.status.value_or(status::kGood))) continue;  // the PLC has no good value: the last stays
    const auto v = change.value.value->number();
    if (!v) continue;
    outputs_[change.handle].fresh = true;
    outputs_[change.handle].newest = *v;
  }
  for (auto& out : outputs_) {
    if (!out.fresh) continue;
    out.fresh = false;
    if (!apply(out, out.newest, why)) return false;
  }
  // the sensors that changed, in one Write (held while the last one is unanswered)
  if (client_->writing()) return true;
  std::vector<WriteItem> items;
  for (auto& in : inputs_) {
    const double v = io_.read(in.point);
    if (in.sent && plc_detail::same(v, in.last)) continue;
    items.push_back({in.node, plc_detail::variantOf(in.plc_type, v)});
    in.sent = true;
    in.last = v;
  }
  if (items.empty()) return true;
  if (!client_->writeAsync(items, why)) return false;
  stats_.writes += items.size();
  return true;
}

void PlcLink::close() {
  if (client_) client_->close();
  client_.reset();
}

}  // namespace gdpn::opcua
