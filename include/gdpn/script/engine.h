#pragma once
/// \file
/// The script engine: CPython 3.11, embedded through pybind11, running the Python scripts of
/// a net's constructs (semantics §8) as the kernel's ScriptHooks. Each script is compiled
/// once; inline code keeps its model-file line numbers, so tracebacks point into the model.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/hooks.h"
#include "gdpn/net/kernel.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/hub.h"

namespace gdpn::script {

/// A model parameter as scripts read it (`sim.params.NAME`).
struct ScriptParam {
  std::string name;      ///< an identifier
  double value = 0.0;    ///< in effect for this run
  bool integer = false;  ///< read as a Python int
};

/// One of the model's own figures: a label and what `summary()` gave for it.
struct Figure {
  std::string label;             ///< the dict's key
  std::string text;              ///< as shown: the number with its unit, or the text
  std::optional<double> value;   ///< the number, when summary() gave one (not for text)
  std::string unit;              ///< its unit ("s", "%"), "" for none
  bool integer = false;          ///< the number is a Python int (the report writes it whole)
  friend bool operator==(const Figure&, const Figure&) = default;
};

/// The script timeout every command gives unless told otherwise (`--script-timeout`, the
/// Python module's `script_timeout`, the IDE's runs): a script call (the globals script
/// included) that runs longer stops the run with a located error rather than hanging it;
/// seconds.
inline constexpr double kDefaultScriptTimeout = 10.0;

/// The memory Python may hold unless told otherwise (`--script-memory`, the Python module's
/// `script_memory`): an allocation past it is refused, and the run stops with "ran out of
/// memory" at the script line that asked; MiB.
inline constexpr double kDefaultScriptMemory = 2048.0;

/// What scripts may take before the run stops: the bounds every command gives.
struct ScriptLimits {
  double timeout_s = kDefaultScriptTimeout;  ///< one call running longer is stopped (0: never), seconds
  double memory_mib = kDefaultScriptMemory;  ///< Python may hold at most this much (0: no bound), MiB
};

/// How scripts run.
struct EngineOptions {
  /// a single script call (the globals script, a script file's top level, a hook, a
  /// breakpoint's predicate) running longer than this is stopped (0: never), seconds
  double timeout_s = 0.0;
  /// the most memory Python may hold (an allocation past it raises MemoryError, and the run
  /// stops as "ran out of memory"; 0: no bound), MiB
  double memory_mib = 0.0;
  /// how long a call that does not stop when told (stuck in C code) is given after its
  /// timeout before the process ends with the message on stderr (0: never), seconds
  double grace_s = 2.0;
  /// the unit of the angles scripts read and write (joint fields, `angle`, `rate`)
  scene::AngleUnit angles = scene::AngleUnit::Degrees;
  /// the model's parameters, read-only to scripts as `sim.params`
  std::vector<ScriptParam> params;
};

/// What `sim.part(name)` and a construct's `self.part` reach: the run's parts, each with its
/// parameters and its named inputs and outputs (the model's PartRun provides them).
struct PartAccess {
  /// The part `name` names (its instance's name, or qualified); nullopt with `why`.
  std::function<std::optional<std::size_t>(const std::string& name, std::string& why)> find;
  /// The part the construct with qualified name `construct` belongs to or controls, if any.
  std::function<std::optional<std::size_t>(const std::string& construct)> of_construct;
  /// The part or control pattern instance the construct belongs to itself, if any.
  std::function<std::optional<std::size_t>(const std::string& construct)> owner;
  /// A control pattern instance's roles and the part filling each (none: left unfilled).
  std::function<std::vector<std::pair<std::string, std::optional<std::size_t>>>(std::size_t)> uses;
  /// A part's qualified name (`main/pusher1`).
  std::function<std::string(std::size_t)> name;
  /// A part's I/O, in declaration order: name and whether it is digital.
  std::function<std::vector<std::pair<std::string, bool>>(std::size_t)> io;
  /// A part's parameters as this instance has them.
  std::function<std::vector<ScriptParam>(std::size_t)> params;
  /// The Transform that holds its machine (0: none).
  std::function<scene::NodeHandle(std::size_t)> frame;
  /// An I/O's value now; nullopt with `why`.
  std::function<std::optional<double>(std::size_t, const std::string&, std::string& why)> read;
  /// Sets an output; false with `why`.
  std::function<bool(std::size_t, const std::string&, double, std::string& why)> write;
};

/// What scripts reach outside the net.
struct EngineCallbacks {
  std::function<void(const std::string&)> log;  ///< sim.log(...) text
  std::function<std::string(net::NodeRef)> node_name;  ///< the path of a node token
  scene::Scene* plant = nullptr;      ///< the run's scene, whose handles node tokens are (null: none)
  physics::World* physics = nullptr;  ///< its physics (null: none)
  /// node.spawn(...): copies a template under a parent, at a world position if given
  std::function<scene::Node*(const scene::Node&, scene::Node&, std::optional<core::Vec3>, std::string&)> spawn;
  /// node.delete(): removes a node, its subtree and their tokens
  std::function<void(scene::Node&)> erase;
  /// the current reading of a sensor node
  std::function<const sensors::Reading&(scene::NodeHandle)> reading;
  /// the picture of a camera sensor at its latest sample (null with why when there is none)
  std::function<std::shared_ptr<const sensors::Image>(scene::NodeHandle, std::string&)> image;
  /// the run's parts (empty functions: the model has none)
  PartAccess parts;
};

/// Why the engine halted.
enum class Halt : std::uint8_t {
  None,         ///< still running
  Error,        ///< a script raised an exception
  Interrupted,  ///< Ctrl-C (requestInterrupt) during a script
  Timeout,      ///< a script ran longer than EngineOptions::timeout_s
  Stop,         ///< a script called sim.stop(reason)
};

/// Runs one net's scripts for one kernel.
class Engine final : public net::ScriptHooks {
 public:
  /// Starts the interpreter if needed, compiles every script of `net` and runs the model's
  /// globals. Problems (syntax errors, missing files or functions, an exception in the
  /// globals, globals running past the timeout) are reported into `diags` at their
  /// file:line:col; then nullptr.
  static std::unique_ptr<Engine> create(const net::Net& net, net::Kernel& kernel, const std::string& model_path,
                                        EngineOptions options, EngineCallbacks callbacks, core::Diagnostics& diags);
  ~Engine() override;
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  bool guard(net::TransitionId t) override;
  bool eligible(net::TermId term, net::NodeRef token) override;
  void preFire(net::TransitionId t) override;
  void inFire(net::TransitionId t) override;
  void postFire(net::TransitionId t) override;
  void onDeposit(net::PlaceSlotId ps, const net::NodeRef* token) override;
  void onRemove(net::PlaceSlotId ps, const net::NodeRef* token) override;
  [[nodiscard]] bool halted() const override;

