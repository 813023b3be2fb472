// Scripts on transitions, places and arcs (semantics §3, §4, §6, §8), run through Simulation.
// Scripts report through sim.log, which the tests read back from the trace.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "script/script_model.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

namespace fs = std::filesystem;
using testing::ScriptModel;

/// Runs `sim` and returns the text of its sim.log lines and the outcome.
std::pair<std::vector<std::string>, RunOutcome> runLogs(Simulation& sim, RunLimits limits = {}) {
  std::ostringstream trace;
  sim.traceTo(trace);
  const auto outcome = sim.run(limits);
  return {testing::logLines(trace.str()), outcome};
}

/// Runs the model and returns the text of its sim.log lines and the outcome.
std::pair<std::vector<std::string>, RunOutcome> runLogs(const ScriptModel& model, RunLimits limits = {}) {
  core::Diagnostics diags;
  auto sim = model.open(diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  return runLogs(*sim, limits);
}

TEST(Scripts, HooksRunInTheOrderOfTheStep) {
  // T takes a token from P (on_remove), starts (pre_fire), occurs for 2 steps (in_fire each
  // step), completes (post_fire) and deposits on Q (on_deposit). U waits on its guard.
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 4}
pages:
  main:
    places:
      P:
        tokens: 1
        on_remove: 'sim.log(sim.step, "on_remove", self.name)'
      Q:
        on_deposit: 'sim.log(sim.step, "on_deposit", self.name, self.a0.get())'
    transitions:
      T:
        duration: 2
        guard: 'sim.log(sim.step, "guard", self.name) or True'
        pre_fire: 'sim.log(sim.step, "pre_fire", self.a0.get())'
        in_fire: 'sim.log(sim.step, "in_fire", self.elapsed, self.progress)'
        post_fire: 'sim.log(sim.step, "post_fire", self.a0.get())'
    arcs:
      - P -> T
      - T -> Q
)Y");
  const auto [logs, outcome] = runLogs(m);
  EXPECT_EQ(logs, (std::vector<std::string>{
                      "0 guard main/T", "0 on_remove main/P", "0 pre_fire 1",     //
                      "1 in_fire 1.0 0.5",                                        //
                      "2 in_fire 2.0 1.0", "2 post_fire 1", "2 on_deposit main/Q 1"}));
}

TEST(Scripts, AGuardBlocksItsTransition) {
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 10}
pages:
  main:
    places:
      P: {tokens: 5}
    transitions:
      T:
        guard: "sim.time >= 3"
        pre_fire: "sim.log(sim.step)"
    arcs:
      - P -> T
)Y");
  const auto [logs, outcome] = runLogs(m);
  EXPECT_EQ(logs, (std::vector<std::string>{"3", "4", "5", "6", "7"}));
  EXPECT_EQ(outcome.reason, StopReason::Dead);
}

TEST(Scripts, APredicateSelectsTokens) {
  // boxes arrive in FIFO order; the arc takes only the painted ones, skipping the others
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 10}
pages:
  main:
    places:
      line: {tokens: {d0: [plain1, painted1, plain2, painted2]}}
      out: {}
    transitions:
      take:
        pre_fire: 'sim.log(self.d0[0].name)'
    arcs:
      - {from: line, to: take, weight: {d0: 1}, predicate: 'token.name.startswith("painted")'}
      - {from: take, to: out, weight: {d0: 1}}
)Y");
  const auto [logs, outcome] = runLogs(m);
  EXPECT_EQ(logs, (std::vector<std::string>{"painted1", "painted2"}));
}

TEST(Scripts, TheGlobalsAreSharedByEveryScript) {
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 3}
scripts:
  globals: |
    counts = {"a": 0, "b": 0}
    total = 0
    def bump(key):
        global total
        counts[key] += 1
        total += 1
