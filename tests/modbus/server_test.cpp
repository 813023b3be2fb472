// The Modbus TCP server in process, over loopback sockets: answers built by libmodbus from the
// io map, pipelined and split frames, exceptions, a stream that is no Modbus TCP, too many
// clients, a read-only server and the lockstep wait. The server is single-threaded: each test
// sends, lets it serve a round, then reads the answer.

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <vector>

#include "gdpn/modbus/server.h"
#include "gdpn/model/io.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"

namespace gdpn::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;
using namespace std::chrono_literals;

constexpr const char* kCell = R"(gdpn: 1
scene:
  - Transform: {name: belt, children: [{Conveyor: {name: drive, speed: 0.25}}, {Cube: {size: [2, 0.5, 0.1]}}]}
io:
  lockstep: 9
  input_registers: {0: {name: speed, node: belt/drive, of: speed, scale: 1000}}
  coils: {0: {name: running, node: belt/drive, field: speed, on: 0.5}}
  holding_registers: {0: {node: belt/drive, field: speed, scale: 1000}, 1: {place: main/parts}}
pages:
  main: {places: {parts: {tokens: 2}}}
)";

Bytes frame(std::uint16_t tid, const Bytes& pdu) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);
  // filled byte by byte: GCC 12 warns wrongly (array-bounds) on inserting into a short vector
  Bytes out(7 + pdu.size());
  const std::uint8_t head[] = {static_cast<std::uint8_t>(tid >> 8), static_cast<std::uint8_t>(tid), 0, 0,
                               static_cast<std::uint8_t>(length >> 8), static_cast<std::uint8_t>(length), 0xFF};
  for (std::size_t k = 0; k < 7; ++k) out[k] = head[k];
  for (std::size_t k = 0; k < pdu.size(); ++k) out[7 + k] = pdu[k];
  return out;
}

/// A client socket on loopback.
class Client {
 public:
  explicit Client(std::uint16_t port) {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(port);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(connect(fd_, reinterpret_cast<sockaddr*>(&to), sizeof to), 0);
    const int on = 1;
    setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);  // each send goes out at once
  }
  ~Client() { ::close(fd_); }
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;
  void send(const Bytes& b) const { ASSERT_EQ(::send(fd_, b.data(), b.size(), MSG_NOSIGNAL), static_cast<ssize_t>(b.size())); }
  /// Whether something has arrived (or the connection closed).
  [[nodiscard]] bool readable() const {
    pollfd p{fd_, POLLIN, 0};
    return poll(&p, 1, 0) > 0;
  }
  /// What has arrived (waiting up to a second for the first byte); empty when closed.
  Bytes receive() const {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, 1000) <= 0) return {};
    std::uint8_t buffer[1024];
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    return n <= 0 ? Bytes{} : Bytes(buffer, buffer + n);
  }
  /// Whether the server has closed it.
  [[nodiscard]] bool closed() const {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, 1000) <= 0) return false;
    std::uint8_t byte = 0;
    return recv(fd_, &byte, 1, 0) <= 0;
  }

 private:
  int fd_ = -1;
};

class ServerTest : public ::testing::Test {
 protected:
  void start(ServerOptions options = {}) {
    core::Diagnostics diags;
    model_ = model::parseModel(kCell, "cell.gdpn.yaml", diags);
    ASSERT_TRUE(model_) << diags.str();
    sim_ = model::Simulation::create(*model_, diags);
    ASSERT_TRUE(sim_) << diags.str();
    io_ = model::IoMap::create(*sim_, model_->io, diags);
    ASSERT_TRUE(io_) << diags.str();
    options.port = 0;
    std::string why;
    server_ = Server::listen(*io_, options, why);
    ASSERT_TRUE(server_) << why;
  }
  /// Lets the server answer what has come (a few rounds on loopback).
  void serve() { server_->serveUntil(Server::Clock::now() + 5ms); }
  /// Serves until `c` has something to read, or a second has gone.
  void serveFor(const Client& c) {
    for (int round = 0; round < 200 && !c.readable(); ++round) serve();
  }
  Bytes ask(Client& c, const Bytes& request) {
    c.send(request);
    serveFor(c);
    return c.receive();
  }
  std::optional<model::Model> model_;
  std::unique_ptr<model::Simulation> sim_;
  std::unique_ptr<model::IoMap> io_;
  std::unique_ptr<Server> server_;
};

