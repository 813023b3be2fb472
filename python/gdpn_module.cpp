// The gdpn Python module: load a model, run it, read markings, the trace and the report.

#include "gdpn/experiments/python_sources.h"
#include "gdpn/capture/sensor_imager.h"
#include <pybind11/pybind11.h>
#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/model/analysis.h"
#include "gdpn/model/part_library.h"
#include "gdpn/model/part_run.h"
#include "gdpn/model/report.h"
#include "gdpn/session/analysis_request.h"
#include "gdpn/session/breakpoint_syntax.h"
#include "gdpn/session/session.h"

namespace py = pybind11;
using namespace gdpn;

namespace {

/// The module object; leaked on purpose, as Python may be gone when statics are destroyed.
py::module_& module() {
  static auto* m = new py::module_();
  return *m;
}

/// Raises gdpn.ModelError for the first error in `diags`, carrying all of them.
[[noreturn]] void raiseModelError(const core::Diagnostics& diags) {
  const core::Diagnostic* first = nullptr;
  py::list all;
  for (const auto& d : diags.all()) {
    all.append(d.str());
    if (!first && d.severity == core::Severity::Error) first = &d;
  }
  const std::string message = first ? first->str() : diags.str();
  py::object err = module().attr("ModelError")(message, first ? first->loc.file : "", first ? first->loc.line : 0,
                                               first ? first->loc.column : 0, all);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(err.ptr())), err.ptr());
  throw py::error_already_set();
}

/// An analysis request from Python's arguments; ValueError for a limit out of range.
session::AnalysisRequest checkedAnalysisRequest(std::uint64_t max_states, double max_memory_mib, double time_limit) {
  if (max_states < 1) throw py::value_error("max_states is a whole number of states from 1");
  if (!std::isfinite(max_memory_mib) || max_memory_mib < 0.0 || max_memory_mib > 1e9) {
    throw py::value_error("max_memory_mib is MiB from 0 to 1e9 (0: 3/4 of the memory available at the start)");
  }
  if (!std::isfinite(time_limit) || time_limit < 0.0 || time_limit > 1e9) {
    throw py::value_error("time_limit is seconds from 0 to 1e9 (0: none)");
  }
  session::AnalysisRequest request;
  request.max_states = max_states;
  request.max_memory_mib = max_memory_mib;
  request.time_limit_s = time_limit;
  return request;
}

