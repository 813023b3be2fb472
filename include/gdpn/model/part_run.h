#pragma once
/// \file
/// The parts of a run: each instance of a part type with its parameters as set, and its named
/// inputs and outputs bound to the plant: read, written and forced (as a PLC's force table
/// does). Scripts (`sim.part("pusher1").front_limit`), the `io` section (`part:`, `io:`) and
/// the IDE's I/O list all go through here.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/part.h"
#include "gdpn/scene/node.h"

namespace gdpn::model {

class Simulation;

/// Where a part instance was placed: what InstancePlacer found (internal to the model).
struct PlacedPart {
  std::string name;    ///< qualified: `main/pusher1`
  std::string type;    ///< its page type
  std::string frame;   ///< the scene path of the Transform that holds its machine
  std::string controls;  ///< a control pattern's: the qualified name of the part it controls
  std::vector<std::pair<std::string, std::string>> uses;  ///< a control pattern's: role and the qualified part filling it
  std::vector<std::pair<std::string, double>> params;  ///< every parameter's value here, in the type's order
  core::SourceLoc loc;  ///< where the instance is declared
};

/// The parts of a run and their I/O. Single-threaded: call between steps.
class PartRun {
 public:
  /// One part instance.
  struct Instance {
    PlacedPart placed;          ///< where it stands, what it was given
    const PartSpec* spec;       ///< its type's part section (the run's model's)
    scene::NodeHandle frame = 0;  ///< its Transform
  };
  /// One input or output's state, as the I/O list shows it.
  struct Row {
    std::size_t part = 0;     ///< index into instances()
    const PartIoSpec* io;     ///< its declaration
    double value = 0;         ///< now (a digital one's: 1 or 0); forced: the forced value
    bool forced = false;      ///< held by a force
    bool pending = false;     ///< a force or release is asked for the next step boundary
    std::optional<double> asked;  ///< pending: the value asked for (none: a release)
  };

  /// Binds every part's I/O to the plant of `sim`; problems (a node or quantity the scene
  /// lacks, an `on` the field refuses) are located at the part's I/O declaration. Null on error.
  static std::unique_ptr<PartRun> create(Simulation& sim, std::vector<PlacedPart> placed, core::Diagnostics& diags);

  /// Every part instance, in placement order.
  [[nodiscard]] const std::vector<Instance>& instances() const { return instances_; }
  /// The part `name` names: its qualified name (`main/pusher1`) or, when only one has it, its
  /// own (`pusher1`). Nullopt and `why` (with what there is) otherwise.
  [[nodiscard]] std::optional<std::size_t> find(const std::string& name, std::string& why) const;
  /// The part the construct with qualified name `construct` belongs to (a construct of a part
  /// type's instance) or controls (of a control pattern's instance with `part:`); nullopt when none.
  [[nodiscard]] std::optional<std::size_t> ofConstruct(const std::string& construct) const;
  /// The part or control pattern instance the construct `construct` belongs to itself (a
  /// pattern's own, not the part it controls); nullopt when none.
  [[nodiscard]] std::optional<std::size_t> ownerOf(const std::string& construct) const;
  /// The roles of the control pattern instance `owner` (ownerOf) and the part filling each
  /// (none: an optional role left unfilled), in the type's order.
  [[nodiscard]] std::vector<std::pair<std::string, std::optional<std::size_t>>> usesOf(std::size_t owner) const;

  /// The value of `part`'s I/O `io` now: an input's reading (a digital one: 1 or 0), an
  /// output's field (a digital one: 1 while it holds `on`); a forced one's forced value.
  /// Nullopt and `why` when the part has no such I/O or its node was deleted.
  [[nodiscard]] std::optional<double> read(std::size_t part, const std::string& io, std::string& why) const;
  /// Sets output `io` of `part` (a digital one: non-zero is on); a forced output keeps its
  /// force and remembers the value for its release. False and `why` for an input, an unknown
  /// name or a value the field refuses.
  bool write(std::size_t part, const std::string& io, double value, std::string& why);

  /// Why output `io` of `part` would refuse `value` ("" when it takes it): no such output,
  /// an input, or a value its field refuses. Nothing is written.
  [[nodiscard]] std::string refusal(std::size_t part, const std::string& io, double value) const;

  /// Forces `io` of `part` to `value` from the next step boundary on: an input reads it
  /// whatever the plant says; an output holds it whatever is written. False and `why` when
  /// there is no such I/O or an output's field refuses the value.
  bool force(std::size_t part, const std::string& io, double value, std::string& why);
  /// Releases the force on `io` of `part` at the next step boundary (false: none is asked).
  bool release(std::size_t part, const std::string& io);
  /// Releases every force at the next step boundary.
  void releaseAll();
  /// Applies the forces and releases asked for since the last boundary, and holds forced
  /// outputs; each change goes to the trace (`"ev":"force"`, `"ev":"release"`). Called by the
  /// simulation at the start of each step.
  void atStepBoundary();
  /// Every I/O of every part with its value now, and the force or release that waits for the
  /// next step boundary (the IDE's I/O list shows both).
  [[nodiscard]] std::vector<Row> rows() const;

 private:
  struct Bound;
  explicit PartRun(Simulation& sim);
  [[nodiscard]] const Bound* bound(std::size_t part, const std::string& io, std::string& why) const;
  [[nodiscard]] double plantValue(const Bound& b) const;  // what the plant says, no force
  bool assign(Bound& b, double value, std::string& why);   // sets an output's field
  [[nodiscard]] std::string fieldRefusal(const Bound& b, double value) const;  // an analogue output's field's "no"
  Simulation* sim_;
  std::vector<Instance> instances_;
  std::vector<Bound> bound_;                         // every I/O of every part, by part then declaration
  std::vector<std::size_t> first_;                   // per part: its first entry in bound_
  std::map<std::size_t, std::optional<double>> asked_;  // bound_ index -> force (a value) or release (none)
  // what names found: scripts ask every step, and a run's parts do not change
  mutable std::unordered_map<std::string, std::optional<std::size_t>> found_, of_construct_, owner_of_;
 public:
  ~PartRun();
  PartRun(const PartRun&) = delete;
  PartRun& operator=(const PartRun&) = delete;
};

}  // namespace gdpn::model
