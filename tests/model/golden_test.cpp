// The gdpn program as a user runs it: exit codes, diagnostics on stderr, summary, report, trace.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli.h"
#include "support/scratch.h"

namespace {

namespace fs = std::filesystem;

using Result = gdpn::testing::CliResult;

/// Runs `commands` (a shell line that calls "$GDPN") in the source folder.
Result shell(const std::string& commands) { return gdpn::testing::runShell(commands); }

/// Runs gdpn with `args` (shell words) in the source folder.
Result gdpn(const std::string& args) { return gdpn::testing::runGdpn(args); }

/// Expects every line of `text` to fit 100 columns; returns how many lines it has.
std::size_t expectFitsAHundredColumns(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    ++n;
    EXPECT_LE(line.size(), 100u) << "line " << n << ": " << line;
  }
  return n;
}

/// A path in the temporary folder, this test process's own.
std::string temp(const std::string& name) {
  return (fs::temp_directory_path() / (std::to_string(::getpid()) + "_" + name)).string();
}

TEST(Cli, CheckAcceptsEveryExampleAndGoodModel) {
  for (const char* dir : {"examples", "tests/data/good"}) {
    for (const auto& e : fs::recursive_directory_iterator(fs::path(GDPN_SOURCE_DIR) / dir)) {
      if (!e.path().string().ends_with(".gdpn.yaml")) continue;
      const auto r = gdpn("check '" + e.path().string() + "'");
      EXPECT_EQ(r.code, 0) << e.path() << "\n" << r.out;
      EXPECT_NE(r.out.find(": ok ("), std::string::npos) << r.out;
    }
  }
  // one of a kind in the singular
  const auto r = gdpn("check tests/data/good/user_data.gdpn.yaml");
  EXPECT_NE(r.out.find(": ok (1 place, 0 transitions, 0 arc terms)\n"), std::string::npos) << r.out;
}

TEST(Cli, TheVisionExampleSortsEveryBoxByWhatItsCameraSees) {
  // the camera's pictures, rendered offscreen during the run, are the net's only source of
  // a box's colour; the summary checks where each box ended against its true colour
  const auto r = gdpn("run examples/vision");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("  boxes fed:              10\n  red in the red bin:     7\n  green in the green bin: 3\n"
                       "  in the wrong bin:       0\n  not sorted:             0\n  pictures classified:    10\n"),
            std::string::npos)
      << r.out;
}

TEST(Cli, CheckReportsMistakesAtTheirLocationAndFails) {
  const auto r = gdpn("check tests/data/bad/unknown_key.gdpn.yaml");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("tests/data/bad/unknown_key.gdpn.yaml:6:23: error: unknown key 'capacty' in place "
                       "(did you mean 'capacity'?)"),
            std::string::npos)
      << r.out;
}

TEST(Cli, CheckRefusesAnEmptyModelFileAtItsFirstLine) {
  const std::string empty = temp("gdpn_empty.gdpn.yaml");
  std::ofstream(empty).close();
  const auto r = gdpn("check '" + empty + "'");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(empty + ":1:1: error: the model file is empty"), std::string::npos) << r.out;
  fs::remove(empty);
}

TEST(Cli, RunPrintsTheSummary) {
  const auto r = gdpn("run examples/basics/producer_consumer");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("6000 steps of 0.01 s, t = 60.000 s, seed 7"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("main/consume"), std::string::npos);
  EXPECT_NE(r.out.find("utilisation"), std::string::npos);
  EXPECT_NE(r.out.find("thru [1/s]"), std::string::npos);
}

TEST(Cli, AColouredModelRunsToItsValuesAndIsAnalysedUnfoldedUnderItsOwnNames) {
  // the job shop (value tokens): every job shipped, the machines idle again
  auto r = gdpn("run examples/coloured/job_shop");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("values at the end:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  main/idle: 1'lathe ++ 1'mill ++ 1'drill\n"), std::string::npos) << r.out;
  // gdpn analyze unfolds it; queries name its places as written, a place counting all its values
  r = gdpn("analyze examples/coloured/job_shop --query 'AG operators + loaded <= 2' --query 'bound(idle)'");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("query 1: AG main/operators + main/loaded <= 2\n  true (by the state equation"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("query 2: bound(main/idle)\n  3 "), std::string::npos) << r.out;
}

TEST(Cli, TheColouredSortingDeviceIsAnalysedToItsBinsByHand) {
  // examples/sorting/coloured unfolded (docs/examples.md): a state is the stock s, the balls
  // falling f, the blue balls in the left bin b and the red in the right r, and the gate's one
  // token, clear, seen blue, seen red or passing. Clear and passing: s + f + b + r = 50,
  // C(53,3) = 23426 each, less the 51 passing ones with b + r = 0; seen: s + f + b + r = 49,
  // C(52,3) = 22100 each. 23426 + 23375 + 2 x 22100 = 91001 markings. Edges: from clear, drop
  // (s >= 1: 22100) and two reads (f >= 1: 2 x 22100); from each seen, drop (C(51,3) = 20825)
  // and its push (22100); from passing, drop (22100 - 50) and leave (23375): 197575.
  auto r = gdpn("analyze examples/sorting/coloured");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("91001 states, 197575 edges (complete"), std::string::npos) << r.out;
  // dead only when every ball is in a bin: b + r = 50, 51 ways
  EXPECT_NE(r.out.find("  dead markings:   51 in all\n"), std::string::npos) << r.out;
  // no transition of the unfolded net puts a red token into the left bin, nor a blue one into
  // the right
  EXPECT_NE(r.out.find("at most 0: main/gate main/left_bin_red main/right_bin_blue\n"), std::string::npos) << r.out;
  // no ball lost: one P-invariant counts every ball wherever it is; the gate holds one at a time
  EXPECT_NE(r.out.find("    main/stock + main/falling + main/seen_blue + main/seen_red + main/left_bin_blue +\n"
                       "      main/right_bin_red = 50\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("    main/clear + main/seen_blue + main/seen_red + main/passing = 1\n"), std::string::npos) << r.out;
  r = gdpn("analyze examples/sorting/coloured --query 'AG left_bin_red + right_bin_blue = 0' --query 'AG (not deadlock or "
           "left_bin + right_bin = 50)' --query 'AF deadlock' --query 'EF left_bin_blue = 50' --query 'bound(seen)'");
  EXPECT_EQ(r.code, 0) << r.out;
  // the two places no transition feeds are 0 before the search
  EXPECT_NE(r.out.find("query 1: AG 0 = 0\n  true"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("query 2: AG (not deadlock or main/left_bin_blue + main/right_bin_red = 50)\n  true"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("query 3: AF deadlock\n  true"), std::string::npos) << r.out;
  // the analysis does not run the sensor: all fifty may be blue
  EXPECT_NE(r.out.find("query 4: EF main/left_bin_blue = 50\n  true"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("query 5: bound(main/seen)\n  1 "), std::string::npos) << r.out;
  // the scene-node-data version: one transition, the routing hidden in a handler
  r = gdpn("analyze examples/sorting");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("51 states, 50 edges (complete"), std::string::npos) << r.out;
}

TEST(Cli, ReportHoldsTheExactCycleTimes) {
  const auto report = temp("gdpn_cycles_report.json");
  const auto r = gdpn("run tests/data/good/cycles.gdpn.yaml --quiet --report " + report);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(r.out.empty()) << r.out;  // --quiet
  std::ifstream in(report);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["steps"], 320);
  EXPECT_EQ(j["stopped"], "until");
  std::map<std::string, double> cycle;
  for (const auto& t : j["transitions"]) cycle[t["name"]] = t["mean_cycle"];
  EXPECT_EQ(cycle["main/a1"], 4.0);
  EXPECT_EQ(cycle["main/a2"], 4.0);
  EXPECT_EQ(cycle["main/b1"], 1.0);
  EXPECT_EQ(cycle["main/b3"], 1.0);
  fs::remove(report);
}

TEST(Cli, TraceIsJsonLinesAndRepeatable) {
  const auto a = temp("gdpn_trace_a.jsonl");
  const auto b = temp("gdpn_trace_b.jsonl");
  ASSERT_EQ(gdpn("run tests/data/good/stochastic.gdpn.yaml -q --trace " + a).code, 0);
  ASSERT_EQ(gdpn("run tests/data/good/stochastic.gdpn.yaml -q --trace " + b).code, 0);
  std::stringstream ta, tb;
  ta << std::ifstream(a).rdbuf();
  tb << std::ifstream(b).rdbuf();
  EXPECT_EQ(ta.str(), tb.str());
  std::istringstream lines(ta.str());
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    EXPECT_TRUE(j.contains("step") && j.contains("t") && j.contains("ev")) << line;
    ++n;
  }
  EXPECT_GT(n, 100);
  fs::remove(a);
  fs::remove(b);
}

TEST(CliRun, TheTankRunsToItsFiguresAndTracesTheSameTwice) {
  // examples/plant/tank (docs/examples.md): four rounds of the pump in 300 s, each started by
  // the low switch and stopped by the high one; crossings in the trace at their exact times
  const auto a = temp("gdpn_tank_a.jsonl");
  const auto b = temp("gdpn_tank_b.jsonl");
  const auto r = gdpn("run examples/plant/tank/tank.gdpn.yaml --until 300 --trace " + a);
  ASSERT_EQ(r.code, 0) << r.out;
  expectFitsAHundredColumns(r.out);
  EXPECT_NE(r.out.find("examples/plant/tank/tank.gdpn.yaml: 30000 steps of 0.01 s, t = 300.000 s, seed 1\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  pump starts (low switch): 4\n  pump stops (high switch): 4\n  valve openings:           8\n"),
            std::string::npos)
      << r.out;
  ASSERT_EQ(gdpn("run examples/plant/tank -q --until 300 --trace " + b).code, 0);
  const std::string ta = gdpn::testing::fileBytes(a);
  EXPECT_EQ(ta, gdpn::testing::fileBytes(b));
  EXPECT_NE(ta.find("\"ev\":\"cross\",\"place\":\"main/tank\",\"level\":20,\"rising\":false}"), std::string::npos);
  fs::remove(a);
  fs::remove(b);
}

TEST(Cli, SeedChangesTheRun) {
  const auto a = gdpn("run tests/data/good/stochastic.gdpn.yaml --seed 1");
  const auto b = gdpn("run tests/data/good/stochastic.gdpn.yaml --seed 2");
  EXPECT_EQ(a.code, 0);
  EXPECT_NE(a.out.find("seed 1"), std::string::npos);
  EXPECT_NE(a.out, b.out);
}

TEST(Cli, HelpAndVersion) {
  auto r = gdpn("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("check"), std::string::npos);
  EXPECT_NE(r.out.find("run"), std::string::npos);
  r = gdpn("run --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--until"), std::string::npos);
  EXPECT_NE(r.out.find("--trace"), std::string::npos);
  r = gdpn("check --help");
  EXPECT_EQ(r.code, 0);
  r = gdpn("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("gdpn ", 0), 0u) << r.out;
}

TEST(Cli, BadArgumentsFailWithAMessage) {
  for (const char* args : {"", "frobnicate", "run", "run examples/basics/figure31 --until -3",
                           "run examples/basics/figure31 --steps many", "run examples/basics/figure31 --until 1 --steps 2",
                           "check a b"}) {
    const auto r = gdpn(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_NE(r.out.find("gdpn: error:"), std::string::npos) << args << "\n" << r.out;
  }
}

TEST(Cli, MissingModelFails) {
  const auto r = gdpn("run no/such/model");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("no/such/model: error: no such file or folder"), std::string::npos) << r.out;
}

}  // namespace

namespace {

TEST(Cli, ASourceTransitionIsAWarningNotAnError) {
  const auto r = gdpn("check tests/data/good/source_transition.gdpn.yaml");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("source_transition.gdpn.yaml:11:7: warning: transition 'tick' has no input arcs"),
            std::string::npos) << r.out;
}

TEST(Cli, TheTwoCellLineFinishesEveryPart) {
  const auto r = gdpn("run examples/basics/two_cells");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("stopped: the net is dead"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("line/outfeed"), std::string::npos);
}

}  // namespace

