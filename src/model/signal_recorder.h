#pragma once
// Internal: no promises. Samples a run's signals into a SignalTable after each step.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/signals.h"
#include "gdpn/net/net.h"
#include "gdpn/scene/node.h"
#include "probe.h"

namespace gdpn::model {

class Simulation;

/// Reads each signal of a run at its period and keeps the samples.
class SignalRecorder {
 public:
  /// A recorder of `specs` over `sim`'s net and plant; null with located diagnostics when a
  /// signal names no place, no node, or a quantity its node does not have.
  static std::unique_ptr<SignalRecorder> create(Simulation& sim, const std::vector<SignalSpec>& specs,
                                                core::Diagnostics& diags);
  /// Takes the samples due at the simulation's current step.
  void sample();
  /// The samples so far.
  [[nodiscard]] const SignalTable& table() const { return table_; }
  /// Why an expression failed ("" while none has): the run stops there.
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  struct Entry {
    SignalSpec spec;
    Probe probe;                   // what it reads (unused for an expression)
    double period_steps = 0;       // the period in steps (0: every step)
    double next = 0;               // the next multiple of the period to sample at
    bool due_now = false;
    std::size_t first_column = 0;  // its first column in the table
  };
  explicit SignalRecorder(Simulation& sim) : sim_(sim) {}
  void read(const Entry& p, std::vector<std::optional<double>>& row);
  Simulation& sim_;
  std::vector<Entry> probes_;
  SignalTable table_;
  std::string error_;
};

}  // namespace gdpn::model
