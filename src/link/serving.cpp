// A run's outside links (`gdpn run --modbus / --opcua / --opcua-client / --realtime /
// --lockstep`), hooked in before each step: the servers serve, the monitored items are sampled
// at the step boundary, the PLC's values are exchanged, and the step waits for the wall clock
// or for a controller to ask for it.

#include "gdpn/link/serving.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <iomanip>
#include <thread>

#include "gdpn/net/kernel.h"
#include "gdpn/opcua/model_space.h"
#include "gdpn/opcua/plc_link.h"

namespace gdpn::link {

/// The PLC whose own server drives the plant (--opcua-client).
struct Serving::Plc {
  std::unique_ptr<opcua::PlcLink> link;
  std::string url;
};

Serving::Serving() = default;
Serving::~Serving() = default;

std::string Serving::opcuaUrl() const { return opcua_ ? opcua_->url() : std::string(); }

bool Serving::start(const ServeRequest& args, model::Simulation& sim, std::atomic<bool>* interrupt, bool quiet,
                    std::ostream& err, int& code) {
  interrupt_ = interrupt;
  lockstep_ = args.lockstep;
  const bool linked = !args.modbus.empty() || !args.opcua.empty() || !args.opcua_client.empty();
  pacing_ = args.pace && (args.realtime || (linked && !args.lockstep));
  const auto& spec = sim.model().io;
  const std::string file = sim.model().path.empty() ? "the model" : sim.model().path;
  modbus::ServerOptions modbus_options;
  opcua::ServerOptions opcua_options;
  std::string why;
  if (!args.modbus.empty() && !modbus::parseEndpoint(args.modbus, modbus_options, why)) {
    err << "error: --modbus: " << why << "\n";
    code = 2;
    return false;
  }
  if (!args.opcua.empty() && !opcua::parseEndpoint(args.opcua, opcua_options, why)) {
    err << "error: --opcua: " << why << "\n";
    code = 2;
    return false;
  }
  if (spec.empty() && (!args.modbus.empty() || !args.opcua_client.empty())) {
    err << file << ": error: "
        << (args.modbus.empty() ? "--opcua-client links the PLC's nodes to the model's io section"
                                : "--modbus serves the model's io section")
        << ", and it has none (docs/format.md, I/O)\n";
    code = 1;
    return false;
  }
  if (args.lockstep && args.modbus.empty() && args.opcua.empty()) {
    err << "error: --lockstep needs a controller to ask for steps: --modbus or --opcua\n";
    code = 2;
    return false;
  }
  if (args.lockstep && args.opcua.empty() && !spec.lockstep) {
    err << file << ": error: --lockstep needs a lockstep register in the io section (io: {lockstep: ADDRESS}), "
        << "or --opcua (a client calls Step)\n";
    code = 1;
    return false;
  }
  if (!spec.empty() && linked) {
    core::Diagnostics diags;
    io_ = model::IoMap::create(sim, spec, diags);
    diags.print(err);
    if (!io_) {
      code = 1;
      return false;
    }
  }
  if (!args.modbus.empty()) {
    modbus_options.read_only = args.read_only;
    modbus_ = modbus::Server::listen(*io_, modbus_options, why);
    if (!modbus_) {
      err << "error: --modbus: " << why << "\n";
      code = 1;
      return false;
    }
    if (!quiet) modbus_->setLog(&err);
    modbus_endpoint_ = modbus_options.address + ":" + std::to_string(modbus_->port());
    // the line a controller's launcher waits for (the port, when the system picked it)
    err << "modbus: serving " << modbus_endpoint_ << (args.read_only ? " read-only" : "")
        << (lockstep_ ? ", in lockstep" : ", in real time") << std::endl;
  }
  if (!args.opcua.empty()) {
    space_ = opcua::modelAddressSpace(sim, io_.get(), client_name_);
    opcua_options.read_only = args.read_only;
    opcua_ = opcua::Server::listen(*space_, opcua_options, why);
    if (!opcua_) {
      err << "error: --opcua: " << why << "\n";
      code = 1;
      return false;
    }
    opcua_->endpoint().setLockstep(lockstep_);
    if (!quiet) opcua_->setLog(&err);
    err << "opcua: serving " << opcua_->url() << (args.read_only ? " read-only" : "")
        << (lockstep_ ? ", in lockstep" : ", in real time") << std::endl;
  }
  if (!args.opcua_client.empty()) {
    core::Diagnostics diags;
    plc_ = std::make_unique<Plc>();
    plc_->url = args.opcua_client;
    plc_->link = opcua::PlcLink::connect(args.opcua_client, *io_, file, diags, why);
    if (!plc_->link) {
      diags.print(err);
      if (!diags.hasErrors()) err << "error: --opcua-client: " << why << "\n";
      code = 1;
      return false;
    }
    err << "opcua-client: linked to " << args.opcua_client << std::endl;
  }
  if (modbus_ || opcua_) sim.setOpen(true);  // a controller may yet act: a dead net does not end the run
  if (pacing_ || linked) sim.setBeforeStep([this, &sim] { beforeStep(sim); });
  return true;
}

bool Serving::stepAsked() const {
  return (modbus_ && io_ && io_->pendingSteps() > 0) || (opcua_ && opcua_->endpoint().pendingSteps() > 0);
}

void Serving::serveUntil(Clock::time_point deadline) {
  if (modbus_ && opcua_) {
    // both: in turns of at most a millisecond each
    do {
      const auto slice = std::min(deadline, Clock::now() + std::chrono::milliseconds(1));
      modbus_->serveUntil(slice, interrupt_);
      opcua_->serveUntil(std::min(deadline, Clock::now() + std::chrono::milliseconds(1)), interrupt_);
    } while (Clock::now() < deadline && !(interrupt_ && interrupt_->load(std::memory_order_relaxed)) &&
             !(lockstep_ && stepAsked()));
  } else if (modbus_) {
    modbus_->serveUntil(deadline, interrupt_);
  } else if (opcua_) {
    opcua_->serveUntil(deadline, interrupt_);
  } else {
    std::this_thread::sleep_until(deadline);
  }
}

void Serving::idle() {
  if (modbus_) modbus_->serveUntil(Clock::now(), interrupt_);
  if (opcua_) opcua_->round(0);
}

void Serving::beforeStep(model::Simulation& sim) {
  const net::Kernel& k = sim.kernel();
  if (!started_) {
    started_ = true;
    wall0_ = Clock::now();
    step0_ = k.steps();
    t0_ = k.now();
  } else if (granted_opcua_) {
    opcua_->endpoint().stepTaken();  // the step a Step call asked for is taken: its answer may go
    granted_opcua_ = false;
  }
  if (opcua_) {
    opcua_->endpoint().sample(k.now());  // a step boundary: every monitored item sampled
    opcua_->flush();
  }
  if (lockstep_) {
    if (modbus_ && !opcua_) {
      modbus_->serveUntilStepAsked(interrupt_);
    } else if (opcua_ && !modbus_) {
      opcua_->serveUntilStepAsked(interrupt_);
    } else {
      while (!stepAsked() && !(interrupt_ && interrupt_->load(std::memory_order_relaxed))) {
        serveUntil(Clock::now() + std::chrono::milliseconds(100));
      }
    }
    if (io_ && io_->pendingSteps() > 0) {
      io_->stepTaken();
    } else if (opcua_ && opcua_->endpoint().pendingSteps() > 0) {
      granted_opcua_ = true;
    }
    exchangeWithPlc();
    return;
  }
  if (!pacing_) {
    idle();
  } else {
    // the state at model time t is shown from wall time t until the next step's
    serveUntil(wall0_ + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(static_cast<double>(k.steps() - step0_) * k.dt())));
  }
  exchangeWithPlc();
}

