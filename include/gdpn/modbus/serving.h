#pragma once
/// \file
/// A run's outside links: serving the model's `io` section over Modbus TCP (`gdpn run --modbus
/// [ADDR:]PORT`), pacing the run to the wall clock (`--realtime`), taking a step only when the
/// controller asks for it (`--lockstep`). They hook in before each step of the run; any face
/// (the command line, later the IDE) starts them with the same request.

#include <atomic>
#include <chrono>
#include <memory>
#include <ostream>
#include <string>

#include "gdpn/modbus/server.h"
#include "gdpn/model/io.h"
#include "gdpn/model/simulation.h"

namespace gdpn::modbus {

/// What a run serves and how it is paced.
struct ServeRequest {
  std::string modbus;      ///< "[ADDR:]PORT" ("" : no server)
  bool realtime = false;   ///< pace to the wall clock (implied by a server without lockstep)
  bool lockstep = false;   ///< step only when the controller asks (the io section's lockstep register)
  bool read_only = false;  ///< refuse every write
};

/// The link during one run.
class Serving {
 public:
  /// Checks `request`, binds the server and hooks into `sim`'s steps. False with the message
  /// printed to `err` and `code` the exit status (2: the request, 1: the model or the port).
  bool start(const ServeRequest& request, model::Simulation& sim, const std::atomic<bool>* interrupt, bool quiet,
             std::ostream& err, int& code);
  /// Unhooks; prints what was served and the real-time factor to `out` (nothing when none).
  void finish(model::Simulation& sim, std::ostream& out);

 private:
  using Clock = std::chrono::steady_clock;
  void beforeStep(model::Simulation& sim);
  std::unique_ptr<model::IoMap> io_;
  std::unique_ptr<Server> server_;
  std::string endpoint_;
  bool pacing_ = false, lockstep_ = false, started_ = false;
  const std::atomic<bool>* interrupt_ = nullptr;
  Clock::time_point wall0_;
  std::int64_t step0_ = 0;
  double t0_ = 0;
};

}  // namespace gdpn::modbus
