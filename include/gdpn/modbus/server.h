#pragma once
/// \file
/// A Modbus TCP server on a model's `io` map (libmodbus builds the replies): it accepts several
/// clients, reads their requests without ever blocking the run, and answers each between two
/// steps, reading the plant and the net then and applying writes there. Single-threaded: the
/// run calls it between steps.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>

#include "gdpn/model/io.h"

namespace gdpn::modbus {

/// Where and how to serve.
struct ServerOptions {
  std::string address = "127.0.0.1";  ///< the IPv4 address to bind ("0.0.0.0": every interface)
  std::uint16_t port = 502;           ///< the TCP port (0: one the system picks; see Server::port)
  bool read_only = false;             ///< refuse every write (exception 01, illegal function)
  int max_clients = 32;               ///< clients beyond this many are closed as they connect
};

/// What the server has done so far.
struct ServerStats {
  std::uint64_t requests = 0;    ///< requests answered, exceptions included
  std::uint64_t exceptions = 0;  ///< requests answered with an exception code
  std::uint64_t writes = 0;      ///< requests that wrote (coils, holding registers)
  std::uint64_t clients = 0;     ///< connections accepted
  std::uint64_t refused = 0;     ///< connections closed at once: too many clients
  std::uint64_t dropped = 0;     ///< connections closed for bytes that are no Modbus TCP
};

/// "[ADDR:]PORT" taken apart into `options` (address dotted IPv4, or `*` for every interface;
/// port 0 to 65535). False with `why` when it is neither.
bool parseEndpoint(const std::string& text, ServerOptions& options, std::string& why);

/// The server. Construct with listen(); it closes its sockets when destroyed.
class Server {
 public:
  using Clock = std::chrono::steady_clock;
  /// Binds and listens on `options`' address and port, serving `map`. Null with `why` when the
  /// address cannot be bound (in use, not this machine's, not permitted).
  static std::unique_ptr<Server> listen(model::IoMap& map, const ServerOptions& options, std::string& why);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The port it listens on (the one the system picked when asked for 0).
  [[nodiscard]] std::uint16_t port() const { return port_; }
  /// Serves requests until `deadline` has passed (at least one round, so that a run slower
  /// than the wall clock still serves between every two steps), or `stop` becomes true.
  void serveUntil(Clock::time_point deadline, const std::atomic<bool>* stop = nullptr);
  /// Serves requests until the map has steps asked for (lockstep), or `stop` becomes true.
  void serveUntilStepAsked(const std::atomic<bool>* stop = nullptr);
  /// What it has done so far.
  [[nodiscard]] const ServerStats& stats() const { return stats_; }
  /// Where to write a line when a client connects or goes ("" lines: none). Off by default.
  void setLog(std::ostream* log) { log_ = log; }

 private:
  struct Client;
  struct Impl;
  explicit Server(model::IoMap& map, const ServerOptions& options);
  // one round: waits at most `timeout_ns` for something to read, then serves it all
  void round(std::int64_t timeout_ns);
  void accept();
  // reads what `c` has sent and answers its whole frames; why it must be closed, or null
  const char* serve(Client& c);
  // answers one whole frame; false when the reply could not be sent
  bool answer(Client& c, const std::uint8_t* frame, std::size_t length);
  void close(std::size_t index, const char* why);
  model::IoMap& map_;
  ServerOptions options_;
  std::unique_ptr<Impl> impl_;
  std::uint16_t port_ = 0;
  ServerStats stats_;
  std::ostream* log_ = nullptr;
};

}  // namespace gdpn::modbus
