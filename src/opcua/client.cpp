// The OPC UA client: a socket that never blocks longer than asked, UA TCP's Hello and
// Acknowledge, the secure conversation with policy None (chunks cut and put together within
// the limits, the token renewed), the session, and the services gdpn's PLC link uses.

#include "gdpn/opcua/client.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <deque>
#include <map>
#include <optional>
#include <random>
#include <utility>

#include "endpoint_state.h"
#include "gdpn/opcua/status.h"

namespace gdpn::opcua {

namespace client_wire {

inline constexpr std::uint32_t kAnonymousTokenEncoding = 321;

/// What a response carried: its body after the response header, or why it failed.
struct Answer {
  bool ok = false;
  std::string body;   // the fields after the response header
  std::string error;  // why not
  StatusCode status = 0;  // the service result (bad when the server refused)
};

/// A request sent and not answered yet.
struct Outstanding {
  std::uint32_t service = 0;          // the request's encoding id
  Client::Clock::time_point deadline;  // max: a Publish, which waits as long as the server likes
  bool keep = false;                  // a blocking call waits for it: keep its answer
  std::vector<NodeId> nodes;          // a writeAsync's nodes, to say which one was refused
};

std::string serviceName(std::uint32_t service) {
  switch (service) {
    case detail::kGetEndpoints: return "GetEndpoints";
    case detail::kOpenSecureChannel: return "OpenSecureChannel";
    case detail::kCreateSession: return "CreateSession";
    case detail::kActivateSession: return "ActivateSession";
    case detail::kCloseSession: return "CloseSession";
    case detail::kRead: return "Read";
    case detail::kWrite: return "Write";
    case detail::kCreateSubscription: return "CreateSubscription";
    case detail::kCreateMonitoredItems: return "CreateMonitoredItems";
    case detail::kPublish: return "Publish";
    default: return "request " + std::to_string(service);
  }
}

std::string clientRandomBytes(std::size_t n) {
  static std::mt19937_64 random{std::random_device{}()};
  std::string out(n, '\0');
  for (auto& ch : out) ch = static_cast<char>(random() & 0xFF);
  return out;
}

}  // namespace client_wire


bool parseOpcUrl(const std::string& url, std::string& host, std::uint16_t& port, std::string& why) {
  const std::string scheme = "opc.tcp://";
  if (url.compare(0, scheme.size(), scheme) != 0) {
    why = "'" + url + "' is no OPC UA URL: write opc.tcp://HOST:PORT";
    return false;
  }
  std::string rest = url.substr(scheme.size());
  rest = rest.substr(0, rest.find('/'));
  std::string port_text;
  if (!rest.empty() && rest[0] == '[') {
    const auto close = rest.find(']');
    if (close == std::string::npos) {
      why = "'" + url + "': an IPv6 address without its ']'";
      return false;
    }
    host = rest.substr(1, close - 1);
    const std::string after = rest.substr(close + 1);
    if (!after.empty()) {
      if (after[0] != ':') {
        why = "'" + url + "': what follows the address is no :PORT";
        return false;
      }
      port_text = after.substr(1);
    }
  } else {
    const auto colon = rest.find(':');
    host = rest.substr(0, colon);
    if (colon != std::string::npos) port_text = rest.substr(colon + 1);
    else port_text = "4840";
  }
  if (port_text.empty()) port_text = "4840";
  if (host.empty()) {
    why = "'" + url + "' names no host";
    return false;
  }
  if (port_text.size() > 5 || port_text.find_first_not_of("0123456789") != std::string::npos ||
      std::stoul(port_text) == 0 || std::stoul(port_text) > 65535) {
    why = "'" + url + "': the port is a number from 1 to 65535";
    return false;
  }
  port = static_cast<std::uint16_t>(std::stoul(port_text));
  return true;
}

struct Client::Impl {
  ClientOptions options;
  std::string url;
  int fd = -1;
  bool broken = false;      // an error ended the connection: `error` says which
  std::string error;
  // UA TCP
  std::uint32_t send_buffer = 8192;   // the largest chunk the server takes
  std::uint32_t server_message = 0;   // the largest message the server takes (0: any)
  std::uint32_t server_chunks = 0;    // chunks a message to the server may take (0: any)
  std::string in;                     // bytes received, not yet a whole chunk
  std::string unsent;                 // bytes the kernel would not take yet
  // the secure channel
  std::uint32_t channel = 0, token = 0;
  // the tokens issued and until when each is good (a server may answer a request with the
  // token it came with, until a quarter of a lifetime after the token's end)
  std::deque<std::pair<std::uint32_t, Clock::time_point>> tokens;
  std::uint32_t send_sequence = 0, receive_sequence = 0;
  bool sequenced = false;
  Clock::time_point renew_at = Clock::time_point::max();
  bool renewing = false;
  std::deque<std::pair<std::uint32_t, std::string>> held;  // messages waiting for the renewed token
  // assembling a response in chunks
  std::uint32_t partial_request = 0;
  std::string partial;
  std::uint32_t partial_chunks = 0;
  // requests
  std::uint32_t next_request = 1;
  std::map<std::uint32_t, client_wire::Outstanding> outstanding;
  std::map<std::uint32_t, client_wire::Answer> answers;
  Clock::time_point last_heard = Clock::now();
  // the session
  NodeId auth_token;
  std::string anonymous_policy;
  bool session = false;
  // subscriptions
  bool subscribed = false;
  double interval = 0;               // ms, revised
  std::uint32_t keepalive = 10;      // revised keep-alive count
  std::size_t publishing = 0;        // Publish requests outstanding
  std::vector<std::pair<std::uint32_t, std::uint32_t>> acks;  // subscription, sequence number
  std::vector<ItemChange> changes;
  bool writing = false;
  ClientStats stats;

