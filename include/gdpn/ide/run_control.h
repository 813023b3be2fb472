#pragma once
/// \file
/// The toolbar's run controls over a Session made from the document: run (real time, faster,
/// as fast as possible), pause, step, run N steps, fire a transition, plant only, reset. The
/// run never changes the document; reset goes back to the document's state exactly. No
/// ImGui: the toolbar calls these, and so do the tests.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/math.h"
#include "gdpn/link/serving.h"
#include "gdpn/sensors/mouse_sensor.h"
#include "gdpn/session/session.h"

namespace gdpn::ide {

class Document;

/// How fast Run goes.
enum class RunSpeed : std::uint8_t {
  RealTime,  ///< one second of model time per second
  Faster,    ///< kFasterFactor seconds of model time per second
  Fastest,   ///< as many steps as fit in a frame
};

/// Model seconds per real second at RunSpeed::Faster.
inline constexpr double kFasterFactor = 8.0;

/// "real time", "faster", "as fast as possible".
[[nodiscard]] const char* runSpeedName(RunSpeed speed);

/// Edit mode (nothing has run since the last reset), running, or paused.
enum class RunMode : std::uint8_t { Edit, Running, Paused };

/// "edit", "running", "paused".
[[nodiscard]] const char* runModeName(RunMode mode);

/// The run of a document and its controls.
class RunControl {
 public:
  /// Makes the session from `doc` (which must outlive this), with `options` (the IDE's
  /// platform gives the imager of camera sensors). False with diagnostics when the model does
  /// not compile; the controls then do nothing until a later rebuild() works.
  bool open(Document& doc, core::Diagnostics& diags, session::SessionOptions options = {});

  /// Starts running at `speed` (advance() takes the steps). In edit mode, a document edited since
  /// the run was made is compiled first (as by reset()); this and the controls below do nothing
  /// when it does not compile (buildDiagnostics() says why).
  void run(RunSpeed speed);
  /// Stops running.
  void pause();
  /// Exactly one step (or one plant step when plant only is on); pauses.
  void step();
  /// `n` steps now; pauses.
  void runSteps(std::int64_t n);
  /// Runs until model time has advanced by `seconds` (rounded to whole steps); pauses.
  void runFor(double seconds);
  /// Starts transition `name` now: "" when it started, else why not (the Session's words).
  std::string fire(const std::string& name);
  /// Starts coloured transition `name` now in `binding` (one of the kernel's bindings()): ""
  /// when it started, else why not.
  std::string fire(const std::string& name, const net::Binding& binding);
  /// Plant only: the net switched off, the plant and sensors go on.
  void setPlantOnly(bool on) { plant_only_ = on; }
  /// True while plant only is on.
  [[nodiscard]] bool plantOnly() const { return plant_only_; }
  /// Back to the document's state exactly (rebuilt from it when it changed since the run was
  /// made); edit mode. False with diagnostics when the edited model does not compile.
  bool reset(core::Diagnostics& diags);

  /// Adds a breakpoint (kept across resets): "" or why not (no such transition or place).
  std::string addBreakpoint(session::Breakpoint breakpoint);
  /// Removes the breakpoint described as `description` (Breakpoint::describe()); false when
  /// there is none.
  bool removeBreakpoint(const std::string& description);
  /// The breakpoints, described ("starts main/T", "main/buffer >= 3"), in the order added.
  [[nodiscard]] std::vector<std::string> breakpoints() const;

  /// Called once a frame with the real seconds since the last: takes the steps Run owes
  /// (none when not running). A run ends on its own when the net is dead, a script halts or
  /// a breakpoint holds; outcome() says why.
  void advance(double wall_seconds);
  /// Delivers a live input event (a key or a click of the world view) to the sensors.
  void push(sensors::InputEvent event);
  /// A click of the world view along pick ray `ray` (world frame) while a run is going or
  /// paused: handed to the run as an input event at the current time, so that the
  /// MouseSensors count it at the next step, as they count `gdpn run --input`'s clicks. Returns
  /// what the ray hits in the run's plant now and the sensors that will count it; message()
  /// names them. In edit mode nothing runs: nothing is handed over, and nothing is returned.
  sensors::ClickTarget click(const core::Ray& ray);

  /// The problems found when the run was last made from the document (empty when it compiled),
  /// with those of its `io` section as `gdpn check` finds them (an address that names an I/O
  /// its part no longer has): located errors, though the run is made (only a Modbus
  /// controller reads the io section).
  [[nodiscard]] const core::Diagnostics& buildDiagnostics() const { return diags_; }

  /// The document's revision the run was last made from.
  [[nodiscard]] std::uint64_t revision() const { return revision_; }

  /// The session (null when the model never compiled).
  [[nodiscard]] session::Session* session() const { return session_.get(); }
  /// Edit, running or paused.
  [[nodiscard]] RunMode mode() const { return mode_; }
  /// The speed Run uses.
  [[nodiscard]] RunSpeed speed() const { return speed_; }
  /// Model time, seconds.
  [[nodiscard]] double time() const;
  /// Steps taken since the start of the run.
  [[nodiscard]] std::int64_t steps() const;
  /// Model seconds per real second over the last frames (0 when not running).
  [[nodiscard]] double realTimeFactor() const { return rtf_; }
  /// The transitions of the net (qualified names, in declaration order).
  [[nodiscard]] std::vector<std::string> transitions() const;
  /// The last message for the user (why a fire was refused, why a run ended); "" when none.
  [[nodiscard]] const std::string& message() const { return message_; }
  /// Steps stop as soon as `*flag` becomes true (the IDE asked to end by a signal); null: never.
  void stopOn(const std::atomic<bool>* flag) { stop_ = flag; }

  /// Serves the run over OPC UA on `where` ("[ADDR:]PORT", as `gdpn run --opcua`) from now on,
  /// through resets and rebuilds, paced by the IDE's own clock: "" or why not (the port taken).
  std::string serveOpcua(const std::string& where);
  /// Stops serving over OPC UA.
  void stopServing();
  /// The OPC UA endpoint served (`opc.tcp://127.0.0.1:4840`), "" when none.
  [[nodiscard]] std::string opcuaUrl() const { return serving_ ? serving_->opcuaUrl() : std::string(); }

 private:
  void takeSteps(std::int64_t n);  // n steps (or plant steps), stopping on a halt
  bool prepare();  // in edit mode, the run made again from an edited document; false when it fails
  void checkIo(core::Diagnostics& diags);  // the made run's io section resolved against it, its problems into diags
  std::string startServing();  // serve_where_ on the session's simulation: "" or why not
  void endServing();           // unhooked from the simulation, the server closed (serve_where_ kept)
  core::Diagnostics diags_;  // what the last build of the run found
  Document* doc_ = nullptr;
  std::unique_ptr<session::Session> session_;
  session::SessionOptions options_;  // how each session is made
  std::uint64_t revision_ = 0;  // the document's revision the session was made from
  RunMode mode_ = RunMode::Edit;
  RunSpeed speed_ = RunSpeed::RealTime;
  bool plant_only_ = false;
  double owed_ = 0.0;  // model seconds Run owes
  double rtf_ = 0.0;
  std::string message_;
  const std::atomic<bool>* stop_ = nullptr;  // stopOn()
  std::unique_ptr<link::Serving> serving_;  // the OPC UA server on the run (serveOpcua)
  std::string serve_where_;                  // where it serves, kept through resets
};

}  // namespace gdpn::ide
