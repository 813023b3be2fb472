// The script engine: compiles a net's scripts once and runs them as kernel hooks.
// The hot path (one script call) uses the raw C API: set `self` (and `token`) in the model's
// one globals dict, evaluate the code object, check the result.

#include "gdpn/script/engine.h"
#include "gdpn/script/syntax.h"

#include <pybind11/embed.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <csignal>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <pthread.h>
#include <sstream>
#include <thread>
#include <unordered_map>

#include "gdpn/core/text.h"
#include "gdpn/scene/actions.h"
#include "memory_limit.h"
#include "views.h"

namespace py = pybind11;

namespace gdpn::script {
namespace {

/// Set once the user interrupts (requestInterrupt: Ctrl-C, SIGTERM): only then is a script's
/// KeyboardInterrupt an interruption; a script that raises one itself has failed.
std::atomic<bool> interrupt_requested{false};

/// Makes the script running in the main thread raise KeyboardInterrupt soon. Safe from any
/// thread and from a signal handler; needs Python's SIGINT entry to be default_int_handler.
void interruptScript() {
  interrupt_requested.store(true);
  if (Py_IsInitialized()) PyErr_SetInterruptEx(SIGINT);
}

/// The pending exception is the user's interruption (not a KeyboardInterrupt a script raised).
bool interruptedByUser() { return interrupt_requested.load() && PyErr_ExceptionMatches(PyExc_KeyboardInterrupt); }

using net::ScriptKind;

/// The index in Net::scripts() of script `kind` of construct `id` (-1: none).
std::int32_t indexOf(const net::Net& net, ScriptKind kind, std::uint32_t id) {
  const auto& index = net.scriptIndex();
  switch (net::info(kind).owner) {
    case net::ScriptOwner::Transition: return index.transitions[id][net::info(kind).position];
    case net::ScriptOwner::PlaceSlot: return index.slots[id][net::info(kind).position];
    case net::ScriptOwner::Arc: return index.predicates[id];
    case net::ScriptOwner::Model: return net.globalsScript();
  }
  return -1;
}

}  // namespace

void requestInterrupt() { interruptScript(); }

/// One compiled script.
struct Compiled {
  /// inline code: its code object made a function over the model's globals once, so that a
  /// call runs it with the globals as its namespace, as exec would, without building a
  /// function (and looking up the builtins) each time; or none
  py::object code;
  py::object function;  // callable (file form), or none
  bool expression = false;
};

namespace {

/// The signal that breaks a script's blocking call when its time is up: a real-time signal
/// that nothing else sends. Python's C-level handler for it (installed with signal.signal,
/// without SA_RESTART) makes the blocked system call return EINTR, and the call then runs
/// the Python-level handler, onStopSignal, which raises.
int stopSignal() { return SIGRTMAX - 4; }

/// Python's thread ident of the thread whose signal handlers Python runs (0: the handler for
/// stopSignal() is not installed, and the watchdog falls back on an asynchronous exception).
std::atomic<unsigned long> g_signal_thread{0};

class Watchdog;
/// The watchdog of the script call running in this thread (null: none).
thread_local Watchdog* t_watched = nullptr;

PyObject* onStopSignal(PyObject* self, PyObject* args);
int traceStop(PyObject* obj, PyFrameObject* frame, int what, PyObject* arg);

/// Watches script calls from a thread of its own. When a call runs longer than the timeout,
/// it is stopped in three rising steps:
/// - stopSignal() is sent to the script's thread every 100 ms: a blocking call returns, and
///   the handler raises KeyboardInterrupt and installs a C-level trace function;
/// - that trace function raises again on every line and call event, so a script that
///   catches the stop cannot go on; it is removed when the call returns;
/// - a call still running `grace_s` after its timeout (stuck inside C code that never
///   looks at signals) ends the process, with the message on stderr.
/// timedOut() tells a stop from a Ctrl-C. A script on a thread that is not Python's main
/// thread gets the stop as an asynchronous exception instead (busy loops only).
/// A call's start and end are a few atomic stores (no lock): the watchdog decides a stop and
/// sends the signal while it sees the call running and marks that it is doing so (kicking_);
/// a call that ends meanwhile waits for it, so that no stop reaches code after the call.
class Watchdog {
 public:
  Watchdog(double timeout_s, double grace_s, std::function<void()> hard_stop)
      : timeout_s_(timeout_s), grace_s_(grace_s), hard_stop_(std::move(hard_stop)) {
    if (timeout_s_ > 0) thread_ = std::thread([this] { loop(); });
  }
  ~Watchdog() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    // the thread may be waiting for the GIL: let it have it
    if (PyGILState_Check()) {
      py::gil_scoped_release nogil;
      thread_.join();
    } else {
      thread_.join();
    }
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  /// While a call runs, Python may hold at most `bytes` (as detail::memoryHeld() counts; 0:
  /// no bound): an allocation past it raises MemoryError in the script.
  void capMemory(std::int64_t bytes) { memory_cap_ = bytes; }

  /// A script call starts in this thread (under the GIL). A call made from inside another
  /// (a hook run by what a script did) is part of it: the outer call's clock runs on.
  void enter() {
    if (depth_++ > 0) return;
    if (memory_cap_ != 0) detail::setMemoryCap(memory_cap_);
    if (!thread_.joinable()) return;
    // who runs it, seen by the watchdog through the release of call_
    const unsigned long ident = PyThread_get_thread_ident();
    thread_id_.store(ident, std::memory_order_relaxed);
    target_.store(pthread_self(), std::memory_order_relaxed);
    by_signal_.store(ident == g_signal_thread.load(std::memory_order_relaxed), std::memory_order_relaxed);
    call_.store(((generation_ + 1) << 1) | 1, std::memory_order_release);
    ++generation_;
    previous_ = t_watched;
    t_watched = this;
  }
  /// The call has returned (under the GIL): the stop's trace function goes.
  void leave() {
    if (--depth_ > 0) return;
    if (memory_cap_ != 0) detail::setMemoryCap(0);
    if (!thread_.joinable()) return;
    call_.store(generation_ << 1, std::memory_order_seq_cst);
    // a stop being decided or sent now, or sent to this call: let it reach this call (a
    // pending signal is delivered at the return of a system call), not the code after it
    if (kicking_.load(std::memory_order_seq_cst) || stopped_.load(std::memory_order_acquire) == generation_) {
      while (kicking_.load(std::memory_order_acquire)) std::this_thread::yield();
      std::this_thread::yield();
    }
    t_watched = previous_;
    if (tracing_) {
      tracing_ = false;
      PyEval_SetTrace(saved_trace_, saved_trace_obj_);  // whatever tracer ran before (a debugger)
      Py_XDECREF(saved_trace_obj_);
      saved_trace_obj_ = nullptr;
    }
  }
  /// Whether the current (or last) call was stopped for running too long.
  [[nodiscard]] bool timedOut() const {
    const auto stopped = stopped_.load();
    return stopped != 0 && stopped == generation_;
  }
  /// Installs the trace function that raises on every event, once per call (under the GIL).
  void traceUntilReturn() {
    if (tracing_) return;
    PyThreadState* state = PyThreadState_Get();
    saved_trace_ = state->c_tracefunc;
    saved_trace_obj_ = state->c_traceobj;
    Py_XINCREF(saved_trace_obj_);
    PyEval_SetTrace(traceStop, nullptr);
    tracing_ = true;
  }