  ~Impl() {
    if (fd >= 0) ::close(fd);
  }

  bool fail(const std::string& why) {
    if (!broken) {
      broken = true;
      error = why;
    }
    return false;
  }

  // ---- the socket ----

  bool openSocket(const std::string& host, std::uint16_t port) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const std::string where = host + ":" + std::to_string(port);
    const int rc = getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found);
    if (rc != 0) return fail("cannot find " + host + ": " + gai_strerror(rc));
    std::string last = "no address";
    for (addrinfo* a = found; a; a = a->ai_next) {
      const int s = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
      if (s < 0) continue;
      if (::connect(s, a->ai_addr, a->ai_addrlen) != 0 && errno != EINPROGRESS) {
        last = std::strerror(errno);
        ::close(s);
        continue;
      }
      pollfd p{s, POLLOUT, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(options.timeout.count()));
      int err = 0;
      socklen_t size = sizeof err;
      if (ready <= 0) {
        last = "no answer within " + std::to_string(options.timeout.count()) + " ms";
        ::close(s);
        continue;
      }
      getsockopt(s, SOL_SOCKET, SO_ERROR, &err, &size);
      if (err != 0) {
        last = std::strerror(err);
        ::close(s);
        continue;
      }
      const int on = 1;
      setsockopt(s, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
      fd = s;
      break;
    }
    freeaddrinfo(found);
    if (fd < 0) return fail("cannot connect to " + where + ": " + last);
    return true;
  }

  // sends what it can of `unsent` without waiting
  bool flush() {
    while (!unsent.empty()) {
      const ssize_t n = send(fd, unsent.data(), unsent.size(), MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
      if (n <= 0) return fail("the connection to " + url + " was lost: " + std::strerror(errno));
      unsent.erase(0, static_cast<std::size_t>(n));
    }
    if (unsent.size() > 4 * static_cast<std::size_t>(options.message_bytes)) {
      return fail("the server at " + url + " takes in nothing of what is sent to it");
    }
    return true;
  }

  // waits at most `timeout_ms` for bytes, reads all there are and handles every whole chunk
  bool pump(std::int64_t timeout_ms) {
    if (broken) return false;
    if (!flush()) return false;
    pollfd p{fd, static_cast<short>(POLLIN | (unsent.empty() ? 0 : POLLOUT)), 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::clamp<std::int64_t>(timeout_ms, 0, 60000)));
    if (ready < 0 && errno != EINTR) return fail(std::string("cannot wait for the server: ") + std::strerror(errno));
    if (ready <= 0) return true;
    if ((p.revents & POLLOUT) != 0 && !flush()) return false;
    if ((p.revents & (POLLIN | POLLHUP | POLLERR)) == 0) return true;
    char buffer[16384];
    // at most 1 MiB a round, so that a flood cannot hold the run
    for (int reads = 0; reads < 64; ++reads) {
      const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
      if (n == 0) return fail("the server at " + url + " closed the connection");
      if (n < 0) return fail("the connection to " + url + " was lost: " + std::strerror(errno));
      in.append(buffer, static_cast<std::size_t>(n));
      if (!chunks()) return false;
      if (static_cast<std::size_t>(n) < sizeof buffer) break;
    }
    return !broken;
  }

  // every whole chunk in `in`
  bool chunks() {
    std::size_t at = 0;
    while (!broken && in.size() - at >= 8) {
      Decoder head(std::string_view(in).substr(at + 4, 4));
      const std::uint32_t length = head.u32();
      if (length < 8 || length > options.buffer_bytes) {
        return fail("the server at " + url + " sent a chunk of " + std::to_string(length) + " bytes (at most " +
                    std::to_string(options.buffer_bytes) + ")");
      }
      if (in.size() - at < length) break;
      const std::string chunk = in.substr(at, length);
      at += length;
      try {
        if (!handleChunk(chunk)) return false;
      } catch (const DecodeError& bad) {
        return fail("the server at " + url + " sent a message that cannot be read: " + bad.what());
      }
    }
    in.erase(0, at);
    return !broken;
  }

