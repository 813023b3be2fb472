// The script timeout (semantics §8): a script that does not return is stopped, wherever it
// waits (a sleep, a blocking read, a lock), however it runs (a hook, the globals, a script
// file, a breakpoint's predicate) and even when it catches the stop; the run ends as a script
// error located at the script's line, its trace kept.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <tuple>
#include <utility>
#include <vector>

#include "gdpn/model/report.h"
#include "gdpn/model/simulation.h"
#include "gdpn/session/session.h"
#include "script/script_model.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

using ::testing::HasSubstr;
using testing::ScriptModel;
using clock = std::chrono::steady_clock;

/// Seconds since `start`.
double since(clock::time_point start) { return std::chrono::duration<double>(clock::now() - start).count(); }

/// A model whose one transition T runs `pre_fire` (lines from 9 on) when it starts and whose
/// place Q runs `on_deposit` (lines from 14 on) when T completes.
std::string hooks(const std::string& pre_fire, const std::string& on_deposit = "pass") {
  auto indent = [](const std::string& code) {
    std::string out;
    std::istringstream lines(code);
    for (std::string line; std::getline(lines, line);) out += "          " + line + "\n";
    return out;
  };
  return "gdpn: 1\n"                 // 1
         "settings: {dt: 1, until: 5}\n"  // 2
         "pages:\n"                  // 3
         "  main:\n"                 // 4
         "    arcs: [P -> T, T -> Q]\n"  // 5
         "    transitions:\n"        // 6
         "      T:\n"                // 7
         "        pre_fire: |\n" +   // 8
         indent(pre_fire) +          // 9...
         "    places:\n"
         "      P: {tokens: 3}\n"
         "      Q:\n"
         "        on_deposit: |\n" +
         indent(on_deposit);
}

/// The outcome of running `text` with the script timeout `timeout_s`, the trace it wrote, and
/// the seconds it took.
struct Timed {
  RunOutcome outcome;
  std::string trace;
  double seconds = 0;
};
Timed runTimed(const ScriptModel& m, double timeout_s) {
  core::Diagnostics diags;
  auto sim = m.open(diags, timeout_s);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto start = clock::now();
  Timed t;
  t.outcome = sim->run({});
  t.seconds = since(start);
  t.trace = trace.str();
  return t;
}

/// Seconds within which a stopped script must have ended: far below the 100 s its sleep would
/// take, and far above what the stop takes on a loaded machine under the sanitizers (a run
/// there once took 4.4 s), so that the tests say whether it was stopped, not how fast.
constexpr double kStoppedWithin = 30.0;

/// How a stop for running too long is told: "`what` ran longer than ... `timeout` s".
std::string late(const std::string& what, const std::string& timeout) {
  return what + " ran longer than the script timeout of " + timeout + " s";
}

/// Expects the run to have ended within a few seconds as a timeout of `what`, located at
/// `file:line`, with the trace ending in the error.
void expectTimedOut(const Timed& t, const std::string& where, const std::string& what, const std::string& timeout) {
  EXPECT_EQ(t.outcome.reason, StopReason::ScriptError);
  EXPECT_EQ(t.outcome.message, where + ": error: " + late(what, timeout));
  EXPECT_LT(t.seconds, kStoppedWithin);
  EXPECT_THAT(t.trace, HasSubstr("\"ev\":\"error\""));
}

TEST(ScriptTimeout, StopsAPreFireSleepingInACall) {
  ScriptModel m(hooks("sim.log('start')\nimport time\ntime.sleep(100)"));
  const auto t = runTimed(m, 0.3);
  expectTimedOut(t, m.path() + ":11", "pre_fire of transition 'main/T' at t = 0 s", "0.3");
  EXPECT_EQ(testing::logLines(t.trace), std::vector<std::string>{"start"});
}