 private:
  void loop() {
    // signals sent to the process (Ctrl-C) are for the main thread, not this one
    sigset_t all;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, nullptr);
    using clock = std::chrono::steady_clock;
    std::uint64_t seen = 0;
    clock::time_point since = clock::now(), kicked{};
    while (true) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        if (wake_.wait_for(lock, std::chrono::milliseconds(10), [this] { return done_; })) return;
      }
      const std::uint64_t call = call_.load(std::memory_order_acquire);
      if ((call & 1) == 0) {
        seen = 0;
        continue;
      }
      const std::uint64_t gen = call >> 1;
      const auto now = clock::now();
      if (gen != seen) {
        seen = gen;
        since = now;
        continue;
      }
      const double late = std::chrono::duration<double>(now - since).count() - timeout_s_;
      if (late <= 0) continue;
      const bool by_signal = by_signal_.load(std::memory_order_relaxed);
      // decided and sent while the call certainly runs: leave() waits while kicking_ is set
      kicking_.store(true, std::memory_order_seq_cst);
      if (call_.load(std::memory_order_seq_cst) != call) {
        kicking_.store(false, std::memory_order_release);
        continue;
      }
      const bool first = stopped_.exchange(gen) != gen;
      if (grace_s_ > 0 && late > grace_s_) hard_stop_();
      if (by_signal && (first || now - kicked >= std::chrono::milliseconds(100))) {
        kicked = now;
        pthread_kill(target_.load(std::memory_order_relaxed), stopSignal());
      }
      kicking_.store(false, std::memory_order_release);
      if (!by_signal && first) {
        // leave() runs under the GIL: the call is still this one while the GIL is held here
        const unsigned long ident = thread_id_.load(std::memory_order_relaxed);
        const PyGILState_STATE state = PyGILState_Ensure();
        if (call_.load() == call) PyThreadState_SetAsyncExc(ident, PyExc_KeyboardInterrupt);
        PyGILState_Release(state);
      }
    }
  }

  double timeout_s_;
  double grace_s_;
  std::function<void()> hard_stop_;
  // the call: written by enter() before it publishes call_, read by the watchdog after
  std::atomic<std::uint64_t> call_{0};     // the generation << 1, | 1 while the call runs
  std::atomic<bool> kicking_{false};       // the watchdog is deciding or sending a stop
  std::atomic<std::uint64_t> stopped_{0};  // the generation that was stopped (0: none)
  std::atomic<unsigned long> thread_id_{0};
  std::atomic<pthread_t> target_{};
  std::atomic<bool> by_signal_{false};
  // the script's thread only
  Watchdog* previous_ = nullptr;
  std::uint64_t generation_ = 0;  // calls so far (the current or last one's number)
  int depth_ = 0;  // calls inside calls
  std::int64_t memory_cap_ = 0;  // bytes Python may hold during a call (0: no bound)
  bool tracing_ = false;
  Py_tracefunc saved_trace_ = nullptr;
  PyObject* saved_trace_obj_ = nullptr;
  // the watchdog thread's life
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

/// Watches one call for as long as it lives.
class Watched {
 public:
  explicit Watched(Watchdog& watchdog) : watchdog_(watchdog) { watchdog_.enter(); }
  ~Watched() { watchdog_.leave(); }
  Watched(const Watched&) = delete;
  Watched& operator=(const Watched&) = delete;

 private:
  Watchdog& watchdog_;
};

/// Python-level handler of stopSignal(): raises KeyboardInterrupt in a call that ran out of
/// time, and makes every later line of it raise too; does nothing otherwise (a late signal).
PyObject* onStopSignal(PyObject*, PyObject*) {
  Watchdog* w = t_watched;
  if (!w || !w->timedOut()) Py_RETURN_NONE;
  w->traceUntilReturn();
  PyErr_SetNone(PyExc_KeyboardInterrupt);
  return nullptr;
}

/// The trace function of a stopped call: every new line and every call raises again.
int traceStop(PyObject*, PyFrameObject*, int what, PyObject*) {
  if (what != PyTrace_LINE && what != PyTrace_CALL) return 0;
  PyErr_SetNone(PyExc_KeyboardInterrupt);
  return -1;
}

/// Installs onStopSignal for stopSignal(), once, from Python's main thread (elsewhere
/// signal.signal refuses, and the watchdog falls back on asynchronous exceptions).
void installStopHandler() {
  if (g_signal_thread.load() != 0) return;
  static PyMethodDef def{"gdpn_script_stop", onStopSignal, METH_VARARGS, "stops a script that ran out of time"};
  try {
    auto handler = py::reinterpret_steal<py::object>(PyCFunction_New(&def, nullptr));
    if (!handler) throw py::error_already_set();
    py::module_::import("signal").attr("signal")(stopSignal(), handler);
    g_signal_thread.store(PyThread_get_thread_ident());
  } catch (const py::error_already_set&) {
  }
}

/// `name` as an interned Python str.
py::str interned(const char* name) {
  PyObject* s = PyUnicode_InternFromString(name);
  if (!s) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

/// A path as Python names files: its bytes decoded as the file system's names are, a byte
/// that is not UTF-8 as a surrogate (PEP 383), so a folder of any bytes can hold a model.
py::object pyPath(const std::string& path) {
  PyObject* s = PyUnicode_DecodeFSDefaultAndSize(path.data(), static_cast<Py_ssize_t>(path.size()));
  if (!s) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(s);
}

/// The bytes of a Python text that may name a path (a code object's file name, a traceback
/// line): encoded as the file system's names are, each surrogate back to the byte it stood
/// for (pyPath's inverse); any other lone surrogate escaped. Never fails.
std::string bytesOf(py::handle text) {
  py::object s = py::str(text);
  PyObject* b = PyUnicode_EncodeFSDefault(s.ptr());
  if (!b) {
    PyErr_Clear();
    b = PyUnicode_AsEncodedString(s.ptr(), "utf-8", "backslashreplace");
  }
  if (!b) {
    PyErr_Clear();
    return "?";
  }
  std::string out(PyBytes_AS_STRING(b), static_cast<std::size_t>(PyBytes_GET_SIZE(b)));
  Py_DECREF(b);
  return out;
}

}  // namespace