pages:
  main:
    places:
      P: {tokens: 2}
      Q: {tokens: 2}
    transitions:
      A: {pre_fire: 'bump("a")'}
      B:
        pre_fire: |
          bump("b")
          total += 100
          sim.log(counts["a"], counts["b"], total)
    arcs:
      - P -> A
      - Q -> B
)Y");
  const auto [logs, outcome] = runLogs(m);
  // A starts before B in each step (declaration order); both see the same names
  EXPECT_EQ(logs, (std::vector<std::string>{"1 1 102", "2 2 204"}));
}

TEST(Scripts, FunctionsInAFileBesideTheModel) {
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 3}
scripts:
  globals: {file: scripts/common.py}
pages:
  main:
    places:
      P: {tokens: 1, on_remove: {file: scripts/cell.py, function: removed}}
    transitions:
      T: {pre_fire: {file: scripts/cell.py, function: start}}
    arcs:
      - P -> T
)Y");
  m.addFile("scripts/common.py", "PREFIX = 'cell'\n");
  m.addFile("scripts/cell.py", "def start(self):\n    sim.log(PREFIX, 'start', self.name)\n\n"
                               "def removed(self, token):\n    sim.log(PREFIX, 'removed', self.name, token)\n");
  const auto [logs, outcome] = runLogs(m);
  EXPECT_EQ(logs, (std::vector<std::string>{"cell removed main/P None", "cell start main/T"}));
}

TEST(Scripts, ScriptsSetMarkingsAndStopTheRun) {
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 100}
pages:
  main:
    places:
      P: {tokens: 1}
      Q: {capacity: 5}
    transitions:
      T:
        pre_fire: |
          sim.place("main/Q").a0.set(sim.step + 1)
          if sim.step == 3:
              sim.stop("three is enough")
    arcs:
      - P -> T
      - T -> P
)Y");
  core::Diagnostics diags;
  auto sim = m.open(diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::Stopped);
  EXPECT_EQ(outcome.message, "three is enough");
  EXPECT_EQ(outcome.steps, 3);
  const auto q = sim->net().findPlace("main/Q");
  EXPECT_EQ(sim->kernel().placeTokens(q.value()), 4);
}