TEST(ScriptTimeout, StopsAnOnDepositBlockedReadingOrWaiting) {
  // a pipe and a socket nobody writes to, a lock nobody releases, an event nobody sets
  for (const std::string call : {"import os\nr, w = os.pipe()\nos.read(r, 1)",
                                 "import socket\na, b = socket.socketpair()\na.recv(1)",
                                 "import select, os\nr, w = os.pipe()\nselect.select([r], [], [])",
                                 "import threading\nlock = threading.Lock()\nlock.acquire()\nlock.acquire()",
                                 "import threading\nthreading.Event().wait()"}) {
    SCOPED_TRACE(call);
    ScriptModel m(hooks("pass", call));
    const auto t = runTimed(m, 0.3);
    const int last = 14 + static_cast<int>(std::count(call.begin(), call.end(), '\n'));
    // a wait inside Python's library (threading.py) is located at the script's line that
    // called it: the model file's
    expectTimedOut(t, m.path() + ":" + std::to_string(last), "on_deposit of place 'main/Q' slot a0 at t = 1 s", "0.3");
  }
}

TEST(ScriptTimeout, StopsAScriptThatSwallowsTheStop) {
  for (const std::string loop : {"import time\nwhile True:\n  try: time.sleep(1)\n  except BaseException: pass",
                                 "while True:\n  try:\n    while True: pass\n  except BaseException: pass",
                                 "import time\nwhile True:\n  try: time.sleep(1)\n  except BaseException:\n"
                                 "    time.sleep(100)",
                                 "import time\ndef f():\n  while True:\n    try: time.sleep(1)\n"
                                 "    except BaseException: continue\nf()",
                                 "import time\nwhile True:\n  try: time.sleep(1)\n  finally: time.sleep(100)"}) {
    SCOPED_TRACE(loop);
    ScriptModel m(hooks(loop));
    const auto t = runTimed(m, 0.3);
    EXPECT_EQ(t.outcome.reason, StopReason::ScriptError);
    EXPECT_EQ(t.outcome.message.rfind(m.path() + ":", 0), 0u) << t.outcome.message;
    EXPECT_THAT(t.outcome.message, HasSubstr(": error: " + late("pre_fire of transition 'main/T' at t = 0 s", "0.3")));
    EXPECT_LT(t.seconds, kStoppedWithin);
    EXPECT_THAT(t.trace, HasSubstr("\"ev\":\"error\""));
  }
}

