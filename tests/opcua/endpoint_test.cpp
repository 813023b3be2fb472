// The OPC UA endpoint without sockets: bytes in, bytes out. A small client written here from
// Part 6 speaks to it: the handshake, sessions (and their limit), reads and writes with their
// status codes, Browse with continuation points, a Step call that waits for the run's steps,
// subscriptions sampled at step boundaries with a deadband, and hostile streams (malformed
// chunks, oversized messages, unknown services) that close their own connection only.

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "gdpn/opcua/endpoint.h"
#include "gdpn/opcua/status.h"

namespace gdpn::opcua {
namespace {

using namespace std::chrono_literals;

/// An address space with a writable Double, a read-only Int32, a Step method and 30 children.
struct Space {
  AddressSpace space{{"http://opcfoundation.org/UA/", "urn:gdpn:model:test"}, "urn:gdpn:server", "gdpn", "test"};
  double x = 1.5;
  std::int32_t count = 7;
  Space() {
    const NodeId model = NodeId::str("model");
    space.addObject(NodeId::num(id::kObjectsFolder), model, 1, "test", id::kBaseObjectType);
    space.addObject(model, NodeId::str("io"), 1, "IO");
    Node& v = space.addVariable(NodeId::str("io"), NodeId::str("io/x"), 1, "x", 11);
    v.read = [this] { return Variant::dbl(x); };
    v.write = [this](const Variant& value) {
      x = *value.number();
      return StatusCode{0};
    };
    v.numeric = true;
    space.addVariable(NodeId::str("io"), NodeId::str("io/count"), 1, "count", 6).read = [this] { return Variant::int32(count); };
    for (int i = 0; i < 30; ++i) {
      space.addVariable(model, NodeId::str("v" + std::to_string(i)), 1, "v" + std::to_string(i), 11).value = Variant::dbl(i);
    }
    Node m;
    m.id = NodeId::str("step");
    m.node_class = NodeClass::Method;
    m.browse_name = {1, "Step"};
    m.executable = true;
    m.references.push_back({NodeId::num(id::kHasComponent), model, false});
    m.call = [](const std::vector<Variant>& in, std::vector<Variant>& out, std::vector<StatusCode>&, CallContext& ctx) {
      if (in.size() != 1 || in[0].type != BuiltinType::UInt32) return status::kBadInvalidArgument;
      if (!ctx.lockstep) return status::kBadInvalidState;
      ctx.wait_steps = static_cast<std::uint32_t>(std::get<std::uint64_t>(in[0].scalar));
      ctx.complete = [](std::vector<Variant>& o) { o = {Variant::dbl(1.0)}; };
      out.clear();
      return status::kGood;
    };
    space.add(std::move(m));
  }
};

/// A response taken apart: its type (the encoding's number) and a decoder after its header's
/// request handle, at the service result.
struct Reply {
  std::uint32_t type = 0;
  std::uint32_t handle = 0;
  StatusCode result = 0;
  std::string body;  // after the response header
};

/// A client of the endpoint, one connection.
class TestClient {
 public:
  TestClient(Endpoint& ep) : ep_(ep), id_(ep.open("test:1")) {}

  /// Sends raw bytes; false when the endpoint closes the connection.
  bool send(const std::string& bytes) {
    open_ = ep_.receive(id_, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) && open_;
    received_ += ep_.takeOutput(id_);
    return open_;
  }
  [[nodiscard]] bool open() const { return open_; }

