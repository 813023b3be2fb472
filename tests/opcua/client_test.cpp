// gdpn's OPC UA client against gdpn's own server (in a thread of the test, on a free port):
// connect, read, write, subscribe and receive changes, the token renewed, answers in chunks;
// and against servers that close, stay silent or send bytes that are no OPC UA.

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <random>
#include <thread>

#include "gdpn/opcua/client.h"
#include "gdpn/opcua/status.h"
#include "opcua/test_plc.h"

namespace gdpn::opcua {
namespace {

// polls until `done` or 200 rounds of 20 ms have passed; whether `done` came
template <class Done>
bool pollUntil(Client& client, Done done, std::string& why) {
  for (int i = 0; i < 200; ++i) {
    if (!client.poll(20, why)) return false;
    if (done()) return true;
  }
  why = "not within 200 polls";
  return false;
}

TEST(OpcUaClient, ConnectsAnonymouslyAndReads) {
  TestPlc plc;
  std::string why;
  auto client = Client::connect(plc.url(), {}, why);
  ASSERT_TRUE(client) << why;
  EXPECT_EQ(client->anonymousPolicy(), "anonymous");  // as gdpn's GetEndpoints gives it
  std::vector<DataValue> values;
  ASSERT_TRUE(client->read({{NodeId::str("Height"), 14}, {NodeId::str("Limit"), 13}, {NodeId::str("Nothing"), 13},
                            {NodeId::str("Eye"), 17}, {NodeId::str("Limit"), 17}},
                           values, why))
      << why;
  ASSERT_EQ(values.size(), 5u);
  ASSERT_TRUE(values[0].value);
  EXPECT_EQ(std::get<NodeId>(values[0].value->scalar), NodeId::num(4));  // Int16
  ASSERT_TRUE(values[1].value);
  EXPECT_EQ(values[1].value->number(), 2.5);
  EXPECT_EQ(values[2].status.value_or(0), status::kBadNodeIdUnknown);
  EXPECT_EQ(values[3].value->number(), 3);  // CurrentRead | CurrentWrite
  EXPECT_EQ(values[4].value->number(), 1);  // CurrentRead
  EXPECT_EQ(client->stats().reads, 5u);
  client->close();
  EXPECT_FALSE(client->read({{NodeId::str("Limit"), 13}}, values, why));
  EXPECT_NE(why.find("closed"), std::string::npos) << why;
}

TEST(OpcUaClient, WritesAndIsToldWhatWasRefused) {
  TestPlc plc;
  std::string why;
  auto client = Client::connect(plc.url(), {}, why);
  ASSERT_TRUE(client) << why;
  std::vector<StatusCode> results;
  ASSERT_TRUE(client->write({{NodeId::str("Height"), Variant::of(BuiltinType::Int16, std::int64_t{-420})},
                             {NodeId::str("Eye"), Variant::boolean(true)},
                             {NodeId::str("Height"), Variant::dbl(1.0)},  // no Int16
                             {NodeId::str("Limit"), Variant::dbl(1.0)}},   // read-only
                            results, why))
      << why;
  ASSERT_EQ(results.size(), 4u);
  EXPECT_EQ(results[0], status::kGood);
  EXPECT_EQ(results[1], status::kGood);
  EXPECT_EQ(results[2], status::kBadTypeMismatch);
  EXPECT_EQ(results[3], status::kBadNotWritable);
  EXPECT_EQ(plc.height_.load(), -420);
  EXPECT_TRUE(plc.eye_.load());
  EXPECT_EQ(client->stats().writes, 2u);

  // without waiting: the answer is checked by poll
  ASSERT_TRUE(client->writeAsync({{NodeId::str("Height"), Variant::of(BuiltinType::Int16, std::int64_t{77})}}, why)) << why;
  EXPECT_TRUE(client->writing());
  ASSERT_TRUE(pollUntil(*client, [&] { return !client->writing(); }, why)) << why;
  EXPECT_EQ(plc.height_.load(), 77);
  ASSERT_TRUE(client->writeAsync({{NodeId::str("Limit"), Variant::dbl(9)}}, why)) << why;
  EXPECT_FALSE(pollUntil(*client, [] { return false; }, why));
  EXPECT_NE(why.find("refused to write ns=1;s=Limit: BadNotWritable"), std::string::npos) << why;
}

TEST(OpcUaClient, SubscribesAndReceivesChanges) {
  TestPlc plc;
  std::string why;
  auto client = Client::connect(plc.url(), {}, why);
  ASSERT_TRUE(client) << why;
  std::uint32_t subscription = 0;
  ASSERT_TRUE(client->subscribe(10, subscription, why)) << why;
  EXPECT_GE(client->publishingInterval(), 10);
  std::vector<StatusCode> results;
  ASSERT_TRUE(client->monitor(subscription, {{NodeId::str("Belt"), 7, -1}, {NodeId::str("Nothing"), 8, -1}}, results, why)) << why;
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0], status::kGood);
  EXPECT_EQ(results[1], status::kBadNodeIdUnknown);
  // the first value, then each change
  std::vector<ItemChange> seen;
  auto collect = [&] {
    for (auto& c : client->takeChanges()) seen.push_back(std::move(c));
    return !seen.empty() && seen.back().value.value && seen.back().value.value->number() == (plc.belt_.load() ? 1 : 0);
  };
  ASSERT_TRUE(pollUntil(*client, collect, why)) << why;
  EXPECT_EQ(seen.front().handle, 7u);
  EXPECT_EQ(seen.front().value.value->number(), 0);
  plc.belt_ = true;
  ASSERT_TRUE(pollUntil(*client, collect, why)) << why;
  EXPECT_EQ(seen.back().handle, 7u);
  EXPECT_EQ(seen.back().value.value->type, BuiltinType::Boolean);
  plc.belt_ = false;
  ASSERT_TRUE(pollUntil(*client, collect, why)) << why;
  EXPECT_EQ(client->stats().notifications, seen.size());
  EXPECT_GE(seen.size(), 3u);
}