class Model {
 public:
  Model(std::string path, std::optional<std::uint64_t> seed, script::ScriptLimits limits, const py::dict& params,
        const std::vector<std::string>& signals)
      : path_(std::move(path)) {
    for (const auto& arg : signals) {
      std::string why;
      auto spec = model::parseSignalArgument(arg, why);
      if (!spec) throw py::value_error("signals: " + why);
      signals_.push_back(std::move(*spec));
    }
    core::Diagnostics diags;
    auto resolved = model::resolveModelPath(path_, diags);
    if (!resolved) raiseModelError(diags);
    path_ = *resolved;
    std::vector<model::ParamOverride> overrides;
    for (const auto& [name, value] : params) {
      // an int (numpy's too) as its digits, any other real number as its shortest exact text
      const std::string key = py::str(name).cast<std::string>();
      std::string text;
      if (!PyBool_Check(value.ptr()) && PyObject_HasAttrString(value.ptr(), "__index__")) {
        text = py::str(py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr())));
      } else if (!PyBool_Check(value.ptr()) && !PyUnicode_Check(value.ptr()) &&
                 PyObject_HasAttrString(value.ptr(), "__float__")) {
        text = core::formatDouble(value.cast<double>());
      } else {
        throw py::type_error("params: '" + key + "' expects a number, got " + py::repr(value).cast<std::string>());
      }
      overrides.push_back({key, text, "params="});
    }
    auto m = model::loadModel(path_, diags, overrides);
    if (!m) raiseModelError(diags);
    session_ = session::Session::create(std::move(*m), diags, {seed, limits, capture::makeSensorImager, {}});
    if (!session_) raiseModelError(diags);
    session_->traceTo(trace_);
    recordSignals();
  }

  /// Records the model's signals and those given to load(), when there are any.
  void recordSignals() {
    if (signals_.empty() && session_->simulation().model().signals.empty()) return;
    core::Diagnostics diags;
    if (!session_->simulation().recordSignals(signals_, diags)) raiseModelError(diags);
  }

  /// The signals recorded so far as a pandas DataFrame indexed by time (s).
  py::object signalFrame() const {
    const model::SignalTable* table = session_->simulation().signals();
    py::module_ pandas;
    try {
      pandas = py::module_::import("pandas");
    } catch (const py::error_already_set&) {
      throw py::import_error("Model.signals() needs pandas (Debian: apt-get install python3-pandas)");
    }
    py::dict columns;
    std::vector<std::string> names = table ? table->columns : std::vector<std::string>{};
    for (std::size_t c = 0; c < names.size(); ++c) {
      py::list values;
      for (const auto& row : table->rows) {
        if (row[c]) values.append(*row[c]);
        else values.append(py::float_(std::nan("")));
      }
      columns[py::str(names[c])] = values;
    }
    py::list time;
    if (table) {
      for (double t : table->time) time.append(t);
    }
    py::object index = pandas.attr("Index")(time, py::arg("name") = "time");
    return pandas.attr("DataFrame")(columns, py::arg("index") = index);
  }

  const std::vector<model::Param>& params() const { return session_->simulation().model().params; }

  py::dict run(std::optional<double> until, std::optional<std::int64_t> steps, std::optional<std::uint64_t> seed) {
    if (seed) reset(seed);
    std::atomic<bool> interrupted{false};
    // Ctrl-C between steps: Python's handler runs here and the run stops cleanly
    auto check = [&](std::int64_t, std::int64_t) {
      if (PyErr_CheckSignals() != 0) {
        PyErr_Clear();
        interrupted = true;
      }
    };
    outcome_ = session_->run({until, steps}, check, &interrupted);
    raiseIfFailed();
    return report();
  }

  void step() {
    session_->step();
    raiseIfHalted();
  }

  void stepPlant() { session_->stepPlant(); }

  void fire(const std::string& transition) {
    const std::string why = session_->fire(transition);
    raiseIfHalted();
    if (!why.empty()) {
      py::object err = module().attr("FireError")(why);
      PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(err.ptr())), err.ptr());
      throw py::error_already_set();
    }
  }

  void reset(std::optional<std::uint64_t> seed) {
    core::Diagnostics diags;
    trace_.str("");
    trace_.clear();
    if (!session_->reset(diags, seed)) raiseModelError(diags);
    outcome_ = {};
    recordSignals();
  }

  int addBreakpoint(const std::optional<std::string>& written, std::optional<std::string> starts,
                    std::optional<std::string> completes, std::optional<std::string> place, const std::string& compare,
                    const py::object& value, const py::object& predicate) {
    const int given = static_cast<int>(written.has_value()) + static_cast<int>(starts.has_value()) +
                      static_cast<int>(completes.has_value()) + static_cast<int>(place.has_value()) +
                      static_cast<int>(!predicate.is_none());
    if (given != 1) {
      throw py::value_error("a breakpoint watches one thing: as written ('start:T', 'P>=3', 'when:EXPR'), starts=, "
                            "completes=, place= or predicate=");
    }
    std::string why;
    if (written) {
      // the one syntax of gdpn run --break and the IDE's replay
      const auto bp = session::parseBreakpoint(*written);
      if (!bp) throw py::value_error("column " + std::to_string(bp.error().loc.column) + ": " + bp.error().message);
      const auto id = session_->addBreakpoint(*bp, why);
      if (!id) throw py::value_error(why);
      return *id;
    }
    session::Breakpoint bp;
    bp.kind = starts      ? session::BreakKind::Starts
              : completes ? session::BreakKind::Completes
              : place     ? session::BreakKind::Marking
                          : session::BreakKind::Predicate;
    bp.target = starts ? *starts : completes ? *completes : place ? *place : "";
    if (py::isinstance<py::str>(predicate)) {
      bp.expression = predicate.cast<std::string>();
    } else if (!predicate.is_none()) {
      if (!PyCallable_Check(predicate.ptr())) throw py::type_error("predicate is a Python expression or a callable");
      // a callable is asked after each step, in this interpreter (the GIL is held by run())
      bp.test = [predicate] { return py::bool_(predicate()).cast<bool>(); };
    }
    if (place) {
      const auto how = session::parseCompare(compare);
      if (!how) throw py::value_error("compare is one of <, <=, ==, !=, >=, >; got '" + compare + "'");
      bp.compare = *how;
      // a whole number as tokens (or an amount), a float as a real one (a continuous place's amount)
      if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
        throw py::type_error("value is a number, got " + py::repr(value).cast<std::string>());
      }
      if (py::isinstance<py::int_>(value)) bp.value = value.cast<std::int64_t>();
      else bp.real = value.cast<double>();
    }
    const auto id = session_->addBreakpoint(bp, why);
    if (!id) throw py::value_error(why);
    return *id;
  }

  /// Plays a witness' firing sequence in this run and after each reset (Session::replay).
  void replay(const std::string& witness) {
    core::Diagnostics diags;
    if (!session_->replay(witness, diags)) raiseModelError(diags);
  }

  /// How far the replay got: {done, message}, or None when no witness is replayed.
  py::object replayVerdict() const {
    const auto verdict = session_->replayVerdict();
    if (!verdict) return py::none();
    py::dict out;
    out["done"] = verdict->done;
    out["message"] = verdict->message;
    return out;
  }

  void enableBreakpoint(int id, bool enabled) {
    if (!session_->enableBreakpoint(id, enabled)) throw py::key_error("no breakpoint " + std::to_string(id));
  }

  void push(std::optional<std::string> key, bool down, std::optional<std::array<double, 3>> viewpoint,
            std::optional<std::pair<std::array<double, 3>, std::array<double, 3>>> click, std::optional<double> at) {
    const int given = static_cast<int>(key.has_value()) + static_cast<int>(viewpoint.has_value()) +
                      static_cast<int>(click.has_value());
    if (given != 1) throw py::value_error("an input event is one of key=, viewpoint= or click=");
    auto vec = [](const std::array<double, 3>& a) { return core::Vec3{a[0], a[1], a[2]}; };
    sensors::InputEvent ev;
    ev.t = at.value_or(time());
    if (!std::isfinite(ev.t)) throw py::value_error("at must be a finite time, seconds");
    if (key) {
      ev.kind = sensors::InputEvent::Kind::Key;
      ev.key = *key;
      ev.down = down;
    } else if (viewpoint) {
      ev.kind = sensors::InputEvent::Kind::Viewpoint;
      ev.position = vec(*viewpoint);
    } else {
      const core::Vec3 from = vec(click->first), to = vec(click->second);
      if ((to - from).length() <= 0) throw py::value_error("a click goes from one point to another");
      ev.kind = sensors::InputEvent::Kind::Click;
      ev.ray = {from, (to - from).normalized()};
    }
    session_->push(std::move(ev));
  }

  void removeBreakpoint(int id) {
    if (!session_->removeBreakpoint(id)) throw py::key_error("no breakpoint " + std::to_string(id));
  }

  py::list breakpoints() const {
    py::list out;
    for (const auto& [id, bp] : session_->breakpoints()) {
      py::dict d;
      d["id"] = id;
      d["watches"] = bp.describe();
      d["enabled"] = bp.enabled;
      out.append(d);
    }
    return out;
  }

  [[nodiscard]] std::optional<int> hit() const { return session_->hit(); }

  /// The run's parts, or KeyError-free nothing: raises when the model has none.
  model::PartRun& parts() const {
    model::PartRun* parts = session_->simulation().parts();
    if (!parts) throw py::value_error("the model has no parts");
    return *parts;
  }

  /// Every I/O of every part: [{part, io, direction, signal, unit, value, forced}].
  py::list io() const {
    py::list out;
    const model::PartRun* parts = session_->simulation().parts();
    if (!parts) return out;
    for (const auto& row : parts->rows()) {
      py::dict d;
      d["part"] = parts->instances()[row.part].placed.name;
      d["io"] = row.io->name;
      d["direction"] = model::ioDirectionName(row.io->direction);
      d["signal"] = model::ioSignalName(row.io->signal);
      d["unit"] = row.io->unit;
      d["value"] = row.value;
      d["forced"] = row.forced;
      out.append(d);
    }
    return out;
  }

  /// Forces `io` of `part` to `value` from the next step.
  void force(const std::string& part, const std::string& io, double value) {
    std::string why;
    const auto p = parts().find(part, why);
    if (!p) throw py::key_error(why);
    if (!parts().force(*p, io, value, why)) throw py::value_error(why);
  }

  /// Releases `io` of `part` at the next step; every force when neither is given.
  void release(const std::optional<std::string>& part, const std::optional<std::string>& io) {
    if (!part && !io) {
      parts().releaseAll();
      return;
    }
    if (!part || !io) throw py::value_error("release: give both part and io, or neither (release all)");
    std::string why;
    const auto p = parts().find(*part, why);
    if (!p) throw py::key_error(why);
    if (!parts().release(*p, *io)) throw py::value_error("'" + *io + "' of part '" + *part + "' is not forced");
  }

  py::object marking(const std::string& place) const {
    const model::Simulation* sim_ = &session_->simulation();
    const auto& net = sim_->net();
    const auto p = net.findPlace(place);
    if (!p) throw py::key_error("no place '" + place + "'");
    if (net.continuousPlace(*p)) return py::float_(sim_->kernel().amount(*p));  // its amount, in its unit
    const auto& pl = net.places()[*p];
    py::dict slots;
    for (net::PlaceSlotId ps{pl.slots_begin}; ps < pl.slots_end; ++ps) {
      const auto& slot = net.placeSlots()[ps];
      if (slot.kind == net::SlotKind::Node) {
        py::list names;
        for (auto ref : sim_->kernel().nodes(ps)) names.append(sim_->nodeName(ref));
        slots[py::str(net::slotName(slot.slot))] = names;
      } else if (const net::Colouring* c = net.colouring(); c && c->setOf(ps)) {
        // values as the inscription language writes them, each with its count, in their order
        py::dict values;
        for (const auto& [v, n] : sim_->kernel().values(ps)) values[py::str(c->colours.text(*c->setOf(ps), v))] = n;
        slots[py::str(net::slotName(slot.slot))] = values;
      } else {
        slots[py::str(net::slotName(slot.slot))] = sim_->kernel().marking(ps);
      }
    }
    // a place with only a0 as a control (or value) slot reads as a plain count (or its values)
    if (pl.slots_end - pl.slots_begin == 1 && net.placeSlots()[pl.slots_begin].slot == net::kDefaultSlot &&
        (net.placeSlots()[pl.slots_begin].kind == net::SlotKind::Control ||
         net.placeSlots()[pl.slots_begin].kind == net::SlotKind::Value)) {
      return slots["a0"];
    }
    return slots;
  }

  py::list trace() const {
    py::object loads = py::module_::import("json").attr("loads");
    py::list out;
    std::istringstream lines(trace_.str());
    std::string line;
    while (std::getline(lines, line)) out.append(loads(line));
    return out;
  }

  py::dict report() const {
    const model::Simulation* sim_ = &session_->simulation();
    auto outcome = outcome_;
    outcome.steps = sim_->kernel().steps();
    outcome.time = sim_->kernel().now();
    return py::module_::import("json").attr("loads")(model::reportJson(session_->report(outcome)));
  }

  /// The untimed analysis: without `query`, everything `gdpn analyze --json` reports; with a
  /// formula, its answer; with a list of them, their answers (as `gdpn analyze --query --json`).
  /// Its limits are gdpn analyze's, the memory guard included (max_memory_mib 0).
  py::object analyze(const py::object& query, std::uint64_t max_states, double max_memory_mib, double time_limit) {
    // the net gdpn analyze reads: the model's, unfolded when it has value tokens
    core::Diagnostics read;
    const auto analysed = session::analysedNet(session_->simulation().model().net, read);
    if (!analysed) raiseModelError(read);
    const net::Net& net = *analysed->net;
    const net::NameExpansion* names = analysed->expansion();
    const session::AnalysisRequest request = analysisRequest(max_states, max_memory_mib, time_limit);
    auto loads = py::module_::import("json").attr("loads");
    if (query.is_none()) {
      session::AnalysisAnswer answer;
      {
        py::gil_scoped_release unlocked;
        answer = session::analyze(*analysed, path_, request);
      }
      // as gdpn analyze's note (a warning that a filter turns into an error raises it)
      if (answer.stoppedAtGuard() && PyErr_WarnEx(PyExc_RuntimeWarning, answer.guardNote("max_memory_mib").c_str(), 1) < 0) {
        throw py::error_already_set();
      }
      return loads(model::analysisJson(net, answer.analysis));
    }
    const bool one = py::isinstance<py::str>(query);
    const auto texts = one ? std::vector<std::string>{query.cast<std::string>()} : query.cast<std::vector<std::string>>();
    std::vector<model::QueryResult> results;
    std::vector<net::Formula> formulas;
    for (std::size_t i = 0; i < texts.size(); ++i) {
      net::QueryError error;
      auto f = net::parseQuery(net, texts[i], error, names);
      if (!f) {
        core::Diagnostics diags;
        diags.error({"query " + std::to_string(i + 1), 1, static_cast<int>(error.column)}, error.message);
        raiseModelError(diags);
      }
      formulas.push_back(*f);
      results.push_back({texts[i], std::move(*f), {}, {}});
    }
    std::vector<net::QueryAnswer> answers;
    {
      py::gil_scoped_release unlocked;
      answers = session::answerQueries(net, formulas, request);
    }
    for (std::size_t i = 0; i < answers.size(); ++i) results[i].answer = std::move(answers[i]);
    py::list out = loads(model::queriesJson(net, results, names))["queries"];
    return one ? out[0] : py::object(out);
  }

  /// The request of Model.analyze(): the model's step, and the limits given (checked).
  session::AnalysisRequest analysisRequest(std::uint64_t max_states, double max_memory_mib, double time_limit) const {
    session::AnalysisRequest request = checkedAnalysisRequest(max_states, max_memory_mib, time_limit);
    request.dt = session_->simulation().model().settings.dt;
    return request;
  }

  [[nodiscard]] double time() const { return session_->simulation().kernel().now(); }
  [[nodiscard]] std::int64_t steps() const { return session_->simulation().kernel().steps(); }
  [[nodiscard]] std::uint64_t seed() const { return session_->seed(); }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  void raiseIfHalted() {
    if (auto halt = session_->simulation().scriptHalt()) {
      outcome_ = *halt;
      raiseIfFailed();
    }
  }

  void raiseIfFailed() const {
    switch (outcome_.reason) {
      case model::StopReason::ScriptError:
      case model::StopReason::PhysicsError: {
        const char* kind = outcome_.reason == model::StopReason::ScriptError ? "ScriptError" : "PhysicsError";
        py::object err = module().attr(kind)(outcome_.message);
        PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(err.ptr())), err.ptr());
        throw py::error_already_set();
      }
      case model::StopReason::Interrupted:
        PyErr_SetString(PyExc_KeyboardInterrupt, outcome_.message.empty() ? "run interrupted" : outcome_.message.c_str());
        throw py::error_already_set();
      case model::StopReason::Until:
      case model::StopReason::Dead:
      case model::StopReason::Stopped:
      case model::StopReason::Breakpoint: return;  // a run that ended as asked, or by the model
    }
  }

  std::string path_;
  std::ostringstream trace_;  // before the session, which writes into it
  std::vector<model::SignalSpec> signals_;  // those given to load(), recorded with the model's
  std::unique_ptr<session::Session> session_;
  model::RunOutcome outcome_;
};

}  // namespace