namespace {

TEST(CliScripts, ScriptTimeoutStopsAnEndlessScript) {
  const auto trace = temp("gdpn_endless_trace.jsonl");
  const auto r = gdpn("run tests/data/good/endless_script.gdpn.yaml -q --script-timeout 0.3 --trace " + trace);
  EXPECT_EQ(r.code, 1) << r.out;
  // the loop is at line 11 or 12 when it is stopped
  EXPECT_TRUE(r.out.find("endless_script.gdpn.yaml:11: error:") != std::string::npos ||
              r.out.find("endless_script.gdpn.yaml:12: error:") != std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("error: pre_fire of transition 'main/spin' at t = 0 s ran longer than the script timeout of 0.3 s"),
            std::string::npos)
      << r.out;
  // the trace so far was flushed, with the error last
  std::stringstream t;
  t << std::ifstream(trace).rdbuf();
  EXPECT_NE(t.str().find("\"ev\":\"log\",\"text\":\"spinning\""), std::string::npos) << t.str();
  EXPECT_NE(t.str().find("\"ev\":\"error\""), std::string::npos) << t.str();
  fs::remove(trace);
}

TEST(CliScripts, SigintStopsAnEndlessScript) {
  // start the run in the background and interrupt it once the script says it is spinning:
  // by then gdpn has its handler (a background job starts with SIGINT ignored, so a signal
  // sent earlier would be lost); the output file is this process's own. Not --quiet, which
  // would silence the sim.log line waited for (the wait would run out after 60 s).
  const std::string out = temp("gdpn_sigint_" + std::to_string(::getpid()) + ".out");
  const std::string cmd = std::string("cd '") + GDPN_SOURCE_DIR + "' && ('" + GDPN_CLI +
                          "' run tests/data/good/endless_script.gdpn.yaml > '" + out +
                          "' 2>&1 & pid=$!; for i in $(seq 600); do grep -q spinning '" + out +
                          "' && break; sleep 0.1; done; kill -INT $pid; wait $pid; echo \"exit $?\" >> '" + out + "')";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  EXPECT_NE(text.str().find("error: pre_fire of transition 'main/spin' at t = 0 s was interrupted (Ctrl-C)"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("exit 130"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("spinning"), std::string::npos) << text.str();  // interrupted after it, not by the wait's end
  fs::remove(out);
}

TEST(CliScripts, CheckReportsScriptSyntaxErrors) {
  const auto r = gdpn("check tests/data/bad/script_syntax.gdpn.yaml");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("script_syntax.gdpn.yaml:10:"), std::string::npos) << r.out;
}

}  // namespace

namespace {

TEST(CliInput, KeyboardAndMouseSensorsGetTheScriptedInput) {
  const auto trace = temp("gdpn_console.jsonl");
  const auto r = gdpn("run tests/data/input/console.gdpn.yaml -q --input tests/data/input/console.input.yaml --trace " +
                      trace);
  ASSERT_EQ(r.code, 0) << r.out;
  std::stringstream t;
  t << std::ifstream(trace).rdbuf();
  std::vector<std::string> logs;
  std::istringstream lines(t.str());
  std::string line;
  while (std::getline(lines, line)) {
    const auto at = line.find("\"ev\":\"log\",\"text\":\"");
    if (at != std::string::npos) logs.push_back(line.substr(at + 19, line.size() - at - 21));
  }
  EXPECT_EQ(logs, (std::vector<std::string>{
                      "key  False [] 1.0",              // the viewer entered the booth: it listens
                      "key g True ['g'] 2.0", "go 2.0",  // g pressed: the condition lets go start
                      "key g False [] 2.5",
                      "click True panel/#0/button 3.0", "click False panel/#0/button 3.1"}))
      << t.str();
  fs::remove(trace);
}

TEST(CliInput, MistakesInTheInputFileAreLocated) {
  const auto bad = temp("gdpn_bad.input.yaml");
  std::ofstream(bad) << "- {t: 1, key: a}\n- {t: -2, kye: b}\n- {click: {from: [0, 0]}}\n";
  const auto r = gdpn("run tests/data/input/console.gdpn.yaml -q --input " + bad);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find(bad + ":2:7: error: 't' must be a time of at least 0 seconds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(bad + ":2:11: error: unknown key 'kye' in an input event (did you mean 'key'?)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(bad + ":3:18: error: 'from' expects [x, y, z]"), std::string::npos) << r.out;
  fs::remove(bad);
}

}  // namespace

namespace {

TEST(CliAnalyze, APnmlNetAndAModelFile) {
  auto r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("243 states, 945 edges"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("deadlock:        yes after"), std::string::npos) << r.out;
  // one edge is one edge
  const gdpn::testing::ScratchFolder dir("gdpn_one_edge");
  const std::string one = dir.file("one.gdpn.yaml");
  std::ofstream(one) << "gdpn: 1\npages:\n  main:\n    places:\n      p: {tokens: 1}\n    transitions:\n      t: {}\n"
                        "    arcs: [p -> t]\n";
  EXPECT_NE(gdpn("analyze " + one).out.find(": 2 states, 1 edge ("), std::string::npos);
  // the dead marking itself, each place's bound, the constant places by name
  r = gdpn("analyze examples/basics/figure31");
  EXPECT_NE(r.out.find("  deadlock:        yes after 2 firings: main/T1 main/T2\n"
                       "  dead marking:    main/P2 = 1 main/P4 = 1\n"
                       "  bounds:          max 1 in one place, 2 in one marking; one-safe: yes\n"
                       "                   at most 1: main/P1 main/P2 main/P3 main/P4\n"),
            std::string::npos)
      << r.out;
  r = gdpn("analyze tests/data/conformance/Eratosthenes-PT-010.pnml");
  EXPECT_NE(r.out.find("  constant places: 4: net/p2 net/p3 net/p7 net/p5\n"), std::string::npos) << r.out;
  r = gdpn("analyze examples/basics/figure31 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["states"], 3);
  EXPECT_EQ(j["deadlock_path"], (nlohmann::json{"main/T1", "main/T2"}));
  EXPECT_EQ(j["one_safe"], true);
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --threads 2");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("243 states, 945 edges"), std::string::npos) << r.out;
  // ten philosophers: the search's own path is long; asked for, a shortest one (each takes a fork)
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000010.pnml --shortest-path --json");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["deadlock_path"].size(), 10u) << r.out;
  r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml --max-states 100");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("(partial: --max-states"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("live:            unknown"), std::string::npos) << r.out;
  // (1 MiB: past the first progress report, at 4,096 states; with less the search stops
  // before its table first grows, at 709)
  r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml --max-memory 1 --progress");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("(partial: --max-memory"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" states/s, "), std::string::npos) << r.out;  // the progress line
}

TEST(CliRun, QuietSilencesSimLogButTheTraceKeepsItAndAPictureIsOnlyWrittenAsPng) {
  const gdpn::testing::ScratchFolder dir("gdpn_quiet");
  // the factory logs each box it releases
  auto r = gdpn("run examples/factory --until 10");
  EXPECT_NE(r.out.find("[t=4] released boxes/b00/box"), std::string::npos) << r.out;
  r = gdpn("run examples/factory --until 10 --quiet --trace " + dir.file("t.jsonl"));
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(gdpn::testing::fileBytes(dir.file("t.jsonl")).find("\"ev\":\"log\",\"text\":\"released boxes/b00/box"),
            std::string::npos);
  // PNG data under another name would mislead
  r = gdpn("render examples/factory -o " + dir.file("a.jpg"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("a picture of the plant is written as .png"), std::string::npos) << r.out;
  EXPECT_TRUE(dir.names().size() == 1);
  // a picture's run logs too, unless quiet: then only the line that names the picture
  r = gdpn("render examples/factory --at 5 --size 64x36 -o " + dir.file("a.png"));
  EXPECT_NE(r.out.find("[t=4] released boxes/b00/box"), std::string::npos) << r.out;
  r = gdpn("render examples/factory --at 5 --size 64x36 --quiet -o " + dir.file("b.png"));
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, dir.file("b.png") + ": 64x36 at t = 5 s\n");
  // the globals script's lines too (they are logged before the first step)
  const std::string model = dir.file("globals.gdpn.yaml");
  std::ofstream(model) << "gdpn: 1\nsettings: {until: 0.1}\nscripts:\n  globals: |\n    sim.log(\"hello\")\n";
  r = gdpn("run " + model);
  EXPECT_NE(r.out.find("[t=0] hello"), std::string::npos) << r.out;
  r = gdpn("run " + model + " -q");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "");
}

TEST(CliRun, TheFactorysSummaryFitsAHundredColumns) {
  // its long cycle invariants wrapped under their heading and cut after six places, "(+N
  // alike)" explained, the model's own figures aligned
  const auto r = gdpn("run examples/factory");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_GT(expectFitsAHundredColumns(r.out), 60u);
  EXPECT_NE(r.out.find("factory/stationA/reopened.b0 + ... and 4 more\n" + std::string(48, ' ') +
                       "(--report has all) (+4 alike)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n(+N alike): N more invariants with the same transitions, tokens and bound"), std::string::npos);
  // each station's token took one of its circuits only (no box was skipped): its trips measured
  EXPECT_NE(r.out.find("\n              15.010        16.802       1.792    5 trips: push_box, insert, pull_rod, paint,\n" +
                       std::string(50, ' ') + "push_rod, reach, pull_box, release, wait, rearm\n"),
            std::string::npos)
      << r.out;
  // station B's line agrees with its circuit's (both its trips), not its slowest transition's
  EXPECT_NE(r.out.find("\n       1      15.010        16.802       1.792  factory/stationB/ready.b0 +\n"),
            std::string::npos)
      << r.out;
  // the yard's switch, driven by a sensor through transitions that take no time: no bound
  EXPECT_NE(r.out.find("\n       1           -        17.079           -  factory/yard_idle.b0 + "
                       "factory/yard_running.b0\n"),
            std::string::npos)
      << r.out;
  // the boxes end piled at the end of the line: they make no cycle; the places that only read
  // sensors are left out
  EXPECT_EQ(r.out.find("factory/buffer.d0 + "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("factory/stationA/over_left "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("factory/landing "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n(9 places that only read sensors, never holding a token, not listed; --report has them)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\nfactory/stationA/enter "), std::string::npos) << r.out;  // a sensor and boxes
  EXPECT_NE(r.out.find("the model's figures:\n  boxes at the end of the line: 21\n  painted among them:           10\n"),
            std::string::npos)
      << r.out;
  // the figures in --report keep the invariants whole
  const gdpn::testing::ScratchFolder dir("gdpn_factory_report");
  ASSERT_EQ(gdpn("run examples/factory --quiet --report " + dir.file("r.json")).code, 0);
  const auto j = nlohmann::json::parse(gdpn::testing::fileBytes(dir.file("r.json")));
  bool whole = false;
  for (const auto& c : j["cycles"]) whole = whole || c["invariant"].get<std::string>().find("factory/stationB/released.b0") != std::string::npos;
  EXPECT_TRUE(whole);
  const auto yard = std::find_if(j["cycles"].begin(), j["cycles"].end(), [](const auto& c) {
    return c["invariant"] == "factory/yard_idle.b0 + factory/yard_running.b0";
  });
  ASSERT_NE(yard, j["cycles"].end());
  EXPECT_TRUE((*yard)["bound"].is_null());
  EXPECT_NEAR((*yard)["measured"].get<double>(), 17.079, 5e-4);
  std::size_t sensors_only = 0;
  for (const auto& p : j["places"]) {
    if (p["sensors_only"].get<bool>()) ++sensors_only;
  }
  EXPECT_EQ(sensors_only, 9u);
}

TEST(CliRun, TheExamplesSummariesFitAHundredColumnsAndSayTheStepAsItMeans) {
  // why a run stopped goes on a line of its own, wrapped; a step of 1/60 s is not written
  // as 0.016666666666666666
  auto r = gdpn("run examples/sorting");
  ASSERT_EQ(r.code, 0) << r.out;
  expectFitsAHundredColumns(r.out);
  EXPECT_NE(r.out.find("steps of 0.005 s, t = 15.785 s, seed 7\nstopped: the net is dead (nothing enabled or occurring)\n"),
            std::string::npos)
      << r.out;
  r = gdpn("run examples/vehicles");
  ASSERT_EQ(r.code, 0) << r.out;
  expectFitsAHundredColumns(r.out);
  EXPECT_NE(r.out.find(" s, seed 1\nstopped by a script: all 4 vehicles reached the depot\n"), std::string::npos) << r.out;
  r = gdpn("run examples/station --until 10");
  ASSERT_EQ(r.code, 0) << r.out;
  expectFitsAHundredColumns(r.out);
  EXPECT_NE(r.out.find("examples/station/sorting_station.gdpn.yaml: 600 steps of 1/60 s, t = 10.000 s, seed 1\n"),
            std::string::npos)
      << r.out;
}

TEST(CliRun, TheFactorysLogGivesPositionsToTheMillimetre) {
  const auto r = gdpn("run examples/factory --until 10");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto at = r.out.find("[t=4] released boxes/b00/box at (");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
  double x = 0, y = 0, z = 0;
  char close = 0;
  ASSERT_EQ(std::sscanf(line.c_str(), "[t=4] released boxes/b00/box at (%lf, %lf, %lf%c", &x, &y, &z, &close), 4) << line;
  EXPECT_EQ(close, ')') << line;
  // three decimals each: "(-7.975, 1.600, 0.812)"
  std::size_t decimals = 0;
  for (std::size_t i = line.find('('); i < line.size(); ++i) {
    if (line[i] == '.') {
      decimals = 0;
    } else if (std::isdigit(static_cast<unsigned char>(line[i]))) {
      ++decimals;
    } else if (line[i] == ',' || line[i] == ')') {
      EXPECT_EQ(decimals, 3u) << line;
    }
  }
}

TEST(CliRun, TheVehiclesLogAndSummaryGiveTheSameDistances) {
  // a parked car's distance stops counting: its log line and the summary agree
  const auto r = gdpn("run examples/vehicles");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* car : {"car1", "car2", "car3", "car4"}) {
    const auto logged = r.out.find(std::string("] ") + car + " reached the depot at ");
    ASSERT_NE(logged, std::string::npos) << car << "\n" << r.out;
    const auto summary = r.out.find(std::string("  ") + car + ":");
    ASSERT_NE(summary, std::string::npos) << car << "\n" << r.out;
    const auto tail = [&](std::size_t from) {
      const auto end = r.out.find('\n', from);
      const auto after = r.out.rfind(" after ", end);
      return r.out.substr(after, end - after);
    };
    EXPECT_EQ(tail(logged), tail(summary)) << car << "\n" << r.out;
  }
  EXPECT_NE(r.out.find("car4 reached the depot at 20.27 s after 28.2 m"), std::string::npos) << r.out;
}

TEST(CliRun, ASignalOfAMissingNodeSaysHowUnnamedNodesAreAddressed) {
  const gdpn::testing::ScratchFolder dir("gdpn_signal_missing_node");
  const auto r = gdpn("run examples/vehicles --until 1 --signal node:nosuch/body.position --signals " +
                      dir.file("s.csv"));
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("no scene node 'nosuch/body' (a node without a name is addressed by its index among its "
                       "siblings: '#2', '#2/box')"),
            std::string::npos)
      << r.out;
}

TEST(CliAnalyze, TheFactorysAnalysisFitsAHundredColumns) {
  // long invariants and circuits wrapped under their value and cut (--json has them whole)
  const auto r = gdpn("analyze examples/factory --max-states 20000");
  EXPECT_EQ(r.code, 3) << r.out;  // partial: --max-states
  EXPECT_GT(expectFitsAHundredColumns(r.out), 40u);
  EXPECT_NE(r.out.find("\n  15.010 s  factory/stationA/ready.b0 + "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" ... and 2 more (--json has all) (1 token; circuit\n"), std::string::npos) << r.out;
  // the yard's switch is driven by a sensor through transitions that take no time: no bound
  EXPECT_NE(r.out.find("\n         -  factory/yard_idle.b0 + factory/yard_running.b0 (1 token; circuit"),
            std::string::npos)
      << r.out;
  // the boxes end piled at the end of the line: no cycle (no flow row), and
  EXPECT_EQ(r.out.find("(24 tokens)"), std::string::npos) << r.out;
  // the boxes end piled at the end of the line: the net as a whole does not repeat
  EXPECT_NE(r.out.find("\n  the net as a whole does not repeat (no T-invariant covers every transition): no cycle "
                       "time\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("the net's cycle time is at least"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(gdpn("analyze examples/factory --max-states 20000 --json").out);
  EXPECT_TRUE(j["cycle_time"].is_null());
}

TEST(CliAnalyze, ANetThatCannotRepeatClaimsNoCycleTimeAndTokensEndingInASinkAreNoCycle) {
  auto r = gdpn("analyze tests/data/good/cycle_figures.gdpn.yaml");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("\n   2.000 s  main/x + main/y (1 token; circuit main/go -> main/back)\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n         -  main/off + main/on (1 token; circuit"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("main/box + main/piled"), r.out.rfind("main/box + main/piled")) << r.out;  // no cycle
  EXPECT_EQ(r.out.find("cycle time is at least"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the net as a whole does not repeat"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(gdpn("analyze tests/data/good/cycle_figures.gdpn.yaml --json").out);
  EXPECT_TRUE(j["cycle_time"].is_null());
  ASSERT_EQ(j["cycle_times"].size(), 2u);
}

TEST(CliAnalyze, TheFirstDeadMarkingsAreShownWithTheirPathsAndAllAreCounted) {
  // Referendum-PT-0010: each of the 10 voters votes yes or no, then nothing moves: 2^10 dead markings
  auto r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("\n  dead markings:   1024 in all\n"), std::string::npos) << r.out;
  std::size_t also = 0, markings = 0;
  for (auto at = r.out.find("\n  also dead:       after 11 firings: net/start_0 "); at != std::string::npos;
       at = r.out.find("\n  also dead:       after 11 firings: net/start_0 ", at + 1)) {
    ++also;
  }
  for (auto at = r.out.find("\n  dead marking:    "); at != std::string::npos; at = r.out.find("\n  dead marking:    ", at + 1)) {
    ++markings;
  }
  EXPECT_EQ(also, 2u) << r.out;
  EXPECT_EQ(markings, 3u) << r.out;
  r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml --json");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["dead_markings"], 1024);
  ASSERT_EQ(j["more_dead_paths"].size(), 2u);
  EXPECT_EQ(j["more_dead_paths"][0].size(), 11u);
  EXPECT_NE(j["more_dead_paths"][0], j["deadlock_path"]);
}

TEST(CliAnalyze, TheReachabilityGraphIsWrittenAsDotAndAldebaran) {
  const gdpn::testing::ScratchFolder dir("gdpn_graph");
  // figure 3.1: three markings in a row, the last dead
  auto r = gdpn("analyze examples/basics/figure31 --graph " + dir.file("f.dot"));
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string dot = gdpn::testing::fileBytes(dir.file("f.dot"));
  EXPECT_NE(dot.find("  s0 [label=\"main/P1\\nmain/P2\", penwidth=2];\n"), std::string::npos) << dot;
  EXPECT_NE(dot.find("  s2 [label=\"main/P2\\nmain/P4\", style=filled"), std::string::npos) << dot;
  EXPECT_NE(dot.find("  s1 -> s2 [label=\"main/T2\"];\n"), std::string::npos) << dot;
  // Aldebaran: the header counts what the analysis counts (Philosophers-PT-000005: 243, 945)
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --graph " + dir.file("p.aut"));
  ASSERT_EQ(r.code, 0) << r.out;
  std::istringstream aut(gdpn::testing::fileBytes(dir.file("p.aut")));
  std::string line;
  std::getline(aut, line);
  EXPECT_EQ(line, "des (0, 945, 243)");
  std::size_t edges = 0;
  while (std::getline(aut, line)) edges += line.starts_with('(') && line.find(", \"net/") != std::string::npos;
  EXPECT_EQ(edges, 945u);
  // a graph a limit cuts short is not written; an unknown format is refused
  r = gdpn("analyze examples/basics/producer_consumer --max-states 100 --graph " + dir.file("pc.aut"));
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("nothing written: the graph is not whole (partial: --max-states reached)"), std::string::npos);
  r = gdpn("analyze examples/basics/figure31 --graph " + dir.file("f.txt"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"f.dot", "p.aut"}));
}

TEST(CliAnalyze, WhatTheUntimedAnalysisLeavesOutIsSaid) {
  // the sorting example's drop script and gate handler: not run by the analysis, and said so
  auto r = gdpn("analyze examples/sorting --query 'EF deadlock'");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("note: the firing scripts of 1 transition (main/drop) and the token and sensor handlers of 1 "
                       "place\n      (main/gate) are not run"),
            std::string::npos)
      << r.out;
  r = gdpn("analyze examples/factory --max-states 1000 --json");
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["left_out"].size(), 2u) << r.out;
  EXPECT_NE(j["left_out"][0].get<std::string>().find("sensor conditions"), std::string::npos);
  // a net without scripts or sensors: nothing to say
  r = gdpn("analyze examples/basics/figure31");
  EXPECT_EQ(r.out.find("note:"), std::string::npos) << r.out;
}

TEST(CliAnalyze, AWitnessWrittenByAnalyzeIsReplayedByRunAndABadOneIsLocated) {
  const gdpn::testing::ScratchFolder dir("gdpn_witness");
  // a reachability witness: T1 then T2 reach P4
  const std::string w = dir.file("w.json");
  auto r = gdpn("analyze examples/basics/figure31 --query 'EF P4 = 1' --witness " + w);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(gdpn::testing::fileBytes(w));
  EXPECT_EQ(j["path"], nlohmann::json({"main/T1", "main/T2"}));
  EXPECT_EQ(j["marking"], nlohmann::json({{"main/P2", 1}, {"main/P4", 1}}));
  r = gdpn("run examples/basics/figure31 --replay " + w + " --quiet");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("replay: all 2 firings done by t = 2 s; the marking is the witness' (EF P4 = 1)"),
            std::string::npos)
      << r.out;
  // an LTL counterexample: a lasso, its cycle played once and back at its marking
  const std::string ring = dir.file("ring.gdpn.yaml");
  std::ofstream(ring) << "gdpn: 1\npages:\n  main:\n    places:\n      a: {tokens: 1}\n      b: {}\n      c: {}\n"
                         "    transitions:\n      go: {}\n      back: {}\n      leave: {}\n"
                         "    arcs: [a -> go, go -> b, b -> back, back -> a, a -> leave, leave -> c]\n";
  r = gdpn("analyze " + ring + " --query 'A (F c = 1)' --witness " + w);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("  false ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  then forever, 2 firings: main/go main/back\n"), std::string::npos) << r.out;
  EXPECT_EQ(nlohmann::json::parse(gdpn::testing::fileBytes(w))["cycle"], nlohmann::json({"main/go", "main/back"}));
  r = gdpn("run " + ring + " --replay " + w + " --quiet");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("replay: all 2 firings done (its cycle once)"), std::string::npos) << r.out;
  // what cannot be replayed says why, where
  const std::string bad = dir.file("bad.json");
  std::ofstream(bad) << "{\"path\": [\"main/T1\", \"main/T9\"]}";
  r = gdpn("run examples/basics/figure31 --replay " + bad + " --quiet");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(bad + ":1:22: error: the net has no transition 'main/T9'"), std::string::npos) << r.out;
  std::ofstream(bad) << "{\"path\": [\n \"main/T1\",, ]}";
  r = gdpn("run examples/basics/figure31 --replay " + bad + " --quiet");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(bad + ":2:12: error: not JSON: "), std::string::npos) << r.out;
  std::ofstream(bad) << "{\"path\": [\"main/T2\"]}";
  r = gdpn("run examples/basics/figure31 --replay " + bad + " --quiet");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("error: replay stopped after 0 of 1 firings at t = 0 s: 'main/T2' is not enabled"),
            std::string::npos)
      << r.out;
  std::ofstream(bad) << "{\"path\": [\"main/T1\"], \"marking\": {\"main/P4\": 1}}";
  r = gdpn("run examples/basics/figure31 --replay " + bad + " --quiet");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("the marking is not the witness': 'main/P3' holds 1, the witness says 0; 'main/P4' holds 0, "
                       "the witness says 1"),
            std::string::npos)
      << r.out;
  // no answer shown by a path: nothing written, and said
  r = gdpn("analyze examples/basics/figure31 --query 'AG P1 + P3 + P4 <= 1' --witness " + dir.file("none.json"));
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("no answer here is shown by a firing sequence"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("none.json")));
}