struct Engine::Impl : detail::Context {
  const net::Net& net;
  net::Kernel& kernel;
  std::string model_path;
  std::filesystem::path model_dir;
  EngineOptions options;
  EngineCallbacks callbacks;

  py::dict globals;
  py::object sim;
  // the names inline code sees its arguments under, interned as the code's own names are (a
  // dict finds them by identity)
  py::str key_self = interned("self");
  py::str key_token = interned("token");
  py::str key_item = interned("item");
  std::vector<Compiled> compiled;
  std::unordered_map<std::string, py::object> expressions;  // breakpoint predicates, compiled
  std::vector<py::object> transition_views, place_views, node_views;
  // bare slot names (`c0`): each construct's scripts see its own sensor slots under their
  // names, bound in the globals before its script runs and unbound before another's
  std::vector<std::vector<std::pair<py::str, py::object>>> bare;  // by owner key (bareNames)
  std::vector<bool> bare_known;  // bare[key] is made
  bool any_bare = true;          // some construct may see a slot by bare name (a sensor slot in a plant)
  std::vector<std::pair<py::str, py::object>> bound;  // the names bound now, with what they hid
  std::int64_t bound_key = -1;     // whose they are (-1: nobody's)
  py::object geometries;           // gdpn_script.Geometries: on_enter/on_exit's `item`
  std::unique_ptr<Watchdog> watchdog;

  Halt halt = Halt::None;
  std::string message;

  Impl(const net::Net& n, net::Kernel& k) : net(n), kernel(k) {}
  ~Impl() { *alive = false; }

  // ---- detail::Context: what the views ask of the engine ----
  const net::Net& netRef() const override { return net; }
  net::Kernel& kernelRef() override { return kernel; }
  std::string nodeName(net::NodeRef ref) const override {
    return callbacks.node_name ? callbacks.node_name(ref) : "#" + std::to_string(ref);
  }
  py::object transitionView(net::TransitionId t) override { return py::reinterpret_borrow<py::object>(transitionSelf(t)); }
  py::object placeView(net::PlaceId p) override { return py::reinterpret_borrow<py::object>(placeSelf(p)); }
  /// Transition t's view, borrowed (the engine holds it): `self` of its scripts.
  PyObject* transitionSelf(net::TransitionId t) {
    auto& v = transition_views[t];
    if (!v) v = detail::makeTransitionView(detail::refTo(*this), t);
    return v.ptr();
  }
  /// Place p's view, borrowed (the engine holds it): `self` of its scripts.
  PyObject* placeSelf(net::PlaceId p) {
    auto& v = place_views[p];
    if (!v) v = detail::makePlaceView(detail::refTo(*this), p);
    return v.ptr();
  }
  py::object nodeView(net::NodeRef ref) override {
    if (ref < node_views.size()) {
      auto& v = node_views[ref];
      if (!v) v = detail::makeNodeView(detail::refTo(*this), ref);
      return v;
    }
    return detail::makeNodeView(detail::refTo(*this), ref);
  }
  void log(const std::string& text) override {
    if (callbacks.log) callbacks.log(text);
  }
  scene::Node* sceneNode(net::NodeRef ref) const override {
    return callbacks.plant ? callbacks.plant->resolve(ref) : nullptr;
  }
  physics::World* physicsWorld() const override { return callbacks.physics; }
  scene::AngleUnit angles() const override { return options.angles; }
  py::object params() override {
    if (!params_view) {
      py::dict values;
      for (const auto& p : options.params) {
        if (p.integer) values[py::str(p.name)] = py::int_(static_cast<long long>(p.value));
        else values[py::str(p.name)] = py::float_(p.value);
      }
      params_view = detail::makeParamsView(values);
    }
    return params_view;
  }
  py::object params_view;  // made on first use
  scene::Scene* plant() const override { return callbacks.plant; }
  const PartAccess& parts() const override { return callbacks.parts; }
  scene::Node* spawn(const scene::Node& templ, scene::Node& parent, std::optional<core::Vec3> at,
                     std::string& why) override {
    if (!callbacks.spawn) {
      why = "spawning is not available here";
      return nullptr;
    }
    return callbacks.spawn(templ, parent, at, why);
  }
  void erase(scene::Node& node) override {
    if (callbacks.erase) callbacks.erase(node);
  }
  std::shared_ptr<const sensors::Image> image(scene::NodeHandle sensor, std::string& why) const override {
    if (!callbacks.image) {
      why = "this run renders no camera pictures";
      return nullptr;
    }
    return callbacks.image(sensor, why);
  }
  const sensors::Reading& reading(scene::NodeHandle sensor) const override {
    static const sensors::Reading none;
    return callbacks.reading ? callbacks.reading(sensor) : none;
  }
  void stop(const std::string& reason) override {
    if (halt != Halt::None) return;
    halt = Halt::Stop;
    message = reason;
  }

  // ---- compiling ----

  /// The code with blank lines before it, so Python's line numbers are the model file's.
  static std::string padded(const net::ScriptSpec& s) {
    const int pad = std::max(0, s.loc.line - 1);
    return std::string(static_cast<std::size_t>(pad), '\n') + s.code;
  }

