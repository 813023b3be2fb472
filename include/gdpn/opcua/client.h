#pragma once
/// \file
/// An OPC UA client over UA TCP with security policy None and an anonymous session: what
/// `gdpn run --opcua-client URL` talks to a PLC with. It connects (Hello, OpenSecureChannel,
/// GetEndpoints, CreateSession, ActivateSession) and closes (CloseSession,
/// CloseSecureChannel); reads and writes attributes; subscribes to values and keeps Publish
/// requests outstanding; renews its secure channel's token before the token's lifetime ends.
/// Its decoding is strict and bounded, and every wait has a timeout: a server that sends bytes
/// that are no OPC UA, breaks a limit or goes silent is an error with a message, never a crash
/// or a hang. Single-threaded: connect() and the blocking calls wait (at most the timeout);
/// poll() and writeAsync() never wait longer than asked.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/opcua/binary.h"

namespace gdpn::opcua {

/// How a client connects and what it accepts.
struct ClientOptions {
  std::chrono::milliseconds timeout{5000};       ///< the longest wait for a connection or an answer
  std::uint32_t buffer_bytes = 65535;            ///< the largest chunk taken (bytes)
  std::uint32_t message_bytes = 16u << 20;       ///< the largest response taken (bytes, all chunks)
  std::uint32_t chunks = 1024;                   ///< chunks a response may take
  std::uint32_t channel_lifetime_ms = 600000;    ///< the secure channel token's requested lifetime (ms)
  std::uint32_t renew_after_ms = 0;              ///< renew the token this long after it came (ms; 0: at 3/4 of its lifetime)
  double session_timeout_ms = 60000;             ///< the session's requested timeout (ms)
  std::string session_name = "gdpn";             ///< the session's name, as the server shows it
  std::uint32_t publish_requests = 3;            ///< Publish requests kept outstanding once subscribed
};

/// One attribute of a node to read (13: Value, 14: DataType, 17: AccessLevel...).
struct ReadItem {
  NodeId node;                ///< the node
  std::uint32_t attribute = 13;  ///< its attribute id
};

/// One value to write to a node's Value attribute.
struct WriteItem {
  NodeId node;    ///< the node
  Variant value;  ///< the value, of the node's data type
};

/// One node to watch in a subscription.
struct MonitorItem {
  NodeId node;                  ///< the node (its Value is watched)
  std::uint32_t handle = 0;     ///< the client's handle, given back with each change
  double sampling_ms = -1;      ///< the sampling interval (ms; -1: the publishing interval)
};

/// A value a subscription delivered.
struct ItemChange {
  std::uint32_t handle = 0;  ///< the monitored item's handle (MonitorItem::handle)
  DataValue value;           ///< its value, with status and timestamps
};

/// What a client has done so far.
struct ClientStats {
  std::uint64_t requests = 0;       ///< service requests sent
  std::uint64_t reads = 0;          ///< attributes read
  std::uint64_t writes = 0;         ///< values written (answered Good)
  std::uint64_t notifications = 0;  ///< data changes received
  std::uint64_t renewals = 0;       ///< secure channel tokens renewed
};

/// A connection to one OPC UA server, with its secure channel and session. It closes when
/// destroyed.
class Client {
 public:
  using Clock = std::chrono::steady_clock;
  /// Connects to `url` (`opc.tcp://HOST[:PORT][/PATH]`, port 4840 when left out), opens a
  /// secure channel with policy None and an anonymous session (the anonymous token's policy
  /// id as the server's GetEndpoints gives it). Null with `why` when any of it fails.
  static std::unique_ptr<Client> connect(const std::string& url, const ClientOptions& options, std::string& why);
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  /// Reads `items` (one Read request); `values` gets one DataValue each (its status says when
  /// a node or attribute is unknown). False with `why` when the request fails.
  bool read(const std::vector<ReadItem>& items, std::vector<DataValue>& values, std::string& why);
  /// Writes `items` (one Write request) and waits for the answer; `results` gets one status
  /// each. False with `why` when the request fails.
  bool write(const std::vector<WriteItem>& items, std::vector<StatusCode>& results, std::string& why);
  /// Creates a subscription publishing every `interval_ms` (the server may revise it; see
  /// publishingInterval) and starts keeping Publish requests outstanding. False with `why`.
  bool subscribe(double interval_ms, std::uint32_t& subscription, std::string& why);
  /// Watches `items` in `subscription` (reporting, queue of one, newest kept); `results` gets
  /// one status each. Their first values come with the next Publish responses.
  bool monitor(std::uint32_t subscription, const std::vector<MonitorItem>& items, std::vector<StatusCode>& results,
               std::string& why);

  /// Sends one Write request of `items` without waiting; poll() checks its answer (a value
  /// the server refuses is an error there). False with `why` when it cannot be sent.
  bool writeAsync(const std::vector<WriteItem>& items, std::string& why);
  /// Whether a writeAsync() is not answered yet.
  [[nodiscard]] bool writing() const;
  /// Waits at most `timeout_ms` (0: not at all) for what the server sends, handles all that
  /// came (Publish responses, Write answers), sends Publish requests to keep them
  /// outstanding and renews the token when due. False with `why` when the connection is lost
  /// or broken, a request goes unanswered past its timeout, or the server refused a write.
  bool poll(std::int64_t timeout_ms, std::string& why);
  /// The changes delivered since the last call, in the order they came.
  std::vector<ItemChange> takeChanges();

  /// Closes the session and the secure channel (waiting at most a second for the session's
  /// answer) and the socket. Never fails; calls after it fail with "closed".
  void close();

  /// The subscription's publishing interval as the server revised it (ms; 0 before subscribe).
  [[nodiscard]] double publishingInterval() const;
  /// The anonymous token's policy id the session was activated with.
  [[nodiscard]] const std::string& anonymousPolicy() const;
  /// What it has done so far.
  [[nodiscard]] const ClientStats& stats() const;

 private:
  struct Impl;
  explicit Client(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// "opc.tcp://HOST[:PORT][/PATH]" taken apart (an IPv6 address in brackets). False with `why`.
bool parseOpcUrl(const std::string& url, std::string& host, std::uint16_t& port, std::string& why);

}  // namespace gdpn::opcua
