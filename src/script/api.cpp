// The names scripts reach, read from the registered view classes themselves; the names a
// globals script binds, read by Python's ast.

#include "gdpn/script/api.h"

#include <pybind11/embed.h>
#include <pybind11/eval.h>

#include <mutex>
#include <optional>

#include "gdpn/core/text.h"
#include "gdpn/script/syntax.h"
#include "views.h"

namespace py = pybind11;

namespace gdpn::script {
namespace {

// what reads a class's names and docstrings (pybind11 writes a method's signature as the first
// line of its docstring), and a globals script's top-level names
constexpr const char* kHelpers = R"py(
import ast


def _split_top(text):
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur.strip())
    return parts


def _arguments(signature):
    start = signature.find("(")
    if start < 0:
        return ""
    depth = 0
    end = len(signature)
    for i in range(start, len(signature)):
        if signature[i] in "([":
            depth += 1
        elif signature[i] in ")]":
            depth -= 1
            if depth == 0:
                end = i
                break
    out = []
    for p in _split_top(signature[start + 1:end])[1:]:  # the first is self
        name, _, default = p.partition(" = ")
        name = name.split(":")[0].strip()
        out.append(name + ("=" + default.strip() if default else ""))
    return ", ".join(out)


def _first_line(text):
    for line in (text or "").splitlines():
        if line.strip():
            return line.strip()
    return ""


def describe(cls):
    out = []
    for name in sorted(dir(cls)):
        if name.startswith("_"):
            continue
        attr = cls.__dict__.get(name)
        if attr is None:
            for base in cls.__mro__:
                if name in base.__dict__:
                    attr = base.__dict__[name]
                    break
        if isinstance(attr, property):
            out.append((name, False, "", _first_line(attr.__doc__)))
            continue
        doc = getattr(attr, "__doc__", "") or ""
        lines = doc.splitlines()
        signature = lines[0] if lines else ""
        rest = lines[1:]
        if len(lines) > 1 and lines[1].strip() == "Overloaded function.":
            # the first overload: "1. name(self, ...) -> T", its text after it
            rest = []
            for i, line in enumerate(lines):
                if line.startswith("1. "):
                    signature = line[3:]
                    rest = lines[i + 1:]
                    break
        text = ""
        for line in rest:
            if line.strip() and line[:2] != "2." and not line.startswith(name + "("):
                text = line.strip()
                break
        out.append((name, True, _arguments(signature), text))
    return out


def _short(text, most=60):
    text = " ".join(text.split())
    return text if len(text) <= most else text[:most - 3] + "..."


def _targets(t):
    if isinstance(t, ast.Name):
        yield t.id
    elif isinstance(t, (ast.Tuple, ast.List)):
        for e in t.elts:
            yield from _targets(e)
    elif isinstance(t, ast.Starred):
        yield from _targets(t.value)


def global_names(code):
    try:
        tree = ast.parse(code)
    except (SyntaxError, ValueError):
        return []
    out, seen = [], set()

    def add(name, kind, detail, line):
        if name in seen or (name.startswith("__") and name.endswith("__")):
            return
        seen.add(name)
        out.append((name, kind, detail, line))

    def walk(body):
        for n in body:
            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)):
                doc = _first_line(ast.get_docstring(n))
                add(n.name, "function", "(" + ast.unparse(n.args) + ")" + (": " + doc if doc else ""), n.lineno)
            elif isinstance(n, ast.ClassDef):
                add(n.name, "class", _first_line(ast.get_docstring(n)), n.lineno)
            elif isinstance(n, ast.Assign):
                for t in n.targets:
                    for name in _targets(t):
                        add(name, "variable", "= " + _short(ast.unparse(n.value)), n.lineno)
            elif isinstance(n, (ast.AnnAssign, ast.AugAssign)):
                value = getattr(n, "value", None)
                for name in _targets(n.target):
                    add(name, "variable", "= " + _short(ast.unparse(value)) if value is not None else "", n.lineno)
            elif isinstance(n, (ast.Import, ast.ImportFrom)):
                for a in n.names:
                    name = a.asname or a.name.split(".")[0]
                    if name == "*":
                        continue
                    source = ("from " + (n.module or ".") + " ") if isinstance(n, ast.ImportFrom) else ""
                    add(name, "import", source + "import " + a.name, n.lineno)
            elif isinstance(n, (ast.If, ast.While)):
                walk(n.body)
                walk(n.orelse)
            elif isinstance(n, (ast.For, ast.AsyncFor)):
                for name in _targets(n.target):
                    add(name, "variable", "a loop's variable", n.lineno)
                walk(n.body)
                walk(n.orelse)
            elif isinstance(n, (ast.With, ast.AsyncWith)):
                for item in n.items:
                    if item.optional_vars is not None:
                        for name in _targets(item.optional_vars):
                            add(name, "variable", "= " + _short(ast.unparse(item.context_expr)), n.lineno)
                walk(n.body)
            elif isinstance(n, ast.Try) or type(n).__name__ == "TryStar":
                walk(n.body)
                for h in n.handlers:
                    walk(h.body)
                walk(n.orelse)
                walk(n.finalbody)
    walk(tree.body)
    return out
)py";