  /// Compiles inline code whose lines stand on the model file's lines `s.lines` (a folded
  /// block, a quoted string: net::ScriptSpec::lines): parsed, each node moved to its file line,
  /// compiled; a syntax error is placed on the file's line too. A new reference, or null with
  /// the error pending.
  PyObject* compileMapped(const net::ScriptSpec& s, bool expression) const {
    // made once and kept for the process, as the interpreter is (never destroyed: after the
    // interpreter, a Python object cannot be)
    static const py::object& compile_mapped = *new py::object([] {
      py::dict scope;
      py::exec(R"(
import ast

def compile_mapped(code, filename, mode, lines):
    def at(n):
        return lines[min(max(n, 1), len(lines)) - 1]
    try:
        tree = ast.parse(code, filename, mode)
    except SyntaxError as e:
        if e.lineno:
            e.lineno = at(e.lineno)
        if getattr(e, "end_lineno", None):
            e.end_lineno = at(e.end_lineno)
        raise
    for node in ast.walk(tree):
        if getattr(node, "lineno", None):
            node.lineno = at(node.lineno)
        if getattr(node, "end_lineno", None):
            node.end_lineno = at(node.end_lineno)
    return compile(tree, filename, mode, dont_inherit=True)
)",
               scope);
      return py::object(scope["compile_mapped"]);
    }());
    try {
      py::list lines;
      for (const int l : s.lines) lines.append(l);
      py::object code = compile_mapped(s.code, pyPath(model_path), expression ? "eval" : "exec", lines);
      return code.release().ptr();
    } catch (py::error_already_set& e) {
      e.restore();
      return nullptr;
    }
  }

  /// Reports the pending SyntaxError at its file:line:col; `indent` shifts inline columns.
  void syntaxError(core::Diagnostics& diags, const std::string& what, int indent) {
    py::error_already_set e;
    int line = 0, col = 0;
    std::string file = model_path, msg = e.what();
    if (e.matches(PyExc_SyntaxError)) {
      const py::object v = e.value();
      if (py::hasattr(v, "lineno") && !v.attr("lineno").is_none()) line = v.attr("lineno").cast<int>();
      if (py::hasattr(v, "offset") && !v.attr("offset").is_none()) col = v.attr("offset").cast<int>() + indent;
      if (py::hasattr(v, "filename") && !v.attr("filename").is_none()) file = bytesOf(v.attr("filename"));
      msg = bytesOf(v.attr("msg"));
    }
    diags.error({file, line, col}, "syntax error in " + what + ": " + msg);
  }

  /// Runs a .py file once in the model's globals; nullopt after reporting a problem.
  std::optional<bool> loadFile(const net::ScriptSpec& s, const std::string& what, core::Diagnostics& diags,
                               std::unordered_map<std::string, bool>& loaded) {
    const std::string path = (model_dir / s.file).string();
    if (auto it = loaded.find(path); it != loaded.end()) return it->second ? std::optional<bool>(true) : std::nullopt;
    loaded[path] = false;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      diags.error(s.loc, "cannot read the script file '" + s.file + "' of " + what + " (looked for " + core::escapeInvalidUtf8(path) + ")");
      return std::nullopt;
    }
    std::stringstream text;
    text << in.rdbuf();
    PyObject* code = Py_CompileString(text.str().c_str(), path.c_str(), Py_file_input);
    if (!code) {
      syntaxError(diags, what, 0);
      return std::nullopt;
    }
    py::object owned = py::reinterpret_steal<py::object>(code);
    PyObject* result = evalWatched(owned.ptr());
    if (!result) {
      const auto where = located(innermost());  // before the exception is cleared
      if (stoppedLate()) {
        diags.error(where, "the script file '" + s.file + "' of " + what + " " + lateText());
      } else if (const auto full = outOfMemory()) {
        diags.error(where, "the script file '" + s.file + "' of " + what + " " + *full);
      } else {
        diags.error(s.loc, "running the script file '" + s.file + "' failed:\n" + formatPending());
      }
      return std::nullopt;
    }
    Py_DECREF(result);
    loaded[path] = true;
    return true;
  }

  bool compile(const net::ScriptSpec& s, bool expression, const std::string& what, Compiled& out,
               core::Diagnostics& diags, std::unordered_map<std::string, bool>& loaded) {
    out.expression = expression;
    if (!s.file.empty()) {
      if (!loadFile(s, what, diags, loaded)) return false;
      if (s.function.empty()) return true;  // a globals file: running it was the point
      PyObject* fn = PyDict_GetItemString(globals.ptr(), s.function.c_str());
      if (!fn || !PyCallable_Check(fn)) {
        diags.error(s.loc, "the script file '" + s.file + "' defines no function '" + s.function + "' for " + what);
        return false;
      }
      out.function = py::reinterpret_borrow<py::object>(fn);
      return true;
    }
    PyObject* code = s.lines.empty() ? Py_CompileString(padded(s).c_str(), model_path.c_str(),
                                                        expression ? Py_eval_input : Py_file_input)
                                     : compileMapped(s, expression);
    if (!code) {
      syntaxError(diags, what, s.indent);
      return false;
    }
    const py::object owned = py::reinterpret_steal<py::object>(code);
    PyObject* fn = PyFunction_New(owned.ptr(), globals.ptr());
    if (!fn) {
      diags.error(s.loc, "cannot prepare " + what + ": " + formatPending());
      return false;
    }
    out.code = py::reinterpret_steal<py::object>(fn);
    return true;
  }

  // ---- running ----

  /// Runs module-level code (a script file) in the globals, under the watchdog.
  PyObject* evalWatched(PyObject* code) {
    watchdog->enter();
    PyObject* result = PyEval_EvalCode(code, globals.ptr(), globals.ptr());
    watchdog->leave();
    return result;
  }

  /// Runs inline code (Compiled::code: the globals script) under the watchdog.
  PyObject* runWatched(PyObject* code) {
    watchdog->enter();
    PyObject* result = PyObject_Vectorcall(code, nullptr, 0, nullptr);
    watchdog->leave();
    return result;
  }

  /// Whether the pending exception is the watchdog's stop; then clears it.
  bool stoppedLate() const {
    if (!PyErr_ExceptionMatches(PyExc_KeyboardInterrupt) || !watchdog->timedOut()) return false;
    PyErr_Clear();
    return true;
  }

  /// When the pending exception is a MemoryError from the script memory limit: how it is told
  /// ("ran out of memory: ..."), the exception cleared (which frees what the call's frames
  /// held). Else nullopt, the exception still pending.
  std::optional<std::string> outOfMemory() const {
    if (!detail::memoryLimitHit() || !PyErr_ExceptionMatches(PyExc_MemoryError)) return std::nullopt;
    detail::clearMemoryLimitHit();
    const detail::MemoryLimitLifted lifted;
    PyErr_Clear();
    return "ran out of memory: the scripts may take " + core::formatDouble(options.memory_mib) +
           " MiB (--script-memory)";
  }

  /// How a script that was stopped for running too long is told.
  std::string lateText() const {
    return "ran longer than the script timeout of " + core::formatDouble(options.timeout_s) + " s";
  }

  /// A place a traceback reached (innermost()), as a diagnostic location.
  core::SourceLoc located(const std::pair<std::string, int>& where) const {
    return {where.first.empty() ? model_path : where.first, where.second, 0};
  }

  /// The pending exception as a traceback text; clears it.
  static std::string formatPending() {
    py::error_already_set e;
    try {
      // the traceback without gdpn's own frames (internalFrame), as the user wrote the code
      py::object tb = py::module_::import("traceback");
      py::object te = tb.attr("TracebackException")(e.type(), e.value(), e.trace());
      py::list kept;
      for (auto f : te.attr("stack")) {
        if (!internalFrame(bytesOf(f.attr("filename")).c_str())) kept.append(f);
      }
      te.attr("stack") = tb.attr("StackSummary").attr("from_list")(kept);
      py::list lines(te.attr("format")());
      std::string text;
      // the bytes of the paths it names, shown escaped where they are not UTF-8
      for (auto line : lines) text += bytesOf(line);
      return core::escapeInvalidUtf8(text);
    } catch (const std::exception&) {
      return core::escapeInvalidUtf8(e.what());
    }
  }

  /// True for a frame of gdpn's own Python (code run by py::exec is named `<string>`): the
  /// user never wrote it, so neither the location nor the traceback names it.
  static bool internalFrame(const char* filename) { return !filename || filename[0] == '<'; }

  /// The innermost frame of the pending exception's traceback in the user's own code: the
  /// model file or a script file beside it (an exception raised inside gdpn's helpers,
  /// `item.nosuch` in on_enter, or inside Python's library is placed at the script line that
  /// called them); else the innermost frame of any file. File and line.
  std::pair<std::string, int> innermost() const {
    PyObject *type = nullptr, *value = nullptr, *tb = nullptr;
    PyErr_Fetch(&type, &value, &tb);
    PyErr_NormalizeException(&type, &value, &tb);
    std::pair<std::string, int> where{"", 0}, mine{"", 0};
    const std::string dir = model_dir.empty() ? std::string() : model_dir.string() + "/";
    for (PyObject* t = tb; t && t != Py_None;) {
      auto* frame = reinterpret_cast<PyTracebackObject*>(t);
      PyCodeObject* code = PyFrame_GetCode(frame->tb_frame);
      const std::string file = bytesOf(code->co_filename);
      if (!internalFrame(file.c_str()) || where.first.empty()) where = {file, frame->tb_lineno};
      if (file == model_path || (!dir.empty() && file.starts_with(dir))) mine = {file, frame->tb_lineno};
      Py_DECREF(code);
      t = reinterpret_cast<PyObject*>(frame->tb_next);
    }
    PyErr_Restore(type, value, tb);
    return mine.first.empty() ? where : mine;
  }

  std::string describe(ScriptKind kind, std::uint32_t id) const {
    switch (net::info(kind).owner) {
      case net::ScriptOwner::Transition: return "transition '" + net.transitionName(net::TransitionId{id}) + "'";
      case net::ScriptOwner::PlaceSlot: {
        const auto& ps = net.placeSlots()[id];
        return "place '" + net.placeName(ps.place) + "' slot " + net::slotName(ps.slot);
      }
      case net::ScriptOwner::Arc: {
        const auto& term = net.terms()[id];
        const auto& ps = net.placeSlots()[term.place_slot];
        return "arc '" + net.placeName(ps.place) + "' -> '" + net.transitionName(term.transition) +
               "' slot " + net::slotName(ps.slot);
      }
      case net::ScriptOwner::Model: return "the model";
    }
    return "the model";
  }

  /// Records the pending exception as the engine's halt.
  void fail(ScriptKind kind, std::uint32_t id) {
    const auto [file, line] = innermost();
    const std::string where =
        core::escapeInvalidUtf8(file.empty() ? model_path : file) + (line > 0 ? ":" + std::to_string(line) : "");
    // the model time too: a fault late in a long run is found again by running to it
    const std::string what = std::string(net::info(kind).key) + " of " + describe(kind, id) + " at t = " +
                             core::formatTime(kernel.now()) + " s";
    if (stoppedLate()) {
      halt = Halt::Timeout;
      message = where + ": error: " + what + " " + lateText();
      return;
    }
    if (interruptedByUser()) {
      PyErr_Clear();
      halt = Halt::Interrupted;
      message = where + ": error: " + what + " was interrupted (Ctrl-C)";
      return;
    }
    if (const auto full = outOfMemory()) {
      halt = Halt::Error;
      message = where + ": error: " + what + " " + *full;
      return;
    }
    halt = Halt::Error;
    message = where + ": error: " + what + " raised an exception\n" + formatPending();
  }

  /// Appends the shapes (geometries) of node `n` to `out`: itself if it is one, else those
  /// below it that belong to no other body.
  void shapesOf(const scene::Node& n, py::list& out) {
    if (n.type().category == scene::Category::Shape) out.append(nodeView(n.handle()));
    for (const auto& c : n.children()) {
      if (c->kind() != scene::NodeKind::Body) shapesOf(*c, out);
    }
  }

  /// on_enter/on_exit's `item`, as the dissertation has it: the geometries of what is in the
  /// region, those of `item` (what entered or left) first; its attributes are `item`'s.
  py::object itemList(scene::NodeHandle item, const std::vector<scene::NodeHandle>& inside) {
    if (!geometries) geometries = py::module_::import("gdpn_script").attr("Geometries");
    py::object out = geometries();
    py::list shapes;
    if (const scene::Node* n = sceneNode(item)) shapesOf(*n, shapes);
    for (auto h : inside) {
      if (h == item) continue;
      if (const scene::Node* n = sceneNode(h)) shapesOf(*n, shapes);
    }
    out.attr("extend")(shapes);
    out.attr("node") = nodeView(item);
    return out;
  }

  /// The key of the construct script (kind, id) belongs to: 2 t + 1 for transition t (its
  /// arcs' predicates and conditions included), 2 p for place p; -1 for the model.
  std::int64_t ownerKey(ScriptKind kind, std::uint32_t id) const {
    switch (net::info(kind).owner) {
      case net::ScriptOwner::Transition: return 2 * static_cast<std::int64_t>(id) + 1;
      case net::ScriptOwner::Arc: return 2 * static_cast<std::int64_t>(net.terms()[id].transition) + 1;
      case net::ScriptOwner::PlaceSlot: return 2 * static_cast<std::int64_t>(net.placeSlots()[id].place);
      case net::ScriptOwner::Model: return -1;
    }
    return -1;
  }

  /// The sensor slots construct `key` sees by bare name: a place's own; a transition's, those
  /// of the places its arcs touch (the first arc's where two share a name).
  const std::vector<std::pair<py::str, py::object>>& bareNames(std::int64_t key) {
    const auto k = static_cast<std::size_t>(key);
    if (k >= bare.size()) {
      bare.resize(k + 1);
      bare_known.resize(k + 1);
    }
    auto& names = bare[k];
    if (bare_known[k] || !callbacks.plant) return names;
    bare_known[k] = true;
    for (int s = 0; s < net::kSlotCount; ++s) {
      const auto slot = static_cast<net::SlotId>(s);
      const std::string* path = nullptr;
      if (key % 2 == 1) {
        path = &detail::sensorAround(net, net::TransitionId{key / 2}, slot);
      } else if (const auto ps = net.findPlaceSlot(net::PlaceId{key / 2}, slot)) {
        path = &net.sensorPath(*ps);
      }
      if (!path || path->empty()) continue;
      if (const scene::Node* sensor = callbacks.plant->find(*path)) {
        names.emplace_back(py::str(net::slotName(slot)), detail::makeSensorView(detail::refTo(*this), sensor->handle()));
      }
    }
    return names;
  }

  /// Binds the bare slot names of the construct script (kind, id) belongs to, unbinding the
  /// last construct's.
  void bindBare(ScriptKind kind, std::uint32_t id) {
    if (!any_bare && bound.empty()) return;
    const std::int64_t key = ownerKey(kind, id);
    if (key == bound_key) return;
    if (bound.empty() && (key < 0 || bareNames(key).empty())) {  // nothing to unbind, nothing to bind
      bound_key = key;
      return;
    }
    // what a slot name hid (a global of the model's, a sensor of that name) comes back
    for (auto it = bound.rbegin(); it != bound.rend(); ++it) {
      if (it->second) PyDict_SetItem(globals.ptr(), it->first.ptr(), it->second.ptr());
      else if (PyDict_DelItem(globals.ptr(), it->first.ptr()) < 0) PyErr_Clear();
    }
    bound.clear();
    bound_key = key;
    if (key < 0) return;
    for (const auto& [name, view] : bareNames(key)) {
      bound.emplace_back(name, py::reinterpret_borrow<py::object>(PyDict_GetItem(globals.ptr(), name.ptr())));
      PyDict_SetItem(globals.ptr(), name.ptr(), view.ptr());
    }
  }

  /// Runs script `index` for construct (kind, id); returns its value (expressions) or None.
  /// On failure records the halt and returns null.
  /// Calls script `index`; a function gets (self), (self, token) or (self, value) / (self,
  /// items, item); inline code sees them as names.
  PyObject* call(std::int32_t index, ScriptKind kind, std::uint32_t id, PyObject* self, PyObject* token,
                 PyObject* value = nullptr, PyObject* items = nullptr) {
    const Compiled& c = compiled[static_cast<std::size_t>(index)];
    bindBare(kind, id);
    watchdog->enter();
    PyObject* result = nullptr;
    if (c.function && items) {
      result = PyObject_CallFunctionObjArgs(c.function.ptr(), self, items, value, nullptr);
    } else if (c.function && value) {
      result = PyObject_CallFunctionObjArgs(c.function.ptr(), self, value, nullptr);
    } else if (c.function) {
      result = token ? PyObject_CallFunctionObjArgs(c.function.ptr(), self, token, nullptr)
                     : PyObject_CallOneArg(c.function.ptr(), self);
    } else {
      PyDict_SetItem(globals.ptr(), key_self.ptr(), self);
      if (token) PyDict_SetItem(globals.ptr(), key_token.ptr(), token);
      if (items) PyDict_SetItem(globals.ptr(), key_item.ptr(), value);
      result = PyObject_Vectorcall(c.code.ptr(), nullptr, 0, nullptr);
    }
    watchdog->leave();
    if (!result) fail(kind, id);
    return result;
  }

  /// A sensor handler: on_enter/on_exit get (items, item); on_sample gets items (Region) or
  /// the sensor; on_change gets the sensor's value.
  void runSensor(std::int32_t index, ScriptKind kind, std::uint32_t id, PyObject* self, bool with_item, PyObject* items,
                 PyObject* arg) {
    if (index < 0 || halt != Halt::None) return;
    PyObject* r = with_item ? call(index, kind, id, self, nullptr, arg, items) : call(index, kind, id, self, nullptr, arg);
    Py_XDECREF(r);
  }

  void run(ScriptKind kind, std::uint32_t id, PyObject* self, PyObject* token) {
    const std::int32_t index = indexOf(net, kind, id);
    if (index < 0 || halt != Halt::None) return;
    PyObject* r = call(index, kind, id, self, token);
    Py_XDECREF(r);
  }

  bool test(ScriptKind kind, std::uint32_t id, PyObject* self, PyObject* token, PyObject* value = nullptr) {
    const std::int32_t index = indexOf(net, kind, id);
    if (index < 0) return true;
    if (halt != Halt::None) return false;
    PyObject* r = value ? call(index, kind, id, self, nullptr, value) : call(index, kind, id, self, token);
    if (!r) return false;
    const int truth = PyObject_IsTrue(r);
    Py_DECREF(r);
    if (truth < 0) {
      fail(kind, id);
      return false;
    }
    return truth == 1;
  }
};

