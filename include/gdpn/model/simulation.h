#pragma once
/// \file
/// Simulation: a compiled model and its step loop (semantics §6). The CLI, the Python module
/// and the IDE all drive models through this one class.

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <unordered_map>
#include <unordered_set>

#include "gdpn/core/assert.h"
#include "gdpn/model/model.h"
#include "gdpn/model/signals.h"
#include "gdpn/net/invariants.h"
#include "gdpn/net/kernel.h"
#include "gdpn/net/round_trips.h"
#include "gdpn/net/stats.h"
#include "gdpn/net/trace.h"
#include "gdpn/physics/world.h"
#include "gdpn/sensors/hub.h"
#include "gdpn/script/engine.h"

namespace gdpn::model {

class SignalRecorder;
class PartRun;

/// When a run ends. With neither set, the model's `until` applies, and without that the run
/// goes on until the net is dead (or it is interrupted).
struct RunLimits {
  std::optional<double> until;        ///< end time, seconds
  std::optional<std::int64_t> steps;  ///< number of steps
};

/// Why a run ended.
enum class StopReason : std::uint8_t {
  Until,        ///< reached the end time or step count
  Dead,         ///< nothing enabled and nothing occurring
  Interrupted,  ///< stopped from outside (Ctrl-C)
  Stopped,      ///< a script called sim.stop(reason)
  ScriptError,  ///< a script raised an exception or ran past the script timeout
  Breakpoint,   ///< a breakpoint held (session::Session)
  PhysicsError, ///< a body ran away (non-finite or beyond physics::kMaxDistance, kMaxSpeed) or ODE failed
};

/// "until", "dead", "interrupted", "stopped", "script error", "breakpoint" or "physics error".
const char* stopReasonName(StopReason reason);

/// How a run ended.
struct RunOutcome {
  std::int64_t steps = 0;              ///< steps taken
  double time = 0.0;                   ///< seconds simulated
  StopReason reason = StopReason::Until;
  std::string message;                 ///< for a script error: the located message and traceback; for a stop: the reason; for a physics error: the body, the time and what went wrong
};

/// Called now and then during a run with the steps done and the steps planned (0 if open).
using ProgressFn = std::function<void(std::int64_t done, std::int64_t total)>;

/// The net's cycles worked out before a run, and the round trips watched during it: what the
/// report sets beside the bounds (watchRoundTrips in report.h).
struct CyclePlan {
  net::Invariants invariants;                    ///< the P-invariants
  std::vector<net::CycleBound> bounds;           ///< their cycle bounds
  net::ExploreStop stop = net::ExploreStop::Done;  ///< why the two were cut short (Done: not)
  std::unique_ptr<net::RoundTrips> trips;        ///< null when no cycle has alternative circuits
  std::map<std::size_t, std::size_t> watch_of;   ///< invariant index -> its watch in `trips`
};

/// A model made ready to run.
class FluidPlant;

class Simulation {
 public:
  /// Compiles `model` and its scripts; returns nullptr with diagnostics on any error. `seed`
  /// overrides the model's seed; `limits` bound each script call's time and what Python holds;
  /// `echo_log` false keeps `sim.log` lines off stderr from the globals script on (`-q`).
  static std::unique_ptr<Simulation> create(const Model& model, core::Diagnostics& diags,
                                            std::optional<std::uint64_t> seed = {}, script::ScriptLimits limits = {},
                                            bool echo_log = true);
  ~Simulation();

  /// Input events (keys, clicks, viewpoint moves) the sensors receive when their time comes.
  void setInput(std::vector<sensors::InputEvent> events) {
    if (hub_) hub_->setInput(std::move(events));
  }
  /// One more input event, live: the sensors receive it at the next step at or after its time.
  void push(sensors::InputEvent event) {
    if (hub_) hub_->push(std::move(event));
  }
  /// Writes the trace (JSON Lines) to `out` from now on; call before start().
  void traceTo(std::ostream& out);
  /// Runs the firing phase at time 0. run() calls it when needed.
  void start();
  /// start(), with `first` run after time 0's sensing and before its firing phase: what the
  /// user fires by hand at time 0 starts before the firing phase chooses for the rest.
  void start(const std::function<void()>& first);
  /// One step (semantics §6).
  void step();
  /// One step of the plant alone, the net switched off: physics and sensors advance, the
  /// marking stays, occurrences pause, no script runs. When the net is on again, conditions
  /// are read anew from the sensors.
  void stepPlant();
  /// Evaluates a Python expression in the model's globals (a breakpoint's predicate). Starts
  /// the interpreter for a model without scripts. Nullopt with `error` when it fails.
  std::optional<bool> evaluate(const std::string& expression, std::string& error);
  /// Evaluates a Python expression that gives a number (a signal), as evaluate().
  std::optional<double> evaluateNumber(const std::string& expression, std::string& error);
  /// Records the model's `signals` and `extra` from now on (call before start()): sampled at
  /// time 0 and after every step at each signal's period. False with located diagnostics
  /// when one names what is not there.
  bool recordSignals(const std::vector<SignalSpec>& extra, core::Diagnostics& diags);
  /// The signals recorded so far, or null when none are recorded.
  [[nodiscard]] const SignalTable* signals() const;
  /// Records the amount of every continuous place from now on (call before start()), as a
  /// signal `place: NAME` would, every step, in a table of its own (the HTML report's levels;
  /// a column per continuous place, named for it). Nothing for a net without one.
  void recordLevels();
  /// The levels recorded so far (a column per continuous place, in place order), or null.
  [[nodiscard]] const SignalTable* levels() const;
  /// The current reading of sensor node `sensor` (an empty reading without sensors).
  [[nodiscard]] const sensors::Reading& reading(scene::NodeHandle sensor) const;
  /// The latest picture a script read of camera sensor `camera`; null when none was (nothing
  /// is rendered for the asking: the run stays as it would be).
  [[nodiscard]] std::shared_ptr<const sensors::Image> lastPicture(scene::NodeHandle camera) const {
    return hub_ ? hub_->lastPicture(camera) : nullptr;
  }
  /// Starts if needed, then steps until `limits` say stop, the net is dead, or `interrupt`
  /// becomes true. Closes the statistics at the end.
  RunOutcome run(const RunLimits& limits, const ProgressFn& progress = {},
                 const std::atomic<bool>* interrupt = nullptr);