TEST(CliAnalyze, QueriesAreAnsweredWithTheirWitnessesAndMistakesLocated) {
  // the example of figure 3.1: T1 then T2 ends in a dead marking
  auto r = gdpn("analyze examples/basics/figure31 --query 'EF deadlock' --query 'AG not fireable(T1)'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("query 1: EF deadlock\n  true (3 markings explored; a breadth-first search over stubborn sets)\n"
                       "  shown by the marking after 2 firings: main/T1 main/T2\n  tokens there:"),
            std::string::npos)
      << r.out;
  // each searched on its own (with stubborn sets no graph is stored): the initial marking decides it
  EXPECT_NE(r.out.find("query 2: AG not fireable(main/T1)\n  false (1 marking explored; a breadth-first search over "
                       "stubborn sets)\n  shown by the initial marking\n"),
            std::string::npos)
      << r.out;
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --json --query 'EF Think_1 + Think_2 = 0'");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto q = nlohmann::json::parse(r.out)["queries"][0];
  EXPECT_EQ(q["answer"], "true");
  EXPECT_EQ(q["path"].size(), 2u);
  EXPECT_FALSE(q["marking"].contains("net/Think_1"));
  // undecided within the limits: said, and exit 3
  r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml --max-states 100 --query 'EF deadlock'");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("  unknown: partial: --max-states reached"), std::string::npos) << r.out;
  // a contest property file: the contest's lines
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --query "
           "tests/data/conformance/queries/Philosophers-PT-000005/UpperBounds.xml --query 'bound(Eat_1 + Eat_2)'");
  ASSERT_EQ(r.code, 0) << r.out;
  // bounds by the state equation, each met by a marking a guided search reaches
  EXPECT_NE(r.out.find("FORMULA Philosophers-PT-000005-UpperBounds-00 5 TECHNIQUES STATE_EQUATION EXPLICIT "
                       "BEST_FIRST_SEARCH\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("FORMULA Philosophers-PT-000005-UpperBounds-15 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("query 17: bound(net/Eat_1 + net/Eat_2)\n  1 (25 markings explored; the state equation's bound, a search guided "
                       "towards it)\n"), std::string::npos)
      << r.out;
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --query "
           "tests/data/conformance/queries/Philosophers-PT-000005/LTLFireability.xml --max-states 100");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("FORMULA Philosophers-PT-000005-LTLFireability-04 CANNOT_COMPUTE (partial: --max-states reached)"),
            std::string::npos)
      << r.out;
  // a file of queries: each mistake at its line and column
  const auto file = temp("gdpn_bad.queries");
  std::ofstream(file) << "# the philosophers\nEF deadlock\n\nAG Think_1 <= 1 and fireable(FF9)\nEF (Eat_1 >= 1\n";
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --query " + file);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(file + ":4:30: error: no transition is called 'FF9'\n  AG Think_1 <= 1 and fireable(FF9)\n" +
                       std::string(31, ' ') + "^\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(file + ":5:15: error: expected ')', found the end"), std::string::npos) << r.out;
  fs::remove(file);
}