void Serving::exchangeWithPlc() {
  // last before the step: the PLC's newest outputs go into it
  if (!plc_ || !failure_.empty()) return;
  std::string why;
  if (plc_->link->exchange(why)) return;
  failure_ = "--opcua-client: " + why;
  if (interrupt_) interrupt_->store(true);  // the run stops at once
}

void Serving::finish(model::Simulation& sim, std::ostream& out) {
  sim.setBeforeStep({});
  if (!started_) return;
  const double wall = std::chrono::duration<double>(Clock::now() - wall0_).count();
  const double simulated = sim.kernel().now() - t0_;
  char line[160];
  if (wall > 0) {
    std::snprintf(line, sizeof line, "%s: %.3f s simulated in %.3f s of wall clock, %.3f x real time\n",
                  lockstep_ ? "lockstep" : "real time", simulated, wall, simulated / wall);
    out << "\n" << line;
  }
  if (granted_opcua_) opcua_->endpoint().stepTaken();  // the last step asked for, taken
  granted_opcua_ = false;
  if (modbus_) {
    const auto& s = modbus_->stats();
    out << "Modbus TCP on " << modbus_endpoint_ << ": " << s.clients << (s.clients == 1 ? " client, " : " clients, ")
        << s.requests << " requests (" << s.writes << " writes, " << s.exceptions << " answered with an exception)";
    if (s.refused > 0) out << ", " << s.refused << " connections refused (too many clients)";
    if (s.dropped > 0) out << ", " << s.dropped << " closed for bytes that are no Modbus TCP";
    out << "\n";
  }
  if (opcua_) {
    opcua_->flush();
    const auto& s = opcua_->endpoint().stats();
    out << "OPC UA on " << opcua_->url() << ": " << s.connections << (s.connections == 1 ? " connection, " : " connections, ")
        << s.sessions << (s.sessions == 1 ? " session, " : " sessions, ") << s.requests << " requests (" << s.writes
        << " writes, " << s.faults << " faults), " << s.notifications << " data changes sent";
    if (opcua_->refused() > 0) out << ", " << opcua_->refused() << " connections refused (too many)";
    if (s.dropped > 0) out << ", " << s.dropped << " closed for bytes that are no OPC UA";
    out << "\n";
  }
  if (plc_) {
    const auto& s = plc_->link->stats();
    out << "PLC at " << plc_->url << ": " << s.reads << " read, " << s.writes << " written, " << s.notifications << " received\n";
    plc_->link->close();
  }
  if (!io_) return;
  out << "\n";
  // the live table, each column as wide as its widest entry, under a heading per Modbus table
  // (the table is no column: the lines stay within 100 columns)
  std::vector<std::array<std::string, 7>> table = {
      {"", "name", "address", "wire", "as", "value", "maps"}};
  std::vector<std::string> writers = {"last writer"};
  const auto rows = io_->rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    char wire[32];
    std::snprintf(wire, sizeof wire, "%.10g", io_->read(i));  // the number on the wire (a Float's exactly)
    std::snprintf(line, sizeof line, "%.6g", r.value);
    table.push_back({model::ioTableKey(r.table), r.name, std::to_string(r.address), wire, r.wire, line, r.what});
    writers.push_back(r.writer);
  }
  std::array<std::size_t, 7> width{};
  for (const auto& row : table) {
    for (std::size_t c = 1; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& row = table[i];
    if (i > 0 && row[0] != table[i - 1][0]) out << row[0] << ":\n";
    std::string text = "  ";
    for (std::size_t c = 1; c < row.size(); ++c) {
      const bool right = c == 2 || c == 3 || c == 5;  // the numbers
      const std::string pad(width[c] - row[c].size(), ' ');
      text += (c == 1 ? "" : "  ") + (right ? pad + row[c] : row[c] + pad);
    }
    text += "  " + writers[i];
    text.erase(text.find_last_not_of(' ') + 1);
    out << text << "\n";
  }
}

}  // namespace gdpn::link
