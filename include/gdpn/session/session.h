#pragma once
/// \file
/// A Session: a model, the run made from it, and the controls an editor needs (the
/// dissertation's chapter 5): reset, step, run, fire one chosen transition, step the plant
/// with the net switched off, breakpoints, live input, and taking an edited model. The IDE,
/// the command line and the Python module are faces over this one class; none holds rules of
/// its own.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/model/witness.h"
#include "gdpn/session/run_request.h"

namespace gdpn::net {
class Timeline;
}  // namespace gdpn::net

namespace gdpn::session {

/// How a session's runs are made.
struct SessionOptions {
  std::optional<std::uint64_t> seed;  ///< overrides the model's seed
  script::ScriptLimits script_limits;  ///< what a script call may take: its time, Python's memory
  /// Makes what renders camera sensors' pictures, given the model's folder; called once, at
  /// the first simulation whose scene has a camera sensor (none: pictures are not rendered,
  /// and a script that reads one fails saying so).
  std::function<std::shared_ptr<sensors::Imager>(const std::string& model_dir)> imager;
  /// What each run collects from its start (the report's figures and circuits, a timeline).
  RunRequest run;
};

/// How far the replay of a witness got (Session::replay).
struct ReplayVerdict {
  bool done = false;    ///< every firing started and the witness' marking reached
  std::string message;  ///< done: "replay: all N firings done by t = ... s; ..."; else where it stopped and why
};

/// What a breakpoint watches.
enum class BreakKind : std::uint8_t {
  Starts,     ///< a transition starts an occurrence
  Completes,  ///< a transition completes an occurrence
  Marking,    ///< a place's tokens (all its slots), or a continuous place's amount, compare with a number
  Predicate,  ///< a Python expression in the model's globals is true
};

/// How a Marking breakpoint compares.
enum class Compare : std::uint8_t { Less, LessEqual, Equal, NotEqual, GreaterEqual, Greater };

/// A condition that stops a run at the end of the step in which it holds.
struct Breakpoint {
  BreakKind kind = BreakKind::Starts;  ///< what it watches
  std::string target;                  ///< Starts, Completes: the transition; Marking: the place (qualified names)
  Compare compare = Compare::GreaterEqual;  ///< Marking: how the tokens compare with `value`
  std::int64_t value = 0;              ///< Marking: tokens (or an amount, whole)
  /// Marking: a number with a fraction to compare with instead of `value` (an amount: `main/tank
  /// >= 2.5`; a place of tokens compares its whole tokens with it)
  std::optional<double> real;
  std::string expression;              ///< Predicate: a Python expression over the model's globals
  /// Predicate, when `expression` is empty: a test of the caller's own (the Python module
  /// passes a callable); it may throw, which ends the run as a script error.
  std::function<bool()> test;
  bool enabled = true;                 ///< a disabled breakpoint is kept but never holds

  /// Holds when transition `transition` starts.
  static Breakpoint starts(std::string transition);
  /// Holds when transition `transition` completes.
  static Breakpoint completes(std::string transition);
  /// Holds while place `place`'s tokens compare with `value` as `how` says.
  static Breakpoint marking(std::string place, Compare how, std::int64_t value);
  /// Holds while place `place`'s tokens or amount compare with `value` as `how` says.
  static Breakpoint level(std::string place, Compare how, double value);
  /// Holds while the Python expression `expression` is true.
  static Breakpoint predicate(std::string expression);

  /// "starts main/T", "main/buffer >= 3", "sim.time > 2", for messages.
  [[nodiscard]] std::string describe() const;
};

/// "<", "<=", "==", "!=", ">=", ">".
[[nodiscard]] const char* compareName(Compare compare);
/// The comparison written `text` ("<", "<=", "==", "!=", ">=", ">"), or nullopt.
[[nodiscard]] std::optional<Compare> parseCompare(std::string_view text);

/// A model and its run, with an editor's controls.
class Session {
 public:
  /// A session over `model` (compiled and made ready to run). Null with located diagnostics
  /// when the model does not compile.
  static std::unique_ptr<Session> create(model::Model model, core::Diagnostics& diags, SessionOptions options = {});
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// Back to the initial state exactly: a run after reset gives the same trace, byte for
  /// byte, as a run of a freshly loaded model with the same seed. Breakpoints and the trace
  /// output stay; input events pushed so far are dropped. With `seed`, the run (and later
  /// resets) use that seed. The model's script files are read again: when one no longer
  /// compiles, the old run stays, `diags` says why, and the result is false.
  bool reset(core::Diagnostics& diags, std::optional<std::uint64_t> seed = {});
  /// One step (semantics §6); starts the run first when needed.
  void step();
  /// Steps until `limits` say stop, the net is dead, a script halts, `interrupt` becomes true,
  /// or a breakpoint holds (StopReason::Breakpoint, then hit() says which). A predicate that
  /// raises ends the run as a script error naming the breakpoint.
  model::RunOutcome run(const model::RunLimits& limits, const model::ProgressFn& progress = {},
                        const std::atomic<bool>* interrupt = nullptr);
  /// Starts the transition named `transition` now (its qualified name). "" when it started,
  /// else why not: no such transition, it is occurring, not enabled (naming the arc that
  /// does not hold), its guard is false, or no node token satisfies its predicates.
  std::string fire(const std::string& transition);
  /// Starts coloured transition `transition` now in `binding` (Kernel::fire(t, b)): "" when it
  /// started, else why not (as fire(), or the binding is not enabled now). A run not begun
  /// begins, this start before its first firing phase.
  std::string fire(const std::string& transition, const net::Binding& binding);
  /// One step with the net switched off: the plant moves and the sensors read it, the
  /// marking stays and occurrences pause. A run that has not begun begins first (time 0's
  /// sensing and firing phase).
  void stepPlant();
  /// One live input event (a key, a click, a viewpoint move) for the sensors, delivered at
  /// the next step at or after its time (`event.t`, seconds; a time in the past means now).
  void push(sensors::InputEvent event);
  /// Takes an edited model: on success the run starts again from the new model's initial
  /// state; on error the old model and its run stay as they were, and the located
  /// diagnostics are in `diags`. False on error.
  bool rebuild(const model::Model& model, core::Diagnostics& diags);