TEST(CliAnalyze, TwoCyclesGiveBothCycleTimesAndTheLargerAsTheBound) {
  auto r = gdpn("analyze tests/data/good/cycles.gdpn.yaml");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("   4.000 s  main/a_ready + main/a_half (1 token; circuit main/a1 -> main/a2)\n"
                       "   1.000 s  main/b_ready + main/b_one + main/b_two (1 token; circuit main/b1 -> main/b2 -> main/b3)\n"
                       "  the net's cycle time is at least 4.000 s"),
            std::string::npos)
      << r.out;
  r = gdpn("analyze tests/data/good/cycles.gdpn.yaml --json");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["cycle_time"], 4.0);
  ASSERT_EQ(j["cycle_times"].size(), 2u);
  EXPECT_EQ(j["cycle_times"][1]["seconds"], 1.0);
  EXPECT_EQ(j["cycle_times"][1]["circuit"], true);
  EXPECT_EQ(j["invariants"]["p"].size(), 2u);
  EXPECT_EQ(j["invariants"]["conservative"], true);
  // the run measures the same cycles and shows them beside the bounds
  r = gdpn("run tests/data/good/cycles.gdpn.yaml");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("       1       4.000         4.000       0.000  main/a_ready + main/a_half\n"),
            std::string::npos)
      << r.out;
}

