#pragma once
/// \file
/// The OPC UA server on TCP (`gdpn run --opcua [ADDR:]PORT`): it accepts clients, reads their
/// bytes without ever blocking the run, hands them to its Endpoint and sends what it answers,
/// between two steps. Single-threaded: the run calls it between steps.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>

#include "gdpn/opcua/endpoint.h"

namespace gdpn::opcua {

/// Where and how to serve.
struct ServerOptions {
  std::string address = "127.0.0.1";  ///< the IPv4 address to bind ("0.0.0.0": every interface)
  std::uint16_t port = 4840;          ///< the TCP port (0: one the system picks; see Server::port)
  bool read_only = false;             ///< refuse every write (BadUserAccessDenied)
  ServerLimits limits;                ///< sessions, subscriptions, message sizes
  std::uint64_t seed = 0;             ///< session tokens' randomness (0: the system's; fixed only in tests)
};

/// "[ADDR:]PORT" taken apart into `options` (dotted IPv4, or `*` for every interface; port 0
/// to 65535). False with `why` when it is neither.
bool parseEndpoint(const std::string& text, ServerOptions& options, std::string& why);

/// The server. Construct with listen(); it closes its sockets when destroyed.
class Server {
 public:
  using Clock = std::chrono::steady_clock;
  /// Binds and listens on `options`' address and port, serving `space`. Null with `why` when
  /// the address cannot be bound.
  static std::unique_ptr<Server> listen(AddressSpace& space, const ServerOptions& options, std::string& why);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The port it listens on (the one the system picked when asked for 0).
  [[nodiscard]] std::uint16_t port() const { return port_; }
  /// The endpoint URL clients connect to: `opc.tcp://ADDRESS:PORT`.
  [[nodiscard]] const std::string& url() const { return url_; }
  /// The protocol state (sampling, lockstep, statistics).
  Endpoint& endpoint() { return *endpoint_; }
  /// Waits at most `timeout_ns` for something to read, serves it all, publishes what is due.
  void round(std::int64_t timeout_ns);
  /// Serves until `deadline` has passed (at least one round), or `stop` becomes true.
  void serveUntil(Clock::time_point deadline, const std::atomic<bool>* stop = nullptr);
  /// Serves until a client has asked for a step (lockstep), or `stop` becomes true.
  void serveUntilStepAsked(const std::atomic<bool>* stop = nullptr);
  /// Sends what the endpoint has for each client (after sampling or a step answered).
  void flush();
  /// Connections closed at once because `limits.connections` were open.
  [[nodiscard]] std::uint64_t refused() const { return refused_; }
  /// Where to write a line when a client connects or goes (null: nowhere). Off by default.
  void setLog(std::ostream* log) { log_ = log; }

 private:
  struct Impl;
  Server(AddressSpace& space, const ServerOptions& options);
  void accept();
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<Endpoint> endpoint_;
  ServerOptions options_;
  std::uint16_t port_ = 0;
  std::string url_;
  std::uint64_t refused_ = 0;
  std::ostream* log_ = nullptr;
};

}  // namespace gdpn::opcua