  /// Adds a breakpoint; returns its id (ids are never reused). Nullopt with `why` when its
  /// target names no transition or place of the net, or its expression is empty.
  std::optional<int> addBreakpoint(Breakpoint breakpoint, std::string& why);
  /// Removes breakpoint `id`; false when there is none.
  bool removeBreakpoint(int id);
  /// Enables or disables breakpoint `id`; false when there is none.
  bool enableBreakpoint(int id, bool enabled);
  /// The breakpoints, by id, in the order added.
  [[nodiscard]] const std::vector<std::pair<int, Breakpoint>>& breakpoints() const { return breakpoints_; }
  /// The breakpoint that stopped the last run (nullopt when none did).
  [[nodiscard]] std::optional<int> hit() const { return hit_; }

  /// Writes the trace (JSON Lines) to `out` from the start of the run, and again from the
  /// start after each reset or rebuild (the caller keeps `out` alive).
  void traceTo(std::ostream& out);
  /// Input events (a whole list, in time order) the sensors receive; they come back on reset.
  void setInput(std::vector<sensors::InputEvent> events);

  /// The report of the run so far, `outcome` being how its last run() ended: the figures
  /// collected (RunRequest::report must be on) and each watched token's circuits.
  [[nodiscard]] model::Report report(const model::RunOutcome& outcome);
  /// The timeline of the run (null unless RunRequest::timeline is on).
  [[nodiscard]] const net::Timeline* timeline() const { return timeline_.get(); }

  /// Plays the firing sequence of the witness in file `path` (`gdpn analyze --witness`), in
  /// this run and in every run after a reset: only its transitions start, in its order, each
  /// as soon as it can (a rebuild drops it). False with located diagnostics in `diags` when
  /// the file is no witness of this net. Call before the run starts.
  bool replay(const std::string& path, core::Diagnostics& diags);
  /// How far the replay got: every firing started, none still occurring and the witness'
  /// marking reached, or where it stopped and why. Nullopt when no witness is replayed.
  [[nodiscard]] std::optional<ReplayVerdict> replayVerdict() const;

  /// The model.
  [[nodiscard]] const model::Model& model() const { return model_; }
  /// The run.
  [[nodiscard]] model::Simulation& simulation() { return *sim_; }
  /// The run, to read.
  [[nodiscard]] const model::Simulation& simulation() const { return *sim_; }
  /// The seed in use.
  [[nodiscard]] std::uint64_t seed() const { return sim_->seed(); }

 private:
  class Watcher;
  Session() = default;
  std::shared_ptr<sensors::Imager> imager_;  // made at the first scene with a camera sensor
  std::unique_ptr<model::Simulation> make(const model::Model& model, core::Diagnostics& diags);
  void adopt(std::unique_ptr<model::Simulation> sim);
  void watch();                  // the watcher listens exactly while a breakpoint needs it
  std::optional<std::uint32_t> targetOf(const Breakpoint& bp) const;  // the index of its transition or place
  std::optional<int> holding();  // the first breakpoint that holds after a step
  model::Model model_;
  SessionOptions options_;
  std::unique_ptr<Watcher> watcher_;  // before the run it listens to: it outlives the kernel
  std::unique_ptr<net::Timeline> timeline_;  // RunRequest::timeline; likewise
  std::unique_ptr<model::Simulation> sim_;
  std::vector<std::pair<int, Breakpoint>> breakpoints_;
  std::vector<std::optional<std::uint32_t>> targets_;  // per breakpoint: the index of its transition or place
  int next_id_ = 1;
  std::optional<int> hit_;
  std::string predicate_error_;  // why a predicate of the last run failed
  std::ostream* trace_out_ = nullptr;
  std::vector<sensors::InputEvent> input_;
  std::optional<model::Witness> witness_;  // replayed in every run (Session::replay)
};

}  // namespace gdpn::session