TEST(OpcUaClient, RenewsItsToken) {
  TestPlc plc;
  std::string why;
  ClientOptions options;
  options.renew_after_ms = 20;
  auto client = Client::connect(plc.url(), options, why);
  ASSERT_TRUE(client) << why;
  std::uint32_t subscription = 0;
  ASSERT_TRUE(client->subscribe(10, subscription, why)) << why;
  std::vector<StatusCode> results;
  ASSERT_TRUE(client->monitor(subscription, {{NodeId::str("Belt"), 1, -1}}, results, why)) << why;
  // gdpn's server takes the new token only: requests sent after the renewal wait for it
  ASSERT_TRUE(pollUntil(*client, [&] { return client->stats().renewals >= 3; }, why)) << why;
  std::vector<DataValue> values;
  ASSERT_TRUE(client->read({{NodeId::str("Limit"), 13}}, values, why)) << why;
  EXPECT_EQ(values.at(0).value->number(), 2.5);
}

TEST(OpcUaClient, TakesAnswersInChunksWithinItsLimit) {
  TestPlc plc;
  std::string why;
  ClientOptions options;
  options.buffer_bytes = 8192;
  auto client = Client::connect(plc.url(), options, why);
  ASSERT_TRUE(client) << why;
  std::vector<ReadItem> items(900, ReadItem{NodeId::num(id::kServerStatus), 13});  // about 100 bytes each
  std::vector<DataValue> values;
  ASSERT_TRUE(client->read(items, values, why)) << why;
  EXPECT_EQ(values.size(), 900u);

  // the limit told in Hello: gdpn's server answers with a fault in place of a larger answer
  options.message_bytes = 16384;
  client = Client::connect(plc.url(), options, why);
  ASSERT_TRUE(client) << why;
  EXPECT_FALSE(client->read(items, values, why));
  EXPECT_EQ(why, "Read failed: BadResponseTooLarge");
  EXPECT_TRUE(client->read({items[0]}, values, why)) << why;  // the connection stays
}

TEST(OpcUaClient, SaysWhenTheServerGoes) {
  TestPlc plc;
  std::string why;
  auto client = Client::connect(plc.url(), {}, why);
  ASSERT_TRUE(client) << why;
  plc.shutdown();
  EXPECT_FALSE(pollUntil(*client, [] { return false; }, why));
  EXPECT_NE(why.find("closed the connection"), std::string::npos) << why;
  std::vector<DataValue> values;
  EXPECT_FALSE(client->read({{NodeId::str("Limit"), 13}}, values, why));
}

TEST(OpcUaClient, RefusesBadUrlsAndAbsentServers) {
  std::string why;
  EXPECT_FALSE(Client::connect("http://127.0.0.1:4840", {}, why));
  EXPECT_NE(why.find("no OPC UA URL"), std::string::npos) << why;
  EXPECT_FALSE(Client::connect("opc.tcp://127.0.0.1:99999", {}, why));
  EXPECT_NE(why.find("port"), std::string::npos) << why;
  EXPECT_FALSE(Client::connect("opc.tcp://:4840", {}, why));
  EXPECT_NE(why.find("no host"), std::string::npos) << why;
  std::string host;
  std::uint16_t port = 0;
  ASSERT_TRUE(parseOpcUrl("opc.tcp://[::1]:4841/plc", host, port, why)) << why;
  EXPECT_EQ(host, "::1");
  EXPECT_EQ(port, 4841);
  ASSERT_TRUE(parseOpcUrl("opc.tcp://plc.local", host, port, why)) << why;
  EXPECT_EQ(port, 4840);

  // a port nobody listens on: a listener closed again leaves one
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  socklen_t size = sizeof addr;
  getsockname(s, reinterpret_cast<sockaddr*>(&addr), &size);
  ::close(s);
  EXPECT_FALSE(Client::connect("opc.tcp://127.0.0.1:" + std::to_string(ntohs(addr.sin_port)), {}, why));
  EXPECT_NE(why.find("cannot connect"), std::string::npos) << why;
}