  /// The model as loaded.
  [[nodiscard]] const Model& model() const { return model_; }
  /// The frozen net.
  [[nodiscard]] const net::Net& net() const { return *net_; }
  /// The plant: this run's own copy of the model's scene (null when the model has none).
  [[nodiscard]] scene::Scene* plant() const { return scene_.get(); }
  /// The physics of the plant (null when the model has no scene).
  [[nodiscard]] physics::World* physics() const { return physics_.get(); }
  /// The kernel (markings, clock).
  net::Kernel& kernel() { return *kernel_; }
  [[nodiscard]] const net::Kernel& kernel() const { return *kernel_; }
  /// Statistics so far (the report's figures); not after dropStatistics().
  [[nodiscard]] const net::StatsCollector& stats() const {
    GDPN_ASSERT(stats_ != nullptr, "the statistics were dropped");
    return *stats_;
  }
  /// Stops collecting statistics, for a run whose report is never made: the kernel then
  /// calls one observer less on every start, completion and change of tokens.
  void dropStatistics();
  /// What renders camera sensors' pictures when a script reads them (the application's: the
  /// model knows nothing of OpenGL). Without one, reading a picture is a script error.
  void setImager(std::shared_ptr<sensors::Imager> imager) {
    if (hub_) hub_->setImager(std::move(imager));
  }
  /// True when the scene has a ColorCamera or DepthCamera (an imager is worth making).
  [[nodiscard]] bool hasCameras() const;
  /// The seed in use.
  [[nodiscard]] std::uint64_t seed() const { return seed_; }
  /// Keeps `plan` for the report and lets its round trips watch the run (before it starts).
  void keepCycles(std::unique_ptr<CyclePlan> plan);
  /// The plan kept by keepCycles, or null.
  [[nodiscard]] const CyclePlan* cycles() const { return cycles_.get(); }
  /// The name of a node token.
  [[nodiscard]] std::string nodeName(net::NodeRef ref) const;
  /// True once start() has run.
  [[nodiscard]] bool started() const { return started_; }
  /// Copies `templ` (a node of the plant) as a new child of `parent`, named after it with a
  /// number. With `at`, the copy's origin goes to that world position (m): a Transform copy is
  /// moved itself, anything else is put under a new Transform. Where a Material is in effect at
  /// `templ`, the copy keeps it (a copy of it goes first under a new Transform when another is
  /// in effect at `parent`); the copy is no template, whatever `templ` is. Its bodies join the
  /// physics, its sensors are read from the next step (refused, with `why`, when one cannot
  /// work); the trace records it. Refused into `templ` itself or into any template. Returns
  /// the copy, or null and `why`.
  scene::Node* spawn(const scene::Node& templ, scene::Node& parent, std::optional<core::Vec3> at, std::string& why);
  /// Deletes `node` and its subtree from the plant: tokens that hold any of them leave the
  /// net, their bodies leave the physics, and the trace records it. The root stays. The
  /// Transform spawn made to hold `node` goes too once it holds nothing else.
  void deleteNode(scene::Node& node);
  /// The model's own figures: what its globals' `summary()` returns (empty without one).
  std::vector<script::Figure> modelFigures(std::string& error) {
    return engine_ ? engine_->summary(error) : std::vector<script::Figure>{};
  }
  /// Whether sim.log writes its lines to stderr (`[t=1.5] text`; on by default). They go to
  /// the trace either way.
  void setLogEcho(bool echo) { log_echo_ = echo; }
  /// Replays a firing sequence (one the analysis found): from now on the firing phase starts
  /// only the transitions of `sequence`, in its order, each as soon as it may start, and
  /// nothing else. A run ends as dead once the next one cannot start, nothing occurs and the
  /// plant is still (or the sequence is done).
  void replay(std::vector<net::TransitionId> sequence);
  /// How many transitions of the replayed sequence have started.
  [[nodiscard]] std::size_t replayed() const { return replayed_; }
  /// Why the next transition of the replayed sequence could not start at the last firing phase
  /// ("" when it started, or when the sequence is done or none is replayed).
  [[nodiscard]] const std::string& replayBlocked() const { return replay_blocked_; }
  /// Writes an event of the caller's to the trace (when one is written) at the current step:
  /// `{"step":..,"t":..,"ev":"<event>",<fields>}`; `fields` is JSON members without braces.
  void note(const char* event, const std::string& fields);
  /// Whether input from outside the model may come at any time (a Modbus controller): then a
  /// dead net does not end run(), which goes on to its limits or an interrupt. Off by default.
  void setOpen(bool open) { open_ = open; }
  /// Asks `check` after every step that run() takes; true ends the run there
  /// (StopReason::Breakpoint). An empty function asks nothing.
  void setStopCheck(std::function<bool()> check) { stop_check_ = std::move(check); }
  /// Calls `hook` after every step that run() takes (a recorder takes its frames there).
  void setStepHook(std::function<void()> hook) { step_hook_ = std::move(hook); }
  /// Calls `hook` before every step that run() takes, once the checks that may end the run
  /// have passed (a Modbus server answers its clients there, and waits for the wall clock or
  /// for a step asked for). When the run's `interrupt` is true after it, the run ends there.
  void setBeforeStep(std::function<void()> hook) { before_step_ = std::move(hook); }
  /// Why the run must end now, if a script says so (an error, a timeout, an interrupt or
  /// sim.stop) or a signal's expression failed; nullopt while scripts are content.
  [[nodiscard]] std::optional<RunOutcome> scriptHalt() const;
  /// Why the run must end now because the physics failed (StopReason::PhysicsError, its
  /// message naming the body and the model time, s); nullopt while the physics is sound.
  [[nodiscard]] std::optional<RunOutcome> physicsHalt() const;
  /// The run's parts and their I/O (null when the model has none).
  [[nodiscard]] PartRun* parts() { return parts_.get(); }
  /// The run's parts, read-only (null when the model has none).
  [[nodiscard]] const PartRun* parts() const { return parts_.get(); }