TEST(ScriptTimeout, StopsTheGlobalsScriptAndLocatesIt) {
  ScriptModel m("gdpn: 1\nscripts:\n  globals: |\n    import time\n    time.sleep(100)\n"
                "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  core::Diagnostics diags;
  const auto start = clock::now();
  EXPECT_FALSE(m.open(diags, 0.5));
  EXPECT_LT(since(start), kStoppedWithin);
  EXPECT_EQ(diags.str(), m.path() + ":5: error: " + late("the globals script", "0.5") + "\n");
}

TEST(ScriptTimeout, StopsTheTopLevelOfAScriptFile) {
  ScriptModel m("gdpn: 1\nscripts:\n  globals: {file: cell.py}\npages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  m.addFile("cell.py", "import time\n\nwhile True:\n    try:\n        time.sleep(1)\n    except KeyboardInterrupt:\n"
                       "        pass\n");
  core::Diagnostics diags;
  const auto start = clock::now();
  EXPECT_FALSE(m.open(diags, 0.3));
  EXPECT_LT(since(start), kStoppedWithin);
  const std::string file = (std::filesystem::path(m.path()).parent_path() / "cell.py").string();
  EXPECT_EQ(diags.str().rfind(file + ":", 0), 0u) << diags.str();
  EXPECT_THAT(diags.str(), HasSubstr(": error: " + late("the script file 'cell.py' of the globals script", "0.3")));
}

TEST(ScriptTimeout, ASleepingSummaryGivesAFiguresErrorAndTheReport) {
  ScriptModel m("gdpn: 1\nscripts:\n  globals: |\n    def summary():\n        import time\n        time.sleep(100)\n"
                "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  core::Diagnostics diags;
  auto sim = m.open(diags, 0.3);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  const auto start = clock::now();
  const auto report = makeReport(*sim, outcome);
  EXPECT_LT(since(start), kStoppedWithin);
  EXPECT_TRUE(report.figures.empty());
  EXPECT_EQ(report.figures_error, late("summary()", "0.3"));
}

TEST(ScriptTimeout, APredicateBreakpointThatSleepsEndsTheRunNamingIt) {
  core::Diagnostics diags;
  const std::string path = "/examples/basics/producer_consumer/producer_consumer.gdpn.yaml";
  auto model = loadModel(std::string(GDPN_SOURCE_DIR) + path, diags);
  ASSERT_TRUE(model) << diags.str();
  auto s = session::Session::create(std::move(*model), diags, {std::nullopt, {0.3, 0}, {}, {}});
  ASSERT_TRUE(s) << diags.str();
  std::string why;
  ASSERT_TRUE(s->addBreakpoint(session::Breakpoint::predicate("__import__('time').sleep(100)"), why)) << why;
  const auto start = clock::now();
  const auto outcome = s->run({{}, 100});
  EXPECT_LT(since(start), kStoppedWithin);
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_EQ(outcome.steps, 0);
  EXPECT_THAT(outcome.message, HasSubstr("breakpoint 1 (__import__('time').sleep(100)) failed: " + late("it", "0.3")));
}

TEST(ScriptTimeout, ScriptsThatReturnInTimeRunToTheEndAndLeaveNoTracer) {
  // blocking calls that return, under a timeout and without one; then, after a run that
  // timed out, a run without a timeout in the same process: no late stop reaches it
  const std::string pre_fire = "import os, sys, time\nr, w = os.pipe()\nos.write(w, b'x')\nos.read(r, 1)\n"
                               "time.sleep(0.05)\nsim.log('start', sys.gettrace() is None)";
  const std::string text = hooks(pre_fire, "sim.log('deposit')\nimport time\ntime.sleep(0.02)");
  const std::vector<std::string> expected = {"start True", "deposit", "start True",
                                             "deposit",    "start True", "deposit"};
  for (const double timeout : {0.0, 1.0}) {
    SCOPED_TRACE(timeout);
    ScriptModel m(text);
    const auto t = runTimed(m, timeout);
    EXPECT_EQ(t.outcome.reason, StopReason::Dead) << t.outcome.message;
    EXPECT_EQ(testing::logLines(t.trace), expected);
  }
  ScriptModel late(hooks("import time\nwhile True:\n  try: time.sleep(1)\n  except BaseException: pass"));
  EXPECT_EQ(runTimed(late, 0.2).outcome.reason, StopReason::ScriptError);
  ScriptModel m(text);
  const auto t = runTimed(m, 0.0);
  EXPECT_EQ(t.outcome.reason, StopReason::Dead) << t.outcome.message;
  EXPECT_EQ(testing::logLines(t.trace), expected);
}

#ifdef GDPN_CLI
/// Runs the gdpn program with `args`: its exit code, and its stdout and stderr together.
std::pair<int, std::string> cli(const std::string& args, const ScriptModel& m) {
  const std::string out = m.path() + ".out";
  const int status = std::system(("'" + std::string(GDPN_CLI) + "' " + args + " > '" + out + "' 2>&1").c_str());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

TEST(ScriptTimeout, CheckStopsASleepingGlobalsScriptAndSaysWhere) {
  ScriptModel m("gdpn: 1\nscripts:\n  globals: |\n    import time\n    time.sleep(100)\n"
                "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  const auto start = clock::now();
  const auto [code, out] = cli("check --script-timeout 0.5 '" + m.path() + "'", m);
  EXPECT_LT(since(start), kStoppedWithin);
  EXPECT_EQ(code, 1);
  EXPECT_EQ(out, m.path() + ":5: error: " + late("the globals script", "0.5") + "\n1 error\n");
}

TEST(ScriptTimeout, WithoutTheOptionCheckStillStopsAGlobalsScriptThatNeverEnds) {
  // the default bound (script::kDefaultScriptTimeout): `gdpn check` of a model whose globals
  // script loops for ever ends, located, instead of hanging
  ScriptModel m("gdpn: 1\nscripts:\n  globals: |\n    n = 0\n    while True:\n      n += 1\n"
                "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  const auto start = clock::now();
  const auto [code, out] = cli("check '" + m.path() + "'", m);
  EXPECT_LT(since(start), 60.0);
  EXPECT_EQ(code, 1);
  EXPECT_THAT(out, HasSubstr(": error: " + late("the globals script", "10")));
}

TEST(ScriptMemory, AScriptThatTakesMemoryWithoutEndStopsOutOfMemoryAtItsLine) {
  // big blocks (Python's raw allocator) and small objects (its arenas) alike
  for (const std::string grow : {"x.append(bytearray(1 << 20))", "x.append([object() for _ in range(1000)])"}) {
    ScriptModel m(hooks("x = []\nwhile True:\n    " + grow));
    const auto [code, out] = cli("run -q --script-memory 64 '" + m.path() + "'", m);
    EXPECT_EQ(code, 1) << out;
    EXPECT_THAT(out, HasSubstr(m.path() + ":11: error: pre_fire of transition 'main/T' at t = 0 s ran out of memory: "
                               "the scripts may take 64 MiB (--script-memory)"));
  }
}

TEST(ScriptMemory, AScriptThatCatchesTheRefusalIsStoppedByTheTimeout) {
  ScriptModel m(hooks("x = []\nwhile True:\n    try: x.append(bytearray(1 << 20))\n    except MemoryError: pass"));
  const auto [code, out] = cli("run -q --script-memory 32 --script-timeout 0.5 '" + m.path() + "'", m);
  EXPECT_EQ(code, 1) << out;
  EXPECT_THAT(out, HasSubstr(late("pre_fire of transition 'main/T' at t = 0 s", "0.5")));
}

TEST(ScriptMemory, TheGlobalsScriptIsBoundAndScriptsWithinTheBoundRunOn) {
  ScriptModel m("gdpn: 1\nscripts:\n  globals: |\n    keep = [bytearray(1 << 20) for _ in range(8)]\n"
                "    more = [bytearray(1 << 20) for _ in range(100)]\n"
                "pages:\n  main:\n    places:\n      P: {tokens: 1}\n");
  auto [code, out] = cli("check --script-memory 50 '" + m.path() + "'", m);
  EXPECT_EQ(code, 1);
  EXPECT_THAT(out, HasSubstr(m.path() + ":5: error: the globals script ran out of memory"));
  std::tie(code, out) = cli("check --script-memory 200 '" + m.path() + "'", m);
  EXPECT_EQ(code, 0) << out;
}

TEST(ScriptTimeout, RunStopsASwallowingScriptAndKeepsTheTrace) {
  ScriptModel m(
      hooks("sim.log('start')\nimport time\nwhile True:\n  try: time.sleep(1)\n  except BaseException: pass"));
  const std::string trace = m.path() + ".jsonl";
  const auto start = clock::now();
  // located where the stop came last: in the except clause that swallowed the first
  const auto [code, out] = cli("run -q --script-timeout 0.3 --trace '" + trace + "' '" + m.path() + "'", m);
  EXPECT_LT(since(start), kStoppedWithin);
  EXPECT_EQ(code, 1);
  EXPECT_THAT(out, HasSubstr(m.path() + ":13: error: " + late("pre_fire of transition 'main/T' at t = 0 s", "0.3")));
  std::ifstream in(trace);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(testing::logLines(text.str()), std::vector<std::string>{"start"});
  EXPECT_THAT(text.str(), HasSubstr("\"ev\":\"error\""));
}
#endif

TEST(ScriptTimeoutDeathTest, ACallStuckWhereNoSignalReachesItEndsTheProcessAfterTheGrace) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // the script blocks every real-time signal, so the stop cannot reach its sleep
  ScriptModel m(hooks("import signal, time\nsignal.pthread_sigmask(signal.SIG_BLOCK, "
                      "range(signal.SIGRTMIN, signal.SIGRTMAX + 1))\ntime.sleep(100)"));
  EXPECT_EXIT(
      {
        core::Diagnostics diags;
        auto sim = m.open(diags, 0.2);
        if (sim) sim->run({});
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(1),
      "error: a script ran longer than the script timeout of 0.2 s and did not stop within 2 s more; the process ends");
}

}  // namespace
}  // namespace gdpn::model