TEST(Scripts, DeletingANodeInOnRemoveLeavesTheOtherTokensOfTheRemovalTheirCalls) {
  // issue 14: box1's on_remove deletes box1; its token left the net re-entrantly and the
  // kernel lost the rest of the removal, so box2 and box3 never got on_remove
  auto sim = testing::openModelFile("tests/data/good/delete_on_remove.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto [logs, outcome] = runLogs(*sim);
  ASSERT_EQ(outcome.reason, StopReason::Dead) << outcome.message;  // once the two are in the bin
  EXPECT_EQ(logs, (std::vector<std::string>{"0 on_remove boxes/box1", "0 on_remove boxes/box2",
                                            "0 on_remove boxes/box3", "1 on_deposit boxes/box2",
                                            "1 on_deposit boxes/box3"}));
  EXPECT_EQ(sim->plant()->find("boxes/box1"), nullptr);
  const auto bin = sim->net().findPlace("main/bin");
  EXPECT_EQ(sim->kernel().placeTokens(bin.value()), 2);
}

TEST(ScriptErrors, SyntaxErrorInlineIsLocatedInTheModelFile) {
  ScriptModel m(R"Y(gdpn: 1
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T:
        pre_fire: |
          x = 1
          y = (x +
        guard: "x >> > 1"
    arcs:
      - P -> T
)Y");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  const std::string all = diags.str();
  EXPECT_NE(all.find(m.path() + ":10:15: error: syntax error in pre_fire of transition 'main/T': '(' was never closed"), std::string::npos)
      << all;
  EXPECT_NE(all.find(m.path() + ":11:22: error: syntax error in guard of transition 'main/T': invalid syntax"), std::string::npos) << all;
}

TEST(ScriptErrors, SyntaxErrorInAScriptFileIsLocatedInThatFile) {
  ScriptModel m(R"Y(gdpn: 1
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T: {pre_fire: {file: cell.py, function: start}}
    arcs:
      - P -> T
)Y");
  m.addFile("cell.py", "def start(self):\n    return 1 +\n");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  const std::string file = (fs::path(m.path()).parent_path() / "cell.py").string();
  EXPECT_NE(diags.str().find(file + ":2:"), std::string::npos) << diags.str();
  EXPECT_NE(diags.str().find("syntax error"), std::string::npos) << diags.str();
}

TEST(ScriptErrors, AMissingFileOrFunctionIsReportedWhereItIsNamed) {
  ScriptModel m(R"Y(gdpn: 1
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T: {pre_fire: {file: none.py, function: start}}
      U: {pre_fire: {file: cell.py, function: nope}}
    arcs:
      - P -> T
      - P -> U
)Y");
  m.addFile("cell.py", "def start(self):\n    pass\n");
  core::Diagnostics diags;
  EXPECT_FALSE(m.open(diags));
  EXPECT_NE(diags.str().find(m.path() + ":7:21: error: cannot read the script file 'none.py'"), std::string::npos)
      << diags.str();
  EXPECT_NE(diags.str().find(m.path() + ":8:21: error: the script file 'cell.py' defines no function 'nope'"),
            std::string::npos)
      << diags.str();
}

TEST(ScriptErrors, AKeyboardInterruptAScriptRaisesIsAScriptErrorNotAnInterruption) {
  // no Ctrl-C came: the script's own KeyboardInterrupt fails the run as any exception does
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 10}
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T:
        pre_fire: |
          raise KeyboardInterrupt("not the user")
    arcs:
      - P -> T
)Y");
  core::Diagnostics diags;
  auto sim = m.open(diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_EQ(outcome.message.rfind(m.path() + ":10: error: pre_fire of transition 'main/T' at t = 0 s raised an exception", 0), 0u)
      << outcome.message;
  EXPECT_NE(outcome.message.find("KeyboardInterrupt: not the user"), std::string::npos) << outcome.message;
}

TEST(ScriptErrors, AnExceptionStopsTheRunAndNamesConstructKindAndLine) {
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 1, until: 10}
pages:
  main:
    places:
      P: {tokens: 5}
    transitions:
      T:
        post_fire: |
          sim.log("post", sim.step)
          ratio = 1 / (3 - sim.step)
    arcs:
      - P -> T
)Y");
  core::Diagnostics diags;
  auto sim = m.open(diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_EQ(outcome.steps, 3);  // the exception came in step 3's completion phase
  // the message says the model time: a fault late in a long run is found again by running to it
  EXPECT_EQ(outcome.message.rfind(m.path() + ":11: error: post_fire of transition 'main/T' at t = 3 s raised an exception",
                                  0),
            0u)
      << outcome.message;
  EXPECT_NE(outcome.message.find("Traceback (most recent call last)"), std::string::npos);
  EXPECT_NE(outcome.message.find("ZeroDivisionError: division by zero"), std::string::npos);
  // the trace so far is kept and ends with the error
  EXPECT_NE(trace.str().find("\"ev\":\"error\""), std::string::npos);
  // the run stopped at the end of the completion phase: nothing started in step 3
  EXPECT_EQ(trace.str().find("{\"step\":3,\"t\":3,\"ev\":\"start\""), std::string::npos);
}

/// The message of the run of `text` (a script error expected).
std::string failureOf(const ScriptModel& m) {
  core::Diagnostics diags;
  auto sim = m.open(diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError) << outcome.message;
  return outcome.message;
}