  bool handleChunk(std::string_view bytes) {
    last_heard = Clock::now();
    const std::string_view type = bytes.substr(0, 3);
    const char final = bytes[3];
    Decoder d(bytes.substr(8));
    if (type == "ERR") {
      const StatusCode code = d.u32();
      const std::string reason = d.string(4096);
      return fail("the server at " + url + " ended the connection: " + status::name(code) + (reason.empty() ? "" : ": " + reason));
    }
    if (type == "ACK") return fail("the server at " + url + " sent a second Acknowledge");
    if (type == "OPN") {
      if (final != 'F') return fail("the server at " + url + " sent an OpenSecureChannel response in chunks");
      const std::uint32_t id = d.u32();
      const std::string policy = d.string(4096);
      (void)d.string();  // sender certificate
      (void)d.string();  // receiver thumbprint
      if (policy != detail::kPolicyNone) return fail("the server at " + url + " answered with security policy '" + policy + "'");
      if (channel != 0 && id != channel) return fail("the server at " + url + " renewed another secure channel");
      if (!sequence(d.u32())) return false;
      const std::uint32_t request = d.u32();
      return message(request, d.rest(), true);
    }
    if (type != "MSG") return fail("the server at " + url + " sent a message of type '" + std::string(type) + "'");
    if (d.u32() != channel) return fail("the server at " + url + " sent a message for another secure channel");
    const std::uint32_t token_id = d.u32();
    const auto now = Clock::now();
    const bool known = std::any_of(tokens.begin(), tokens.end(), [&](const auto& t) { return t.first == token_id && now < t.second; });
    if (!known) return fail("the server at " + url + " sent a message with security token " + std::to_string(token_id) + ", unknown or expired");
    if (!sequence(d.u32())) return false;
    const std::uint32_t request = d.u32();
    switch (final) {
      case 'A': {
        const StatusCode code = d.u32();
        const std::string reason = d.string(4096);
        partial.clear();
        partial_chunks = 0;
        const auto it = outstanding.find(request);
        if (it == outstanding.end()) return true;
        const client_wire::Outstanding out = std::move(it->second);
        outstanding.erase(it);
        return answer(request, {false, {}, "the server gave up on its answer: " + status::name(code) + (reason.empty() ? "" : ": " + reason), code},
                      out);
      }
      case 'C':
      case 'F': break;
      default: return fail("the server at " + url + " sent a chunk of type '" + std::string(1, final) + "'");
    }
    if (partial_chunks > 0 && request != partial_request) return fail("the server at " + url + " interleaved the chunks of two answers");
    partial_request = request;
    partial += d.rest();
    ++partial_chunks;
    if (partial.size() > options.message_bytes || partial_chunks > options.chunks) {
      return fail("the server at " + url + " sent an answer of more than " + std::to_string(options.message_bytes) + " bytes or " +
                  std::to_string(options.chunks) + " chunks");
    }
    if (final == 'C') return true;
    const std::string body = std::exchange(partial, {});
    partial_chunks = 0;
    return message(request, body, false);
  }

  // sequence numbers go up by one (they may wrap below 1024 after 4294966271)
  bool sequence(std::uint32_t n) {
    if (sequenced && n != receive_sequence + 1 && !(receive_sequence > 4294966271u && n < 1024)) {
      return fail("the server at " + url + " sent sequence number " + std::to_string(n) + " after " + std::to_string(receive_sequence));
    }
    receive_sequence = n;
    sequenced = true;
    return true;
  }

  // a whole response to `request`
  bool message(std::uint32_t request, std::string_view body, bool open) {
    const auto it = outstanding.find(request);
    if (it == outstanding.end()) return fail("the server at " + url + " answered request " + std::to_string(request) + ", which was not asked");
    const client_wire::Outstanding out = std::move(it->second);
    outstanding.erase(it);
    Decoder d(body);
    const NodeId type = d.nodeId();
    (void)d.i64();  // timestamp
    (void)d.u32();  // request handle
    const StatusCode result = d.u32();
    d.skipDiagnosticInfo();
    (void)d.strings();          // string table
    (void)d.extensionObject();  // additional header
    if (type == NodeId::num(detail::kServiceFault) || status::isBad(result)) {
      return answer(request, {false, {}, client_wire::serviceName(out.service) + " failed: " + status::name(result), result}, out);
    }
    if (type != NodeId::num(out.service + 3)) {
      return fail("the server at " + url + " answered a " + client_wire::serviceName(out.service) + " request with " + type.str());
    }
    if (open != (out.service == detail::kOpenSecureChannel)) return fail("the server at " + url + " sent an answer of the wrong message type");
    return answer(request, {true, std::string(d.rest()), {}, result}, out);
  }

  bool answer(std::uint32_t request, client_wire::Answer a, const client_wire::Outstanding& out) {
    switch (out.service) {
      case detail::kPublish: return publishAnswer(a);
      case detail::kOpenSecureChannel:
        // the token at once: the chunks after this one may carry it
        if (!out.keep) return renewAnswer(a);
        if (a.ok) {
          try {
            if (!takeToken(a.body)) return false;
          } catch (const DecodeError& bad) {
            return fail("the server at " + url + " sent an OpenSecureChannel answer that cannot be read: " + bad.what());
          }
        }
        break;
      case detail::kWrite:
        if (!out.keep) return writeAnswer(a, out.nodes);
        break;
      default: break;
    }
    if (out.keep) answers[request] = std::move(a);
    return true;
  }

  // ---- sending ----