  static std::string frame(const char* type, char final, const std::string& body) {
    std::string out(type, 3);
    out += final;
    Encoder(out).u32(static_cast<std::uint32_t>(8 + body.size()));
    return out + body;
  }
  std::string hello(std::uint32_t buffer = 65536) {
    std::string body;
    Encoder e(body);
    e.u32(0);
    e.u32(buffer);
    e.u32(buffer);
    e.u32(0);
    e.u32(0);
    e.string("opc.tcp://localhost:4840");
    return frame("HEL", 'F', body);
  }
  std::string requestHeader(std::uint32_t handle) {
    std::string out;
    Encoder e(out);
    e.nodeId(token_);
    e.i64(0);
    e.u32(handle);
    e.u32(0);
    e.nullString();
    e.u32(10000);
    e.nodeId({});
    e.u8(0);
    return out;
  }
  std::string openChannel(std::uint32_t request_type = 0) {
    std::string body;
    Encoder e(body);
    e.u32(request_type == 0 ? 0 : channel_);
    e.string("http://opcfoundation.org/UA/SecurityPolicy#None");
    e.nullString();
    e.nullString();
    e.u32(++sequence_);
    e.u32(++request_);
    e.nodeId(NodeId::num(446));
    body += requestHeader(1);
    e.u32(0);
    e.u32(request_type);
    e.u32(1);
    e.nullString();
    e.u32(600000);
    return frame("OPN", 'F', body);
  }
  /// Renews the channel's token; the token the answer gives (the client keeps using the old
  /// one until it says `useNewToken()`).
  std::uint32_t renew() {
    received_.clear();
    send(openChannel(1));
    received_ += ep_.takeOutput(id_);
    if (received_.substr(0, 4) != "OPNF") return 0;
    const auto [channel, token] = openAnswer();
    (void)channel;
    received_.clear();
    return token;
  }
  /// The channel and token an OpenSecureChannel answer (first in what was received) gives.
  std::pair<std::uint32_t, std::uint32_t> openAnswer() {
    Decoder d(std::string_view(received_).substr(8));
    const std::uint32_t channel = d.u32();
    (void)d.string();
    (void)d.string();
    (void)d.string();
    (void)d.u32();
    (void)d.u32();
    EXPECT_EQ(d.nodeId(), NodeId::num(449));
    (void)d.i64();
    (void)d.u32();
    EXPECT_EQ(d.u32(), 0u);
    d.skipDiagnosticInfo();
    (void)d.strings();
    (void)d.extensionObject();
    (void)d.u32();
    EXPECT_EQ(d.u32(), channel);
    return {channel, d.u32()};
  }
  void useToken(std::uint32_t token) { token_id_ = token; }
  [[nodiscard]] std::uint32_t token() const { return token_id_; }
  /// A request `type` whose fields after the header are `fields`, in one chunk.
  std::string message(std::uint32_t type, const std::string& fields, char final = 'F') {
    std::string body;
    Encoder e(body);
    e.u32(channel_);
    e.u32(token_id_);
    e.u32(++sequence_);
    e.u32(++request_);
    e.nodeId(NodeId::num(type));
    body += requestHeader(request_);
    body += fields;
    return frame("MSG", final, body);
  }
  /// Hello, OpenSecureChannel, and what they answer.
  void connect() {
    ASSERT_TRUE(send(hello()));
    ASSERT_EQ(received_.substr(0, 4), "ACKF");
    received_.clear();
    ASSERT_TRUE(send(openChannel()));
    ASSERT_EQ(received_.substr(0, 4), "OPNF");
    std::tie(channel_, token_id_) = openAnswer();
    received_.clear();
  }
  /// The replies received so far, taken.
  std::vector<Reply> replies() {
    received_ += ep_.takeOutput(id_);
    std::vector<Reply> out;
    std::size_t at = 0;
    while (received_.size() - at >= 8) {
      Decoder h(std::string_view(received_).substr(at + 4, 4));
      const std::uint32_t size = h.u32();
      if (received_.compare(at, 3, "MSG") != 0 || received_[at + 3] != 'F') break;
      Decoder d(std::string_view(received_).substr(at + 24, size - 24));
      Reply r;
      r.type = d.nodeId().numeric;
      (void)d.i64();
      r.handle = d.u32();
      r.result = d.u32();
      d.skipDiagnosticInfo();
      (void)d.strings();
      (void)d.extensionObject();
      r.body = std::string(d.rest());
      out.push_back(std::move(r));
      at += size;
    }
    received_.erase(0, at);
    return out;
  }
  /// Sends a request and returns its one reply.
  Reply call(std::uint32_t type, const std::string& fields) {
    send(message(type, fields));
    auto r = replies();
    EXPECT_EQ(r.size(), 1u);
    return r.empty() ? Reply{} : r.front();
  }
  /// CreateSession and ActivateSession (anonymous); the result of the first that fails.
  StatusCode session() {
    std::string fields;
    Encoder e(fields);
    e.nullString();
    e.nullString();
    e.localizedText({});
    e.u32(1);
    e.nullString();
    e.nullString();
    e.length(0);
    e.nullString();
    e.string("opc.tcp://localhost:4840");
    e.string("test");
    e.string(std::string(32, 'n'));
    e.nullString();
    e.f64(60000);
    e.u32(0);
    const Reply created = call(461, fields);
    if (created.result != 0) return created.result;
    Decoder d(created.body);
    (void)d.nodeId();
    token_ = d.nodeId();
    std::string act;
    Encoder a(act);
    a.nullString();
    a.nullString();
    a.length(0);
    a.length(0);
    std::string policy;
    Encoder(policy).string("anonymous");
    a.extensionObject({NodeId::num(321), 1, policy});
    a.nullString();
    a.nullString();
    return call(467, act).result;
  }
  /// Read of `node`'s Value: the DataValue.
  DataValue read(const NodeId& node, std::uint32_t attribute = 13) {
    std::string f;
    Encoder e(f);
    e.f64(0);
    e.u32(2);
    e.length(1);
    e.nodeId(node);
    e.u32(attribute);
    e.nullString();
    e.qualifiedName({});
    const Reply r = call(631, f);
    Decoder d(r.body);
    EXPECT_EQ(d.length(), 1u);
    return d.dataValue();
  }
  /// Write of `node`'s Value: its status.
  StatusCode write(const NodeId& node, const Variant& v) {
    std::string f;
    Encoder e(f);
    e.length(1);
    e.nodeId(node);
    e.u32(13);
    e.nullString();
    e.dataValue({v, std::nullopt, std::nullopt, std::nullopt});
    const Reply r = call(673, f);
    Decoder d(r.body);
    return d.length() == 1 ? d.u32() : r.result;
  }