TEST(ScriptErrors, AnExceptionInsideGdpnsHelpersIsPlacedAtTheScriptLineThatCalledThem) {
  // `item.nosuch` in on_enter fails inside the helper that stands for the item: the location
  // and the traceback are the model file's, never gdpn's own `<string>`
  ScriptModel m(R"Y(gdpn: 1
settings: {until: 1}
pages:
  main:
    places:
      p:
        slots: {c0: sensor}
        sensors: {c0: zone}
        on_enter:
          c0: |
            x = 1
            print(item.nosuch)
scene:
  - Region: {name: zone, size: [2, 2, 2]}
  - Transform:
      name: box
      children:
        - Body: {mass: 1}
        - Cube: {size: [0.1, 0.1, 0.1]}
)Y");
  const std::string message = failureOf(m);
  EXPECT_EQ(message.rfind(m.path() + ":12: error: on_enter of place 'main/p' slot c0 at t = 0 s raised an exception", 0), 0u)
      << message;
  EXPECT_EQ(message.find("<string>"), std::string::npos) << message;
  EXPECT_NE(message.find("print(item.nosuch)"), std::string::npos) << message;
}

TEST(ScriptErrors, FoldedAndQuotedScriptsAreLocatedAtTheirOwnLines) {
  // a folded block drops its blank lines, a quoted string may hold \n or run over lines: each
  // line of code is still placed on the file's line it stands on
  const auto model = [](const std::string& pre_fire) {
    return "gdpn: 1\n"                           // 1
           "settings: {dt: 1, until: 5}\n"       // 2
           "pages:\n"                            // 3
           "  main:\n"                           // 4
           "    arcs: [P -> T]\n"                // 5
           "    places: {P: {tokens: 1}}\n"      // 6
           "    transitions:\n"                  // 7
           "      T:\n"                          // 8
           "        pre_fire: " + pre_fire + "\n";  // 9...
  };
  ScriptModel folded(model(">\n          x = 1\n\n          y = 2\n\n          raise ValueError(\"folded\")"));
  const std::string message = failureOf(folded);
  EXPECT_EQ(message.rfind(folded.path() + ":14: error: pre_fire of transition 'main/T'", 0), 0u) << message;
  EXPECT_NE(message.find("line 14"), std::string::npos) << message;
  ScriptModel quoted(model("\"a = 1\\nb = 2\\nraise ValueError('quoted')\""));
  EXPECT_EQ(failureOf(quoted).rfind(quoted.path() + ":9: error: pre_fire of transition 'main/T'", 0), 0u)
      << failureOf(quoted);
  ScriptModel spread(model("\"a = 1\n\n          raise ValueError('spread')\""));
  EXPECT_EQ(failureOf(spread).rfind(spread.path() + ":11: error: pre_fire of transition 'main/T'", 0), 0u)
      << failureOf(spread);
}

TEST(ScriptErrors, AMotorSetBeyondWhatThePlantCanHoldIsRefusedAtTheAssignment) {
  // not "physics error: body ran away" a step later, with no location
  ScriptModel m(R"Y(gdpn: 1
settings: {until: 1}
pages:
  main:
    places:
      p: {tokens: 1}
    transitions:
      t:
        pre_fire: |
          j = sim.node("arm/hinge")
          j.fmax1 = 100
          j.vel1 = 1e300
    arcs:
      - p -> t
scene:
  - Transform:
      name: arm
      children:
        - Joint:
            name: hinge
            kind: hinge
            children:
              - Body: {mass: 1}
              - Cube: {size: [1, 0.1, 0.1]}
)Y");
  const std::string message = failureOf(m);
  EXPECT_EQ(message.rfind(m.path() + ":12: error: pre_fire of transition 'main/t'", 0), 0u) << message;
  EXPECT_NE(message.find("'vel1' must be at most 1e+12, got 1e+300"), std::string::npos) << message;
  // and in the file, on load
  ScriptModel file(R"Y(gdpn: 1
scene:
  - Joint: {name: hinge, kind: hinge, fmax1: 1e300, children: [Body: {mass: 1}, Cube: {size: [1, 1, 1]}]}
)Y");
  core::Diagnostics diags;
  EXPECT_FALSE(model::loadModel(file.path(), diags)) << diags.str();
  EXPECT_NE(diags.str().find("'fmax1' must lie in [0, 1e+12], got 1e+300"), std::string::npos) << diags.str();
}