TEST(CliAnalyze, AnUnboundedNetNamesItsUnboundedPlaces) {
  auto r = gdpn("analyze examples/basics/producer_consumer --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["bounded"], false);
  EXPECT_EQ(j["unbounded_places"], (nlohmann::json{"main/consumed"}));
  EXPECT_EQ(j["bounds"]["main/consumed"], "omega");
  EXPECT_TRUE(j["live"].is_null());
}

}  // namespace

namespace {

TEST(CliRender, APictureAMovieAndTheirMistakes) {
  const std::string png = (fs::temp_directory_path() / "gdpn_cli_render.png").string();
  auto r = gdpn("render tests/data/render/cube_lit.gdpn.yaml --at 0.5 --size 64x48 -o " + png);
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find(": 64x48 at t = 0.5 s"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(png));
  fs::remove(png);
  r = gdpn("render tests/data/render/cube_lit.gdpn.yaml --size 64by48 -o " + png);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: --size '64by48' is not WIDTHxHEIGHT"), std::string::npos) << r.out;
  r = gdpn("render tests/data/render/cube_lit.gdpn.yaml --camera nowhere -o " + png);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("error: no node at 'nowhere'; the scene's cameras: #0"), std::string::npos) << r.out;
  {
    // a wrong camera is told before the run to the picture's time: this model's script
    // fails at t = 1 s, and the camera's error comes instead
    const std::string model = temp("gdpn_camera_first.gdpn.yaml");
    std::ofstream(model) << "gdpn: 1\nscene:\n  - Transform: {name: rig, children: [{Camera: {name: top}}]}\n"
                            "  - Cube: {name: box}\npages:\n  main:\n    places:\n      P: {}\n    transitions:\n"
                            "      T:\n        guard: 'sim.time >= 1'\n        pre_fire: 'raise ValueError(\"late\")'\n"
                            "    arcs:\n      - T -> P\n";
    r = gdpn("render " + model + " --at 5 --camera rig/tpo -o " + png);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("error: no node at 'rig/tpo' (did you mean 'rig/top'?); the scene's cameras: rig/top"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("late"), std::string::npos) << r.out;
    r = gdpn("render " + model + " --at 5 --camera box -o " + png);
    EXPECT_NE(r.out.find("error: 'box' is a Cube, not a Camera or a camera sensor; the scene's cameras: rig/top"), std::string::npos)
        << r.out;
    fs::remove(model);
  }
  r = gdpn("render examples/basics/figure31 -o " + png);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("error: the model has no scene to draw"), std::string::npos) << r.out;
  r = gdpn("render tests/data/bad/mesh_corrupt.gdpn.yaml -o " + png);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("mesh_corrupt.gdpn.yaml:4:18: error: cannot read the mesh file 'files/corrupt.ply'"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(png));

  const std::string mp4 = (fs::temp_directory_path() / "gdpn_cli_record.mp4").string();
  r = gdpn("record tests/data/render/cube_lit.gdpn.yaml --until 1 --fps 10 --size 64x48 -o " + mp4);
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find(": 10 frames of 64x48 at 10 fps"), std::string::npos) << r.out;
  fs::remove(mp4);
  r = gdpn("record tests/data/render/cube_lit.gdpn.yaml --size 63x48 -o " + mp4);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: a movie needs an even width and height"), std::string::npos) << r.out;
}

TEST(CliRender, FromACameraSensorAtItsOwnSize) {
  // without --size, a picture or a movie from a ColorCamera takes the camera's 64 x 48
  const std::string png = temp("gdpn_cli_sensor.png"), mp4 = temp("gdpn_cli_sensor.mp4");
  auto r = gdpn("render examples/vision --camera line/mast/cam --at 1 -q -o " + png);
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find(": 64x48 at t = 1 s"), std::string::npos) << r.out;
  r = gdpn("record examples/vision --camera line/mast/cam --until 0.5 --fps 10 -q -o " + mp4);
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find(": 5 frames of 64x48 at 10 fps"), std::string::npos) << r.out;
  r = gdpn("record examples/vision --camera line/mast/cam --until 0.5 --size 96x72 -q -o " + mp4);
  EXPECT_NE(r.out.find("frames of 96x72"), std::string::npos) << r.out;
  // an odd camera cannot be filmed at its own size: the error says where the size came from
  const std::string odd = temp("gdpn_odd_camera.gdpn.yaml");
  std::ofstream(odd) << "gdpn: 1\nscene:\n  - ColorCamera: {name: cam, width: 65, height: 48}\n  - Cube: {}\n";
  r = gdpn("record " + odd + " --camera cam --until 0.5 -q -o " + mp4);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: a movie needs an even width and height, not 65x48 (the size of camera 'cam'; give --size)"),
            std::string::npos)
      << r.out;
  fs::remove(png);
  fs::remove(mp4);
  fs::remove(odd);
}