TEST_F(ServerTest, AReadIsAnsweredWithTheTransactionAndTheValue) {
  start();
  Client c(server_->port());
  // 0.25 m/s x 1000 = 250 = 0x00FA
  EXPECT_EQ(ask(c, frame(0x0102, {4, 0, 0, 0, 1})), (Bytes{1, 2, 0, 0, 0, 5, 0xFF, 4, 2, 0x00, 0xFA}));
  EXPECT_EQ(server_->stats().requests, 1u);
  EXPECT_EQ(server_->stats().clients, 1u);
}

TEST_F(ServerTest, AWriteIsEchoedAndChangesThePlant) {
  start();
  Client c(server_->port());
  EXPECT_EQ(ask(c, frame(7, {6, 0, 0, 0x01, 0xF4})), frame(7, {6, 0, 0, 0x01, 0xF4}));  // 500 mm/s
  EXPECT_EQ(ask(c, frame(8, {3, 0, 0, 0, 1})), (Bytes{0, 8, 0, 0, 0, 5, 0xFF, 3, 2, 0x01, 0xF4}));
  EXPECT_EQ(ask(c, frame(9, {1, 0, 0, 0, 1})), (Bytes{0, 9, 0, 0, 0, 4, 0xFF, 1, 1, 1})) << "0.5 m/s: the coil is on";
  EXPECT_EQ(ask(c, frame(10, {5, 0, 0, 0, 0})), frame(10, {5, 0, 0, 0, 0}));
  EXPECT_EQ(ask(c, frame(11, {4, 0, 0, 0, 1})), (Bytes{0, 11, 0, 0, 0, 5, 0xFF, 4, 2, 0, 0}));
  EXPECT_EQ(server_->stats().writes, 2u);
}

TEST_F(ServerTest, PipelinedAndSplitFramesAreAnsweredInOrder) {
  start();
  Client c(server_->port());
  Bytes two = frame(1, {4, 0, 0, 0, 1});
  const Bytes second = frame(2, {1, 0, 0, 0, 1});
  two.insert(two.end(), second.begin(), second.end());
  Bytes both = ask(c, two);
  if (both.size() < 21) {
    serveFor(c);
    const Bytes more = c.receive();
    both.insert(both.end(), more.begin(), more.end());
  }
  EXPECT_EQ(both, (Bytes{0, 1, 0, 0, 0, 5, 0xFF, 4, 2, 0, 0xFA, 0, 2, 0, 0, 0, 4, 0xFF, 1, 1, 0}));
  const Bytes f = frame(3, {4, 0, 0, 0, 1});
  c.send(Bytes(f.begin(), f.begin() + 5));
  serve();
  c.send(Bytes(f.begin() + 5, f.end()));
  serveFor(c);
  EXPECT_EQ(c.receive(), (Bytes{0, 3, 0, 0, 0, 5, 0xFF, 4, 2, 0, 0xFA}));
}

TEST_F(ServerTest, BadRequestsGetExceptionsAndTheConnectionStays) {
  start();
  Client c(server_->port());
  EXPECT_EQ(ask(c, frame(1, {0x2B, 0x0E, 1, 0})), (Bytes{0, 1, 0, 0, 0, 3, 0xFF, 0xAB, 1}));  // illegal function
  EXPECT_EQ(ask(c, frame(2, {4, 0, 1, 0, 1})), (Bytes{0, 2, 0, 0, 0, 3, 0xFF, 0x84, 2}));     // unmapped
  EXPECT_EQ(ask(c, frame(3, {2, 0, 0, 0, 1})), (Bytes{0, 3, 0, 0, 0, 3, 0xFF, 0x82, 2}))
      << "no discrete inputs are mapped";
  EXPECT_EQ(ask(c, frame(4, {6, 0, 1, 0xFF, 0xFF})), (Bytes{0, 4, 0, 0, 0, 3, 0xFF, 0x86, 3})) << "-1 tokens";
  EXPECT_EQ(ask(c, frame(5, {3, 0, 0})), (Bytes{0, 5, 0, 0, 0, 3, 0xFF, 0x83, 3}));
  EXPECT_EQ(ask(c, frame(6, {4, 0, 0, 0, 1})), (Bytes{0, 6, 0, 0, 0, 5, 0xFF, 4, 2, 0, 0xFA}));
  EXPECT_EQ(server_->stats().exceptions, 5u);
}

TEST_F(ServerTest, AStreamThatIsNoModbusIsClosedAndTheOthersGoOn) {
  start();
  Client good(server_->port());
  Client bad(server_->port());
  bad.send({'G', 'E', 'T', ' ', '/', ' ', 'H', 'T', 'T', 'P', '/', '1', '.', '1', '\r', '\n'});
  serveFor(bad);
  EXPECT_TRUE(bad.closed());
  EXPECT_EQ(server_->stats().dropped, 1u);
  EXPECT_EQ(ask(good, frame(1, {4, 0, 0, 0, 1})).size(), 11u);
}

