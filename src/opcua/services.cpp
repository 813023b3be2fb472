// The view, attribute and method services: Browse, BrowseNext, TranslateBrowsePathsToNodeIds,
// RegisterNodes, Read, Write, Call (a call may wait for the run's steps).

#include <algorithm>
#include <cmath>
#include <set>

#include "endpoint_state.h"

namespace gdpn::opcua::detail {

namespace {

constexpr std::uint32_t kAllAttributes = 27;
constexpr std::size_t kMostPathElements = 32;  // elements of one relative path

// the references of `node` a BrowseDescription asks for, encoded as ReferenceDescriptions
std::vector<std::string> matching(const AddressSpace& space, const Node& node, std::uint32_t direction,
                                  const NodeId& type, bool subtypes, std::uint32_t class_mask, std::uint32_t result_mask) {
  std::vector<std::string> out;
  for (const auto& r : node.references) {
    if ((direction == 0 && !r.forward) || (direction == 1 && r.forward)) continue;
    if (!type.isNull() && !(r.type == type || (subtypes && space.isSubtype(r.type, type)))) continue;
    const Node* target = space.find(r.target);
    if (!target) continue;
    if (class_mask != 0 && (class_mask & static_cast<std::uint32_t>(target->node_class)) == 0) continue;
    std::string d;
    Encoder e(d);
    e.nodeId(result_mask & 1 ? r.type : NodeId{});
    e.boolean(result_mask & 2 ? r.forward : false);
    e.expandedNodeId({r.target, {}, 0});
    e.qualifiedName(result_mask & 8 ? target->browse_name : QualifiedName{});
    e.localizedText(result_mask & 16 ? target->display_name : LocalizedText{});
    e.u32(result_mask & 4 ? static_cast<std::uint32_t>(target->node_class) : 0);
    const bool typed = target->node_class == NodeClass::Object || target->node_class == NodeClass::Variable;
    e.expandedNodeId({result_mask & 32 && typed ? space.typeDefinition(*target) : NodeId{}, {}, 0});
    out.push_back(std::move(d));
  }
  return out;
}

// a BrowseResult: the first `max` references, the rest kept behind a continuation point
void browseResult(Encoder& e, std::string& out, Session& s, std::vector<std::string> refs, std::size_t max,
                  std::size_t max_points, StatusCode status = 0) {
  if (status != 0) {
    e.u32(status);
    e.nullString();
    e.length(0);
    return;
  }
  std::string point;
  if (refs.size() > max) {
    if (s.continuations.size() >= max_points) {
      e.u32(status::kBadNoContinuationPoints);
      e.nullString();
      e.length(0);
      return;
    }
    point = "cp" + std::to_string(s.next_continuation++);
    s.continuations[point] = {max, std::vector<std::string>(refs.begin() + static_cast<std::ptrdiff_t>(max), refs.end())};
    refs.resize(max);
  }
  e.u32(0);
  if (point.empty()) e.nullString(); else e.string(point);
  e.length(refs.size());
  for (const auto& r : refs) out += r;
}

// whether `v` may be written to a variable of `node`'s data type and rank
bool typeFits(const Node& node, const Variant& v) {
  if (v.is_array != (node.value_rank >= 1)) return false;
  return v.type == builtinOf(node.data_type);
}

}  // namespace

void EndpointState::browse(const Pending& to, Session& s, Decoder& d) {
  const NodeId view = d.nodeId();
  (void)d.i64();
  (void)d.u32();
  std::uint32_t max = d.u32();
  const std::size_t n = d.length(8);
  if (!view.isNull()) return fault(to, status::kBadViewIdUnknown);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  if (max == 0 || max > limits.references_per_node) max = static_cast<std::uint32_t>(limits.references_per_node);
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.length(n);
  for (std::size_t i = 0; i < n; ++i) {
    const NodeId node = d.nodeId();
    const std::uint32_t direction = d.u32();
    const NodeId type = d.nodeId();
    const bool subtypes = d.boolean();
    const std::uint32_t class_mask = d.u32();
    const std::uint32_t result_mask = d.u32();
    const Node* at = space.find(node);
    const Node* ref_type = type.isNull() ? nullptr : space.find(type);
    StatusCode why = 0;
    if (!at) why = status::kBadNodeIdUnknown;
    else if (direction > 2) why = status::kBadBrowseDirectionInvalid;
    else if (!type.isNull() && (!ref_type || ref_type->node_class != NodeClass::ReferenceType)) why = status::kBadReferenceTypeIdInvalid;
    browseResult(e, out, s, why ? std::vector<std::string>{} : matching(space, *at, direction, type, subtypes, class_mask, result_mask),
                 max, limits.continuation_points, why);
  }
  e.length(0);
  respond(to, kBrowse, out);
}

void EndpointState::browseNext(const Pending& to, Session& s, Decoder& d) {
  const bool release = d.boolean();
  const std::vector<std::string> points = d.strings();
  if (points.empty()) return fault(to, status::kBadNothingToDo);
  if (points.size() > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.length(points.size());
  for (const auto& p : points) {
    const auto it = s.continuations.find(p);
    if (it == s.continuations.end()) {
      browseResult(e, out, s, {}, 0, 0, status::kBadContinuationPointInvalid);
      continue;
    }
    auto [max, refs] = std::move(it->second);
    s.continuations.erase(it);
    if (release) refs.clear();
    browseResult(e, out, s, std::move(refs), max, limits.continuation_points);
  }
  e.length(0);
  respond(to, kBrowseNext, out);
}

void EndpointState::translate(const Pending& to, Decoder& d) {
  const std::size_t n = d.length(8);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.length(n);
  std::size_t all_elements = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const NodeId start = d.nodeId();
    const std::size_t elements = d.length(8);
    // each element walks the references of every node reached: the work is bounded by them
    all_elements += elements;
    if (elements > kMostPathElements || all_elements > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
    std::vector<NodeId> at{start};
    StatusCode why = space.find(start) ? 0 : status::kBadNodeIdUnknown;
    if (elements == 0 && why == 0) why = status::kBadNothingToDo;
    for (std::size_t k = 0; k < elements; ++k) {
      const NodeId type = d.nodeId();
      const bool inverse = d.boolean();
      const bool subtypes = d.boolean();
      const QualifiedName name = d.qualifiedName();
      if (why != 0) continue;
      if (name.name.empty()) {
        why = status::kBadBrowseNameInvalid;
        continue;
      }
      std::vector<NodeId> next;
      std::set<NodeId> reached;
      for (const auto& from : at) {
        const Node* node = space.find(from);
        if (!node) continue;
        for (const auto& r : node->references) {
          if (r.forward == inverse) continue;
          if (!type.isNull() && !(r.type == type || (subtypes && space.isSubtype(r.type, type)))) continue;
          const Node* target = space.find(r.target);
          if (target && target->browse_name == name && reached.insert(r.target).second) next.push_back(r.target);
        }
      }
      at = std::move(next);
      if (at.empty()) why = status::kBadNoMatch;
    }
    e.u32(why);
    if (why != 0) {
      e.length(0);
      continue;
    }
    e.length(at.size());
    for (const auto& t : at) {
      e.expandedNodeId({t, {}, 0});
      e.u32(0xFFFFFFFFu);
    }
  }
  e.length(0);
  respond(to, kTranslateBrowsePaths, out);
}

void EndpointState::registerNodes(const Pending& to, Decoder& d, bool register_them) {
  const std::size_t n = d.length(2);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::vector<NodeId> ids(n);
  for (auto& id : ids) id = d.nodeId();
  std::string out = responseHeader(to.handle);
  if (register_them) {  // the same NodeIds serve: every lookup is as fast as it gets
    Encoder e(out);
    e.length(n);
    for (const auto& id : ids) e.nodeId(id);
  }
  respond(to, register_them ? kRegisterNodes : kUnregisterNodes, out);
}

DataValue EndpointState::readValue(const NodeId& node, std::uint32_t attribute, std::uint32_t timestamps) const {
  const Node* n = space.find(node);
  if (!n) return DataValue{std::nullopt, status::kBadNodeIdUnknown, std::nullopt, std::nullopt};
  DataValue v = readAttribute(space, *n, attribute);
  // a read-only server: nothing is writable by this user
  if (read_only && attribute == static_cast<std::uint32_t>(AttributeId::UserAccessLevel) && v.value) {
    v.value = Variant::of(BuiltinType::Byte, std::uint64_t{1});
  }
  if (attribute == static_cast<std::uint32_t>(AttributeId::Value) && !v.status) {
    // the model's values are of model time; the server's own of the wall clock
    if (timestamps == 0 || timestamps == 2) v.source_time = node.ns == 1 ? model_time : dateTimeNow();
    if (timestamps == 1 || timestamps == 2) v.server_time = dateTimeNow();
  }
  return v;
}

void EndpointState::read(const Pending& to, Decoder& d) {
  const double max_age = d.f64();
  const std::uint32_t timestamps = d.u32();
  const std::size_t n = d.length(8);
  if (!(max_age >= 0)) return fault(to, status::kBadMaxAgeInvalid);
  if (timestamps > 3) return fault(to, status::kBadTimestampsToReturnInvalid);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.length(n);
  for (std::size_t i = 0; i < n; ++i) {
    const NodeId node = d.nodeId();
    const std::uint32_t attribute = d.u32();
    const std::string range = d.string(256);
    const QualifiedName encoding = d.qualifiedName();
    if (!range.empty()) {
      e.dataValue({std::nullopt, status::kBadIndexRangeInvalid, std::nullopt, std::nullopt});
    } else if (!defaultEncoding(encoding)) {
      e.dataValue({std::nullopt, attribute == 13 ? status::kBadDataEncodingUnsupported : status::kBadDataEncodingInvalid,
                   std::nullopt, std::nullopt});
    } else {
      e.dataValue(readValue(node, attribute, timestamps));
    }
  }
  e.length(0);
  respond(to, kRead, out);
}

void EndpointState::write(const Pending& to, Session& s, Decoder& d) {
  const std::size_t n = d.length(8);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::vector<StatusCode> results;
  for (std::size_t i = 0; i < n; ++i) {
    const NodeId node = d.nodeId();
    const std::uint32_t attribute = d.u32();
    const std::string range = d.string(256);
    const DataValue value = d.dataValue();
    Node* target = space.find(node);
    StatusCode r = 0;
    if (!target) r = status::kBadNodeIdUnknown;
    else if (attribute < 1 || attribute > kAllAttributes) r = status::kBadAttributeIdInvalid;
    else if (attribute != 13 || !target->write) r = status::kBadNotWritable;
    else if (read_only) r = status::kBadUserAccessDenied;
    else if (!range.empty()) r = status::kBadWriteNotSupported;
    else if (!value.value || !typeFits(*target, *value.value)) r = status::kBadTypeMismatch;
    else r = target->write(*value.value);
    if (r == 0) ++stats.writes;
    results.push_back(r);
  }
  (void)s;
  respondResults(to, kWrite, results);
}

void EndpointState::call(const Pending& to, Decoder& d) {
  const std::size_t n = d.length(8);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  // calls that wait for steps are held: a connection may keep a few waiting, not a flood
  const auto waiting = std::count_if(calls.begin(), calls.end(), [&](const PendingCall& c) { return c.to.connection == to.connection; });
  if (static_cast<std::size_t>(waiting) >= limits.publish_requests) return fault(to, status::kBadTooManyOperations);
  PendingCall pc;
  pc.to = to;
  std::uint64_t wait = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const NodeId object = d.nodeId();
    const NodeId method = d.nodeId();
    const std::size_t args = d.length(1);
    std::vector<Variant> in;
    in.reserve(std::min<std::size_t>(args, 16));
    for (std::size_t k = 0; k < args; ++k) in.push_back(d.variant());
    const Node* o = space.find(object);
    const Node* m = space.find(method);
    StatusCode r = 0;
    std::vector<Variant> outputs;
    std::vector<StatusCode> in_results;
    CallContext ctx;
    ctx.lockstep = lockstep;
    if (!o) r = status::kBadNodeIdUnknown;
    else if (!m || m->node_class != NodeClass::Method) r = status::kBadMethodInvalid;
    else if (std::none_of(o->references.begin(), o->references.end(),
                          [&](const Reference& ref) { return ref.forward && ref.target == method && ref.type == NodeId::num(id::kHasComponent); })) {
      r = status::kBadMethodInvalid;
    } else if (!m->executable || !m->call) {
      r = status::kBadNotExecutable;
    } else {
      r = m->call(in, outputs, in_results, ctx);
    }
    if (r == 0 && ctx.wait_steps > 0) {
      asked += ctx.wait_steps;
      wait = asked;
    }
    pc.status.push_back(r);
    pc.in_results.push_back(std::move(in_results));
    pc.outputs.push_back(std::move(outputs));
    pc.complete.push_back(r == 0 ? std::move(ctx.complete) : nullptr);
  }
  pc.due = wait;
  calls.push_back(std::move(pc));
  answerCalls();
}

void EndpointState::answerCalls() {
  for (auto it = calls.begin(); it != calls.end();) {
    if (it->due > taken) {
      ++it;
      continue;
    }
    std::string out = responseHeader(it->to.handle);
    Encoder e(out);
    e.length(it->status.size());
    for (std::size_t i = 0; i < it->status.size(); ++i) {
      if (it->complete[i]) it->complete[i](it->outputs[i]);
      e.u32(it->status[i]);
      e.statuses(it->in_results[i]);
      e.length(0);
      e.length(it->outputs[i].size());
      for (const auto& v : it->outputs[i]) e.variant(v);
    }
    e.length(0);
    respond(it->to, kCall, out);
    it = calls.erase(it);
  }
}

}  // namespace gdpn::opcua::detail