  // chunks `body` (after the security header) as `type` ("OPN", "MSG", "CLO") for `request`
  bool sendChunks(const char* type, std::uint32_t request, const std::string& body) {
    const bool asymmetric = type[0] == 'O';
    std::string security;
    Encoder s(security);
    if (asymmetric) {
      s.string(detail::kPolicyNone);
      s.nullString();
      s.nullString();
    } else {
      s.u32(token);
    }
    const std::size_t overhead = 12 + security.size() + 8;
    const std::size_t room = send_buffer > overhead ? send_buffer - overhead : 1;
    const std::size_t count = std::max<std::size_t>((body.size() + room - 1) / room, 1);
    if ((server_message != 0 && body.size() > server_message) || (server_chunks != 0 && count > server_chunks) || (asymmetric && count > 1)) {
      return fail("a request of " + std::to_string(body.size()) + " bytes is more than the server at " + url + " takes");
    }
    for (std::size_t k = 0; k < count; ++k) {
      const std::string_view part = std::string_view(body).substr(k * room, room);
      std::string chunk(type, 3);
      chunk += k + 1 == count ? 'F' : 'C';
      Encoder e(chunk);
      e.u32(static_cast<std::uint32_t>(overhead + part.size()));
      e.u32(channel);
      chunk += security;
      e.u32(++send_sequence);
      e.u32(request);
      chunk += part;
      unsent += chunk;
    }
    return flush();
  }

  // the request header of every request
  std::string header(std::uint32_t request, std::uint32_t timeout_ms, bool with_session = true) const {
    std::string out;
    Encoder e(out);
    e.nodeId(with_session ? auth_token : NodeId{});
    e.i64(dateTimeNow());
    e.u32(request);  // the handle: the request id
    e.u32(0);        // no diagnostics
    e.nullString();  // audit entry
    e.u32(timeout_ms);
    e.nodeId({});    // no additional header
    e.u8(0);
    return out;
  }

  // sends a service request: `fields` after its header; the request id (0: it could not go)
  std::uint32_t request(std::uint32_t service, const std::string& fields, bool keep, std::vector<NodeId> nodes = {}) {
    if (broken) return 0;
    const std::uint32_t id = next_request++;
    if (next_request == 0) next_request = 1;
    const bool publish = service == detail::kPublish;
    std::string body;
    Encoder(body).nodeId(NodeId::num(service));
    body += header(id, publish ? 0 : static_cast<std::uint32_t>(options.timeout.count()), service != detail::kOpenSecureChannel);
    body += fields;
    client_wire::Outstanding out;
    out.service = service;
    out.deadline = publish ? Clock::time_point::max() : Clock::now() + options.timeout;
    out.keep = keep;
    out.nodes = std::move(nodes);
    outstanding[id] = std::move(out);
    ++stats.requests;
    if (service == detail::kOpenSecureChannel) return sendChunks("OPN", id, body) ? id : 0;
    if (renewing) {
      held.emplace_back(id, std::move(body));
      return id;
    }
    return sendChunks("MSG", id, body) ? id : 0;
  }

  // waits for the answer to `id` (it came or the timeout passed)
  bool await(std::uint32_t id, std::string& body, std::string& why) {
    if (id == 0) {
      why = error;
      return false;
    }
    const auto deadline = Clock::now() + options.timeout;
    while (true) {
      const auto it = answers.find(id);
      if (it != answers.end()) {
        client_wire::Answer a = std::move(it->second);
        answers.erase(it);
        if (!a.ok) {
          why = a.error;
          return false;
        }
        body = std::move(a.body);
        return true;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        const auto o = outstanding.find(id);
        fail("the server at " + url + " did not answer " + client_wire::serviceName(o == outstanding.end() ? 0 : o->second.service) + " within " +
             std::to_string(options.timeout.count()) + " ms");
        why = error;
        return false;
      }
      if (!pump(left) || !housekeeping()) {
        why = error;
        return false;
      }
    }
  }

  // ---- the secure channel ----