TEST(CliConvert, AMeshBecomesAModelWithItsSubtree) {
  const auto dir = fs::temp_directory_path() / "gdpn_cli_convert";
  fs::create_directories(dir);
  std::ofstream((dir / "part.iv").string()) << "#Inventor V2.1 ascii\nSeparator { Material { diffuseColor 1 0 0 } Cube {} "
                                               "Material { diffuseColor 0 0 1 } Sphere {} }\n";
  auto r = gdpn("convert " + (dir / "part.iv").string() + " " + (dir / "part.gdpn.yaml").string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(dir / "part.gdpn.yaml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("file: part.iv"), std::string::npos) << text;
  EXPECT_NE(text.find("part: 1"), std::string::npos) << text;
  EXPECT_NE(text.find("diffuse: [0, 0, 1]"), std::string::npos) << text;
  r = gdpn("check " + (dir / "part.gdpn.yaml").string());
  EXPECT_EQ(r.code, 0) << r.out;
  r = gdpn("convert " + (dir / "missing.obj").string() + " " + (dir / "x.gdpn.yaml").string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("missing.obj: error: cannot read the mesh file: no such file"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

}  // namespace

namespace {

TEST(Cli, RunStopsAtABreakpointAndSaysWhich) {
  const std::string model = "run examples/basics/producer_consumer --report /dev/stdout -q ";
  auto r = gdpn(model + "--break start:main/consume");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("stopped at breakpoint 1: starts main/consume"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"steps\": 100"), std::string::npos) << r.out;
  r = gdpn(model + "--break 'main/consumed>=2' --break 'when:sim.time >= 3'");
  EXPECT_NE(r.out.find("stopped at breakpoint 2: sim.time >= 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"stopped\": \"breakpoint\""), std::string::npos) << r.out;
  // a breakpoint the net cannot have, or one not written as one, is refused before the run
  r = gdpn(model + "--break complete:main/nope");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("error: --break 'complete:main/nope': no transition 'main/nope' in the net"),
            std::string::npos)
      << r.out;
  r = gdpn(model + "--break 'main/buffer=>3'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("expected start:TRANSITION"), std::string::npos) << r.out;
}

}  // namespace

namespace {

using gdpn::testing::fileBytes;
using gdpn::testing::ScratchFolder;

/// What `gdpn(args)` said about one bad number: exit 2, the option named, the text quoted.
void expectRefused(const std::string& args, const std::string& message) {
  const auto r = gdpn(args);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
  EXPECT_NE(r.out.find("gdpn: error: " + message), std::string::npos) << args << "\n" << r.out;
}

TEST(CliNumbers, NotANumberInfinityAndOutOfRangeAreRefusedNamingTheOption) {
  const std::string run = "run examples/basics/figure31 ";
  for (const char* bad : {"nan", "inf", "-inf", "-1", "1e400", "2e9", "5s", ""}) {
    expectRefused(run + "--until '" + bad + "'", std::string("--until: expected seconds from 0 to 1e9, got '") + bad + "'");
  }
  for (const char* bad : {"1e3", "-1", "2.5", "1000000000001"}) {
    expectRefused(run + "--steps " + bad, std::string("--steps: expected a whole number of steps from 0 to 10^12, got '") +
                                              bad + "'");
  }
  for (const char* bad : {"-1", "1.5", "18446744073709551616", "nan"}) {
    expectRefused(run + "--seed " + bad, std::string("--seed: expected a whole number from 0 to 2^64-1, got '") + bad + "'");
  }
  for (const char* bad : {"-0.5", "nan", "inf", "1e7"}) {
    expectRefused(run + "--script-timeout " + bad,
                  std::string("--script-timeout: expected seconds from 0 (never) to 1e6, got '") + bad + "'");
  }
  for (const char* bad : {"-1", "nan", "inf", "2e9"}) {
    expectRefused(run + "--script-memory " + bad,
                  std::string("--script-memory: expected mebibytes from 0 (no bound) to 1e9, got '") + bad + "'");
  }
  const std::string analyze = "analyze examples/basics/figure31 ";
  expectRefused(analyze + "--max-states 0", "--max-states: expected a whole number of states from 1 to 10^12, got '0'");
  expectRefused(analyze + "--max-states nan", "--max-states: expected a whole number of states from 1 to 10^12, got 'nan'");
  expectRefused(analyze + "--max-memory nan", "--max-memory: expected MiB above 0, at most 1e9, got 'nan'");
  expectRefused(analyze + "--max-memory=-inf", "--max-memory: expected MiB above 0, at most 1e9, got '-inf'");
  expectRefused(analyze + "--max-memory 1e300", "--max-memory: expected MiB above 0, at most 1e9, got '1e300'");
  expectRefused(analyze + "--threads 0", "--threads: expected a whole number of threads from 1 to 256, got '0'");
  expectRefused(analyze + "--threads 257", "--threads: expected a whole number of threads from 1 to 256, got '257'");
  const std::string render = "render tests/data/render/cube_lit.gdpn.yaml -o /tmp/gdpn_never.png ";
  expectRefused(render + "--at nan", "--at: expected seconds from 0 to 1e9, got 'nan'");
  expectRefused(render + "--at=-1", "--at: expected seconds from 0 to 1e9, got '-1'");
  expectRefused(render + "--samples 0", "--samples: expected a whole number of samples from 1 to 16, got '0'");
  const std::string record = "record tests/data/render/cube_lit.gdpn.yaml -o /tmp/gdpn_never.mp4 ";
  for (const char* bad : {"0", "nan", "inf", "1000.5", "-30"}) {
    expectRefused(record + "--fps " + bad,
                  std::string("--fps: expected frames per second above 0, at most 1000, got '") + bad + "'");
  }
  expectRefused(record + "--until 0", "--until: expected seconds above 0, at most 1e9, got '0'");
  expectRefused(record + "--until inf", "--until: expected seconds above 0, at most 1e9, got 'inf'");
  EXPECT_FALSE(fs::exists("/tmp/gdpn_never.png"));
  EXPECT_FALSE(fs::exists("/tmp/gdpn_never.mp4"));
}

TEST(CliNumbers, AHugeNumberIsQuotedShort) {
  const std::string digits(300, '9');
  const auto r = gdpn("run examples/basics/figure31 --until " + digits);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("gdpn: error: --until: expected seconds from 0 to 1e9, got '" + std::string(37, '9') +
                       "...' (300 characters)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find(std::string(38, '9')), std::string::npos) << r.out;
}

TEST(CliNumbers, SizesOutsideSixteenTo16384AreRefused) {
  // (the long one is a named string: a temporary's c_str() would dangle by the time the loop reads it)
  const std::string long_size(200, '1');
  for (const std::string& bad : {std::string("8x8"), std::string("16385x16"), std::string("0x720"), std::string("-64x48"),
                                 std::string("nanxnan"), std::string("64x48x2"), long_size}) {
    const auto r = gdpn("render tests/data/render/cube_lit.gdpn.yaml -o /tmp/gdpn_never.png --size=" + bad);
    EXPECT_EQ(r.code, 2) << bad << "\n" << r.out;
    EXPECT_NE(r.out.find("error: --size '"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("is not WIDTHxHEIGHT (for example 1280x720), each side 16 to 16384 pixels"), std::string::npos)
        << r.out;
    EXPECT_LT(r.out.size(), 200u) << r.out;
  }
  EXPECT_FALSE(fs::exists("/tmp/gdpn_never.png"));
}

TEST(CliNumbers, TheEdgesOfEachRangeAreAccepted) {
  EXPECT_EQ(gdpn("run examples/basics/figure31 -q --until 0").code, 0);
  EXPECT_EQ(gdpn("run examples/basics/figure31 -q --steps 0").code, 0);
  EXPECT_EQ(gdpn("run examples/basics/figure31 -q --seed 18446744073709551615").code, 0);
  EXPECT_EQ(gdpn("run examples/basics/figure31 -q --until +2.5e0 --script-timeout 1e6").code, 0);
  EXPECT_EQ(gdpn("analyze examples/basics/figure31 --threads 256 --max-states 1 --max-memory 1e9").code, 3);
}

/// A PNML net copied into `folder` as `name`.
std::string copyNet(const ScratchFolder& folder, const std::string& name) {
  const auto path = folder.file(name);
  fs::copy_file(fs::path(GDPN_SOURCE_DIR) / "tests/data/conformance/Philosophers-PT-000005.pnml", path);
  return path;
}

TEST(CliOutputs, ConvertWritesTheFormatOfTheOutputsExtension) {
  ScratchFolder folder("gdpn_cli_convert_formats");
  const auto net = copyNet(folder, "net.pnml");
  auto r = gdpn("convert " + net + " " + folder.file("copy.pnml"));
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fileBytes(folder.file("copy.pnml")).starts_with("<?xml")) << fileBytes(folder.file("copy.pnml"));
  r = gdpn("convert " + net + " " + folder.file("net.gdpn.yaml"));
  ASSERT_EQ(r.code, 0) << r.out;
  // the net's name (here its id: it has no <name>) is the model's description, and back
  EXPECT_NE(fileBytes(folder.file("net.gdpn.yaml")).find("description: \"Philosophers-PT-000005\""), std::string::npos);
  r = gdpn("convert " + folder.file("net.gdpn.yaml") + " " + folder.file("back.pnml"));
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fileBytes(folder.file("back.pnml")).starts_with("<?xml"));
  EXPECT_NE(fileBytes(folder.file("back.pnml")).find("<name><text>Philosophers-PT-000005</text></name>"), std::string::npos);
  // an extension that names no format is refused before anything is read or written
  r = gdpn("convert " + net + " " + folder.file("net.txt"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: OUT '" + folder.file("net.txt") + "' must end in .pnml (a PNML net) or .gdpn.yaml (a model)"),
            std::string::npos)
      << r.out;
  r = gdpn("convert " + folder.file("part.obj") + " " + folder.file("part.pnml"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: a mesh converts to a model (.gdpn.yaml), not to PNML"), std::string::npos) << r.out;
  EXPECT_EQ(folder.names(), (std::vector<std::string>{"back.pnml", "copy.pnml", "net.gdpn.yaml", "net.pnml"}));
}

TEST(CliOutputs, AnOutputOverAnInputIsRefusedBeforeAnythingIsWritten) {
  ScratchFolder folder("gdpn_cli_same_file");
  const auto net = copyNet(folder, "net.pnml");
  const auto before = fileBytes(net);
  auto r = gdpn("convert " + net + " " + net);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: OUT '" + net + "' is the input file; gdpn writes no output over it"), std::string::npos)
      << r.out;
  const auto dotted = (folder.dir() / "." / "net.pnml").string();
  r = gdpn("convert " + net + " " + dotted);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: OUT '" + dotted + "' is the input file"), std::string::npos) << r.out;
  EXPECT_EQ(fileBytes(net), before);

  ASSERT_EQ(gdpn("convert " + net + " " + folder.file("m.gdpn.yaml")).code, 0);
  const auto model = fileBytes(folder.file("m.gdpn.yaml"));
  r = gdpn("run " + folder.dir().string() + " -q --report " + folder.file("m.gdpn.yaml"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: --report '" + folder.file("m.gdpn.yaml") + "' is the model file"), std::string::npos)
      << r.out;
  r = gdpn("run " + folder.file("m.gdpn.yaml") + " -q --trace " + folder.file("m.gdpn.yaml"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: --trace '" + folder.file("m.gdpn.yaml") + "' is the model file"), std::string::npos)
      << r.out;
  r = gdpn("run " + folder.file("m.gdpn.yaml") + " -q --trace " + folder.file("t.jsonl") + " --report " +
           folder.file("t.jsonl"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: --report '" + folder.file("t.jsonl") + "' is the --trace file"), std::string::npos)
      << r.out;
  EXPECT_EQ(fileBytes(folder.file("m.gdpn.yaml")), model);
  r = gdpn("render tests/data/render/cube_lit.gdpn.yaml -o tests/data/render/../../data/render/cube_lit.gdpn.yaml");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("error: -o 'tests/data/render/../../data/render/cube_lit.gdpn.yaml' is the model file"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(folder.names(), (std::vector<std::string>{"m.gdpn.yaml", "net.pnml"}));
}

/// `gdpn(args)` with files limited to about 1 KiB, as on a disk that is full.
Result gdpnOnAFullDisk(const std::string& args) {
  return shell("trap '' XFSZ; ulimit -f 2; \"$GDPN\" " + args); }

TEST(CliOutputs, AFailedWriteKeepsTheOldFileByteForByteAndLeavesNoTemporary) {
  ScratchFolder folder("gdpn_cli_full_disk");
  const auto net = copyNet(folder, "net.pnml");
  const std::string old = "the old file\n";
  for (const char* name : {"out.pnml", "out.gdpn.yaml", "trace.jsonl", "picture.png"}) std::ofstream(folder.file(name)) << old;
  const auto expectFailed = [&](const std::string& args, const std::string& file) {
    const auto r = gdpnOnAFullDisk(args);
    EXPECT_EQ(r.code, 1) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(folder.file(file) + ": error: cannot write the file: File too large"), std::string::npos)
        << args << "\n" << r.out;
    EXPECT_EQ(fileBytes(folder.file(file)), old) << file;
  };
  expectFailed("convert " + net + " " + folder.file("out.pnml"), "out.pnml");
  expectFailed("convert " + net + " " + folder.file("out.gdpn.yaml"), "out.gdpn.yaml");
  expectFailed("run tests/data/good/stochastic.gdpn.yaml -q --trace " + folder.file("trace.jsonl"), "trace.jsonl");
  expectFailed("render tests/data/render/cube_lit.gdpn.yaml --size 256x256 -o " + folder.file("picture.png"),
               "picture.png");
  // a stream that cannot take the bytes is a failed write too
  const auto r = gdpn("run examples/basics/figure31 -q --report /dev/full");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("/dev/full: error: cannot write the file: No space left on device"), std::string::npos) << r.out;
  EXPECT_EQ(folder.names(),
            (std::vector<std::string>{"net.pnml", "out.gdpn.yaml", "out.pnml", "picture.png", "trace.jsonl"}));
}

TEST(CliOutputs, AKilledEncoderKeepsTheOldMovie) {
  ScratchFolder folder("gdpn_cli_killed_ffmpeg");
  // an ffmpeg that writes a little of its output, then dies
  fs::create_directories(folder.dir() / "bin");
  const auto fake = folder.file("bin/ffmpeg");
  std::ofstream(fake) << "#!/bin/sh\nfor a in \"$@\"; do out=\"$a\"; done\nprintf partial > \"$out\"\nkill -9 $$\n";
  fs::permissions(fake, fs::perms::owner_all);
  const auto movie = folder.file("movie.mp4");
  std::ofstream(movie) << "the old movie\n";
  const auto r = shell("PATH='" + folder.file("bin") + "':\"$PATH\" \"$GDPN\" record tests/data/render/cube_lit.gdpn.yaml "
                       "--until 1 --fps 10 --size 64x48 -o " + movie);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(movie + ": error: ffmpeg "), std::string::npos) << r.out;
  EXPECT_EQ(fileBytes(movie), "the old movie\n");
  EXPECT_EQ(folder.names(), (std::vector<std::string>{"bin", "movie.mp4"}));
}

TEST(CliOutputs, AMovieCutShortByAFullDiskFailsAndKeepsTheOldOne) {
  // under a file size limit (a full disk) ffmpeg's writes fail; SIGXFSZ ignored, as a full
  // disk sends none, ffmpeg used to log "Error writing trailer" and exit 0: a cut movie
  ScratchFolder folder("gdpn_cli_movie_full_disk");
  const auto movie = folder.file("movie.mp4");
  std::ofstream(movie) << "the old movie\n";
  const auto r = gdpnOnAFullDisk("record tests/data/render/cube_lit.gdpn.yaml --until 2 --fps 10 --size 320x240 -o " +
                                 movie);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(movie + ": error: ffmpeg failed: "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("frames of"), std::string::npos) << r.out;
  EXPECT_EQ(fileBytes(movie), "the old movie\n");
  EXPECT_EQ(folder.names(), (std::vector<std::string>{"movie.mp4"}));
}

TEST(CliOutputs, ARecordedMovieReplacesTheOldOne) {
  ScratchFolder folder("gdpn_cli_movie_replaced");
  const auto movie = folder.file("movie.mp4");
  std::ofstream(movie) << "the old movie\n";
  const auto r = gdpn("record tests/data/render/cube_lit.gdpn.yaml --until 0.5 --fps 10 --size 64x48 -o " + movie);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_GT(fs::file_size(movie), 100u);
  EXPECT_EQ(folder.names(), (std::vector<std::string>{"movie.mp4"}));
}


TEST(CliRun, ParamSetsAParameterForTheRunAndMistakesNameTheArgument) {
  // three parts of 0.5 s by default; two of 0.25 s with the parameters set
  auto r = gdpn("run tests/data/good/params.gdpn.yaml --until 10 --quiet --report /dev/stdout");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("\"name\": \"main/work\",\n      \"occurrences\": 3"), std::string::npos) << r.out;
  r = gdpn("run tests/data/good/params.gdpn.yaml --until 10 --quiet --param parts=2 --param wait=0.25 --report /dev/stdout");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("\"name\": \"main/work\",\n      \"occurrences\": 2"), std::string::npos) << r.out;
  // the report says what the run had, so that it can be made again
  EXPECT_NE(r.out.find("\"params\": {\n    \"wait\": 0.25,\n    \"parts\": 2,\n"), std::string::npos) << r.out;
  r = gdpn("run tests/data/good/params.gdpn.yaml --until 1 --param parts=2 2>/dev/null");
  EXPECT_NE(r.out.find("\nparameters: wait = 0.5 s, parts = 2, spread = 0.25, belt_speed = 0.4 m/s, lane = 2, chance = "
                       "0.5\n\n"),
            std::string::npos)
      << r.out;
  r = gdpn("check tests/data/good/params.gdpn.yaml --param wiat=1");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "--param: error: no parameter 'wiat' in tests/data/good/params.gdpn.yaml (did you mean 'wait'?)\n1 error\n");
  r = gdpn("run tests/data/good/params.gdpn.yaml --param parts");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--param: expects NAME=VALUE, got 'parts'"), std::string::npos) << r.out;
  r = gdpn("analyze tests/data/good/params.gdpn.yaml --param parts=two");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("--param: error: parameter 'parts' expects a number, got 'two'"), std::string::npos) << r.out;
}
TEST(CliParts, APatternIsAddedWithItsRolesAndAMistakeLeavesTheModelAlone) {
  const gdpn::testing::ScratchFolder dir("gdpn_parts_cli");
  const std::string model = dir.file("s.gdpn.yaml");
  { std::ofstream(model) << "gdpn: 1\n"; }
  for (const char* add : {"belt_conveyor --at 1 0 0", "diffuse_sensor --at 1.3 0 0"}) {
    const auto r = gdpn(std::string("parts --model ") + model + " --add " + add);
    ASSERT_EQ(r.code, 0) << r.out;
  }
  const std::string before = gdpn::testing::fileBytes(model);
  // a role filled by a part without its I/O, a role given twice, an unknown pattern: refused,
  // and the file as it was
  auto r = gdpn("parts --model " + model + " --add pusher --at 1 0 0 --pattern pusher_sort --use eye=belt_conveyor1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("--add: error: 'belt_conveyor1' is a belt_conveyor, which has no detected, colour: role 'eye' of "
                       "'pusher_sort' needs a part with detected, colour (the model is left as it was)"),
            std::string::npos)
      << r.out;
  r = gdpn("parts --model " + model + " --add pusher --pattern pusher_sort --use eye=diffuse_sensor1 --use eye=diffuse_sensor1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("role 'eye' is given twice"), std::string::npos) << r.out;
  r = gdpn("parts --model " + model + " --add pusher --pattern pusher_sorts");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("'pusher_sorts' is no control pattern of 'pusher' (it has: pusher_control, pusher_sort)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(gdpn::testing::fileBytes(model), before);
  // the roles filled by the nearest parts that fit
  r = gdpn("parts --model " + model + " --add pusher --at 1 0 0 --pattern pusher_sort");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out, "added main/pusher1\nadded main/pusher1_sort\n");
  EXPECT_NE(gdpn::testing::fileBytes(model).find(
                "pusher1_sort: {type: pusher_sort, part: pusher1, uses: {eye: diffuse_sensor1, belt: belt_conveyor1}}"),
            std::string::npos);
  EXPECT_EQ(gdpn("check " + model).code, 0);
}

TEST(CliRun, SignalsAreWrittenAsCsvAndMistakesNameTheArgument) {
  const gdpn::testing::ScratchFolder dir("gdpn_signals");
  auto r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --quiet --signals " + dir.file("s.csv") +
                " --signal place:main/clock --signal 'python:sim.step' --signal-every 0.5");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string csv = gdpn::testing::fileBytes(dir.file("s.csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n') + 1), "time,ball.x,ball.y,ball.z,speed.x,speed.y,speed.z,ticks,clock,main/clock,sim.step\n");
  EXPECT_NE(csv.find("\n0.5,0,0,18.749225,0,0,-4.9049999999999985,5,1,0,50\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n0.51,0,0,18.699194,,,,,,,\n"), std::string::npos) << csv;
  r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --signal place:main/clock");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "error: --signal records into a table or a page: add --signals FILE.csv or --html FILE.html\n");
  r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --signals " + dir.file("t.csv") + " --signal clock");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--signal: expects place:NAME, node:PATH.QUANTITY or python:EXPRESSION, got 'clock'"),
            std::string::npos);
  r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --signals " + dir.file("t.csv") + " --signal node:drop/ball.mas");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "--signal node:drop/ball.mas: error: signal 'drop/ball.mas': a Body has no number 'mas' (did you mean "
                   "'mass'?) (it has: position, velocity, mass, density, linear_damping, angular_damping)\n");
  EXPECT_FALSE(fs::exists(dir.file("t.csv")));
}

TEST(CliRun, HtmlWritesOnePageWithThePlotsAndTheSignalsAndRefusesToOverwriteInputs) {
  const gdpn::testing::ScratchFolder dir("gdpn_html");
  auto r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --quiet --until 1 --html " + dir.file("r.html") +
                " --signal 'python:sim.step'");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string page = gdpn::testing::fileBytes(dir.file("r.html"));
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>")) << page.substr(0, 200);
  EXPECT_TRUE(page.ends_with("</html>\n"));
  // the section's signals and the --signal one, each in the signals plot's list
  EXPECT_NE(page.find("<h2>Signals</h2>"), std::string::npos);
  EXPECT_NE(page.find("<h2>Tokens over time</h2>"), std::string::npos);
  EXPECT_NE(page.find("<svg"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);  // nothing runs, nothing is fetched
  // the same run gives the same page
  r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --quiet --until 1 --html " + dir.file("s.html") +
           " --signal 'python:sim.step'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(gdpn::testing::fileBytes(dir.file("s.html")), page);
  // a folder that is not there: an error naming the file, and nothing written
  r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --quiet --until 0.1 --html " + dir.file("no/r.html"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(r.out.starts_with(dir.file("no/r.html") + ": error: ")) << r.out;
  EXPECT_FALSE(fs::exists(dir.file("no")));
  r = gdpn("run tests/data/good/falling_ball.gdpn.yaml --quiet --report " + dir.file("r.json") + " --html " +
           dir.file("r.json"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--html"), std::string::npos) << r.out;
}

TEST(CliRun, AHybridNetsPagePlotsEveryLevelAndItsSummarySaysTheAmounts) {
  // the fill model: 0.3 L/s for 3.4 s, then held until the net is dead at 3.5 s
  const gdpn::testing::ScratchFolder dir("gdpn_html_hybrid");
  auto r = gdpn("run tests/data/hybrid/fill.gdpn.yaml --until 5 --break 'main/tank>=0.5' --html " + dir.file("h.html"));
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("stopped at breakpoint 1: main/tank >= 0.5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  main/tank: 0.51 L at the end (0 to 0.51 L, mean 0.255 L)\n"), std::string::npos) << r.out;
  const std::string page = gdpn::testing::fileBytes(dir.file("h.html"));
  EXPECT_NE(page.find("<h2>Levels over time</h2>"), std::string::npos);
  EXPECT_NE(page.find("<h2>Continuous places</h2>"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"\">main/tank</td><td class=\"\">L</td><td class=\"num\">0.51</td>"),
            std::string::npos);
}

TEST(CliRun, RandomTiesChooseByTheSeedAndTheSameSeedGivesTheSameTrace) {
  const gdpn::testing::ScratchFolder dir("gdpn_ties");
  // the routes each part took: {go_left, go_right} occurrences
  auto routes = [&](const std::string& model, int seed) {
    const auto r = gdpn("run " + model + " --quiet --seed " + std::to_string(seed) + " --report " +
                        dir.file("r.json") + " --trace " + dir.file("t" + std::to_string(seed) + ".jsonl"));
    EXPECT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(gdpn::testing::fileBytes(dir.file("r.json")));
    return std::pair<std::int64_t, std::int64_t>{j["transitions"][1]["occurrences"], j["transitions"][2]["occurrences"]};
  };
  const std::string model = "tests/data/good/random_ties.gdpn.yaml";
  EXPECT_EQ(routes(model, 1), (std::pair<std::int64_t, std::int64_t>{16, 24}));
  const std::string first = gdpn::testing::fileBytes(dir.file("t1.jsonl"));
  EXPECT_EQ(routes(model, 2), (std::pair<std::int64_t, std::int64_t>{18, 22}));
  EXPECT_EQ(routes(model, 1), (std::pair<std::int64_t, std::int64_t>{16, 24}));
  EXPECT_EQ(gdpn::testing::fileBytes(dir.file("t1.jsonl")), first);
  // in declaration order every part goes left, whatever the seed
  std::string text = gdpn::testing::fileBytes(std::string(GDPN_SOURCE_DIR) + "/" + model);
  text.replace(text.find(", ties: random"), 14, "");
  std::ofstream(dir.file("order.gdpn.yaml")) << text;
  EXPECT_EQ(routes(dir.file("order.gdpn.yaml"), 1), (std::pair<std::int64_t, std::int64_t>{40, 0}));
  EXPECT_EQ(routes(dir.file("order.gdpn.yaml"), 2), (std::pair<std::int64_t, std::int64_t>{40, 0}));
}

TEST(CliRun, ServersRunOccurrencesAtOnceEachWithItsOwnScriptsAndFigures) {
  const gdpn::testing::ScratchFolder dir("gdpn_servers");
  auto run = [&](const std::string& extra) {
    const auto r = gdpn("run tests/data/good/servers.gdpn.yaml --report " + dir.file("r.json") + " " + extra);
    EXPECT_EQ(r.code, 0) << r.out;
    return std::pair{r.out, nlohmann::json::parse(gdpn::testing::fileBytes(dir.file("r.json")))};
  };
  const auto [text, j] = run("");
  // ten parts fed every 0.5 s through two spindles of 2 s: done when the last has cooled
  EXPECT_EQ(j["time"], 14.0);
  const auto& machine = j["transitions"][1];
  EXPECT_EQ(machine["servers"], 2);
  EXPECT_NEAR(machine["mean_busy"].get<double>(), 20.0 / 14.0, 1e-12);  // ten occurrences of 2 s
  EXPECT_NEAR(machine["utilisation"].get<double>(), 10.0 / 14.0, 1e-12);
  EXPECT_EQ(j["transitions"][2]["servers"], "unlimited");
  EXPECT_TRUE(j["transitions"][2]["utilisation"].is_null());
  EXPECT_FALSE(j["transitions"][0].contains("servers"));
  // post_fire sees its own occurrence: every machining took 2 s, and every cooling's start
  // read at its completion is one of the starts read at pre_fire, though some overtook others
  const auto& f = j["figures"];
  EXPECT_EQ(f["machining shortest"], 2.0);
  EXPECT_EQ(f["machining longest"], 2.0);
  EXPECT_EQ(f["parts cooled"], 10);
  EXPECT_EQ(f["cooling starts match"], "True");
  EXPECT_EQ(f["coolings overtaken"], 3);
  EXPECT_EQ(f["most cooling at once"], 5);
  EXPECT_NE(text.find("utilisation  at once  servers\n"), std::string::npos) << text;
  EXPECT_NE(text.find("main/machine             10           0.944          1.500       71.4 %     1.43        2\n"),
            std::string::npos)
      << text;
  // one spindle: the machine is the bottleneck, a part every 2 s, and the run is cut at 20 s
  const auto [one_text, one] = run("--param spindles=1");
  EXPECT_FALSE(one["transitions"][1].contains("servers"));
  EXPECT_EQ(one["transitions"][1]["mean_cycle"], 2.0);
  EXPECT_EQ(one["figures"]["parts machined"], 9);
}

TEST(Cli, CheckSaysEachWarningOnceWhenItAlsoBuildsThePlant) {
  const gdpn::testing::ScratchFolder dir("gdpn_check_once");
  std::ofstream(dir.file("w.gdpn.yaml")) << "gdpn: 1\nscene:\n  - World: {}\npages:\n  main:\n"
                                            "    places: {p: {}}\n    transitions: {t: {}}\n    arcs: [t -> p]\n";
  const auto r = gdpn("check " + dir.file("w.gdpn.yaml") + " 2>&1 >/dev/null");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, dir.file("w.gdpn.yaml") +
                       ":7:19: warning: transition 't' has no input arcs: it starts again in every step it is not "
                       "occurring\n");
}

}  // namespace
