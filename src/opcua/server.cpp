// The OPC UA server's sockets: accepted without blocking, read and written without blocking,
// each connection's bytes handed to the Endpoint.

#include "gdpn/opcua/server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "gdpn/core/listen_address.h"

namespace gdpn::opcua {

bool parseEndpoint(const std::string& text, ServerOptions& options, std::string& why) {
  return core::parseListenAddress(text, options.address, options.port, why);
}

/// One socket and its connection at the endpoint.
struct ServerSocket {
  int fd = -1;
  ConnectionId id = 0;
  std::string name;
  std::string unsent;  // what the kernel would not take yet
  bool closing = false;
  Server::Clock::time_point closing_since;  // a closing socket whose client reads nothing is dropped after a while
  Server::Clock::time_point progress;       // when the kernel last took bytes of it (or it connected)
};

struct Server::Impl {
  int listener = -1;
  std::vector<ServerSocket> sockets;
  std::vector<pollfd> fds;
  ~Impl() {
    for (auto& s : sockets) ::close(s.fd);
    if (listener >= 0) ::close(listener);
  }
};

Server::Server(AddressSpace& space, const ServerOptions& options) : impl_(std::make_unique<Impl>()), options_(options) {
  (void)space;
}

Server::~Server() = default;

std::unique_ptr<Server> Server::listen(AddressSpace& space, const ServerOptions& options, std::string& why) {
  auto server = std::unique_ptr<Server>(new Server(space, options));
  Impl& im = *server->impl_;
  const std::string where = options.address + ":" + std::to_string(options.port);
  im.listener = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (im.listener < 0) {
    why = std::string("cannot make a socket: ") + std::strerror(errno);
    return nullptr;
  }
  const int on = 1;
  setsockopt(im.listener, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(options.port);
  inet_pton(AF_INET, options.address.c_str(), &addr.sin_addr);
  if (bind(im.listener, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(im.listener, 64) != 0) {
    why = "cannot listen on " + where + ": " + std::strerror(errno);
    return nullptr;
  }
  sockaddr_in bound{};
  socklen_t size = sizeof bound;
  getsockname(im.listener, reinterpret_cast<sockaddr*>(&bound), &size);
  server->port_ = ntohs(bound.sin_port);
  std::string host = options.address;
  if (host == "0.0.0.0") {
    char name[256] = "localhost";
    gethostname(name, sizeof name - 1);
    host = name;
  }
  server->url_ = "opc.tcp://" + host + ":" + std::to_string(server->port_);
  server->endpoint_ = std::make_unique<Endpoint>(space, server->url_, options.limits, options.read_only, options.seed);
  return server;
}

void Server::accept() {
  sockaddr_in peer{};
  socklen_t size = sizeof peer;
  const int fd = accept4(impl_->listener, reinterpret_cast<sockaddr*>(&peer), &size, SOCK_NONBLOCK | SOCK_CLOEXEC);
  if (fd < 0) return;
  if (impl_->sockets.size() >= options_.limits.connections) {
    ++refused_;
    if (log_) *log_ << "opcua: a client refused: " << options_.limits.connections << " are connected\n";
    ::close(fd);
    return;
  }
  const int on = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
  char ip[INET_ADDRSTRLEN] = "?";
  inet_ntop(AF_INET, &peer.sin_addr, ip, sizeof ip);
  ServerSocket s;
  s.fd = fd;
  s.name = std::string(ip) + ":" + std::to_string(ntohs(peer.sin_port));
  s.id = endpoint_->open(s.name);
  s.progress = Clock::now();
  if (log_) *log_ << "opcua: " << s.name << " connected\n";
  impl_->sockets.push_back(std::move(s));
}

void Server::flush() {
  auto& sockets = impl_->sockets;
  for (std::size_t k = sockets.size(); k-- > 0;) {
    ServerSocket& s = sockets[k];
    if (s.unsent.empty() && endpoint_->hasOutput(s.id)) s.progress = Clock::now();  // the wait for the client starts now
    s.unsent += endpoint_->takeOutput(s.id);
    while (!s.unsent.empty()) {
      const ssize_t n = send(s.fd, s.unsent.data(), s.unsent.size(), MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
      if (n <= 0) {
        s.closing = true;
        s.unsent.clear();
        break;
      }
      s.unsent.erase(0, static_cast<std::size_t>(n));
      s.progress = Clock::now();
    }
    // a client that reads nothing while answers pile up is let go at once; a closing one that
    // does not take its last bytes, after five seconds
    const auto now = Clock::now();
    if (s.unsent.size() > 4 * options_.limits.message_bytes) {
      s.unsent.clear();
      s.closing = true;
    }
    if (!s.unsent.empty() && now - s.progress > std::chrono::seconds(30)) {  // it has read nothing for 30 s
      s.unsent.clear();
      s.closing = true;
    }
    if (s.closing && s.closing_since == Clock::time_point{}) s.closing_since = now;
    if (s.closing && now - s.closing_since > std::chrono::seconds(5)) s.unsent.clear();
    if (s.closing && s.unsent.empty()) {
      if (log_) *log_ << "opcua: " << s.name << " disconnected\n";
      endpoint_->close(s.id);
      ::close(s.fd);
      sockets.erase(sockets.begin() + static_cast<std::ptrdiff_t>(k));
    }
  }
}

void Server::round(std::int64_t timeout_ns) {
  Impl& im = *impl_;
  // no longer than the next publishing interval
  const auto due = endpoint_->nextDue();
  if (due != Clock::time_point::max()) {
    const auto until = std::chrono::duration_cast<std::chrono::nanoseconds>(due - Clock::now()).count();
    timeout_ns = std::clamp<std::int64_t>(until, 0, timeout_ns);
  }
  im.fds.clear();
  im.fds.push_back({im.listener, POLLIN, 0});
  for (const auto& s : im.sockets) {
    // a closing socket is only written; one whose answers back up is not read until they go
    const bool read = !s.closing && s.unsent.size() < options_.limits.message_bytes;
    im.fds.push_back({s.fd, static_cast<short>((read ? POLLIN : 0) | (s.unsent.empty() ? 0 : POLLOUT)), 0});
  }
  timespec wait{};
  wait.tv_sec = static_cast<time_t>(timeout_ns / 1'000'000'000);
  wait.tv_nsec = static_cast<long>(timeout_ns % 1'000'000'000);
  const int ready = ppoll(im.fds.data(), im.fds.size(), &wait, nullptr);
  if (ready > 0) {
    for (std::size_t k = 1; k < im.fds.size(); ++k) {
      ServerSocket& s = im.sockets[k - 1];
      if ((im.fds[k].revents & (POLLERR | POLLNVAL)) != 0 || ((im.fds[k].revents & POLLHUP) != 0 && (im.fds[k].events & POLLIN) == 0)) {
        s.closing = true;
        s.unsent.clear();
        continue;
      }
      if ((im.fds[k].revents & (POLLIN | POLLHUP)) == 0) continue;
      std::uint8_t buffer[16384];
      // at most 256 KiB a round: a client that floods is served in turn with the others
      for (int reads = 0; reads < 16 && !s.closing && s.unsent.size() < options_.limits.message_bytes; ++reads) {
        const ssize_t n = recv(s.fd, buffer, sizeof buffer, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        if (n <= 0) {
          s.closing = true;
          break;
        }
        const auto dropped = endpoint_->stats().dropped;
        if (!endpoint_->receive(s.id, buffer, static_cast<std::size_t>(n))) {
          s.closing = true;
          if (log_ && endpoint_->stats().dropped > dropped) {
            *log_ << "opcua: " << s.name << " closed: it sent bytes that are no OPC UA, or broke a limit\n";
          }
        }
        if (s.unsent.empty() && endpoint_->hasOutput(s.id)) s.progress = Clock::now();
        s.unsent += endpoint_->takeOutput(s.id);  // the answers, counted against what may wait
        if (static_cast<std::size_t>(n) < sizeof buffer) break;
      }
    }
    if ((im.fds[0].revents & POLLIN) != 0) accept();
  }
  endpoint_->tick(Clock::now());
  flush();
}

void Server::serveUntil(Clock::time_point deadline, const std::atomic<bool>* stop) {
  do {
    const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now()).count();
    round(std::max<std::int64_t>(left, 0));
  } while (Clock::now() < deadline && !(stop && stop->load(std::memory_order_relaxed)));
}

void Server::serveUntilStepAsked(const std::atomic<bool>* stop) {
  while (endpoint_->pendingSteps() == 0 && !(stop && stop->load(std::memory_order_relaxed))) round(100'000'000);
}

}  // namespace gdpn::opcua