  bool hello() {
    std::string body;
    Encoder e(body);
    e.u32(0);
    e.u32(options.buffer_bytes);  // receive buffer
    e.u32(options.buffer_bytes);  // send buffer
    e.u32(options.message_bytes);
    e.u32(options.chunks);
    e.string(url.substr(0, 4096));
    std::string msg = "HELF";
    Encoder(msg).u32(static_cast<std::uint32_t>(8 + body.size()));
    unsent += msg + body;
    if (!flush()) return false;
    // the Acknowledge (or an Error), read by hand: it is no secure conversation chunk
    const auto deadline = Clock::now() + options.timeout;
    while (true) {
      if (in.size() >= 8) {
        const std::uint32_t length = Decoder(std::string_view(in).substr(4, 4)).u32();
        if (length < 8 || length > 8192) return fail("the server at " + url + " answered Hello with " + std::to_string(length) + " bytes");
        if (in.size() >= length) break;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return fail("the server at " + url + " did not answer Hello within " + std::to_string(options.timeout.count()) + " ms");
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left)) <= 0) continue;
      char buffer[8192];
      const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
      if (n < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
      if (n == 0) return fail("the server at " + url + " closed the connection after Hello");
      if (n < 0) return fail("the connection to " + url + " was lost: " + std::strerror(errno));
      in.append(buffer, static_cast<std::size_t>(n));
    }
    const std::uint32_t length = Decoder(std::string_view(in).substr(4, 4)).u32();
    const std::string ack = in.substr(0, length);
    in.erase(0, length);
    try {
      Decoder d(std::string_view(ack).substr(8));
      if (ack.compare(0, 3, "ERR") == 0) {
        const StatusCode code = d.u32();
        const std::string reason = d.string(4096);
        return fail("the server at " + url + " refused the connection: " + status::name(code) + (reason.empty() ? "" : ": " + reason));
      }
      if (ack.compare(0, 4, "ACKF") != 0) return fail("the server at " + url + " answered Hello with no Acknowledge: is it an OPC UA server?");
      (void)d.u32();  // protocol version
      const std::uint32_t server_receive = d.u32();
      const std::uint32_t server_send = d.u32();
      server_message = d.u32();
      server_chunks = d.u32();
      if (server_receive < 8192 || server_send < 8192) return fail("the server at " + url + " has buffers of fewer than 8192 bytes");
      if (server_send > options.buffer_bytes) {
        return fail("the server at " + url + " sends chunks of " + std::to_string(server_send) + " bytes, more than " +
                    std::to_string(options.buffer_bytes));
      }
      send_buffer = std::min(server_receive, options.buffer_bytes);
    } catch (const DecodeError& bad) {
      return fail("the server at " + url + " sent an Acknowledge that cannot be read: " + bad.what());
    }
    return true;
  }

  std::string openFields(std::uint32_t request_type) const {
    std::string out;
    Encoder e(out);
    e.u32(0);             // protocol version
    e.u32(request_type);  // 0 issue, 1 renew
    e.u32(1);             // MessageSecurityMode None
    e.nullString();       // client nonce
    e.u32(options.channel_lifetime_ms);
    return out;
  }

  // the token an OpenSecureChannel answer gives; false when it cannot be read
  bool takeToken(const std::string& body) {
    Decoder d(body);
    (void)d.u32();  // protocol version
    const std::uint32_t id = d.u32();
    const std::uint32_t new_token = d.u32();
    (void)d.i64();  // created at
    const std::uint32_t lifetime = d.u32();
    (void)d.string();  // server nonce
    if (channel != 0 && id != channel) return fail("the server at " + url + " renewed another secure channel");
    channel = id;
    token = new_token;
    tokens.emplace_back(token, Clock::now() + std::chrono::milliseconds(std::int64_t{lifetime} * 5 / 4));
    if (tokens.size() > 16) tokens.pop_front();
    // renew at three quarters of the lifetime (at least a second after now)
    const auto ms = options.renew_after_ms > 0 ? std::int64_t{options.renew_after_ms}
                                               : std::max<std::int64_t>(1000, static_cast<std::int64_t>(lifetime) * 3 / 4);
    renew_at = Clock::now() + std::chrono::milliseconds(ms);
    return true;
  }

  bool renewAnswer(const client_wire::Answer& a) {
    if (!a.ok) return fail("the server at " + url + " did not renew the secure channel: " + a.error);
    try {
      if (!takeToken(a.body)) return false;
    } catch (const DecodeError& bad) {
      return fail("the server at " + url + " sent an OpenSecureChannel answer that cannot be read: " + bad.what());
    }
    ++stats.renewals;
    renewing = false;
    while (!held.empty()) {
      auto [id, body] = std::move(held.front());
      held.pop_front();
      if (!sendChunks("MSG", id, body)) return false;
    }
    return true;
  }

  // ---- subscriptions ----

  bool publishAnswer(const client_wire::Answer& a) {
    if (publishing > 0) --publishing;
    if (!a.ok) {
      // a Publish that waited too long, or one too many: asked again by housekeeping
      if (a.status == status::kBadTimeout || a.status == status::kBadTooManyPublishRequests) return true;
      if (a.status == status::kBadSessionClosed || a.status == status::kBadSessionIdInvalid || a.status == status::kBadShutdown ||
          a.status == status::kBadServerHalted) {
        return fail("the server at " + url + " ended the session (" + status::name(a.status) + ")");
      }
      return fail("the server at " + url + " ended the subscription: " + a.error);
    }
    try {
      Decoder d(a.body);
      const std::uint32_t subscription = d.u32();
      (void)d.u32s();     // available sequence numbers
      (void)d.boolean();  // more notifications
      const std::uint32_t sequence_number = d.u32();
      (void)d.i64();      // publish time
      const std::size_t n = d.length(3);
      if (n > 0) acks.emplace_back(subscription, sequence_number);
      for (std::size_t k = 0; k < n; ++k) {
        const ExtensionObject data = d.extensionObject();
        if (data.encoding != 1) continue;
        if (data.type == NodeId::num(detail::kDataChangeNotification)) {
          Decoder c(data.body);
          const std::size_t items = c.length(5);
          for (std::size_t i = 0; i < items; ++i) {
            ItemChange change;
            change.handle = c.u32();
            change.value = c.dataValue();
            changes.push_back(std::move(change));
            ++stats.notifications;
          }
          const std::size_t diagnostics = c.length(1);
          for (std::size_t i = 0; i < diagnostics; ++i) c.skipDiagnosticInfo();
        } else if (data.type == NodeId::num(detail::kStatusChangeNotification)) {
          Decoder c(data.body);
          const StatusCode code = c.u32();
          if (status::isBad(code)) return fail("the server at " + url + " ended the subscription: " + status::name(code));
        }
        // events and other notifications: not asked for, left alone
      }
      (void)d.u32s();  // acknowledgement results
    } catch (const DecodeError& bad) {
      return fail("the server at " + url + " sent a Publish answer that cannot be read: " + bad.what());
    }
    return true;
  }

  bool writeAnswer(const client_wire::Answer& a, const std::vector<NodeId>& nodes) {
    writing = false;
    if (!a.ok) return fail("the server at " + url + " refused a write: " + a.error);
    try {
      Decoder d(a.body);
      const auto results = d.u32s();
      if (results.size() != nodes.size()) {
        return fail("the server at " + url + " answered a Write of " + std::to_string(nodes.size()) + " values with " +
                    std::to_string(results.size()) + " results");
      }
      for (std::size_t i = 0; i < results.size(); ++i) {
        if (status::isBad(results[i])) return fail("the server at " + url + " refused to write " + nodes[i].str() + ": " + status::name(results[i]));
        ++stats.writes;
      }
    } catch (const DecodeError& bad) {
      return fail("the server at " + url + " sent a Write answer that cannot be read: " + bad.what());
    }
    return true;
  }

  // Publish requests outstanding, the token renewed, no request overdue
  bool housekeeping() {
    if (broken) return false;
    const auto now = Clock::now();
    if (!renewing && now >= renew_at && channel != 0) {
      renewing = true;
      if (request(detail::kOpenSecureChannel, openFields(1), false) == 0) return false;
    }
    while (subscribed && publishing < options.publish_requests) {
      std::string fields;
      Encoder e(fields);
      e.length(acks.size());
      for (const auto& [sub, seq] : acks) {
        e.u32(sub);
        e.u32(seq);
      }
      acks.clear();
      if (request(detail::kPublish, fields, false) == 0) return false;
      ++publishing;
    }
    for (const auto& [id, out] : outstanding) {
      if (now > out.deadline) {
        return fail("the server at " + url + " did not answer " + client_wire::serviceName(out.service) + " within " +
                    std::to_string(options.timeout.count()) + " ms");
      }
    }
    // a subscription's keep-alives stopped: the server is gone
    if (subscribed) {
      const double quiet_ms = interval * keepalive * 2 + static_cast<double>(options.timeout.count());
      if (std::chrono::duration<double, std::milli>(now - last_heard).count() > quiet_ms) {
        return fail("the server at " + url + " has sent nothing for " + std::to_string(static_cast<long long>(quiet_ms)) +
                    " ms, not even a keep-alive");
      }
    }
    return flush();
  }

  // ---- the session ----

  static void applicationDescription(Encoder& e, const std::string& name) {
    e.string("urn:gdpn:client");
    e.string("https://gdpn.dev/gdpn");
    e.localizedText({"", name});
    e.u32(1);  // Client
    e.nullString();
    e.nullString();
    e.length(0);
  }

  // the anonymous token's policy id of the None endpoint, from GetEndpoints' answer
  bool readEndpoints(const std::string& body, std::string& why) {
    Decoder d(body);
    const std::size_t n = d.length(16);
    bool none_endpoint = false, anonymous = false;
    for (std::size_t i = 0; i < n; ++i) {
      (void)d.string(4096);  // endpoint URL
      (void)d.string(4096);  // application: URI
      (void)d.string(4096);  //              product URI
      (void)d.localizedText();
      (void)d.u32();
      (void)d.string(4096);
      (void)d.string(4096);
      (void)d.strings();
      (void)d.string();  // certificate
      const std::uint32_t mode = d.u32();
      const std::string policy = d.string(4096);
      const std::size_t token_count = d.length(8);
      std::string anonymous_id;
      bool has_anonymous = false;
      for (std::size_t k = 0; k < token_count; ++k) {
        const std::string policy_id = d.string(4096);
        const std::uint32_t token_type = d.u32();
        (void)d.string(4096);
        (void)d.string(4096);
        (void)d.string(4096);
        if (token_type == 0 && !has_anonymous) {
          has_anonymous = true;
          anonymous_id = policy_id;
        }
      }
      (void)d.string(4096);  // transport profile
      (void)d.u8();          // security level
      if (mode != 1 || policy != detail::kPolicyNone) continue;
      none_endpoint = true;
      if (has_anonymous && !anonymous) {
        anonymous = true;
        anonymous_policy = anonymous_id;
      }
    }
    if (!none_endpoint) {
      why = "the server at " + url + " offers no endpoint with security policy None";
      return false;
    }
    if (!anonymous) {
      why = "the server at " + url + " takes no anonymous users";
      return false;
    }
    return true;
  }

  bool openSession(std::string& why) {
    // discovery: the anonymous token's policy id
    std::string fields, body;
    Encoder g(fields);
    g.string(url);
    g.length(0);
    g.length(0);
    if (!await(request(detail::kGetEndpoints, fields, true), body, why)) return false;
    try {
      if (!readEndpoints(body, why)) return false;
    } catch (const DecodeError& bad) {
      why = std::string("the server's GetEndpoints answer cannot be read: ") + bad.what();
      return false;
    }
    // CreateSession
    fields.clear();
    Encoder c(fields);
    applicationDescription(c, options.session_name);
    c.nullString();  // server URI
    c.string(url);
    c.string(options.session_name);
    c.string(client_wire::clientRandomBytes(32));  // client nonce
    c.nullString();                   // client certificate
    c.f64(options.session_timeout_ms);
    c.u32(options.message_bytes);
    if (!await(request(detail::kCreateSession, fields, true), body, why)) return false;
    try {
      Decoder d(body);
      (void)d.nodeId();  // session id
      auth_token = d.nodeId();
    } catch (const DecodeError& bad) {
      why = std::string("the server's CreateSession answer cannot be read: ") + bad.what();
      return false;
    }
    // ActivateSession, anonymous
    fields.clear();
    Encoder a(fields);
    a.nullString();  // client signature: algorithm
    a.nullString();  //                   signature
    a.length(0);     // software certificates
    a.length(0);     // locales
    ExtensionObject token_object{NodeId::num(client_wire::kAnonymousTokenEncoding), 1, {}};
    Encoder(token_object.body).string(anonymous_policy);
    a.extensionObject(token_object);
    a.nullString();  // user token signature
    a.nullString();
    if (!await(request(detail::kActivateSession, fields, true), body, why)) return false;
    try {
      Decoder d(body);
      (void)d.string();  // server nonce
      const auto results = d.u32s();
      for (const auto r : results) {
        if (status::isBad(r)) {
          why = "the server at " + url + " refused the anonymous session: " + status::name(r);
          return false;
        }
      }
    } catch (const DecodeError& bad) {
      why = std::string("the server's ActivateSession answer cannot be read: ") + bad.what();
      return false;
    }
    session = true;
    return true;
  }

  void closeAll() {
    if (fd < 0) return;
    if (!broken) {
      if (session) {
        std::string fields;
        Encoder(fields).boolean(true);  // delete the subscriptions
        const std::uint32_t id = request(detail::kCloseSession, fields, true);
        const auto deadline = Clock::now() + std::min<std::chrono::milliseconds>(options.timeout, std::chrono::milliseconds(1000));
        while (id != 0 && !broken && answers.find(id) == answers.end() && Clock::now() < deadline) {
          pump(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count());
        }
      }
      if (!broken && !renewing) {
        std::string body;
        Encoder(body).nodeId(NodeId::num(detail::kCloseSecureChannel));
        const std::uint32_t id = next_request++;
        body += header(id, 0, false);
        sendChunks("CLO", id, body);
      }
    }
    ::shutdown(fd, SHUT_RDWR);
    ::close(fd);
    fd = -1;
    session = false;
    subscribed = false;
    if (!broken) {
      broken = true;
      error = "the connection to " + url + " is closed";
    }
  }
};

