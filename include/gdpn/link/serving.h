#pragma once
/// \file
/// A run's outside links: the model's named I/O served over Modbus TCP (`gdpn run --modbus
/// [ADDR:]PORT`), the model served over OPC UA (`--opcua [ADDR:]PORT`), a PLC's own OPC UA
/// server driving the plant (`--opcua-client URL`), the run paced to the wall clock
/// (`--realtime`) or taking a step only when a controller asks for it (`--lockstep`). They hook
/// in before each step of the run; any face (the command line, the IDE) starts them with the
/// same request.

#include <atomic>
#include <chrono>
#include <memory>
#include <ostream>
#include <string>

#include "gdpn/modbus/server.h"
#include "gdpn/model/io.h"
#include "gdpn/model/simulation.h"
#include "gdpn/opcua/address_space.h"
#include "gdpn/opcua/server.h"

namespace gdpn::link {

/// What a run serves and how it is paced.
struct ServeRequest {
  std::string modbus;        ///< "[ADDR:]PORT" ("" : no Modbus server)
  std::string opcua;         ///< "[ADDR:]PORT" ("" : no OPC UA server)
  std::string opcua_client;  ///< `opc.tcp://HOST:PORT` of a PLC's server the plant is driven by ("" : none)
  bool realtime = false;     ///< pace to the wall clock (implied by a server or a PLC without lockstep)
  bool lockstep = false;     ///< step only when a controller asks (Modbus: the lockstep register; OPC UA: Step)
  bool read_only = false;    ///< the servers refuse every write
  bool pace = true;          ///< false: the face paces the run itself (the IDE), the links only serve
};

/// The links during one run.
class Serving {
 public:
  Serving();
  ~Serving();
  Serving(const Serving&) = delete;
  Serving& operator=(const Serving&) = delete;
  /// Checks `request`, binds the servers, connects to the PLC and hooks into `sim`'s steps;
  /// `interrupt` stops the run from outside (Ctrl-C), and the links set it when the PLC goes.
  /// False with the message printed to `err` and `code` the exit status (2: the request, 1:
  /// the model, the port or the PLC).
  bool start(const ServeRequest& request, model::Simulation& sim, std::atomic<bool>* interrupt, bool quiet,
             std::ostream& err, int& code);
  /// Serves what has come in without stepping (a paused IDE calls it each frame).
  void idle();
  /// Why the run stopped ("" : it did not): the PLC went away, or refused what was written.
  [[nodiscard]] const std::string& failure() const { return failure_; }
  /// Unhooks; prints what was served and the real-time factor to `out` (nothing when none).
  void finish(model::Simulation& sim, std::ostream& out);
  /// The OPC UA endpoint URL served ("" : none).
  [[nodiscard]] std::string opcuaUrl() const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Plc;
  void beforeStep(model::Simulation& sim);
  void exchangeWithPlc();
  void serveUntil(Clock::time_point deadline);
  bool stepAsked() const;
  std::unique_ptr<model::IoMap> io_;
  std::unique_ptr<modbus::Server> modbus_;
  std::unique_ptr<opcua::AddressSpace> space_;
  std::unique_ptr<opcua::Server> opcua_;
  std::unique_ptr<Plc> plc_;
  std::string modbus_endpoint_, failure_, client_name_ = "opcua";
  bool pacing_ = false, lockstep_ = false, started_ = false, granted_opcua_ = false;
  std::atomic<bool>* interrupt_ = nullptr;
  Clock::time_point wall0_;
  std::int64_t step0_ = 0;
  double t0_ = 0;
};

}  // namespace gdpn::link