  /// Evaluates condition term `term` (an expression over its sensor slot, seen under the
  /// slot's name and as `value`) for sensor `sensor`. False when it fails.
  bool condition(net::TermId term, scene::NodeHandle sensor);
  /// Runs sensor slot `ps`'s script of kind `kind` (on_enter or on_exit with `item`,
  /// on_sample, on_change) for sensor `sensor`.
  void sensorEvent(net::PlaceSlotId ps, net::ScriptKind kind, scene::NodeHandle sensor, scene::NodeHandle item = 0);

  /// The model's own figures for the summary: when the globals define a function
  /// `summary()`, the dict it returns, in its order; empty otherwise. A value is a number
  /// (an int or a float), a pair `(number, "unit")`, or anything else as its text.
  std::vector<Figure> summary(std::string& error);

  /// Evaluates the Python expression `expression` in the model's globals (what its scripts
  /// see: `sim`, the sensors by name, the globals script's names) for its truth: a
  /// breakpoint's predicate. Nullopt with `error` (the exception, or a syntax error) when it
  /// fails; a failure does not halt the engine.
  std::optional<bool> evaluate(const std::string& expression, std::string& error);
  /// Evaluates a Python expression that gives a number (an int, a float or a bool) in the
  /// model's globals (a signal). Nullopt with `error` when it fails or gives something else.
  std::optional<double> evaluateNumber(const std::string& expression, std::string& error);

  /// Why the engine halted (None while it has not).
  [[nodiscard]] Halt halt() const;
  /// The message for the halt: the located error with its traceback, or the stop reason.
  [[nodiscard]] const std::string& message() const;

 private:
  struct Impl;
  /// Evaluates `expression` (compiled once, under the name `source`) and hands the result to
  /// `read`, which returns false with a Python error set when it cannot take it.
  bool evaluateWith(const std::string& expression, const char* source, std::string& error,
                    const std::function<bool(void*)>& read);  // read gets the PyObject*
  explicit Engine(std::shared_ptr<Impl> impl);
  std::shared_ptr<Impl> impl_;
};

/// Asks a running script to stop as if Ctrl-C had reached it. Async-signal-safe: call it from
/// a SIGINT handler. A script that is running raises KeyboardInterrupt at once.
void requestInterrupt();

}  // namespace gdpn::script
