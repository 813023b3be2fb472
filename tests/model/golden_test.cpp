// The gdpn program as a user runs it: exit codes, diagnostics on stderr, summary, report, trace.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli.h"

namespace {

namespace fs = std::filesystem;

using Result = gdpn::testing::CliResult;

Result gdpn(const std::string& args) { return gdpn::testing::runGdpn(args); }

std::string temp(const std::string& name) { return (fs::temp_directory_path() / name).string(); }

TEST(Cli, CheckAcceptsEveryExampleAndGoodModel) {
  for (const char* dir : {"examples", "tests/data/good"}) {
    for (const auto& e : fs::recursive_directory_iterator(fs::path(GDPN_SOURCE_DIR) / dir)) {
      if (!e.path().string().ends_with(".gdpn.yaml")) continue;
      const auto r = gdpn("check '" + e.path().string() + "'");
      EXPECT_EQ(r.code, 0) << e.path() << "\n" << r.out;
      EXPECT_NE(r.out.find(": ok ("), std::string::npos) << r.out;
    }
  }
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
  EXPECT_NE(r.out.find("error: pre_fire of transition 'main/spin' ran longer than the script timeout of 0.3 s"),
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
  // start the run in the background, interrupt it once the script is spinning
  const std::string out = temp("gdpn_sigint.out");
  const std::string cmd = std::string("cd '") + GDPN_SOURCE_DIR + "' && ('" + GDPN_CLI +
                          "' run tests/data/good/endless_script.gdpn.yaml -q > '" + out +
                          "' 2>&1 & pid=$!; sleep 1; kill -INT $pid; wait $pid; echo \"exit $?\" >> '" + out + "')";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  EXPECT_NE(text.str().find("error: pre_fire of transition 'main/spin' was interrupted (Ctrl-C)"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("exit 130"), std::string::npos) << text.str();
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
  r = gdpn("analyze examples/basics/figure31 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["states"], 3);
  EXPECT_EQ(j["deadlock_path"], (nlohmann::json{"main/T1", "main/T2"}));
  EXPECT_EQ(j["one_safe"], true);
  r = gdpn("analyze tests/data/conformance/Philosophers-PT-000005.pnml --threads 2");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("243 states, 945 edges"), std::string::npos) << r.out;
  r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml --max-states 100");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("(partial: --max-states reached;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("live:            unknown"), std::string::npos) << r.out;
  r = gdpn("analyze tests/data/conformance/Referendum-PT-0010.pnml --max-memory 0.5 --progress");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("(partial: --max-memory reached;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" states/s, "), std::string::npos) << r.out;  // the progress line
}

TEST(CliAnalyze, TwoCyclesGiveBothCycleTimesAndTheLargerAsTheBound) {
  auto r = gdpn("analyze tests/data/good/cycles.gdpn.yaml");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("  4.000 s  main/a_ready + main/a_half (1 token; circuit main/a1 -> main/a2)\n"
                       "  1.000 s  main/b_ready + main/b_one + main/b_two (1 token; circuit main/b1 -> main/b2 -> main/b3)\n"
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
  EXPECT_NE(r.out.find("main/a_ready + main/a_half                     1       4.000         4.000       0.000"),
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
  EXPECT_NE(r.out.find("error: no Camera node at 'nowhere'"), std::string::npos) << r.out;
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
