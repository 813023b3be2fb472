// A run's Modbus server and pacing (`gdpn run --modbus / --realtime / --lockstep`), hooked in
// before each step.

#include "gdpn/modbus/serving.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <iomanip>
#include <thread>

#include "gdpn/net/kernel.h"

namespace gdpn::modbus {

bool Serving::start(const ServeRequest& args, model::Simulation& sim, const std::atomic<bool>* interrupt, bool quiet,
                    std::ostream& err, int& code) {
  interrupt_ = interrupt;
  lockstep_ = args.lockstep;
  pacing_ = args.realtime || (!args.modbus.empty() && !args.lockstep);
  if (!args.modbus.empty()) {
    ServerOptions options;
    std::string why;
    if (!parseEndpoint(args.modbus, options, why)) {
      err << "error: --modbus: " << why << "\n";
      code = 2;
      return false;
    }
    const auto& spec = sim.model().io;
    const std::string file = sim.model().path.empty() ? "the model" : sim.model().path;
    if (spec.empty()) {
      err << file << ": error: --modbus serves the model's io section, and it has none (docs/format.md, I/O)\n";
      code = 1;
      return false;
    }
    if (args.lockstep && !spec.lockstep) {
      err << file << ": error: --lockstep needs a lockstep register in the io section (io: {lockstep: ADDRESS})\n";
      code = 1;
      return false;
    }
    core::Diagnostics diags;
    io_ = model::IoMap::create(sim, spec, diags);
    diags.print(err);
    if (!io_) {
      code = 1;
      return false;
    }
    options.read_only = args.read_only;
    server_ = Server::listen(*io_, options, why);
    if (!server_) {
      err << "error: --modbus: " << why << "\n";
      code = 1;
      return false;
    }
    if (!quiet) server_->setLog(&err);
    endpoint_ = options.address + ":" + std::to_string(server_->port());
    // the line a controller's launcher waits for (the port, when the system picked it)
    err << "modbus: serving " << endpoint_ << (args.read_only ? " read-only" : "")
        << (lockstep_ ? ", in lockstep" : ", in real time") << std::endl;
    sim.setOpen(true);  // a controller may yet act: a dead net does not end the run
  }
  if (pacing_ || server_) sim.setBeforeStep([this, &sim] { beforeStep(sim); });
  return true;
}

void Serving::beforeStep(model::Simulation& sim) {
  const net::Kernel& k = sim.kernel();
  if (!started_) {
    started_ = true;
    wall0_ = Clock::now();
    step0_ = k.steps();
    t0_ = k.now();
  }
  if (lockstep_) {
    server_->serveUntilStepAsked(interrupt_);
    io_->stepTaken();
    return;
  }
  // the state at model time t is shown from wall time t until the next step's
  const auto deadline =
      wall0_ + std::chrono::duration_cast<Clock::duration>(
                   std::chrono::duration<double>(static_cast<double>(k.steps() - step0_) * k.dt()));
  if (server_) {
    server_->serveUntil(deadline, interrupt_);
  } else {
    std::this_thread::sleep_until(deadline);
  }
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
  if (!server_) return;
  const auto& s = server_->stats();
  out << "Modbus TCP on " << endpoint_ << ": " << s.clients << (s.clients == 1 ? " client, " : " clients, ")
      << s.requests << " requests (" << s.writes << " writes, " << s.exceptions << " answered with an exception)";
  if (s.refused > 0) out << ", " << s.refused << " connections refused (too many clients)";
  if (s.dropped > 0) out << ", " << s.dropped << " closed for bytes that are no Modbus TCP";
  out << "\n\n";
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

}  // namespace gdpn::modbus
