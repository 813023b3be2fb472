#pragma once
/// \file
/// The I/O list: every input and output of every part instance of the document's model, with
/// what uses it (the constructs whose scripts mention it, the `io` section's addresses), its
/// value in the run, and forcing (as a PLC's watch and force tables do). The forces go through
/// the run's `model::PartRun`: they apply at the next step boundary and are traced. Mapping a
/// part's I/O for a PLC is one undoable command. No ImGui: the view (src/ide/views/io_list.cpp)
/// and the tests call these.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/ide/command.h"
#include "gdpn/model/io.h"
#include "gdpn/model/model.h"
#include "gdpn/model/part.h"

namespace gdpn::ide {

class RunControl;

/// One input or output of a part instance, as the model says it (the run changes none of it).
struct IoListRow {
  std::string part;                    ///< the instance, qualified: `main/lamp1`
  std::string page;                    ///< the top-level page it stands on ("" inside another instance)
  std::string instance;                ///< its name on its page: `lamp1`
  std::string type;                    ///< its part type: `lamp`
  model::PartIoSpec io;                ///< its declaration
  std::vector<std::string> uses;       ///< the constructs whose scripts mention it: `main/lamp1_control/light guard`
  std::vector<std::string> addresses;  ///< the `io` section's addresses mapping it: `coil 3`
  std::vector<std::string> names;      ///< those entries' point names, one per address: `lamp1_light`
  /// `part.io`: `main/lamp1.seen`, the row's key in the view's report.
  [[nodiscard]] std::string key() const { return part + "." + io.name; }
};

/// Every I/O of every part instance of `model` (on the top-level pages and inside the page
/// types they instantiate), part by part in declaration order, each part's I/O in its type's
/// order. A use is found by a scan of the inline scripts' text: `self.part.NAME` in a construct
/// of the part's own page type or of a control pattern's instance bound to it, and
/// `part("INSTANCE").NAME` (its own or its qualified name) in any script, the globals too, or
/// `.NAME` on a name such a call was assigned to (`p = sim.part("lamp1")` ... `p.NAME`).
[[nodiscard]] std::vector<IoListRow> ioListRows(const model::Model& model);

/// One I/O's state in a run.
struct IoLive {
  double value = 0;             ///< now (a digital one's 1 or 0); a forced one's forced value
  bool forced = false;          ///< held by a force
  bool pending = false;         ///< a force or release waits for the next step boundary
  std::optional<double> asked;  ///< pending: the value asked for (none: a release)
};

/// The state of every part's I/O in `run`, by `part.io` (IoListRow::key); empty in edit mode
/// (nothing has run) or when the run has no parts.
[[nodiscard]] std::map<std::string, IoLive> ioLiveValues(const RunControl& run);

/// Forces I/O `io` of part `part` (qualified) to `value` from the run's next step boundary (a
/// digital one: non-zero is 1). "" when asked, else why not: no run is going or paused, no such
/// I/O, a value the output's field refuses.
std::string forceIo(RunControl& run, const std::string& part, const std::string& io, double value);
/// Releases the force on `io` of `part` at the next step boundary: "" or why not (no run, no
/// force on it).
std::string releaseIo(RunControl& run, const std::string& part, const std::string& io);
/// Releases every force at the next step boundary: "" or why not (no run is going or paused).
std::string releaseAllIo(RunControl& run);

/// Maps the I/O of part instance `instance` on page `page` into the `io` section at the first
/// free addresses (model::mapPartIo), as one step of undo: a digital input a discrete input, an
/// analogue one an input register (Float), a digital output a coil, an analogue one a
/// holding register (Float). Refused when nothing is left to map.
class MapPartIoCommand final : public Command {
 public:
  /// Maps `instance` on `page`.
  MapPartIoCommand(std::string page, std::string instance) : page_(std::move(page)), instance_(std::move(instance)) {}
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override { return "map " + instance_ + "'s I/O for a PLC"; }
  void absorb(const Command&) override {}
  [[nodiscard]] bool changesScene() const override { return false; }
  /// The entries the last apply added.
  [[nodiscard]] const std::vector<model::IoEntry>& added() const { return added_; }

 private:
  std::string page_, instance_;
  model::IoSpec before_;               // the section before apply, for revert
  std::vector<model::IoEntry> added_;  // what apply added
};

}  // namespace gdpn::ide