 private:
  Endpoint& ep_;
  ConnectionId id_;
  bool open_ = true;
  std::string received_;
  std::uint32_t channel_ = 0, token_id_ = 0, sequence_ = 0, request_ = 0;
  NodeId token_;
};

/// The test space served, and one client connected with an activated session.
struct Connected {
  Space s;
  Endpoint ep{s.space, "opc.tcp://127.0.0.1:4840"};
  TestClient c{ep};
  Connected() {
    c.connect();
    EXPECT_EQ(c.session(), 0u);
  }
};

TEST(OpcuaEndpoint, ConnectsReadsAndWritesWithTheRightStatusCodes) {
  Space s;
  Endpoint ep(s.space, "opc.tcp://127.0.0.1:4840");
  TestClient c(ep);
  c.connect();
  // nothing but discovery before a session
  EXPECT_EQ(c.call(631, "").result, status::kBadSessionIdInvalid);
  ASSERT_EQ(c.session(), status::kGood);
  const DataValue ns = c.read(NodeId::num(id::kNamespaceArray));
  ASSERT_TRUE(ns.value);
  ASSERT_EQ(ns.value->elements.size(), 2u);
  EXPECT_EQ(std::get<std::string>(ns.value->elements[1].scalar), "urn:gdpn:model:test");
  EXPECT_EQ(*c.read(NodeId::num(id::kServerStatusState)).value->number(), 0.0);  // Running
  EXPECT_EQ(*c.read(NodeId::num(24095)).value->number(), 32.0);  // ServerCapabilities.MaxSessions
  EXPECT_EQ(*c.read(NodeId::num(11705)).value->number(), 1000.0);  // OperationLimits.MaxNodesPerRead
  EXPECT_EQ(*c.read(NodeId::str("io/x")).value->number(), 1.5);
  EXPECT_EQ(c.read(NodeId::str("nothing")).status, status::kBadNodeIdUnknown);
  EXPECT_EQ(c.read(NodeId::str("io/x"), 99).status, status::kBadAttributeIdInvalid);
  EXPECT_EQ(c.read(NodeId::str("io"), 13).status, status::kBadAttributeIdInvalid);  // an object has no value
  // writes: the right type, else BadTypeMismatch; a read-only variable: BadNotWritable
  EXPECT_EQ(c.write(NodeId::str("io/x"), Variant::dbl(4.25)), status::kGood);
  EXPECT_EQ(s.x, 4.25);
  EXPECT_EQ(c.write(NodeId::str("io/x"), Variant::int32(4)), status::kBadTypeMismatch);
  EXPECT_EQ(c.write(NodeId::str("io/count"), Variant::int32(4)), status::kBadNotWritable);
  EXPECT_EQ(c.write(NodeId::num(id::kNamespaceArray), Variant::strings({"x"})), status::kBadNotWritable);
  EXPECT_EQ(s.count, 7);
  // an unknown service is answered, and the connection stays
  EXPECT_EQ(c.call(12208, "").result, status::kBadServiceUnsupported);  // FindServersOnNetwork
  EXPECT_EQ(c.call(9999, "").result, status::kBadServiceUnsupported);
  EXPECT_TRUE(c.open());
  EXPECT_EQ(*c.read(NodeId::str("io/x")).value->number(), 4.25);
}

TEST(OpcuaEndpoint, BrowsesWithContinuationPointsAndTranslatesPaths) {
  Connected served;
  auto& [s, ep, c] = served;
  std::string f;
  Encoder e(f);
  e.nodeId({});
  e.i64(0);
  e.u32(0);
  e.u32(10);  // ten references a node at most
  e.length(1);
  e.nodeId(NodeId::str("model"));
  e.u32(0);
  e.nodeId(NodeId::num(id::kHierarchical));
  e.boolean(true);
  e.u32(0);
  e.u32(63);
  const Reply r = c.call(527, f);
  Decoder d(r.body);
  ASSERT_EQ(d.length(), 1u);
  EXPECT_EQ(d.u32(), 0u);
  std::string point = d.string();
  std::size_t seen = d.length();
  EXPECT_EQ(seen, 10u);
  // IO, 30 variables, Step: 32 forward hierarchical references, ten at a time
  int rounds = 0;
  for (; rounds < 5 && !point.empty(); ++rounds) {
    std::string g;
    Encoder ge(g);
    ge.boolean(false);
    ge.strings({point});
    const Reply next = c.call(533, g);
    Decoder nd(next.body);
    ASSERT_EQ(nd.length(), 1u);
    EXPECT_EQ(nd.u32(), 0u);
    point = nd.string();
    const std::size_t n = nd.length();
    for (std::size_t i = 0; i < n; ++i) {
      (void)nd.nodeId();
      (void)nd.boolean();
      (void)nd.expandedNodeId();
      (void)nd.qualifiedName();
      (void)nd.localizedText();
      (void)nd.u32();
      (void)nd.expandedNodeId();
    }
    seen += n;
  }
  EXPECT_EQ(seen, 32u);
  EXPECT_EQ(rounds, 3);
  EXPECT_TRUE(point.empty());
  // a continuation point used up is invalid
  std::string g;
  Encoder ge(g);
  ge.boolean(false);
  ge.strings({"cp1"});
  const Reply bad_reply = c.call(533, g);
  Decoder bad(bad_reply.body);
  ASSERT_EQ(bad.length(), 1u);
  EXPECT_EQ(bad.u32(), status::kBadContinuationPointInvalid);
  // /1:test/1:IO from Objects
  std::string t;
  Encoder te(t);
  te.length(1);
  te.nodeId(NodeId::num(id::kObjectsFolder));
  te.length(2);
  for (const char* name : {"test", "IO"}) {
    te.nodeId(NodeId::num(id::kHierarchical));
    te.boolean(false);
    te.boolean(true);
    te.qualifiedName({1, name});
  }
  const Reply td_reply = c.call(554, t);
  Decoder td(td_reply.body);
  ASSERT_EQ(td.length(), 1u);
  EXPECT_EQ(td.u32(), 0u);
  ASSERT_EQ(td.length(), 1u);
  EXPECT_EQ(td.expandedNodeId().node, NodeId::str("io"));
}

TEST(OpcuaEndpoint, StepCallsAreAnsweredOnceTheRunHasTakenTheirSteps) {
  Connected served;
  auto& [s, ep, c] = served;
  auto step = [](std::uint32_t n) {
    std::string f;
    Encoder e(f);
    e.length(1);
    e.nodeId(NodeId::str("model"));
    e.nodeId(NodeId::str("step"));
    e.length(1);
    e.variant(Variant::uint32(n));
    return f;
  };
  // not in lockstep: BadInvalidState at once
  const Reply now_reply = c.call(712, step(3));
  Decoder now(now_reply.body);
  ASSERT_EQ(now.length(), 1u);
  EXPECT_EQ(now.u32(), status::kBadInvalidState);
  ep.setLockstep(true);
  c.send(c.message(712, step(3)));
  EXPECT_TRUE(c.replies().empty());
  EXPECT_EQ(ep.pendingSteps(), 3u);
  ep.stepTaken();
  ep.stepTaken();
  EXPECT_TRUE(c.replies().empty());
  ep.stepTaken();
  const auto r = c.replies();
  ASSERT_EQ(r.size(), 1u);
  Decoder d(r[0].body);
  ASSERT_EQ(d.length(), 1u);
  EXPECT_EQ(d.u32(), 0u);
  EXPECT_EQ(d.length(), 0u);
  EXPECT_EQ(d.length(), 0u);
  ASSERT_EQ(d.length(), 1u);
  EXPECT_EQ(*d.variant().number(), 1.0);
  EXPECT_EQ(ep.pendingSteps(), 0u);
  // a connection keeps 16 calls waiting at most: the 17th is refused at once
  for (int i = 0; i < 16; ++i) c.send(c.message(712, step(1)));
  EXPECT_TRUE(c.replies().empty());
  EXPECT_EQ(c.call(712, step(1)).result, status::kBadTooManyOperations);
  EXPECT_EQ(ep.pendingSteps(), 16u);
  for (int i = 0; i < 16; ++i) ep.stepTaken();
  EXPECT_EQ(c.replies().size(), 16u);
}

TEST(OpcuaEndpoint, SubscriptionsSampleAtStepBoundariesThroughTheDeadband) {
  Connected served;
  auto& [s, ep, c] = served;
  std::string f;
  Encoder e(f);
  e.f64(10);
  e.u32(100);
  e.u32(10);
  e.u32(0);
  e.boolean(true);
  e.u8(0);
  const Reply sd_reply = c.call(787, f);
  Decoder sd(sd_reply.body);
  const std::uint32_t sub = sd.u32();
  // io/x with an absolute deadband of 1
  std::string items;
  Encoder ie(items);
  ie.u32(sub);
  ie.u32(0);
  ie.length(1);
  ie.nodeId(NodeId::str("io/x"));
  ie.u32(13);
  ie.nullString();
  ie.qualifiedName({});
  ie.u32(2);
  ie.u32(42);  // client handle
  ie.f64(0);
  ExtensionObject filter{NodeId::num(724), 1, {}};
  Encoder fe(filter.body);
  fe.u32(1);
  fe.u32(1);
  fe.f64(1.0);
  ie.extensionObject(filter);
  ie.u32(10);
  ie.boolean(true);
  const Reply id_reply = c.call(751, items);
  Decoder id(id_reply.body);
  ASSERT_EQ(id.length(), 1u);
  ASSERT_EQ(id.u32(), 0u);
  // steps: x moves by 0.4 (within the deadband), then by 2 (beyond it)
  for (const double x : {1.9, 2.3, 4.3}) {
    s.x = x;
    ep.sample(0.1);
  }
  std::string p;
  Encoder(p).length(0);
  c.send(c.message(826, p));
  ep.tick(Endpoint::Clock::now() + 1s);
  const auto r = c.replies();
  ASSERT_EQ(r.size(), 1u);
  Decoder d(r[0].body);
  EXPECT_EQ(d.u32(), sub);
  (void)d.u32s();
  (void)d.boolean();
  (void)d.u32();
  (void)d.i64();
  ASSERT_EQ(d.length(), 1u);
  const ExtensionObject change = d.extensionObject();
  EXPECT_EQ(change.type, NodeId::num(811));
  Decoder cd(change.body);
  ASSERT_EQ(cd.length(), 2u);  // the first value, and 4.3; not 1.9 nor 2.3
  EXPECT_EQ(cd.u32(), 42u);
  EXPECT_EQ(*cd.dataValue().value->number(), 1.5);
  EXPECT_EQ(cd.u32(), 42u);
  const DataValue last = cd.dataValue();
  EXPECT_EQ(*last.value->number(), 4.3);
  EXPECT_EQ(last.source_time, Endpoint::modelTime(0.1));
}

TEST(OpcuaEndpoint, MalformedStreamsCloseTheirConnectionOnly) {
  Space s;
  Endpoint ep(s.space, "opc.tcp://127.0.0.1:4840");
  TestClient good(ep);
  good.connect();
  ASSERT_EQ(good.session(), 0u);
  auto closed = [&ep](const std::string& bytes, bool handshake) {
    TestClient c(ep);
    if (handshake) c.connect();
    c.send(bytes);
    return !c.open();
  };
  EXPECT_TRUE(closed("GET / HTTP/1.1\r\n\r\n", false));                  // no OPC UA
  EXPECT_TRUE(closed(TestClient::frame("MSG", 'F', "xxxx"), false));      // a message before Hello
  EXPECT_TRUE(closed(TestClient::frame("HEL", 'F', "abc"), false));       // a Hello cut short
  {
    std::string big = "MSGF";
    Encoder(big).u32(1u << 30);  // a chunk of a gigabyte announced
    EXPECT_TRUE(closed(big, true));
  }
  {
    TestClient c(ep);
    c.connect();
    std::string body(60000, 'x');
    bool open = true;
    for (int k = 0; k < 80 && open; ++k) open = c.send(c.message(631, body, 'C'));  // 4.8 MB in chunks
    EXPECT_FALSE(open);
  }
  {
    TestClient c(ep);
    c.connect();
    std::string s2 = c.message(631, "");
    s2[3] = 'Q';  // no such chunk type
    EXPECT_FALSE(c.send(s2));
  }
  {
    TestClient c(ep);
    c.connect();
    ASSERT_EQ(c.session(), 0u);
    std::string f;
    Encoder e(f);
    e.f64(0);
    e.u32(2);
    e.i32(1 << 28);  // 2^28 nodes in a few bytes
    EXPECT_EQ(c.call(631, f).result, status::kBadDecodingError);
    EXPECT_TRUE(c.open());
  }
  // the good client goes on
  EXPECT_EQ(*good.read(NodeId::str("io/x")).value->number(), 1.5);
  EXPECT_GE(ep.stats().dropped, 6u);
}

TEST(OpcuaEndpoint, ARenewedTokenAndTheOldOneServeUntilTheNewOneIsUsed) {
  Connected served;
  auto& [s, ep, c] = served;
  const std::uint32_t old_token = c.token();
  const std::uint32_t new_token = c.renew();
  ASSERT_NE(new_token, 0u);
  EXPECT_NE(new_token, old_token);
  // a request sent before the answer came, with the old token: answered
  EXPECT_EQ(*c.read(NodeId::str("io/x")).value->number(), 1.5);
  c.useToken(new_token);
  EXPECT_EQ(*c.read(NodeId::str("io/x")).value->number(), 1.5);
  // the new one used: the old one is done
  c.useToken(old_token);
  c.send(c.message(631, ""));
  EXPECT_FALSE(c.open());
}

TEST(OpcuaEndpoint, AnExpiredSubscriptionSaysSoInTheNextPublish) {
  Connected served;
  auto& [s, ep, c] = served;
  std::string f;
  Encoder e(f);
  e.f64(10);   // 10 ms
  e.u32(3);    // lifetime 3
  e.u32(1);    // keep-alive 1
  e.u32(0);
  e.boolean(true);
  e.u8(0);
  const Reply created = c.call(787, f);
  Decoder sd(created.body);
  const std::uint32_t sub = sd.u32();
  (void)sd.f64();
  EXPECT_EQ(sd.u32(), 3u);  // lifetime at least 3 keep-alives
  // no Publish request for many intervals
  auto t = Endpoint::Clock::now();
  for (int i = 0; i < 10; ++i) ep.tick(t += std::chrono::milliseconds(20));
  std::string p;
  Encoder(p).length(0);
  c.send(c.message(826, p));
  const auto r = c.replies();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].type, 829u);
  Decoder d(r[0].body);
  EXPECT_EQ(d.u32(), sub);
  (void)d.u32s();
  (void)d.boolean();
  (void)d.u32();
  (void)d.i64();
  ASSERT_EQ(d.length(), 1u);
  const ExtensionObject change = d.extensionObject();
  EXPECT_EQ(change.type, NodeId::num(820));  // StatusChangeNotification
  EXPECT_EQ(Decoder(change.body).u32(), status::kBadTimeout);
  // and it is gone
  std::string del;
  Encoder de(del);
  de.length(1);
  de.u32(sub);
  const Reply deleted = c.call(847, del);
  Decoder dd(deleted.body);
  ASSERT_EQ(dd.length(), 1u);
  EXPECT_EQ(dd.u32(), status::kBadSubscriptionIdInvalid);
}