// Mistakes in scripts are told in the model's terms: the field, what it takes and what it
// got; the slot, what it holds and the index asked for.
TEST(ScriptErrors, MessagesNameTheFieldOrSlotAndWhatWasWrong) {
  ScriptModel m(R"Y(gdpn: 1
scene:
  - World: {}
  - Body: {name: b, children: [{Sphere: {}}]}
  - Joint: {name: j, children: [{Body: {children: [{Sphere: {}}]}}]}
pages:
  main:
    places:
      P: {tokens: {d0: [b]}}
    transitions:
      T:
        pre_fire: |
          for attempt in (lambda: setattr(sim.node("b"), "mass", "heavy"),
                          lambda: setattr(sim.node("j"), "kind", 3),
                          lambda: setattr(sim.node("b"), "mass", (1, 2)),
                          lambda: self.d0[1],
                          lambda: self.d0[-2]):
              try:
                  attempt()
              except (TypeError, IndexError) as e:
                  sim.log(type(e).__name__, e)
    arcs:
      - {from: P, to: T, weight: {d0: 1}}
      - {from: T, to: P, weight: {d0: 1}}
)Y");
  const auto [logs, outcome] = runLogs(m, {0.0, std::nullopt});
  EXPECT_EQ(logs, (std::vector<std::string>{
                      "TypeError 'mass' of a Body expects a number (kg), got str 'heavy'",
                      "TypeError 'kind' of a Joint expects one of 'hinge', 'slider', 'ball', 'universal', 'hinge2', "
                      "'fixed', got int 3",
                      "TypeError 'mass' of a Body expects a number (kg), got tuple (1, 2)",
                      "IndexError transition 'main/T' slot d0 holds 1 node token: no [1]",
                      "IndexError transition 'main/T' slot d0 holds 1 node token: no [-2]",
                  }));
}

TEST(ScriptErrors, TheTimeoutStopsAnEndlessScript) {
  ScriptModel m(R"Y(gdpn: 1
pages:
  main:
    places:
      P: {tokens: 1}
    transitions:
      T:
        pre_fire: |
          while True:
              pass
    arcs:
      - P -> T
)Y");
  core::Diagnostics diags;
  auto sim = m.open(diags, 0.2);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_NE(outcome.message.find("pre_fire of transition 'main/T' at t = 0 s ran longer than the script timeout of 0.2 s"),
            std::string::npos)
      << outcome.message;
}

TEST(ScriptDeterminism, ScriptsUsingSimRandomGiveTheSameTraceBytes) {
  const std::string text = R"Y(gdpn: 1
settings: {dt: 0.01, seed: 99, until: 20}
scripts:
  globals: |
    made = 0
pages:
  main:
    places:
      src: {tokens: 1}
      queue: {capacity: 4}
      done: {}
    transitions:
      make:
        duration: {exponential: 0.3}
        pre_fire: |
          made += 1
          if sim.random.random() < 0.2:
              sim.log("burst", made, round(sim.random.uniform(0, 10), 6))
      serve:
        duration: {uniform: [0.1, 0.9]}
        guard: "sim.random.random() < 0.5"
        post_fire: 'sim.log("served", sim.random.randint(1, 6), sim.random.choice(["a", "b", "c"]))'
    arcs:
      - src -> make
      - make -> src
      - make -> queue
      - queue -> serve
      - serve -> done
)Y";
  auto traceOf = [&] {
    ScriptModel m(text);
    core::Diagnostics diags;
    auto sim = m.open(diags);
    EXPECT_TRUE(sim) << diags.str();
    std::ostringstream trace;
    sim->traceTo(trace);
    sim->run({});
    return trace.str();
  };
  const std::string first = traceOf();
  EXPECT_EQ(first, traceOf());
  EXPECT_GT(first.size(), 20000u);
  EXPECT_EQ(core::fnv1a(first), 0x39d3975a8f7f26c5ULL) << std::hex << core::fnv1a(first);
}