Engine::Engine(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}

Engine::~Engine() {
  if (!impl_) return;
  impl_->watchdog.reset();
  // drop Python references while the interpreter is certainly alive
  py::gil_scoped_acquire gil;
  impl_->compiled.clear();
  impl_->expressions.clear();
  impl_->transition_views.clear();
  impl_->place_views.clear();
  impl_->node_views.clear();
  impl_->bare.clear();
  impl_->bare_known.clear();
  impl_->bound.clear();
  impl_->geometries = py::object();
  impl_->sim = py::object();
  impl_->params_view = py::object();
  impl_->globals.clear();
  impl_->globals = py::dict();
  impl_.reset();
}

std::unique_ptr<Engine> Engine::create(const net::Net& net, net::Kernel& kernel, const std::string& model_path,
                                       EngineOptions options, EngineCallbacks callbacks, core::Diagnostics& diags) {
  startInterpreter();
  py::gil_scoped_acquire gil;
  detail::registerViews();
  if (options.timeout_s > 0) installStopHandler();

  auto impl = std::make_shared<Impl>(net, kernel);
  impl->model_path = model_path;
  impl->model_dir = std::filesystem::path(model_path).parent_path();
  impl->options = options;
  impl->callbacks = std::move(callbacks);
  // the watchdog is there before the first script runs: the globals are watched too
  impl->watchdog = std::make_unique<Watchdog>(options.timeout_s, options.grace_s, [impl = impl.get()] {
    std::fprintf(stderr, "%s: error: a script %s and did not stop within %s s more; the process ends\n",
                 core::escapeInvalidUtf8(impl->model_path).c_str(), impl->lateText().c_str(), core::formatDouble(impl->options.grace_s).c_str());
    std::fflush(stderr);
    std::_Exit(1);
  });
  if (options.memory_mib > 0) {
    // the scripts' share on top of what Python holds now (a notebook's own data is not theirs)
    detail::installMemoryLimit();
    const double share = options.memory_mib * 1024.0 * 1024.0;
    impl->watchdog->capMemory(std::max<std::int64_t>(
        1, detail::memoryHeld() + static_cast<std::int64_t>(std::min(share, 4.0e18))));
  }
  // no construct sees a slot by bare name where no place slot reads a sensor of a plant
  impl->any_bare = false;
  for (std::uint32_t ps = 0; impl->callbacks.plant && ps < net.placeSlots().size(); ++ps) {
    if (!net.sensorPath(net::PlaceSlotId{ps}).empty()) impl->any_bare = true;
  }
  impl->transition_views.resize(net.transitions().size());
  impl->place_views.resize(net.places().size());
  impl->node_views.resize(net.nodeNames().size());
  impl->globals["__builtins__"] = py::reinterpret_borrow<py::object>(PyEval_GetBuiltins());
  impl->globals["__name__"] = "gdpn_model";
  impl->sim = detail::makeSimView(detail::refTo(*impl));
  impl->globals["sim"] = impl->sim;
  // every named sensor of the plant is a variable of its name ("token in gate.items")
  if (impl->callbacks.plant) {
    scene::traverse(impl->callbacks.plant->root(), [&](scene::Node& n, const scene::TraversalState&) {
      if (n.type().category == scene::Category::Sensor && core::isIdentifier(n.name()) &&
          !impl->globals.contains(n.name().c_str())) {
        impl->globals[py::str(n.name())] = detail::makeSensorView(detail::refTo(*impl), n.handle());
      }
    }, {}, scene::Templates::Skip);
  }

  // name each script by its first user ("pre_fire of transition 'main/T'"); guards and
  // predicates are expressions, the rest statements
  const auto scripts = net.scripts();
  const auto& index = net.scriptIndex();
  std::vector<std::optional<ScriptKind>> kind(scripts.size());
  std::vector<std::string> names(scripts.size());
  auto name = [&](ScriptKind k, std::uint32_t id) {
    const std::int32_t i = indexOf(net, k, id);
    if (i < 0 || kind[static_cast<std::size_t>(i)]) return;
    kind[static_cast<std::size_t>(i)] = k;
    names[static_cast<std::size_t>(i)] = std::string(net::info(k).key) + " of " + impl->describe(k, id);
  };
  for (std::uint32_t t = 0; t < index.transitions.size(); ++t) {
    for (const ScriptKind k : net::kTransitionScripts) name(k, t);
  }
  for (std::uint32_t ps = 0; ps < index.slots.size(); ++ps) {
    for (const ScriptKind k : net::kSlotScripts) name(k, ps);
  }
  for (std::uint32_t term = 0; term < index.predicates.size(); ++term) {
    name(net.terms()[term].kind == net::TermKind::Condition ? ScriptKind::Condition : ScriptKind::Predicate, term);
  }
  impl->compiled.resize(scripts.size());
  std::unordered_map<std::string, bool> loaded;
  bool ok = true;
  const auto g = net.globalsScript();
  if (g >= 0) {
    auto& c = impl->compiled[static_cast<std::size_t>(g)];
    ok = impl->compile(scripts[static_cast<std::size_t>(g)], false, "the globals script", c, diags, loaded);
    if (ok && c.code) {
      PyObject* r = impl->runWatched(c.code.ptr());
      if (!r) {
        const auto where = impl->located(impl->innermost());
        if (impl->stoppedLate()) {
          diags.error(where, "the globals script " + impl->lateText());
        } else if (const auto full = impl->outOfMemory()) {
          diags.error(where, "the globals script " + *full);
        } else {
          diags.error(where, "the globals script raised an exception\n" + Impl::formatPending());
        }
        ok = false;
      }
      Py_XDECREF(r);
    }
  }
  for (std::size_t i = 0; i < scripts.size(); ++i) {
    if (static_cast<std::int32_t>(i) == g || !kind[i]) continue;
    ok = impl->compile(scripts[i], net::info(*kind[i]).expression, names[i], impl->compiled[i], diags, loaded) && ok;
  }
  if (!ok) {
    impl->compiled.clear();
    return nullptr;
  }
  return std::unique_ptr<Engine>(new Engine(std::move(impl)));
}