PYBIND11_MODULE(gdpn, m) {
  module() = m;
  m.doc() = "gdpn: geometry-driven Petri nets. Load a model, run it, read what happened.";
  m.attr("__version__") = GDPN_VERSION;
  py::exec(R"py(
class ModelError(Exception):
    """A model file has mistakes. .file, .line and .column locate the first; .diagnostics lists all."""
    def __init__(self, message, file="", line=0, column=0, diagnostics=()):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.diagnostics = list(diagnostics)

class ScriptError(Exception):
    """A script raised an exception, or ran past the script timeout, during a run."""

class PhysicsError(Exception):
    """A body ran away (its position or speed went non-finite or beyond 1e12), or ODE failed, during a run."""

class FireError(ValueError):
    """Model.fire() refused: the transition is not enabled, is occurring, or its guard is false."""
)py",
           m.attr("__dict__"));

  py::class_<Model>(m, "Model", "A loaded model, ready to run")
      .def("run", &Model::run, py::arg("until") = py::none(), py::arg("steps") = py::none(),
           py::arg("seed") = py::none(),
           "Runs until `until` seconds or for `steps` steps (default: the model's until, else until the net is "
           "dead). A seed restarts the model from its initial marking. Returns the report.")
      .def("step", &Model::step, "Runs one step")
      .def("step_plant", &Model::stepPlant,
           "One step of the plant alone, the net switched off: physics and sensors move, the marking stays")
      .def("fire", &Model::fire, py::arg("transition"),
           "Starts the named transition now; raises gdpn.FireError with the reason when it cannot start")
      .def("reset", &Model::reset, py::arg("seed") = py::none(),
           "Back to the initial state: the same run again, byte for byte (with a seed: that seed's run)")
      .def("add_breakpoint", &Model::addBreakpoint, py::arg("written") = py::none(), py::kw_only(),
           py::arg("starts") = py::none(), py::arg("completes") = py::none(), py::arg("place") = py::none(),
           py::arg("compare") = ">=", py::arg("value") = 0, py::arg("predicate") = py::none(),
           "Stops run() at the end of the step where a transition starts or completes, a place's tokens "
           "(a continuous place's amount; a float value compares as a real number) compare with `value`, or a "
           "predicate holds: a Python expression over the model's globals, or a "
           "callable taking no arguments. Or as `gdpn run --break` writes it: 'start:T', 'complete:T', "
           "'P>=3' (or <, <=, ==, !=, >) or 'when:EXPR'. Returns its id.")
      .def("replay", &Model::replay, py::arg("witness"),
           "Plays the firing sequence of a witness (gdpn analyze --witness, as gdpn run --replay) in this run "
           "and after each reset: only its transitions start, in its order, each as soon as it can. Raises "
           "gdpn.ModelError, located, when the file is no witness of this net")
      .def_property_readonly("replay_verdict", &Model::replayVerdict,
                             "how far the replay got: {done, message} (the message gdpn run --replay prints), or None")
      .def("remove_breakpoint", &Model::removeBreakpoint, py::arg("id"),
           "Removes the breakpoint of that id (add_breakpoint's answer)")
      .def("enable_breakpoint", &Model::enableBreakpoint, py::arg("id"), py::arg("enabled") = true,
           "Enables or disables a breakpoint (a disabled one is kept but never stops a run)")
      .def("push", &Model::push, py::kw_only(), py::arg("key") = py::none(), py::arg("down") = true,
           py::arg("viewpoint") = py::none(), py::arg("click") = py::none(), py::arg("at") = py::none(),
           "One live input event for the sensors: a key pressed (or released, down=False), the viewer "
           "moved to a point (m), or a click along a ray ((from), (to)); delivered at the first step at "
           "or after `at` seconds (default: now)")
      .def_property_readonly("breakpoints", &Model::breakpoints, "[{id, watches, enabled}]")
      .def_property_readonly("hit", &Model::hit, "the id of the breakpoint that ended the last run, or None")
      .def("marking", &Model::marking, py::arg("place"),
           "Tokens on a place: a count for a plain place, {value: count} for a place of values (each value as "
           "the inscription language writes it: 'p1', '(1, \"a\")'), else {slot: count, [node names] or {value: "
           "count}}; a continuous place's amount (a float, in its unit)")
      .def("analyze", &Model::analyze, py::arg("query") = py::none(), py::kw_only(),
           py::arg("max_states") = session::kDefaultMaxStates, py::arg("max_memory_mib") = 0.0,
           py::arg("time_limit") = 0.0,
           "The untimed net's analysis as data, under gdpn analyze's limits (max_memory_mib 0: 3/4 of the "
           "memory available at the start; a RuntimeWarning says when that stopped it): without `query`, "
           "what `gdpn analyze --json` reports; with a "
           "formula (docs/queries.md), its answer as a dict (answer, states, technique, and the path, cycle "
           "and marking that show it); with a list of formulas, a list of answers. Raises gdpn.ModelError, "
           "located by column, for a mistake in a formula; an answer a limit stops is 'unknown' with 'why'.")
      .def("trace", &Model::trace, "Every event so far, as dicts")
      .def("signals", &Model::signalFrame,
           "The signals recorded so far (the model's signals section and load(signals=...)) as a pandas "
           "DataFrame indexed by time, s; NaN where a signal was not sampled")
      .def("report", &Model::report, "Figures of the run so far")
      .def_property_readonly("time", &Model::time, "seconds simulated")
      .def_property_readonly("steps", &Model::steps, "steps taken")
      .def_property_readonly("seed", &Model::seed, "the seed of this run (load's, or the last reset's)")
      .def_property_readonly("path", &Model::path, "the model file")
      .def_property_readonly(
          "params",
          [](const Model& mo) {
            py::dict out;
            for (const auto& p : mo.params()) {
              if (p.integer) out[py::str(p.name)] = py::int_(static_cast<long long>(p.value));
              else out[py::str(p.name)] = py::float_(p.value);
            }
            return out;
          },
          "the model's parameters as this run has them: {name: number}")
      .def("io", &Model::io, "Every I/O of every part, with its value now: [{part, io, direction, signal, unit, "
                             "value, forced}]")
      .def("force", &Model::force, py::arg("part"), py::arg("io"), py::arg("value"),
           "Forces a part's I/O to a value from the next step on (an input reads it, an output holds it); traced")
      .def("release", &Model::release, py::arg("part") = py::none(), py::arg("io") = py::none(),
           "Releases a force at the next step; every force when no argument is given")
      .def("__repr__", [](const Model& mo) { return "<gdpn.Model " + mo.path() + ">"; });

  m.def(
      "parts",
      [](const std::string& model_dir) {
        core::Diagnostics diags;
        py::list out;
        for (const auto& p : model::scanParts(model::partSearchPath(model_dir), diags)) {
          py::dict d;
          d["name"] = p.name;
          d["group"] = p.spec.group;
          d["version"] = p.spec.version;
          d["file"] = p.file;
          d["description"] = p.description;
          d["pattern"] = p.pattern;
          py::list io;
          for (const auto& i : p.spec.io) {
            py::dict x;
            x["name"] = i.name;
            x["direction"] = model::ioDirectionName(i.direction);
            x["signal"] = model::ioSignalName(i.signal);
            x["unit"] = i.unit;
            x["description"] = i.description;
            io.append(x);
          }
          d["io"] = io;
          py::dict params;
          for (const auto& q : p.spec.params) params[py::str(q.name)] = q.declared;
          d["params"] = params;
          out.append(d);
        }
        return out;
      },
      py::arg("model_dir") = "",
      "The parts library (as gdpn parts lists it): [{name, group, version, file, description, pattern, io, params}], "
      "searched from model_dir when given, then $XDG_DATA_HOME, $XDG_DATA_DIRS, the install and the source tree");

  m.def(
      "load",
      [](const std::string& path, std::optional<std::uint64_t> seed, double script_timeout, double script_memory,
         const py::dict& params,
         const std::vector<std::string>& signals) {
        return std::make_unique<Model>(path, seed, script::ScriptLimits{script_timeout, script_memory}, params, signals);
      },
      py::arg("path"), py::arg("seed") = py::none(), py::arg("script_timeout") = script::kDefaultScriptTimeout,
      py::arg("script_memory") = script::kDefaultScriptMemory, py::arg("params") = py::dict(),
      py::arg("signals") = std::vector<std::string>{},
      "Loads a model file (or a folder holding one), its parameters set from `params` ({name: number}) where "
      "given; `signals` adds signals to record (\"place:NAME\", \"node:PATH.QUANTITY\", \"python:EXPR\", sampled "
      "every step) to the model's own; `script_timeout` (seconds, 0: none) stops a script call, the globals "
      "script included, that runs longer, `script_memory` (MiB, 0: none) one that makes Python hold more; raises gdpn.ModelError on mistakes");

  m.def(
      "analysis_limits",
      [](std::uint64_t max_states, double max_memory_mib, double time_limit) {
        const net::ExploreOptions limits = checkedAnalysisRequest(max_states, max_memory_mib, time_limit).limits();
        py::dict out;
        out["max_states"] = limits.max_states;
        out["max_bytes"] = limits.max_bytes;
        out["guard"] = limits.max_bytes_guard;
        return out;
      },
      py::kw_only(), py::arg("max_states") = session::kDefaultMaxStates, py::arg("max_memory_mib") = 0.0,
      py::arg("time_limit") = 0.0,
      "The limits Model.analyze() (and gdpn analyze) would run under now: {max_states, max_bytes, guard}; "
      "guard is True when max_bytes is the default, 3/4 of the memory available");

  // sweeps: the same code as `gdpn sweep`, in a namespace of its own that no worker needs to
  // import (Dask sends its functions by value)
  py::dict sweeps;
  sweeps["__builtins__"] = py::module_::import("builtins");
  sweeps["__name__"] = "gdpn_sweep";
  py::module_::import("builtins").attr("exec")(
      py::module_::import("builtins").attr("compile")(gdpn::experiments::kSweepPy, "sweep.py", "exec"), sweeps);
  m.attr("sweep") = sweeps["sweep"];
  m.attr("Sweep") = sweeps["Sweep"];
  m.attr("SweepError") = sweeps["SweepError"];
}
