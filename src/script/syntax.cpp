// Python syntax checks through the embedded interpreter's compile().

#include "gdpn/script/syntax.h"

#include <pybind11/embed.h>

#include <csignal>

namespace py = pybind11;

namespace gdpn::script {

void startInterpreter() {
  if (Py_IsInitialized()) return;
  // Python installs no C signal handlers; its own SIGINT entry is set to raise
  // KeyboardInterrupt, so that requestInterrupt() and the timeout reach a running script
  py::initialize_interpreter(false);
  auto signal = py::module_::import("signal");
  const auto previous = std::signal(SIGINT, SIG_DFL);
  signal.attr("signal")(SIGINT, signal.attr("default_int_handler"));
  std::signal(SIGINT, previous);  // the C-level handler stays the program's
}

void quoteSourceAs(const std::string& file, const std::string& text) {
  if (file.empty()) return;
  startInterpreter();
  py::gil_scoped_acquire gil;
  try {
    // an entry without a modification time is one linecache never checks against the disk
    // the file named as compile() names it: its bytes decoded as the file system's names are
    PyObject* raw = PyUnicode_DecodeFSDefaultAndSize(file.data(), static_cast<Py_ssize_t>(file.size()));
    if (raw == nullptr) throw py::error_already_set();
    const auto name = py::reinterpret_steal<py::object>(raw);
    const py::object lines = py::str(text).attr("splitlines")(true);
    py::module_::import("linecache").attr("cache")[name] = py::make_tuple(text.size(), py::none(), lines, name);
  } catch (py::error_already_set&) {
    // text Python cannot read as UTF-8: tracebacks quote the file on disk
  }
}

std::optional<SyntaxProblem> syntaxProblem(const std::string& code, bool expression) {
  startInterpreter();
  py::gil_scoped_acquire gil;
  PyObject* compiled = Py_CompileString(code.c_str(), "<script>", expression ? Py_eval_input : Py_file_input);
  if (compiled != nullptr) {
    Py_DECREF(compiled);
    return std::nullopt;
  }
  py::error_already_set e;
  SyntaxProblem problem;
  problem.message = e.what();
  if (e.matches(PyExc_SyntaxError)) {
    const py::object v = e.value();
    if (py::hasattr(v, "lineno") && !v.attr("lineno").is_none()) problem.line = v.attr("lineno").cast<int>();
    if (py::hasattr(v, "offset") && !v.attr("offset").is_none()) problem.column = v.attr("offset").cast<int>();
    problem.message = py::str(v.attr("msg"));
  }
  return problem;
}

}  // namespace gdpn::script