TEST(OpcuaEndpoint, WorkARequestCanAskForIsBounded) {
  Connected served;
  auto& [s, ep, c] = served;
  // a relative path of 33 elements
  std::string t;
  Encoder te(t);
  te.length(1);
  te.nodeId(NodeId::num(id::kObjectsFolder));
  te.length(33);
  for (int k = 0; k < 33; ++k) {
    te.nodeId({});
    te.boolean(false);
    te.boolean(true);
    te.qualifiedName({1, "test"});
  }
  EXPECT_EQ(c.call(554, t).result, status::kBadTooManyOperations);
  // a Call whose argument is an array of Null elements, millions claimed in five bytes
  std::string f;
  Encoder e(f);
  e.length(1);
  e.nodeId(NodeId::str("model"));
  e.nodeId(NodeId::str("step"));
  e.length(1);
  e.u8(0x80);  // an array of Null
  e.i32(1 << 22);
  EXPECT_EQ(c.call(712, f).result, status::kBadDecodingError);
  EXPECT_TRUE(c.open());
}

TEST(OpcuaEndpoint, FortySessionsAtOnceGetThirtyTwo) {
  Space s;
  Endpoint ep(s.space, "opc.tcp://127.0.0.1:4840");
  std::vector<std::unique_ptr<TestClient>> clients;
  int ok = 0, refused = 0;
  for (int i = 0; i < 40; ++i) {
    clients.push_back(std::make_unique<TestClient>(ep));
    clients.back()->connect();
    const StatusCode r = clients.back()->session();
    ok += r == 0;
    refused += r == status::kBadTooManySessions;
  }
  EXPECT_EQ(ok, 32);
  EXPECT_EQ(refused, 8);
  EXPECT_EQ(ep.sessions(), 32u);
  // each session reads on
  for (std::size_t i = 0; i < 32; ++i) EXPECT_EQ(*clients[i]->read(NodeId::str("io/x")).value->number(), 1.5);
}

}  // namespace
}  // namespace gdpn::opcua