Client::Client(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Client::~Client() { close(); }

std::unique_ptr<Client> Client::connect(const std::string& url, const ClientOptions& options, std::string& why) {
  std::string host;
  std::uint16_t port = 0;
  if (!parseOpcUrl(url, host, port, why)) return nullptr;
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  impl->options.buffer_bytes = std::max<std::uint32_t>(options.buffer_bytes, 8192);
  impl->url = url;
  Impl& im = *impl;
  if (!im.openSocket(host, port) || !im.hello()) {
    why = im.error;
    return nullptr;
  }
  // the secure channel (its token taken as the answer comes)
  std::string body;
  if (!im.await(im.request(detail::kOpenSecureChannel, im.openFields(0), true), body, why)) return nullptr;
  if (!im.openSession(why)) return nullptr;
  return std::unique_ptr<Client>(new Client(std::move(impl)));
}

bool Client::read(const std::vector<ReadItem>& items, std::vector<DataValue>& values, std::string& why) {
  std::string fields, body;
  Encoder e(fields);
  e.f64(0);   // max age: the value now
  e.u32(0);   // timestamps: source
  e.length(items.size());
  for (const auto& item : items) {
    e.nodeId(item.node);
    e.u32(item.attribute);
    e.nullString();  // index range
    e.u16(0);        // data encoding: none (a null name: node-opcua takes "" for one named)
    e.nullString();
  }
  if (!impl_->await(impl_->request(detail::kRead, fields, true), body, why)) return false;
  try {
    Decoder d(body);
    const std::size_t n = d.length(1);
    if (n != items.size()) {
      why = "the server at " + impl_->url + " answered a Read of " + std::to_string(items.size()) + " values with " + std::to_string(n);
      return false;
    }
    values.clear();
    for (std::size_t i = 0; i < n; ++i) values.push_back(d.dataValue());
  } catch (const DecodeError& bad) {
    why = std::string("the server's Read answer cannot be read: ") + bad.what();
    return false;
  }
  impl_->stats.reads += items.size();
  return true;
}

namespace client_wire {

std::string writeFields(const std::vector<WriteItem>& items) {
  std::string fields;
  Encoder e(fields);
  e.length(items.size());
  for (const auto& item : items) {
    e.nodeId(item.node);
    e.u32(13);  // Value
    e.nullString();
    DataValue v;
    v.value = item.value;
    e.dataValue(v);
  }
  return fields;
}

}  // namespace client_wire

bool Client::write(const std::vector<WriteItem>& items, std::vector<StatusCode>& results, std::string& why) {
  std::string body;
  if (!impl_->await(impl_->request(detail::kWrite, client_wire::writeFields(items), true), body, why)) return false;
  try {
    Decoder d(body);
    results = d.u32s();
  } catch (const DecodeError& bad) {
    why = std::string("the server's Write answer cannot be read: ") + bad.what();
    return false;
  }
  if (results.size() != items.size()) {
    why = "the server at " + impl_->url + " answered a Write of " + std::to_string(items.size()) + " values with " +
          std::to_string(results.size()) + " results";
    return false;
  }
  for (const auto r : results) impl_->stats.writes += status::isBad(r) ? 0u : 1u;
  return true;
}

bool Client::writeAsync(const std::vector<WriteItem>& items, std::string& why) {
  std::vector<NodeId> nodes;
  for (const auto& item : items) nodes.push_back(item.node);
  if (impl_->request(detail::kWrite, client_wire::writeFields(items), false, std::move(nodes)) == 0) {
    why = impl_->error;
    return false;
  }
  impl_->writing = true;
  return true;
}

bool Client::writing() const { return impl_->writing; }

bool Client::subscribe(double interval_ms, std::uint32_t& subscription, std::string& why) {
  std::string fields, body;
  Encoder e(fields);
  e.f64(interval_ms);
  e.u32(0);   // lifetime count: the server's least (three keep-alives)
  e.u32(10);  // keep-alive count
  e.u32(0);   // notifications a Publish: no limit
  e.boolean(true);
  e.u8(0);    // priority
  if (!impl_->await(impl_->request(detail::kCreateSubscription, fields, true), body, why)) return false;
  try {
    Decoder d(body);
    subscription = d.u32();
    impl_->interval = d.f64();
    (void)d.u32();  // revised lifetime count
    impl_->keepalive = d.u32();
  } catch (const DecodeError& bad) {
    why = std::string("the server's CreateSubscription answer cannot be read: ") + bad.what();
    return false;
  }
  if (!std::isfinite(impl_->interval) || impl_->interval < 0 || impl_->interval > 3600000) {
    why = "the server at " + impl_->url + " revised the publishing interval to " + std::to_string(impl_->interval) + " ms";
    return false;
  }
  impl_->subscribed = true;
  impl_->last_heard = Clock::now();
  if (!impl_->housekeeping()) {
    why = impl_->error;
    return false;
  }
  return true;
}

bool Client::monitor(std::uint32_t subscription, const std::vector<MonitorItem>& items, std::vector<StatusCode>& results,
                     std::string& why) {
  std::string fields, body;
  Encoder e(fields);
  e.u32(subscription);
  e.u32(0);  // timestamps: source
  e.length(items.size());
  for (const auto& item : items) {
    e.nodeId(item.node);
    e.u32(13);
    e.nullString();
    e.u16(0);        // data encoding: none (a null name: node-opcua takes "" for one named)
    e.nullString();
    e.u32(2);  // reporting
    e.u32(item.handle);
    e.f64(item.sampling_ms);
    e.extensionObject({});  // no filter
    e.u32(1);               // queue size
    e.boolean(true);        // discard the oldest
  }
  if (!impl_->await(impl_->request(detail::kCreateMonitoredItems, fields, true), body, why)) return false;
  try {
    Decoder d(body);
    const std::size_t n = d.length(4);
    if (n != items.size()) {
      why = "the server at " + impl_->url + " answered for " + std::to_string(n) + " of " + std::to_string(items.size()) + " monitored items";
      return false;
    }
    results.clear();
    for (std::size_t i = 0; i < n; ++i) {
      results.push_back(d.u32());
      (void)d.u32();  // monitored item id
      (void)d.f64();  // revised sampling interval
      (void)d.u32();  // revised queue size
      (void)d.extensionObject();
    }
  } catch (const DecodeError& bad) {
    why = std::string("the server's CreateMonitoredItems answer cannot be read: ") + bad.what();
    return false;
  }
  return true;
}

bool Client::poll(std::int64_t timeout_ms, std::string& why) {
  Impl& im = *impl_;
  if (!im.housekeeping() || !im.pump(timeout_ms) || !im.housekeeping()) {
    why = im.error;
    return false;
  }
  return true;
}

std::vector<ItemChange> Client::takeChanges() { return std::exchange(impl_->changes, {}); }

void Client::close() {
  if (impl_) impl_->closeAll();
}

double Client::publishingInterval() const { return impl_->interval; }
const std::string& Client::anonymousPolicy() const { return impl_->anonymous_policy; }
const ClientStats& Client::stats() const { return impl_->stats; }

}  // namespace gdpn::opcua
