// The Modbus TCP server: sockets read without blocking, frames cut and vetted by request.cpp,
// answers built and sent by libmodbus from a mapping filled for each request.

#include "gdpn/modbus/server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <vector>

#include "gdpn/core/listen_address.h"
#include "gdpn/modbus/request.h"

namespace gdpn::modbus {

bool parseEndpoint(const std::string& text, ServerOptions& options, std::string& why) {
  return core::parseListenAddress(text, options.address, options.port, why);
}

/// One connection: its socket, its name and the bytes of a frame not yet whole.
struct Server::Client {
  int fd = -1;
  std::string name;  // "ip:port"
  std::vector<std::uint8_t> pending;
};

/// libmodbus' context and a mapping as large as the address space: each request's range is
/// filled from the map just before libmodbus reads it.
struct Server::Impl {
  modbus_t* ctx = nullptr;
  modbus_mapping_t* mapping = nullptr;
  int listener = -1;
  std::vector<Client> clients;
  std::vector<pollfd> fds;  // the listener and each client, made anew each round (kept to reuse its memory)
  ~Impl() {
    for (auto& c : clients) ::close(c.fd);
    if (listener >= 0) ::close(listener);
    if (mapping) modbus_mapping_free(mapping);
    if (ctx) modbus_free(ctx);
  }
};

Server::Server(model::IoMap& map, const ServerOptions& options)
    : map_(map), options_(options), impl_(std::make_unique<Impl>()) {}

Server::~Server() = default;

std::unique_ptr<Server> Server::listen(model::IoMap& map, const ServerOptions& options, std::string& why) {
  auto server = std::unique_ptr<Server>(new Server(map, options));
  Impl& im = *server->impl_;
  const std::string where = options.address + ":" + std::to_string(options.port);
  im.ctx = modbus_new_tcp(options.address.c_str(), options.port);
  im.mapping = modbus_mapping_new(65536, 65536, 65536, 65536);
  if (!im.ctx || !im.mapping) {
    why = std::string("libmodbus: ") + modbus_strerror(errno);
    return nullptr;
  }
  im.listener = modbus_tcp_listen(im.ctx, 64);  // a burst of clients waits to be accepted
  if (im.listener < 0) {
    why = "cannot listen on " + where + ": " + modbus_strerror(errno);
    return nullptr;
  }
  // accepting never blocks: a client may be gone between the poll and the accept
  fcntl(im.listener, F_SETFL, fcntl(im.listener, F_GETFL) | O_NONBLOCK);
  sockaddr_in bound{};
  socklen_t size = sizeof bound;
  if (getsockname(im.listener, reinterpret_cast<sockaddr*>(&bound), &size) != 0) {
    why = "cannot listen on " + where + ": " + std::strerror(errno);
    return nullptr;
  }
  server->port_ = ntohs(bound.sin_port);
  return server;
}

void Server::close(std::size_t index, const char* why) {
  auto& clients = impl_->clients;
  if (log_) *log_ << "modbus: " << clients[index].name << " " << why << "\n";
  ::close(clients[index].fd);
  clients.erase(clients.begin() + static_cast<std::ptrdiff_t>(index));
}

void Server::accept() {
  sockaddr_in peer{};
  socklen_t size = sizeof peer;
  const int fd = accept4(impl_->listener, reinterpret_cast<sockaddr*>(&peer), &size, SOCK_NONBLOCK | SOCK_CLOEXEC);
  if (fd < 0) return;  // gone before it was accepted, or out of descriptors: the run goes on
  if (impl_->clients.size() >= static_cast<std::size_t>(options_.max_clients)) {
    ++stats_.refused;
    if (log_) *log_ << "modbus: a client refused: " << options_.max_clients << " are connected\n";
    ::close(fd);
    return;
  }
  const int on = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);  // answers go out at once
  char ip[INET_ADDRSTRLEN] = "?";
  inet_ntop(AF_INET, &peer.sin_addr, ip, sizeof ip);
  Client c;
  c.fd = fd;
  c.name = std::string(ip) + ":" + std::to_string(ntohs(peer.sin_port));
  ++stats_.clients;
  if (log_) *log_ << "modbus: " << c.name << " connected\n";
  impl_->clients.push_back(std::move(c));
}

