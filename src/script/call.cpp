// gdpn's own Python run in the embedded interpreter: a fresh module per call.

#include "gdpn/script/call.h"

#include <pybind11/embed.h>

#include "gdpn/script/syntax.h"

namespace py = pybind11;

namespace gdpn::script {

std::optional<std::string> callPython(const std::string& source, const std::string& filename,
                                      const std::string& function, const std::string& argument,
                                      std::string& error) {
  startInterpreter();
  py::gil_scoped_acquire gil;
  try {
    py::dict scope;
    scope["__builtins__"] = py::module_::import("builtins");
    std::string name = filename;
    if (const auto dot = name.rfind('.'); dot != std::string::npos) name.resize(dot);
    scope["__name__"] = "gdpn_" + name;
    const py::object code = py::module_::import("builtins").attr("compile")(source, filename, "exec");
    py::module_::import("builtins").attr("exec")(code, scope);
    return py::str(scope[function.c_str()](argument)).cast<std::string>();
  } catch (py::error_already_set& e) {
    try {
      const py::object trace = e.trace() ? py::object(e.trace()) : py::object(py::none());
      const py::list lines = py::module_::import("traceback").attr("format_exception")(e.type(), e.value(), trace);
      error.clear();
      for (const auto& line : lines) error += py::str(line).cast<std::string>();
    } catch (py::error_already_set&) {
      error = e.what();
    }
    return std::nullopt;
  } catch (const std::exception& e) {  // a value pybind11 could not convert
    error = e.what();
    return std::nullopt;
  }
}

}  // namespace gdpn::script
