#pragma once
/// \file
/// The OPC UA server without its sockets: bytes in from each connection, bytes out to it. It
/// speaks UA TCP (Hello, Acknowledge, Error), the secure conversation with security policy
/// None (OpenSecureChannel, CloseSecureChannel; chunks assembled and cut), and the services of
/// discovery, sessions, views, attributes, methods, subscriptions and monitored items on an
/// AddressSpace. Monitored items are sampled at the run's step boundaries (sample()),
/// subscriptions publish on the wall clock (tick()). A malformed or hostile stream closes its
/// own connection only. Single-threaded: the run calls it between steps.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "gdpn/opcua/address_space.h"

namespace gdpn::opcua {

/// The limits a server holds to (stated in docs/opcua.md).
struct ServerLimits {
  std::uint32_t buffer_bytes = 65535;            ///< the largest chunk taken or sent
  std::uint32_t message_bytes = 4u << 20;        ///< the largest request taken (4 MiB)
  std::uint32_t chunks = 256;                    ///< chunks a request may take
  std::size_t connections = 64;                  ///< TCP connections at once (the socket layer)
  std::size_t sessions = 32;                     ///< sessions at once
  std::size_t subscriptions_per_session = 16;    ///< subscriptions a session may hold
  std::size_t items_per_subscription = 1000;     ///< monitored items a subscription may hold
  std::size_t items = 10000;                     ///< monitored items of all sessions together
  std::uint32_t response_bytes = 16u << 20;      ///< the largest response sent (16 MiB; less when the client says so)
  std::size_t publish_requests = 16;             ///< Publish requests a session, and Step calls a connection, may have waiting
  std::size_t nodes_per_request = 1000;          ///< nodes one Read, Write, Browse, Call... may name
  std::size_t references_per_node = 1000;        ///< references one Browse returns a node at most
  std::size_t continuation_points = 16;          ///< Browse continuation points a session may hold
  std::size_t retransmissions = 16;              ///< notification messages kept for Republish
  std::size_t queue_size = 100;                  ///< values a monitored item may queue at most
};

/// What the server has done so far.
struct EndpointStats {
  std::uint64_t connections = 0;   ///< connections opened
  std::uint64_t dropped = 0;       ///< connections closed for bytes that are no OPC UA
  std::uint64_t requests = 0;      ///< service requests answered (faults included)
  std::uint64_t faults = 0;        ///< requests answered with a bad service result
  std::uint64_t writes = 0;        ///< values written
  std::uint64_t notifications = 0; ///< data changes sent
  std::uint64_t sessions = 0;      ///< sessions created
};

/// A connection's number, from open().
using ConnectionId = std::uint64_t;

/// The server's protocol state: connections, channels, sessions, subscriptions.
class Endpoint {
 public:
  using Clock = std::chrono::steady_clock;
  /// Serves `space` as `endpoint_url` (`opc.tcp://HOST:PORT`), within `limits`. `read_only`
  /// refuses every write (BadUserAccessDenied). `seed` makes session tokens and nonces (0: the
  /// system's randomness; a fixed seed only for tests, whose recorded streams must match). The
  /// space must outlive it.
  Endpoint(AddressSpace& space, std::string endpoint_url, const ServerLimits& limits = {}, bool read_only = false,
           std::uint64_t seed = 0);
  ~Endpoint();
  Endpoint(const Endpoint&) = delete;
  Endpoint& operator=(const Endpoint&) = delete;

  /// A connection opened by `peer` ("ip:port", for messages).
  ConnectionId open(const std::string& peer);
  /// Bytes received on `c`. False: the connection must close (once its output is sent).
  bool receive(ConnectionId c, const std::uint8_t* data, std::size_t size);
  /// The bytes to send on `c` (taken: the next call returns only what came after).
  std::string takeOutput(ConnectionId c);
  /// Whether `c` has bytes to send.
  [[nodiscard]] bool hasOutput(ConnectionId c) const;
  /// The connection went: its channel with it (its sessions stay until they time out).
  void close(ConnectionId c);

  /// Publishes what is due at wall time `now`: notifications, keep-alives; times out sessions,
  /// subscriptions and Publish requests.
  void tick(Clock::time_point now);
  /// A step boundary at model time `seconds`: every monitored item is sampled.
  void sample(double seconds);
  /// The source timestamp of model time `seconds` (2000-01-01 00:00 UTC plus it).
  static DateTime modelTime(double seconds);

  /// The run takes steps only when a client calls Step (the method sees CallContext::lockstep).
  void setLockstep(bool on);
  /// Steps clients have asked for that the run has not taken.
  [[nodiscard]] std::uint64_t pendingSteps() const;
  /// One asked-for step taken: calls waiting for it are answered.
  void stepTaken();
  /// The time the next wall-clock event is due (a publishing interval): the socket layer waits
  /// no longer than this.
  [[nodiscard]] Clock::time_point nextDue() const;

  /// What it has done so far.
  [[nodiscard]] const EndpointStats& stats() const;
  /// Sessions open now.
  [[nodiscard]] std::size_t sessions() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gdpn::opcua