// A Transform's position is where its children stand (its own translation included), and a
// page type's scripts find their instance's node, so one script places things in every
// instance: each cell spawns a box 0.5 m above its own table.
TEST(Scripts, AnInstancePlacesWhatItsScriptsSpawnRelativeToItself) {
  const ScriptModel model(R"Y(gdpn: 1
settings: {dt: 0.1}
scene:
  - Transform:
      name: hall
      translation: [10, 0, 0]
      children: [{Transform: {name: spot, translation: [1, 2, 3]}}]
  - Transform:
      name: store
      translation: [0, -20, 0]
      children: [{Body: {name: box, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]
  - Group: {name: made}
pages:
  main:
    places:
      go: {tokens: 1}
    transitions:
      look:
        pre_fire: |
          sim.log("spot", sim.node("hall/spot").position, "hall", sim.node("hall").position)
          sim.log("main", self.instance)
    arcs:
      - go -> look
    instances:
      left: {type: cell, translation: [-4, 0, 0]}
      right: {type: cell, translation: [4, 1, 0]}
page_types:
  cell:
    places:
      ready: {tokens: 1}
    transitions:
      make:
        pre_fire: |
          p = self.instance.position
          box = sim.node("made").spawn("store/box", at=(p[0], p[1], p[2] + 0.5))
          sim.log(self.instance.name, p, box.position)
    arcs:
      - ready -> make
    scene:
      - Transform: {name: table, children: [{Cube: {size: [1, 1, 0.1]}}]}
)Y");
  const auto [logs, outcome] = runLogs(model, {.until = 0.3, .steps = std::nullopt});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  const std::vector<std::string> expected = {
      "left (-4.0, 0.0, 0.0) (-4.0, 0.0, 0.5)",
      "right (4.0, 1.0, 0.0) (4.0, 1.0, 0.5)",
      "spot (11.0, 2.0, 3.0) hall (10.0, 0.0, 0.0)",
      "main None",
  };
  EXPECT_EQ(logs, expected);
}
TEST(Scripts, AContinuousPlacesAmountIsReadAndSetAndItsRefusalRaised) {
  // a tank of 2 L (at most 10 L): read, set to 7.5 L, then 12 L refused with the kernel's words;
  // its capacity and unit read-only; a place of tokens has no amount
  ScriptModel m(R"Y(gdpn: 1
settings: {dt: 0.1, until: 0.3}
pages:
  main:
    places:
      tank: {continuous: {amount: 2, capacity: 10, unit: L}}
      box: {tokens: 1}
    transitions:
      probe:
        pre_fire: |
          t = sim.place('main/tank')
          sim.log('read', t.amount, t.capacity, t.unit)
          t.amount = 7.5
          sim.log('set', sim.place('main/tank').amount)
          for wrong in (12, 'lots'):
              try:
                  t.amount = wrong
              except (ValueError, TypeError) as e:
                  sim.log(type(e).__name__, e)
          try:
              t.capacity = 20
          except AttributeError as e:
              sim.log('capacity:', e)
          try:
              sim.place('main/box').amount
          except AttributeError as e:
              sim.log('box:', e)
    arcs: [box -> probe]
)Y");
  core::Diagnostics diags;
  auto sim = m.open(diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto [logs, outcome] = runLogs(*sim);
  const std::vector<std::string> expected = {
      "read 2.0 10.0 L",
      "set 7.5",
      "ValueError amount of main/tank: 'main/tank' holds at most 10 L now (its capacity less the room promised)",
      "TypeError amount of main/tank expects a number, got str 'lots'",
      "capacity: capacity of main/tank is the model's (a continuous place's is read-only)",
      "box: 'main/box' holds tokens, not an amount: it has no amount (a continuous place has; count tokens with "
      "len(place.a0))",
  };
  EXPECT_EQ(logs, expected);
  EXPECT_EQ(sim->kernel().amount(*sim->net().findPlace("main/tank")), 7.5);
}

}  // namespace
}  // namespace gdpn::model