/// A server that answers each message of the client's with the next of `replies` (bytes as
/// given), and then says nothing; a reply "" closes the connection.
class FakeServer {
 public:
  explicit FakeServer(std::vector<std::string> replies) : replies_(std::move(replies)) {
    listener_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(listener_, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    listen(listener_, 1);
    socklen_t size = sizeof addr;
    getsockname(listener_, reinterpret_cast<sockaddr*>(&addr), &size);
    url_ = "opc.tcp://127.0.0.1:" + std::to_string(ntohs(addr.sin_port));
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeServer() {
    stop_ = true;
    thread_.join();
    ::close(listener_);
  }
  const std::string& url() const { return url_; }

 private:
  void serve() {
    pollfd p{listener_, POLLIN, 0};
    while (!stop_ && ::poll(&p, 1, 20) == 0) {}
    if (stop_) return;
    const int fd = accept(listener_, nullptr, nullptr);
    std::size_t next = 0;
    char buffer[65536];
    while (!stop_) {
      pollfd c{fd, POLLIN, 0};
      if (::poll(&c, 1, 20) <= 0) continue;
      if (recv(fd, buffer, sizeof buffer, 0) <= 0) break;
      if (next >= replies_.size()) continue;
      const std::string& reply = replies_[next++];
      if (reply.empty()) break;
      send(fd, reply.data(), reply.size(), MSG_NOSIGNAL);
    }
    ::close(fd);
  }
  std::vector<std::string> replies_;
  int listener_ = -1;
  std::string url_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

// an Acknowledge with 64 KiB buffers
std::string acknowledge() {
  std::string body;
  Encoder e(body);
  for (const std::uint32_t v : {0u, 65535u, 65535u, 0u, 0u}) e.u32(v);
  std::string msg = "ACKF";
  Encoder(msg).u32(static_cast<std::uint32_t>(8 + body.size()));
  return msg + body;
}

// the answer to OpenSecureChannel (request 1): channel 5, token 1
std::string openAnswer() {
  std::string body;
  Encoder b(body);
  b.nodeId(NodeId::num(449));
  b.i64(0);
  b.u32(1);
  b.u32(0);
  b.noDiagnostics();
  b.length(0);
  b.nodeId({});
  b.u8(0);
  for (const std::uint32_t v : {0u, 5u, 1u}) b.u32(v);
  b.i64(0);
  b.u32(600000);
  b.string("");
  std::string head;
  Encoder h(head);
  h.u32(5);
  h.string("http://opcfoundation.org/UA/SecurityPolicy#None");
  h.nullString();
  h.nullString();
  h.u32(1);  // sequence number
  h.u32(1);  // request id
  std::string msg = "OPNF";
  Encoder(msg).u32(static_cast<std::uint32_t>(8 + head.size() + body.size()));
  return msg + head + body;
}

// `count` chunks of a MSG answer to `request` on channel 5, token 1, from sequence number 2
std::string messageChunks(std::uint32_t request, std::size_t count, std::size_t bytes, char last) {
  std::string out;
  for (std::size_t k = 0; k < count; ++k) {
    std::string chunk = "MSG";
    chunk += k + 1 == count ? last : 'C';
    Encoder e(chunk);
    e.u32(static_cast<std::uint32_t>(24 + bytes));
    for (const std::uint32_t v : {5u, 1u, static_cast<std::uint32_t>(2 + k), request}) e.u32(v);
    chunk += std::string(bytes, '\x01');
    out += chunk;
  }
  return out;
}

TEST(OpcUaClient, SaysWhatIsWrongWithServersThatBreakTheProtocol) {
  ClientOptions options;
  options.timeout = std::chrono::milliseconds(300);
  options.message_bytes = 16384;
  std::string why;
  {
    // an answer in chunks of more bytes than the client takes
    FakeServer big({acknowledge(), openAnswer(), messageChunks(2, 3, 8000, 'F')});
    EXPECT_FALSE(Client::connect(big.url(), options, why));
    EXPECT_NE(why.find("an answer of more than 16384 bytes"), std::string::npos) << why;
  }
  {
    // an answer to a request never sent
    FakeServer stray({acknowledge(), openAnswer(), messageChunks(9, 1, 40, 'F')});
    EXPECT_FALSE(Client::connect(stray.url(), options, why));
    EXPECT_NE(why.find("answered request 9, which was not asked"), std::string::npos) << why;
  }
  {
    // a body of bytes that are no response
    FakeServer noise({acknowledge(), openAnswer(), messageChunks(2, 1, 40, 'F')});
    EXPECT_FALSE(Client::connect(noise.url(), options, why));
    EXPECT_NE(why.find("cannot be read"), std::string::npos) << why;
  }
  {
    // a sequence number that skips
    std::string skipping = messageChunks(2, 1, 40, 'F');
    skipping[16] = 7;
    FakeServer skip({acknowledge(), openAnswer(), skipping});
    EXPECT_FALSE(Client::connect(skip.url(), options, why));
    EXPECT_NE(why.find("sequence number 7 after 1"), std::string::npos) << why;
  }
}

TEST(OpcUaClient, TurnsNoiseIntoAnError) {
  // after a good Acknowledge and channel, chunks of random bytes with good headers: each
  // connection ends with a message, none crashes or hangs
  ClientOptions options;
  options.timeout = std::chrono::milliseconds(300);
  std::mt19937 random(61);
  for (int round = 0; round < 40; ++round) {
    std::string noise = messageChunks(2, 1, 8 + random() % 200, 'F');
    for (std::size_t k = 24; k < noise.size(); ++k) noise[k] = static_cast<char>(random() & 0xFF);
    if (round % 2 == 1) {
      // a GetEndpoints answer's header, then noise
      std::string body;
      Encoder b(body);
      b.nodeId(NodeId::num(431));
      b.i64(0);
      b.u32(2);
      b.u32(0);
      b.noDiagnostics();
      b.length(0);
      b.nodeId({});
      b.u8(0);
      noise.replace(24, std::min(body.size(), noise.size() - 24), body.substr(0, noise.size() - 24));
    }
    FakeServer noisy({acknowledge(), openAnswer(), noise});
    std::string why;
    EXPECT_FALSE(Client::connect(noisy.url(), options, why));
    EXPECT_FALSE(why.empty());
  }
}

TEST(OpcUaClient, SaysWhatIsWrongWithServersThatAreNone) {
  ClientOptions options;
  options.timeout = std::chrono::milliseconds(300);
  std::string why;
  {
    FakeServer web({"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n"});
    EXPECT_FALSE(Client::connect(web.url(), options, why));
    EXPECT_NE(why.find("answered Hello with"), std::string::npos) << why;
  }
  {
    FakeServer small({std::string("XYZF\x0c\0\0\0abcd", 12)});
    EXPECT_FALSE(Client::connect(small.url(), options, why));
    EXPECT_NE(why.find("no Acknowledge"), std::string::npos) << why;
  }
  {
    FakeServer closing({""});
    EXPECT_FALSE(Client::connect(closing.url(), options, why));
    EXPECT_NE(why.find("closed the connection after Hello"), std::string::npos) << why;
  }
  {
    FakeServer silent({});
    EXPECT_FALSE(Client::connect(silent.url(), options, why));
    EXPECT_NE(why.find("did not answer Hello within 300 ms"), std::string::npos) << why;
  }
  {
    FakeServer mute({acknowledge()});  // acknowledges, then says nothing
    EXPECT_FALSE(Client::connect(mute.url(), options, why));
    EXPECT_NE(why.find("did not answer OpenSecureChannel within 300 ms"), std::string::npos) << why;
  }
  {
    // a chunk of 4 GiB announced
    FakeServer huge({acknowledge(), std::string("OPNF\xff\xff\xff\xff", 8)});
    EXPECT_FALSE(Client::connect(huge.url(), options, why));
    EXPECT_NE(why.find("a chunk of 4294967295 bytes"), std::string::npos) << why;
  }
  {
    // an OPN chunk whose policy string claims more bytes than there are
    std::string opn = "OPNF";
    Encoder e(opn);
    e.u32(24);
    e.u32(1);
    e.u32(1000);
    e.u32(0);
    e.u32(0);
    FakeServer garbage({acknowledge(), opn});
    EXPECT_FALSE(Client::connect(garbage.url(), options, why));
    EXPECT_NE(why.find("cannot be read"), std::string::npos) << why;
  }
  {
    // an Error message: its status and reason are told
    std::string err = "ERRF";
    std::string body;
    Encoder b(body);
    b.u32(status::kBadTcpServerTooBusy);
    b.string("too many clients");
    Encoder(err).u32(static_cast<std::uint32_t>(8 + body.size()));
    FakeServer busy({err + body});
    EXPECT_FALSE(Client::connect(busy.url(), options, why));
    EXPECT_NE(why.find("refused the connection: BadTcpServerTooBusy: too many clients"), std::string::npos) << why;
  }
}

}  // namespace
}  // namespace gdpn::opcua