bool Engine::guard(net::TransitionId t) {
  return impl_->test(ScriptKind::Guard, t, impl_->transitionSelf(t), nullptr);
}

bool Engine::eligible(net::TermId term, net::NodeRef token) {
  const auto t = impl_->net.terms()[term].transition;
  return impl_->test(ScriptKind::Predicate, term, impl_->transitionSelf(t), impl_->nodeView(token).ptr());
}

void Engine::preFire(net::TransitionId t) {
  impl_->run(ScriptKind::PreFire, t, impl_->transitionSelf(t), nullptr);
}

void Engine::inFire(net::TransitionId t) {
  impl_->run(ScriptKind::InFire, t, impl_->transitionSelf(t), nullptr);
}

void Engine::postFire(net::TransitionId t) {
  impl_->run(ScriptKind::PostFire, t, impl_->transitionSelf(t), nullptr);
}

void Engine::onDeposit(net::PlaceSlotId ps, const net::NodeRef* token) {
  const auto place = impl_->net.placeSlots()[ps].place;
  py::object tok = token ? impl_->nodeView(*token) : py::none();
  impl_->run(ScriptKind::OnDeposit, ps, impl_->placeSelf(place), tok.ptr());
}

void Engine::onRemove(net::PlaceSlotId ps, const net::NodeRef* token) {
  const auto place = impl_->net.placeSlots()[ps].place;
  py::object tok = token ? impl_->nodeView(*token) : py::none();
  impl_->run(ScriptKind::OnRemove, ps, impl_->placeSelf(place), tok.ptr());
}

