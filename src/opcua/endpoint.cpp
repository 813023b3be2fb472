// The endpoint: UA TCP and the secure conversation (policy None), cut into chunks and put
// together again within the limits; requests dispatched; discovery and session services.

#include "gdpn/opcua/endpoint.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "endpoint_state.h"

namespace gdpn::opcua {

using namespace detail;

struct Endpoint::Impl : EndpointState {
  using EndpointState::EndpointState;
  // a whole chunk of `c`: false when the connection must close
  bool chunk(ConnectionId id, Connection& c, std::string_view chunk);
  bool hello(Connection& c, Decoder& d);
  bool openChannel(ConnectionId id, Connection& c, Decoder& d);
  void request(ConnectionId id, Connection& c, std::uint32_t request_id, std::string_view body);
  std::string endpoints() const;
  std::string application() const;
  void createSession(const Pending& to, Connection& c, Decoder& d);
  void activateSession(const Pending& to, Connection& c, const RequestHeader& h, Decoder& d);
};

namespace {

RequestHeader readRequestHeader(Decoder& d) {
  RequestHeader h;
  h.token = d.nodeId();
  (void)d.i64();       // timestamp
  h.handle = d.u32();
  (void)d.u32();       // return diagnostics
  (void)d.string(4096);  // audit entry
  h.timeout_hint = d.u32();
  (void)d.extensionObject();  // additional header
  return h;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The state's helpers used by every service

std::string EndpointState::responseHeader(std::uint32_t handle, StatusCode result) const {
  std::string out;
  Encoder e(out);
  e.i64(dateTimeNow());
  e.u32(handle);
  e.u32(result);
  e.noDiagnostics();
  e.length(0);  // string table
  e.nodeId({});  // additional header: none
  e.u8(0);
  return out;
}

void EndpointState::respond(const Pending& to, std::uint32_t type, const std::string& body) {
  const auto it = connections.find(to.connection);
  if (it == connections.end() || it->second.closing) return;  // gone: the answer with it
  std::string message;
  Encoder e(message);
  e.nodeId(NodeId::num(type + 3));
  message += body;
  ++stats.requests;
  sendChunks(it->second, "MSG", to.request_id, message);
}

void EndpointState::respondResults(const Pending& to, std::uint32_t type, const std::vector<StatusCode>& results) {
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.statuses(results);
  e.length(0);  // diagnostics
  respond(to, type, out);
}

void EndpointState::fault(const Pending& to, StatusCode code, bool counted) {
  if (counted) ++stats.faults;
  const auto it = connections.find(to.connection);
  if (it == connections.end() || it->second.closing) return;
  std::string message;
  Encoder e(message);
  e.nodeId(NodeId::num(kServiceFault));
  message += responseHeader(to.handle, code);
  ++stats.requests;
  sendChunks(it->second, "MSG", to.request_id, message);
}

std::string EndpointState::randomBytes(std::size_t n) {
  std::string out(n, '\0');
  for (auto& ch : out) ch = static_cast<char>(random() & 0xFF);
  return out;
}

Session* EndpointState::session(const Connection& c, const RequestHeader& h, StatusCode& why, bool must_be_active) {
  for (auto& [number, s] : sessions) {
    if (s.token != h.token) continue;
    if (must_be_active && !s.activated) {
      why = status::kBadSessionNotActivated;
      return nullptr;
    }
    if (s.channel != c.channel) {  // a session is used on the channel that activated it
      why = status::kBadSecureChannelIdInvalid;
      return nullptr;
    }
    s.last_seen = now;
    return &s;
  }
  why = status::kBadSessionIdInvalid;
  return nullptr;
}

void EndpointState::closeSession(std::uint64_t number, bool delete_subscriptions) {
  const auto it = sessions.find(number);
  if (it == sessions.end()) return;
  for (auto& p : it->second.publish) fault(p.to, status::kBadSessionClosed, false);
  // subscriptions go with the session (gdpn does not transfer them)
  (void)delete_subscriptions;
  std::vector<std::uint32_t> ids;
  for (const auto& [sid, sub] : subscriptions) {
    if (sub.session == number) ids.push_back(sid);
  }
  for (const auto sid : ids) deleteSubscription(sid);
  sessions.erase(it);
}

// ---------------------------------------------------------------------------------------------
// Connections and chunks

Endpoint::Endpoint(AddressSpace& space, std::string endpoint_url, const ServerLimits& limits, bool read_only,
                   std::uint64_t seed)
    : impl_(std::make_unique<Impl>(space, std::move(endpoint_url), limits, read_only)) {
  impl_->random.seed(seed != 0 ? seed : std::random_device{}());
  // ServerCapabilities: what a client may ask of this server at most
  AddressSpace& a = impl_->space;
  const NodeId caps = NodeId::num(2268);
  if (a.find(caps)) return;
  a.addObject(NodeId::num(id::kServer), caps, 0, "ServerCapabilities", id::kServerCapabilitiesType);
  auto property = [&a](const NodeId& parent, std::uint32_t n, const char* name, std::uint32_t type, Variant v) {
    Node& p = a.addVariable(parent, NodeId::num(n), 0, name, type, true);
    p.value_rank = v.is_array ? 1 : -1;
    p.value = std::move(v);
  };
  auto u32 = [](std::size_t n) { return Variant::uint32(static_cast<std::uint32_t>(n)); };
  property(caps, 2269, "ServerProfileArray", 12, Variant::strings({"http://opcfoundation.org/UA-Profile/Server/MicroEmbeddedDevice"}));
  property(caps, 2271, "LocaleIdArray", id::kLocaleId, Variant::strings({}));
  property(caps, 2272, "MinSupportedSampleRate", id::kDuration, Variant::dbl(0));
  property(caps, 2735, "MaxBrowseContinuationPoints", 5, Variant::of(BuiltinType::UInt16, std::uint64_t{limits.continuation_points}));
  property(caps, 2736, "MaxQueryContinuationPoints", 5, Variant::of(BuiltinType::UInt16, std::uint64_t{0}));
  property(caps, 2737, "MaxHistoryContinuationPoints", 5, Variant::of(BuiltinType::UInt16, std::uint64_t{0}));
  property(caps, 11702, "MaxArrayLength", 7, u32(limits.message_bytes));
  property(caps, 11703, "MaxStringLength", 7, u32(limits.message_bytes));
  property(caps, 12911, "MaxByteStringLength", 7, u32(limits.message_bytes));
  property(caps, 24095, "MaxSessions", 7, u32(limits.sessions));
  property(caps, 24098, "MaxSubscriptionsPerSession", 7, u32(limits.subscriptions_per_session));
  property(caps, 24104, "MaxMonitoredItemsPerSubscription", 7, u32(limits.items_per_subscription));
  const NodeId ops = NodeId::num(11704);
  a.addObject(caps, ops, 0, "OperationLimits", id::kOperationLimitsType);
  const std::size_t per = limits.nodes_per_request;
  for (const auto& [n, name, value] : std::initializer_list<std::tuple<std::uint32_t, const char*, std::size_t>>{
           {11705, "MaxNodesPerRead", per}, {11707, "MaxNodesPerWrite", per}, {11709, "MaxNodesPerMethodCall", per},
           {11710, "MaxNodesPerBrowse", per}, {11711, "MaxNodesPerRegisterNodes", per},
           {11712, "MaxNodesPerTranslateBrowsePathsToNodeIds", per}, {11713, "MaxNodesPerNodeManagement", 0},
           {11714, "MaxMonitoredItemsPerCall", per}}) {
    property(ops, n, name, 7, u32(value));
  }
}

Endpoint::~Endpoint() = default;

ConnectionId Endpoint::open(const std::string& peer) {
  const ConnectionId id = impl_->next_connection++;
  impl_->connections[id].peer = peer;
  ++impl_->stats.connections;
  return id;
}

void Endpoint::close(ConnectionId c) {
  impl_->connections.erase(c);
  // what waits to be answered on it goes with it (its asked-for steps are still taken)
  std::erase_if(impl_->calls, [c](const PendingCall& p) { return p.to.connection == c; });
  for (auto& [number, s] : impl_->sessions) {
    std::erase_if(s.publish, [c](const PublishRequest& p) { return p.to.connection == c; });
  }
}

std::string Endpoint::takeOutput(ConnectionId c) {
  const auto it = impl_->connections.find(c);
  if (it == impl_->connections.end()) return {};
  return std::exchange(it->second.out, {});
}

bool Endpoint::hasOutput(ConnectionId c) const {
  const auto it = impl_->connections.find(c);
  return it != impl_->connections.end() && !it->second.out.empty();
}

bool Endpoint::receive(ConnectionId id, const std::uint8_t* data, std::size_t size) {
  const auto it = impl_->connections.find(id);
  if (it == impl_->connections.end()) return false;
  Connection& c = it->second;
  if (c.closing) return false;
  impl_->now = Clock::now();
  c.in.append(reinterpret_cast<const char*>(data), size);
  std::size_t at = 0;
  bool ok = true;
  while (ok && c.in.size() - at >= 8) {
    Decoder head(std::string_view(c.in).substr(at + 4, 4));
    const std::uint32_t length = head.u32();
    const std::uint32_t limit = c.hello ? c.receive_buffer : 8192;  // before Hello: a Hello's worth
    if (length < 8 || length > std::max(limit, impl_->limits.buffer_bytes)) {
      ok = impl_->error(c, status::kBadTcpMessageTooLarge,
                        "a chunk of " + std::to_string(length) + " bytes (at most " + std::to_string(limit) + ")");
      break;
    }
    if (c.in.size() - at < length) break;
    ok = impl_->chunk(id, c, std::string_view(c.in).substr(at, length));
    at += length;
  }
  c.in.erase(0, at);
  if (!ok) {
    c.closing = true;
    if (!c.goodbye) ++impl_->stats.dropped;
  }
  return ok;
}

bool EndpointState::error(Connection& c, StatusCode code, const std::string& reason) {
  std::string body;
  Encoder e(body);
  e.u32(code);
  e.string(reason.substr(0, 4096));
  std::string msg = "ERRF";
  Encoder(msg).u32(static_cast<std::uint32_t>(8 + body.size()));
  c.out += msg + body;
  c.closing = true;
  return false;
}

void EndpointState::sendChunks(Connection& c, const char* type, std::uint32_t request_id, const std::string& body) {
  const bool asymmetric = type[0] == 'O';
  std::string security;
  Encoder s(security);
  if (asymmetric) {
    s.string(kPolicyNone);
    s.nullString();  // sender certificate
    s.nullString();  // receiver thumbprint
  } else {
    s.u32(c.send_token);
  }
  const std::size_t overhead = 12 + security.size() + 8;
  const std::size_t room = c.send_buffer > overhead ? c.send_buffer - overhead : 1;
  std::size_t chunks = (body.size() + room - 1) / room;
  if (chunks == 0) chunks = 1;
  const std::size_t most = c.max_send_message != 0 ? std::min<std::size_t>(c.max_send_message, limits.response_bytes) : limits.response_bytes;
  if (body.size() > most || (c.max_send_chunks != 0 && chunks > c.max_send_chunks)) {
    if (body.size() <= 64) {  // not even a fault fits: the client's limits leave no room for an answer
      error(c, status::kBadTcpMessageTooLarge, "the client takes no message of " + std::to_string(body.size()) + " bytes");
      return;
    }
    // too large for the client: a fault in its place (the handle is the response header's, after the type)
    Decoder d(body);
    (void)d.nodeId();
    (void)d.i64();
    const std::uint32_t handle = d.u32();
    std::string fault_body;
    Encoder f(fault_body);
    f.nodeId(NodeId::num(kServiceFault));
    fault_body += responseHeader(handle, status::kBadResponseTooLarge);
    return sendChunks(c, type, request_id, fault_body);
  }
  for (std::size_t k = 0; k < chunks; ++k) {
    const std::string_view part = std::string_view(body).substr(k * room, room);
    std::string chunk(type, 3);
    chunk += k + 1 == chunks ? 'F' : 'C';
    Encoder e(chunk);
    e.u32(static_cast<std::uint32_t>(12 + security.size() + 8 + part.size()));
    e.u32(c.channel);
    chunk += security;
    e.u32(++c.send_sequence);
    e.u32(request_id);
    chunk += part;
    c.out += chunk;
  }
}

bool Endpoint::Impl::chunk(ConnectionId id, Connection& c, std::string_view bytes) {
  const std::string_view type = bytes.substr(0, 3);
  const char final = bytes[3];
  Decoder d(bytes.substr(8));
  try {
    if (type == "HEL") {
      if (c.hello) return error(c, status::kBadTcpMessageTypeInvalid, "a second Hello");
      if (final != 'F') return error(c, status::kBadTcpMessageTypeInvalid, "a Hello in chunks");
      return hello(c, d);
    }
    if (!c.hello) return error(c, status::kBadTcpMessageTypeInvalid, "'" + std::string(type) + "' before Hello");
    if (type == "OPN") {
      if (final != 'F') return error(c, status::kBadTcpMessageTypeInvalid, "an OpenSecureChannel in chunks");
      return openChannel(id, c, d);
    }
    if (type != "MSG" && type != "CLO") return error(c, status::kBadTcpMessageTypeInvalid, "no message type '" + std::string(type) + "'");
    if (c.channel == 0) return error(c, status::kBadTcpSecureChannelUnknown, "a message before OpenSecureChannel");
    if (d.u32() != c.channel) return error(c, status::kBadTcpSecureChannelUnknown, "a message for another secure channel");
    const std::uint32_t token = d.u32();
    if (token == c.token && c.previous_token != 0) {
      // the client uses the renewed token: the old one is done, and the server's answers take the new one
      c.previous_token = 0;
      c.send_token = c.token;
    } else if (token != c.token && (token != c.previous_token || token == 0)) {
      return error(c, status::kBadSecureChannelIdInvalid, "a message with an unknown security token");
    }
    const std::uint32_t sequence = d.u32();
    const std::uint32_t request_id = d.u32();
    // sequence numbers go up by one (they may wrap below 1024 after 4294966271)
    if (c.sequenced && sequence != c.receive_sequence + 1 && !(c.receive_sequence > 4294966271u && sequence < 1024)) {
      return error(c, status::kBadSequenceNumberInvalid, "sequence number " + std::to_string(sequence) + " after " +
                                                             std::to_string(c.receive_sequence));
    }
    c.receive_sequence = sequence;
    c.sequenced = true;
    if (type == "CLO") {  // the client says goodbye
      c.goodbye = true;
      c.closing = true;
      return false;
    }
    switch (final) {
      case 'A':  // the client gave up on the message
        c.partial.clear();
        c.partial_chunks = 0;
        return true;
      case 'C':
      case 'F': break;
      default: return error(c, status::kBadTcpMessageTypeInvalid, std::string("chunk type '") + final + "'");
    }
    if (c.partial_chunks > 0 && request_id != c.partial_request) {
      return error(c, status::kBadTcpMessageTypeInvalid, "chunks of two requests interleaved");
    }
    c.partial_request = request_id;
    c.partial += d.rest();
    ++c.partial_chunks;
    if (c.partial.size() > limits.message_bytes || c.partial_chunks > limits.chunks) {
      return error(c, status::kBadTcpMessageTooLarge,
                   "a request of more than " + std::to_string(limits.message_bytes) + " bytes or " + std::to_string(limits.chunks) + " chunks");
    }
    if (final == 'C') return true;
    const std::string body = std::exchange(c.partial, {});
    c.partial_chunks = 0;
    request(id, c, request_id, body);
    return !c.closing;
  } catch (const DecodeError& e) {
    return error(c, e.status(), e.what());
  }
}

bool Endpoint::Impl::hello(Connection& c, Decoder& d) {
  (void)d.u32();  // protocol version: 0 is all there is
  const std::uint32_t client_receive = d.u32();
  const std::uint32_t client_send = d.u32();
  const std::uint32_t max_message = d.u32();
  const std::uint32_t max_chunks = d.u32();
  (void)d.string(4096);  // the endpoint URL
  if (client_receive < 8192 || client_send < 8192) {
    return error(c, status::kBadTcpNotEnoughResources, "buffers of fewer than 8192 bytes");
  }
  c.hello = true;
  c.receive_buffer = std::min(client_send, limits.buffer_bytes);
  c.send_buffer = std::min(client_receive, limits.buffer_bytes);
  c.max_send_message = max_message;
  c.max_send_chunks = max_chunks;
  std::string body;
  Encoder e(body);
  e.u32(0);
  e.u32(c.receive_buffer);
  e.u32(c.send_buffer);
  e.u32(limits.message_bytes);
  e.u32(limits.chunks);
  std::string msg = "ACKF";
  Encoder(msg).u32(static_cast<std::uint32_t>(8 + body.size()));
  c.out += msg + body;
  return true;
}

bool Endpoint::Impl::openChannel(ConnectionId id, Connection& c, Decoder& d) {
  const std::uint32_t channel = d.u32();
  const std::string policy = d.string(4096);
  (void)d.string();  // sender certificate
  (void)d.string();  // receiver thumbprint
  if (policy != kPolicyNone) {
    return error(c, status::kBadSecurityPolicyRejected, "security policy '" + policy + "': gdpn offers None only");
  }
  const std::uint32_t sequence = d.u32();
  const std::uint32_t request_id = d.u32();
  c.receive_sequence = sequence;
  c.sequenced = true;
  if (d.nodeId() != NodeId::num(kOpenSecureChannel)) {
    return error(c, status::kBadTcpMessageTypeInvalid, "an OPN message that is no OpenSecureChannel request");
  }
  const RequestHeader h = readRequestHeader(d);
  (void)d.u32();  // client protocol version
  const std::uint32_t request_type = d.u32();
  const std::uint32_t mode = d.u32();
  (void)d.string();  // client nonce
  const std::uint32_t lifetime = d.u32();
  if (mode != 1) return error(c, status::kBadSecurityModeRejected, "security mode " + std::to_string(mode) + ": gdpn offers None (1) only");
  if (request_type == 0) {
    if (c.channel != 0 || channel != 0) return error(c, status::kBadTcpSecureChannelUnknown, "a second secure channel on one connection");
    c.channel = next_channel++;
  } else if (request_type == 1) {
    if (c.channel == 0 || channel != c.channel) return error(c, status::kBadTcpSecureChannelUnknown, "a renewal of an unknown secure channel");
  } else {
    return error(c, status::kBadTcpMessageTypeInvalid, "request type " + std::to_string(request_type));
  }
  if (request_type == 1) c.previous_token = c.token;  // still taken until the client uses the new one
  ++c.token;
  if (request_type == 0) c.send_token = c.token;
  std::string body;
  Encoder e(body);
  e.nodeId(NodeId::num(kOpenSecureChannel + 3));
  body += responseHeader(h.handle);
  e.u32(0);
  e.u32(c.channel);
  e.u32(c.token);
  e.i64(dateTimeNow());
  e.u32(std::clamp<std::uint32_t>(lifetime, 10000, 3600000));
  e.string("");  // server nonce: none with policy None
  ++stats.requests;
  sendChunks(c, "OPN", request_id, body);
  (void)id;
  return true;
}

void Endpoint::Impl::request(ConnectionId id, Connection& c, std::uint32_t request_id, std::string_view body) {
  Decoder d(body);
  const NodeId type = d.nodeId();
  RequestHeader h;
  try {
    h = readRequestHeader(d);
  } catch (const DecodeError& e) {
    error(c, status::kBadDecodingError, std::string("a request header that cannot be read: ") + e.what());
    return;
  }
  const Pending to{id, request_id, h.handle};
  try {
    if (type.ns != 0 || type.kind != NodeId::Kind::Numeric) return fault(to, status::kBadServiceUnsupported);
    StatusCode why = status::kGood;
    switch (type.numeric) {
      case kGetEndpoints: {
        (void)d.string(4096);
        (void)d.strings();
        (void)d.strings();
        std::string out = responseHeader(h.handle);
        out += endpoints();
        return respond(to, kGetEndpoints, out);
      }
      case kFindServers: {
        (void)d.string(4096);
        (void)d.strings();
        (void)d.strings();
        std::string out = responseHeader(h.handle);
        Encoder(out).length(1);
        out += application();
        return respond(to, kFindServers, out);
      }
      case kCreateSession: return createSession(to, c, d);
      case kActivateSession: return activateSession(to, c, h, d);
      case kCloseSession: {
        Session* s = session(c, h, why, false);
        if (!s) return fault(to, why);
        const bool del = d.boolean();
        closeSession(s->number, del);
        return respond(to, kCloseSession, responseHeader(h.handle));
      }
      case kCancel: {
        Session* s = session(c, h, why);
        if (!s) return fault(to, why);
        std::string out = responseHeader(h.handle);
        Encoder(out).u32(0);  // nothing cancelled: gdpn answers every request at once but Publish
        return respond(to, kCancel, out);
      }
      default: break;
    }
    // the rest need an activated session
    const bool known = type.numeric == kBrowse || type.numeric == kBrowseNext || type.numeric == kTranslateBrowsePaths ||
                       type.numeric == kRegisterNodes || type.numeric == kUnregisterNodes || type.numeric == kRead ||
                       type.numeric == kWrite || type.numeric == kCall || type.numeric == kCreateMonitoredItems ||
                       type.numeric == kModifyMonitoredItems || type.numeric == kSetMonitoringMode ||
                       type.numeric == kDeleteMonitoredItems || type.numeric == kCreateSubscription ||
                       type.numeric == kModifySubscription || type.numeric == kSetPublishingMode ||
                       type.numeric == kPublish || type.numeric == kRepublish || type.numeric == kDeleteSubscriptions;
    if (!known) return fault(to, status::kBadServiceUnsupported);
    Session* s = session(c, h, why);
    if (!s) return fault(to, why);
    switch (static_cast<Service>(type.numeric)) {
      case kBrowse: return browse(to, *s, d);
      case kBrowseNext: return browseNext(to, *s, d);
      case kTranslateBrowsePaths: return translate(to, d);
      case kRegisterNodes: return registerNodes(to, d, true);
      case kUnregisterNodes: return registerNodes(to, d, false);
      case kRead: return read(to, d);
      case kWrite: return write(to, *s, d);
      case kCall: return call(to, d);
      case kCreateSubscription: return createSubscription(to, *s, d);
      case kModifySubscription: return modifySubscription(to, *s, d);
      case kSetPublishingMode: return setPublishingMode(to, *s, d);
      case kDeleteSubscriptions: return deleteSubscriptions(to, *s, d);
      case kCreateMonitoredItems: return createItems(to, *s, d);
      case kModifyMonitoredItems: return modifyItems(to, *s, d);
      case kSetMonitoringMode: return setMonitoringMode(to, *s, d);
      case kDeleteMonitoredItems: return deleteItems(to, *s, d);
      case kPublish: return publish(to, *s, d, h.timeout_hint);
      case kRepublish: return republish(to, *s, d);
      case kFindServers:
      case kGetEndpoints:
      case kOpenSecureChannel:
      case kCloseSecureChannel:
      case kCreateSession:
      case kActivateSession:
      case kCloseSession:
      case kCancel: break;
    }
    return fault(to, status::kBadServiceUnsupported);
  } catch (const DecodeError& e) {
    fault(to, e.status());
  }
}

// ---------------------------------------------------------------------------------------------
// Discovery and sessions

std::string Endpoint::Impl::application() const {
  std::string out;
  Encoder e(out);
  e.string("urn:gdpn:server");
  e.string("https://gdpn.dev/gdpn");
  e.localizedText({"", space.namespaces().size() > 1 ? "gdpn: " + space.namespaces()[1] : "gdpn"});
  e.u32(0);  // server
  e.nullString();
  e.nullString();
  e.strings({url});
  return out;
}

std::string Endpoint::Impl::endpoints() const {
  std::string out;
  Encoder e(out);
  e.length(1);
  e.string(url);
  out += application();
  e.nullString();  // certificate
  e.u32(1);        // MessageSecurityMode None
  e.string(kPolicyNone);
  e.length(1);     // anonymous only
  e.string("anonymous");
  e.u32(0);
  e.nullString();
  e.nullString();
  e.nullString();
  e.string(kTransportProfile);
  e.u8(0);
  return out;
}

void Endpoint::Impl::createSession(const Pending& to, Connection& c, Decoder& d) {
  // client description
  (void)d.string(4096);
  (void)d.string(4096);
  (void)d.localizedText();
  (void)d.u32();
  (void)d.string(4096);
  (void)d.string(4096);
  (void)d.strings();
  (void)d.string(4096);  // server URI
  (void)d.string(4096);  // endpoint URL
  const std::string name = d.string(4096);
  (void)d.string();  // client nonce
  (void)d.string();  // client certificate
  const double timeout = d.f64();
  const std::uint32_t max_response = d.u32();
  (void)max_response;
  if (sessions.size() >= limits.sessions) {
    // full: the oldest session never activated, or whose channel has gone, makes room
    auto live = [this](std::uint32_t channel) {
      return std::any_of(connections.begin(), connections.end(),
                         [channel](const auto& kv) { return kv.second.channel == channel && !kv.second.closing; });
    };
    const Session* oldest = nullptr;
    for (const auto& [number, candidate] : sessions) {
      if ((!candidate.activated || !live(candidate.channel)) && (!oldest || candidate.last_seen < oldest->last_seen)) oldest = &candidate;
    }
    if (!oldest) return fault(to, status::kBadTooManySessions);
    closeSession(oldest->number, true);
  }
  Session s;
  s.number = next_session++;
  s.id = NodeId{1, NodeId::Kind::Opaque, 0, randomBytes(16)};
  s.token = NodeId{0, NodeId::Kind::Opaque, 0, randomBytes(32)};
  s.name = name.empty() ? c.peer : name;
  s.timeout = std::isfinite(timeout) ? std::clamp(timeout, 10000.0, 3600000.0) : 60000.0;
  s.last_seen = now;
  s.created = now;
  s.channel = c.channel;
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.nodeId(s.id);
  e.nodeId(s.token);
  e.f64(s.timeout);
  e.string(randomBytes(32));  // server nonce
  e.nullString();             // certificate
  out += endpoints();
  e.length(0);                // software certificates
  e.nullString();             // signature: algorithm
  e.nullString();             //            signature
  e.u32(limits.message_bytes);
  sessions[s.number] = std::move(s);
  ++stats.sessions;
  respond(to, kCreateSession, out);
}

void Endpoint::Impl::activateSession(const Pending& to, Connection& c, const RequestHeader& h, Decoder& d) {
  StatusCode why = status::kGood;
  Session* s = nullptr;
  for (auto& [number, candidate] : sessions) {
    if (candidate.token == h.token) s = &candidate;
  }
  if (!s) return fault(to, status::kBadSessionIdInvalid);
  (void)d.string(4096);  // client signature: algorithm
  (void)d.string();      //                   signature
  const std::size_t certificates = d.length(8);
  for (std::size_t i = 0; i < certificates; ++i) {
    (void)d.string();
    (void)d.string();
  }
  (void)d.strings();  // locales
  const ExtensionObject token = d.extensionObject();
  (void)d.string(4096);  // user token signature
  (void)d.string();
  if (token.type == NodeId::num(kUserNameToken) || token.type == NodeId::num(kX509Token) || token.type == NodeId::num(kIssuedToken)) {
    return fault(to, status::kBadIdentityTokenRejected);
  }
  if (!token.type.isNull() && token.type != NodeId::num(kAnonymousToken)) return fault(to, status::kBadIdentityTokenInvalid);
  if (!token.type.isNull()) {
    Decoder body(token.body);
    const std::string policy = body.string(4096);
    if (!policy.empty() && policy != "anonymous") return fault(to, status::kBadIdentityTokenInvalid);
  }
  (void)why;
  s->activated = true;
  s->channel = c.channel;  // a client that reconnects brings its session to the new channel
  s->last_seen = now;
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.string(randomBytes(32));
  e.length(0);
  e.length(0);
  respond(to, kActivateSession, out);
}

// ---------------------------------------------------------------------------------------------
// Time and steps

DateTime Endpoint::modelTime(double seconds) {
  return 125911584000000000 + std::llround(seconds * 1e7);  // 2000-01-01 00:00 UTC
}

void Endpoint::sample(double seconds) {
  impl_->model_time = modelTime(seconds);
  impl_->now = Clock::now();
  impl_->sampleAll();
}

void Endpoint::tick(Clock::time_point now) {
  impl_->now = now;
  // sessions that were not heard of for their timeout
  std::vector<std::uint64_t> expired;
  for (auto& [number, s] : impl_->sessions) {
    // a session not heard of for its timeout, or not activated within 10 s, goes
    if (now - s.last_seen > std::chrono::duration<double, std::milli>(s.timeout) ||
        (!s.activated && now - s.created > std::chrono::seconds(10))) {
      expired.push_back(number);
    }
    // Publish requests past their timeout hint
    for (auto it = s.publish.begin(); it != s.publish.end();) {
      if (it->deadline >= now) {
        ++it;
        continue;
      }
      impl_->fault(it->to, status::kBadTimeout, false);
      it = s.publish.erase(it);
    }
  }
  for (const auto n : expired) impl_->closeSession(n, true);
  impl_->publishDue();
}

Endpoint::Clock::time_point Endpoint::nextDue() const {
  auto due = Clock::time_point::max();
  for (const auto& [id, sub] : impl_->subscriptions) due = std::min(due, sub.due);
  return due;
}

void Endpoint::setLockstep(bool on) { impl_->lockstep = on; }
std::uint64_t Endpoint::pendingSteps() const { return impl_->asked - impl_->taken; }

void Endpoint::stepTaken() {
  if (impl_->taken < impl_->asked) ++impl_->taken;
  impl_->answerCalls();
}

const EndpointStats& Endpoint::stats() const { return impl_->stats; }
std::size_t Endpoint::sessions() const { return impl_->sessions.size(); }

}  // namespace gdpn::opcua
