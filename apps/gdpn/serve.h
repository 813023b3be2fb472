#pragma once
/// \file
/// `gdpn run`'s outside links: `--modbus [ADDR:]PORT` serves the model's `io` section over
/// Modbus TCP, `--realtime` paces the run to the wall clock, `--lockstep` takes a step only
/// when the controller asks for it. They hook in before each step of the run.

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <ostream>
#include <string>

#include "gdpn/modbus/server.h"
#include "gdpn/model/io.h"
#include "gdpn/model/simulation.h"

namespace gdpn::app {

/// The options.
struct ServeArgs {
  std::string modbus;      ///< "[ADDR:]PORT" ("" : no server)
  bool realtime = false;   ///< pace to the wall clock (implied by --modbus without --lockstep)
  bool lockstep = false;   ///< step only when the controller asks (the io section's lockstep register)
  bool read_only = false;  ///< refuse every write
};

/// Adds the options to `run`.
void addServeOptions(CLI::App& run, ServeArgs& args);

/// The link during one run.
class Serving {
 public:
  /// Checks `args`, binds the server and hooks into `sim`'s steps. False with the message
  /// printed to `err` and `code` the exit status (2: the arguments, 1: the model or the port).
  bool start(const ServeArgs& args, model::Simulation& sim, const std::atomic<bool>* interrupt, bool quiet,
             std::ostream& err, int& code);
  /// Unhooks; prints what was served and the real-time factor to `out` (nothing when none).
  void finish(model::Simulation& sim, std::ostream& out);

 private:
  using Clock = std::chrono::steady_clock;
  void beforeStep(model::Simulation& sim);
  std::unique_ptr<model::IoMap> io_;
  std::unique_ptr<modbus::Server> server_;
  std::string endpoint_;
  bool pacing_ = false, lockstep_ = false, started_ = false;
  const std::atomic<bool>* interrupt_ = nullptr;
  Clock::time_point wall0_;
  std::int64_t step0_ = 0;
  double t0_ = 0;
};

}  // namespace gdpn::app
