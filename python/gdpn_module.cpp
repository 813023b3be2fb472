// The gdpn Python module: load a model, run it, read markings, the trace and the report.

#include <pybind11/pybind11.h>
#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include <atomic>
#include <sstream>

#include "gdpn/model/report.h"
#include "gdpn/model/simulation.h"

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

class Model {
 public:
  Model(std::string path, std::optional<std::uint64_t> seed, double script_timeout)
      : path_(std::move(path)), timeout_(script_timeout) {
    core::Diagnostics diags;
    auto resolved = model::resolveModelPath(path_, diags);
    if (!resolved) raiseModelError(diags);
    path_ = *resolved;
    auto m = model::loadModel(path_, diags);
    if (!m) raiseModelError(diags);
    model_ = std::move(*m);
    restart(seed, diags);
  }

  py::dict run(std::optional<double> until, std::optional<std::int64_t> steps, std::optional<std::uint64_t> seed) {
    if (seed) {
      core::Diagnostics diags;
      restart(seed, diags);
    }
    std::atomic<bool> interrupted{false};
    // Ctrl-C between steps: Python's handler runs here and the run stops cleanly
    auto check = [&](std::int64_t, std::int64_t) {
      if (PyErr_CheckSignals() != 0) {
        PyErr_Clear();
        interrupted = true;
      }
    };
    outcome_ = sim_->run({until, steps}, check, &interrupted);
    raiseIfFailed();
    return report();
  }

  void step() {
    sim_->step();
    if (auto halt = sim_->scriptHalt()) {
      outcome_ = *halt;
      raiseIfFailed();
    }
  }

  py::object marking(const std::string& place) const {
    const auto& net = sim_->net();
    const auto p = net.findPlace(place);
    if (p < 0) throw py::key_error("no place '" + place + "'");
    const auto& pl = net.places()[static_cast<std::size_t>(p)];
    py::dict slots;
    for (auto ps = pl.slots_begin; ps < pl.slots_end; ++ps) {
      const auto& slot = net.placeSlots()[ps];
      if (slot.kind == net::SlotKind::Node) {
        py::list names;
        for (auto ref : sim_->kernel().nodes(ps)) names.append(sim_->nodeName(ref));
        slots[py::str(net::slotName(slot.slot))] = names;
      } else {
        slots[py::str(net::slotName(slot.slot))] = sim_->kernel().marking(ps);
      }
    }
    // a place with only a0 as a control slot reads as a plain count
    if (pl.slots_end - pl.slots_begin == 1 && net.placeSlots()[pl.slots_begin].slot == net::kDefaultSlot &&
        net.placeSlots()[pl.slots_begin].kind == net::SlotKind::Control) {
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
    auto outcome = outcome_;
    outcome.steps = sim_->kernel().steps();
    outcome.time = sim_->kernel().now();
    return py::module_::import("json").attr("loads")(model::reportJson(model::makeReport(*sim_, outcome)));
  }

  [[nodiscard]] double time() const { return sim_->kernel().now(); }
  [[nodiscard]] std::int64_t steps() const { return sim_->kernel().steps(); }
  [[nodiscard]] std::uint64_t seed() const { return sim_->seed(); }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  void restart(std::optional<std::uint64_t> seed, core::Diagnostics& diags) {
    sim_.reset();
    sim_ = model::Simulation::create(model_, diags, seed, timeout_);
    if (!sim_) raiseModelError(diags);
    trace_.str("");
    trace_.clear();
    sim_->traceTo(trace_);
    outcome_ = {};
  }

  void raiseIfFailed() const {
    switch (outcome_.reason) {
      case model::StopReason::ScriptError: {
        py::object err = module().attr("ScriptError")(outcome_.message);
        PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(err.ptr())), err.ptr());
        throw py::error_already_set();
      }
      case model::StopReason::Interrupted:
        PyErr_SetString(PyExc_KeyboardInterrupt, outcome_.message.empty() ? "run interrupted" : outcome_.message.c_str());
        throw py::error_already_set();
      default:
        return;
    }
  }

  std::string path_;
  double timeout_;
  model::Model model_;
  std::unique_ptr<model::Simulation> sim_;
  std::ostringstream trace_;
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
)py",
           m.attr("__dict__"));

  py::class_<Model>(m, "Model", "A loaded model, ready to run")
      .def("run", &Model::run, py::arg("until") = py::none(), py::arg("steps") = py::none(),
           py::arg("seed") = py::none(),
           "Runs until `until` seconds or for `steps` steps (default: the model's until, else until the net is "
           "dead). A seed restarts the model from its initial marking. Returns the report.")
      .def("step", &Model::step, "Runs one step")
      .def("marking", &Model::marking, py::arg("place"),
           "Tokens on a place: a count for a plain place, else {slot: count or [node names]}")
      .def("trace", &Model::trace, "Every event so far, as dicts")
      .def("report", &Model::report, "Figures of the run so far")
      .def_property_readonly("time", &Model::time, "seconds simulated")
      .def_property_readonly("steps", &Model::steps, "steps taken")
      .def_property_readonly("seed", &Model::seed)
      .def_property_readonly("path", &Model::path)
      .def("__repr__", [](const Model& mo) { return "<gdpn.Model " + mo.path() + ">"; });

  m.def(
      "load",
      [](const std::string& path, std::optional<std::uint64_t> seed, double script_timeout) {
        return std::make_unique<Model>(path, seed, script_timeout);
      },
      py::arg("path"), py::arg("seed") = py::none(), py::arg("script_timeout") = 0.0,
      "Loads a model file (or a folder holding one); raises gdpn.ModelError on mistakes");
}
