#pragma once
// Internal: no promises. The plant side of a hybrid net: the numbers of the plant that flows'
// rates read (fed to the kernel after every step's sensors) and the fields that continuous
// places' amounts drive (set after every step's flows).

#include <memory>
#include <optional>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/fluid.h"
#include "probe.h"

namespace gdpn::model {

class Simulation;

/// The reads and drives of a run's continuous part, resolved against its plant.
class FluidPlant {
 public:
  /// Resolves every read and drive of `sim`'s net; null with located errors (a node that is
  /// not there, a quantity it has not, a field that is no number) in `diags`.
  static std::unique_ptr<FluidPlant> create(Simulation& sim, core::Diagnostics& diags);
  /// Reads every rate's numbers of the plant into the kernel, held over the next step.
  void feed();
  /// Sets every driven field from its place's amount.
  void drive();

 private:
  explicit FluidPlant(Simulation& sim) : sim_(sim) {}
  struct Driven {
    net::PlaceId place;
    scene::NodeHandle node = 0;
    std::size_t field = 0;
    int component = -1;  // a vector field's x, y, z (0..2), or -1 for a number field
    double scale = 1.0, offset = 0.0;
    double last = -1.0;  // the amount last written (-1: none): a field is set only when it changes
  };
  Simulation& sim_;
  std::vector<std::optional<Probe>> reads_;
  std::vector<Driven> drives_;
};

}  // namespace gdpn::model