bool Engine::condition(net::TermId term, scene::NodeHandle sensor) {
  const auto& net = impl_->net;
  const auto& t = net.terms()[term];
  py::object view = detail::makeSensorView(detail::refTo(*impl_), sensor);
  // the sensor is seen as `value` and under its slot's name ("c0"), even where another arc
  // of the transition has a sensor slot of that name; the next script binds afresh
  impl_->bindBare(ScriptKind::Condition, term);
  const py::str name(net::slotName(net.placeSlots()[t.place_slot].slot));
  auto& bound = impl_->bound;
  if (std::none_of(bound.begin(), bound.end(), [&](const auto& b) { return b.first.equal(name); })) {
    bound.emplace_back(name, py::reinterpret_borrow<py::object>(PyDict_GetItem(impl_->globals.ptr(), name.ptr())));
  }
  impl_->globals[name] = view;
  impl_->globals["value"] = view;
  const bool holds =
      impl_->test(ScriptKind::Condition, term, impl_->transitionSelf(t.transition), nullptr, view.ptr());
  impl_->bound_key = -2;
  return holds;
}

void Engine::sensorEvent(net::PlaceSlotId ps, ScriptKind kind, scene::NodeHandle sensor, scene::NodeHandle item) {
  const auto& net = impl_->net;
  const auto index = indexOf(net, kind, ps);
  if (index < 0) return;
  py::object view = detail::makeSensorView(detail::refTo(*impl_), sensor);
  const auto& r = impl_->reading(sensor);
  py::list items;
  for (auto h : r.items()) items.append(impl_->nodeView(h));
  // on_change sees the sensor's value (its main number; the sensor is under its slot's name),
  // the others the sensor
  py::object value = kind == ScriptKind::OnChange ? view.attr("value") : view;
  impl_->globals["items"] = items;
  impl_->globals["value"] = value;
  const bool with_item = kind == ScriptKind::OnEnter || kind == ScriptKind::OnExit;
  py::object arg = with_item ? impl_->itemList(item, r.items())
                             : (kind == ScriptKind::OnSample && !r.items().empty() ? py::object(items) : value);
  impl_->runSensor(index, kind, ps, impl_->placeSelf(net.placeSlots()[ps].place), with_item, items.ptr(),
                   arg.ptr());
}