bool Server::answer(Client& c, const std::uint8_t* frame, std::size_t length) {
  Impl& im = *impl_;
  Request r = decodeRequest({frame, length});
  ++stats_.requests;
  if (r.error == model::IoError::None && r.write && options_.read_only) r.error = model::IoError::IllegalFunction;
  if (r.error == model::IoError::None && !map_.mapped(r.table, r.address, r.count)) {
    r.error = model::IoError::IllegalAddress;
  }
  if (r.error == model::IoError::None && r.write) {
    ++stats_.writes;
    r.error = r.table == model::IoTable::Coils ? map_.writeBits(r.address, r.bits, c.name)
                                               : map_.writeWords(r.address, r.words, c.name);
  } else if (r.error == model::IoError::None) {
    // the range read, filled from the run now
    for (std::uint32_t k = 0; k < r.count; ++k) {
      const auto a = static_cast<std::uint16_t>(r.address + k);
      switch (r.table) {
        case model::IoTable::DiscreteInputs: im.mapping->tab_input_bits[a] = map_.bit(r.table, a) ? 1 : 0; break;
        case model::IoTable::Coils: im.mapping->tab_bits[a] = map_.bit(r.table, a) ? 1 : 0; break;
        case model::IoTable::InputRegisters: im.mapping->tab_input_registers[a] = map_.word(r.table, a); break;
        case model::IoTable::HoldingRegisters: im.mapping->tab_registers[a] = map_.word(r.table, a); break;
      }
    }
  }
  modbus_set_socket(im.ctx, c.fd);
  int sent = 0;
  if (r.error != model::IoError::None) {
    ++stats_.exceptions;
    sent = modbus_reply_exception(im.ctx, frame, static_cast<unsigned>(r.error));
  } else {
    // a write's reply echoes it; libmodbus writes the values into the mapping, which the next
    // read of that range fills anew
    sent = modbus_reply(im.ctx, frame, static_cast<int>(length), im.mapping);
  }
  modbus_set_socket(im.ctx, -1);
  return sent > 0;
}

const char* Server::serve(Client& c) {
  std::uint8_t buffer[4096];
  // at most 64 KiB a round: a client that floods is served in turn with the others
  for (int reads = 0; reads < 16; ++reads) {
    const ssize_t n = recv(c.fd, buffer, sizeof buffer, 0);
    if (n == 0) return c.pending.empty() ? "disconnected" : "disconnected with a frame half sent";
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) break;
      return "disconnected (reset)";
    }
    c.pending.insert(c.pending.end(), buffer, buffer + n);
    // whole frames are answered as they come; at most a frame's bytes wait
    std::size_t at = 0;
    for (;;) {
      const std::ptrdiff_t length = frameLength({c.pending.data() + at, c.pending.size() - at});
      if (length < 0) {
        ++stats_.dropped;
        return "closed: it sent bytes that are no Modbus TCP (a protocol id other than 0, or a wrong length)";
      }
      if (length == 0) break;
      if (!answer(c, c.pending.data() + at, static_cast<std::size_t>(length))) return "disconnected (an answer could not be sent)";
      at += static_cast<std::size_t>(length);
    }
    c.pending.erase(c.pending.begin(), c.pending.begin() + static_cast<std::ptrdiff_t>(at));
    if (static_cast<std::size_t>(n) < sizeof buffer) break;  // read what there was
  }
  return nullptr;
}

void Server::round(std::int64_t timeout_ns) {
  Impl& im = *impl_;
  std::vector<pollfd>& fds = im.fds;
  fds.clear();
  fds.push_back({im.listener, POLLIN, 0});
  for (const auto& c : im.clients) fds.push_back({c.fd, POLLIN, 0});
  timespec wait{};
  wait.tv_sec = static_cast<time_t>(timeout_ns / 1'000'000'000);
  wait.tv_nsec = static_cast<long>(timeout_ns % 1'000'000'000);
  const int ready = ppoll(fds.data(), fds.size(), &wait, nullptr);
  if (ready <= 0) return;  // the time is up, or a signal came (Ctrl-C)
  // clients first, from the last so that closing one leaves the others' indices
  for (std::size_t k = fds.size() - 1; k >= 1; --k) {
    if (fds[k].revents == 0) continue;
    const char* gone = (fds[k].revents & (POLLERR | POLLNVAL)) != 0 ? "disconnected (reset)" : serve(im.clients[k - 1]);
    if (gone != nullptr) close(k - 1, gone);
  }
  if ((fds[0].revents & POLLIN) != 0) accept();
}

void Server::serveUntil(Clock::time_point deadline, const std::atomic<bool>* stop) {
  do {
    const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now()).count();
    round(std::max<std::int64_t>(left, 0));
  } while (Clock::now() < deadline && !(stop && stop->load(std::memory_order_relaxed)));
}

void Server::serveUntilStepAsked(const std::atomic<bool>* stop) {
  while (map_.pendingSteps() == 0 && !(stop && stop->load(std::memory_order_relaxed))) {
    round(100'000'000);  // a tenth of a second at most, to see `stop`
  }
}

}  // namespace gdpn::modbus