TEST_F(ServerTest, ClientsPastTheLimitAreClosedAsTheyCome) {
  ServerOptions options;
  options.max_clients = 2;
  start(options);
  Client a(server_->port());
  Client b(server_->port());
  serve();
  Client c(server_->port());
  serveFor(c);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(server_->stats().refused, 1u);
  EXPECT_EQ(ask(a, frame(1, {4, 0, 0, 0, 1})).size(), 11u);
  EXPECT_EQ(ask(b, frame(1, {4, 0, 0, 0, 1})).size(), 11u);
}

TEST_F(ServerTest, AReadOnlyServerRefusesEveryWrite) {
  ServerOptions options;
  options.read_only = true;
  start(options);
  Client c(server_->port());
  EXPECT_EQ(ask(c, frame(1, {5, 0, 0, 0xFF, 0})), (Bytes{0, 1, 0, 0, 0, 3, 0xFF, 0x85, 1}));
  EXPECT_EQ(ask(c, frame(2, {6, 0, 9, 0, 5})), (Bytes{0, 2, 0, 0, 0, 3, 0xFF, 0x86, 1})) << "steps too";
  EXPECT_EQ(io_->pendingSteps(), 0u);
  EXPECT_EQ(ask(c, frame(3, {4, 0, 0, 0, 1})), (Bytes{0, 3, 0, 0, 0, 5, 0xFF, 4, 2, 0, 0xFA}));
}

TEST_F(ServerTest, LockstepWaitsForStepsAskedFor) {
  start();
  Client c(server_->port());
  c.send(frame(1, {6, 0, 9, 0, 3}));
  server_->serveUntilStepAsked();
  EXPECT_EQ(io_->pendingSteps(), 3u);
  EXPECT_EQ(c.receive(), frame(1, {6, 0, 9, 0, 3}));
  const std::atomic<bool> stop{true};
  io_->stepTaken();
  io_->stepTaken();
  io_->stepTaken();
  server_->serveUntilStepAsked(&stop);  // returns at once: stopped
  EXPECT_EQ(io_->pendingSteps(), 0u);
}

TEST(Endpoint, AddressAndPortAreCheckedOnTheCommandLine) {
  ServerOptions o;
  std::string why;
  ASSERT_TRUE(parseEndpoint("5020", o, why));
  EXPECT_EQ(o.address, "127.0.0.1");
  EXPECT_EQ(o.port, 5020);
  ASSERT_TRUE(parseEndpoint("*:502", o, why));
  EXPECT_EQ(o.address, "0.0.0.0");
  ASSERT_TRUE(parseEndpoint("192.168.1.20:0", o, why));
  EXPECT_EQ(o.address, "192.168.1.20");
  EXPECT_EQ(o.port, 0);
  EXPECT_FALSE(parseEndpoint("65536", o, why));
  EXPECT_NE(why.find("0 to 65535"), std::string::npos) << why;
  EXPECT_FALSE(parseEndpoint("plc.local:502", o, why));
  EXPECT_NE(why.find("no IPv4 address"), std::string::npos) << why;
  EXPECT_FALSE(parseEndpoint("", o, why));
  EXPECT_FALSE(parseEndpoint("127.0.0.1:", o, why));
  EXPECT_FALSE(parseEndpoint("-1", o, why));
}

TEST(Endpoint, AnAddressInUseIsAnErrorNotACrash) {
  core::Diagnostics diags;
  auto m = model::parseModel(kCell, "cell.gdpn.yaml", diags);
  ASSERT_TRUE(m);
  auto sim = model::Simulation::create(*m, diags);
  ASSERT_TRUE(sim);
  auto io = model::IoMap::create(*sim, m->io, diags);
  ASSERT_TRUE(io);
  ServerOptions o;
  o.port = 0;
  std::string why;
  auto first = Server::listen(*io, o, why);
  ASSERT_TRUE(first) << why;
  o.port = first->port();
  EXPECT_FALSE(Server::listen(*io, o, why));
  EXPECT_NE(why.find("cannot listen on 127.0.0.1:"), std::string::npos) << why;
  o.address = "192.0.2.1";  // TEST-NET-1: not this machine's
  o.port = 0;
  EXPECT_FALSE(Server::listen(*io, o, why));
}

}  // namespace
}  // namespace gdpn::modbus