/// The helpers' namespace, made once for the process (never destroyed: after the
/// interpreter, a Python object cannot be). Call with the GIL held.
const py::dict& helpers() {
  static const py::dict& scope = *new py::dict([] {
    py::dict d;
    d["__builtins__"] = py::module_::import("builtins");
    py::exec(kHelpers, d);
    return d;
  }());
  return scope;
}

std::mutex& apiMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

const char* viewClassName(ViewClass c) {
  switch (c) {
    case ViewClass::Sim: return "Sim";
    case ViewClass::Transition: return "Transition";
    case ViewClass::Place: return "Place";
    case ViewClass::Slot: return "Slot";
    case ViewClass::Node: return "Node";
    case ViewClass::Sensor: return "Sensor";
    case ViewClass::Random: return "Random";
    case ViewClass::Params: return "Params";
    case ViewClass::Part: return "Part";
    case ViewClass::Data: return "Data";
  }
  return "?";
}

namespace {

/// A class's names and its own line, read once.
struct ClassNames {
  std::vector<ViewName> names;
  std::string doc;
};

const ClassNames& classNames(ViewClass c) {
  static std::array<std::optional<ClassNames>, kViewClasses.size()> cache;
  const std::lock_guard lock(apiMutex());
  auto& slot = cache[static_cast<std::size_t>(c)];
  if (slot) return *slot;
  startInterpreter();
  py::gil_scoped_acquire gil;
  detail::registerViews();
  ClassNames read;
  const py::object cls = py::module_::import("gdpn_script").attr(viewClassName(c));
  for (const auto& item : helpers()["describe"](cls)) {
    const auto t = item.cast<py::tuple>();
    read.names.push_back({t[0].cast<std::string>(), t[1].cast<bool>(), t[2].cast<std::string>(), t[3].cast<std::string>()});
  }
  read.doc = helpers()["_first_line"](cls.attr("__doc__")).cast<std::string>();
  slot = std::move(read);
  return *slot;
}

}  // namespace

const std::vector<ViewName>& viewNames(ViewClass c) { return classNames(c).names; }

const std::string& viewClassDoc(ViewClass c) { return classNames(c).doc; }

std::string viewNamesMarkdown(ViewClass c) {
  std::string out = "| name | meaning |\n| --- | --- |\n";
  for (const auto& n : viewNames(c)) {
    const std::string written = n.method ? n.name + "(" + n.arguments + ")" : n.name;
    out += "| `" + core::markdownCell(written) + "` | " + core::markdownCell(n.doc) + " |\n";
  }
  return out;
}

std::vector<GlobalName> globalNames(const std::string& code) {
  const std::lock_guard lock(apiMutex());
  startInterpreter();
  py::gil_scoped_acquire gil;
  std::vector<GlobalName> out;
  try {
    for (const auto& item : helpers()["global_names"](code)) {
      const auto t = item.cast<py::tuple>();
      out.push_back({t[0].cast<std::string>(), t[1].cast<std::string>(), t[2].cast<std::string>(), t[3].cast<int>()});
    }
  } catch (py::error_already_set&) {
    return {};  // text Python cannot read (a null byte): no names
  }
  return out;
}

}  // namespace gdpn::script