 private:
  Simulation() = default;
  // phase 4: the enabled transitions start, or, replaying, the sequence's next ones
  void firePhase();
  // nothing more can happen without outside input
  [[nodiscard]] bool dead() const;
  bool log_echo_ = true;
  bool open_ = false;
  std::optional<std::vector<net::TransitionId>> replay_;
  std::size_t replayed_ = 0;
  std::string replay_blocked_;
  std::function<void()> step_hook_;
  std::function<void()> before_step_;
  std::unique_ptr<SignalRecorder> signals_;
  std::unique_ptr<SignalRecorder> levels_;  // the continuous places' amounts (recordLevels)
  std::function<bool()> stop_check_;
  Model model_;
  std::shared_ptr<const net::Net> net_;
  std::unique_ptr<scene::Scene> scene_;
  std::unique_ptr<physics::World> physics_;
  std::unique_ptr<sensors::Hub> hub_;
  std::vector<scene::NodeHandle> slot_sensor_;    // per place slot: the sensor it reads (0: none)
  std::unordered_map<scene::NodeHandle, std::vector<net::PlaceSlotId>> sensor_slots_;
  std::unordered_map<net::PlaceSlotId, std::vector<net::TermId>> conditions_of_;
  void sense(bool net_on);  // phase 2
  void traceSensor(const sensors::Change& change);
  void readConditions();    // every condition term from its sensor's reading
  bool makeEngine(core::Diagnostics& diags);
  // the engine, started for a model without scripts when an expression needs one; false with
  // `error` when it cannot start
  bool engineReady(std::string& error);
  script::ScriptLimits limits_;
  bool stale_conditions_ = false;
  std::optional<double> physics_fault_at_;  // model time (s) of the step whose physics failed
  void stepPhysics();                       // phase 1, and the time of a fault
  std::unique_ptr<net::Kernel> kernel_;
  std::unique_ptr<net::StatsCollector> stats_;
  std::unique_ptr<net::TraceWriter> trace_;
  std::unique_ptr<CyclePlan> cycles_;
  std::unordered_set<scene::NodeHandle> holders_;  // Transforms spawn made to hold a copy
  std::ostream* trace_out_ = nullptr;
  std::unique_ptr<script::Engine> engine_;
  std::unique_ptr<PartRun> parts_;
  std::unique_ptr<FluidPlant> fluid_;  // hybrid nets: what rates read of the plant, what amounts drive
  std::uint64_t seed_ = 1;
  bool started_ = false;
};

/// Checks `model` as `gdpn check` does: the net compiled and, where the model has scripts, a
/// scene or signals, a simulation made (scripts compiled and their globals run under
/// `script_timeout_s`, the plant built) and its signals resolved. Every problem goes to
/// `diags`; returns the net, null when it does not compile.
std::shared_ptr<const net::Net> checkModel(const Model& model, core::Diagnostics& diags, script::ScriptLimits limits = {});

}  // namespace gdpn::model