bool Engine::halted() const { return impl_->halt != Halt::None; }
namespace {

/// A figure's number: an int or a float (numpy's too), not a bool; nullopt for anything else.
std::optional<double> figureNumber(py::handle x) {
  if (PyBool_Check(x.ptr()) || PyUnicode_Check(x.ptr()) || PyBytes_Check(x.ptr())) return std::nullopt;
  if (!PyLong_Check(x.ptr()) && !PyFloat_Check(x.ptr()) && !PyObject_HasAttrString(x.ptr(), "__float__")) {
    return std::nullopt;
  }
  const double v = PyFloat_AsDouble(x.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    return std::nullopt;
  }
  return v;
}

/// True for a Python int (numpy's too) that a double holds exactly.
bool wholeFigure(py::handle x, double v) {
  return (PyLong_Check(x.ptr()) || PyObject_HasAttrString(x.ptr(), "__index__")) && std::abs(v) < 9.0e15;
}

/// The text of a figure's number: a whole number in full, others to 4 significant digits
/// (the figures are read by people; the report keeps the number itself).
std::string figureText(py::handle x, double v) {
  if (wholeFigure(x, v)) return py::str(x);
  char buf[64];
  const bool wide = std::abs(v) >= 1e4 && std::abs(v) < 1e15;
  std::snprintf(buf, sizeof buf, wide ? "%.0f" : "%.4g", v);
  return buf;
}

}  // namespace

std::vector<Figure> Engine::summary(std::string& error) {
  std::vector<Figure> out;
  try {
    if (!impl_->globals.contains("summary")) return out;
    py::object f = impl_->globals["summary"];
    if (!PyCallable_Check(f.ptr())) return out;
    // watched like any script: the guard leaves before the exception is formatted; it sees
    // the model's names, no construct's slots
    impl_->bindBare(ScriptKind::Globals, 0);
    const Watched watched(*impl_->watchdog);
    py::object result = f();
    if (!py::isinstance<py::dict>(result)) {
      error = "summary() must return a dict of figures, not " + std::string(py::str(py::type::of(result).attr("__name__")));
      return out;
    }
    for (auto item : py::reinterpret_borrow<py::dict>(result)) {
      Figure fig;
      fig.label = py::str(item.first);
      py::handle v = item.second;
      // (number, "unit")
      if (PyTuple_Check(v.ptr()) && PyTuple_Size(v.ptr()) == 2 && PyUnicode_Check(PyTuple_GetItem(v.ptr(), 1)) &&
          figureNumber(PyTuple_GetItem(v.ptr(), 0))) {
        fig.unit = py::str(PyTuple_GetItem(v.ptr(), 1));
        v = PyTuple_GetItem(v.ptr(), 0);
      }
      const auto number = figureNumber(v);
      if (number && std::isfinite(*number)) {
        fig.value = *number;
        fig.integer = wholeFigure(v, *number);
        fig.text = figureText(v, *number) + (fig.unit.empty() ? "" : " " + fig.unit);
      } else {
        fig.text = py::str(item.second);
        fig.unit.clear();
      }
      out.push_back(std::move(fig));
    }
  } catch (const py::error_already_set& e) {
    const bool late = e.matches(PyExc_KeyboardInterrupt) && impl_->watchdog->timedOut();
    error = late ? "summary() " + impl_->lateText() : std::string("summary() failed: ") + e.what();
  }
  return out;
}

bool Engine::evaluateWith(const std::string& expression, const char* source, std::string& error,
                          const std::function<bool(void*)>& read) {
  // each expression is compiled once
  auto& code = impl_->expressions[expression];
  if (!code) {
    PyObject* c = Py_CompileString(expression.c_str(), source, Py_eval_input);
    if (!c) {
      error = Impl::formatPending();
      impl_->expressions.erase(expression);
      return false;
    }
    code = py::reinterpret_steal<py::object>(c);
  }
  // the script timeout and Ctrl-C reach an expression as they reach any script; it sees the
  // model's names, no construct's slots
  impl_->bindBare(ScriptKind::Globals, 0);
  impl_->watchdog->enter();
  PyObject* r = PyEval_EvalCode(code.ptr(), impl_->globals.ptr(), impl_->globals.ptr());
  const bool ok = r != nullptr && read(r);
  impl_->watchdog->leave();
  Py_XDECREF(r);
  if (ok) return true;
  if (impl_->stoppedLate()) {
    error = "it " + impl_->lateText();
    return false;
  }
  if (interruptedByUser()) {
    PyErr_Clear();
    error = "it was interrupted (Ctrl-C)";
    return false;
  }
  error = Impl::formatPending();
  return false;
}

std::optional<bool> Engine::evaluate(const std::string& expression, std::string& error) {
  bool truth = false;
  const bool ok = evaluateWith(expression, "<breakpoint>", error, [&](void* result) {
    auto* r = static_cast<PyObject*>(result);
    const int t = PyObject_IsTrue(r);
    truth = t == 1;
    return t >= 0;
  });
  if (!ok) return std::nullopt;
  return truth;
}

std::optional<double> Engine::evaluateNumber(const std::string& expression, std::string& error) {
  double value = 0.0;
  const bool ok = evaluateWith(expression, "<signal>", error, [&](void* result) {
    auto* r = static_cast<PyObject*>(result);
    if (PyUnicode_Check(r) || PyBytes_Check(r) || !(PyLong_Check(r) || PyFloat_Check(r) || PyObject_HasAttrString(r, "__float__"))) {
      PyErr_Format(PyExc_TypeError, "a signal is a number, not %s", Py_TYPE(r)->tp_name);
      return false;
    }
    value = PyFloat_AsDouble(r);
    return !PyErr_Occurred();
  });
  if (!ok) return std::nullopt;
  return value;
}

Halt Engine::halt() const { return impl_->halt; }
const std::string& Engine::message() const { return impl_->message; }

}  // namespace gdpn::script
