// `gdpn run`: a headless run of a model (session::RunRequest) with its summary, report,
// trace, signals, HTML page, breakpoints, witness replay and Modbus serving.

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <sstream>

#include "cli_checks.h"
#include "commands.h"
#include "gdpn/core/output_file.h"
#include "gdpn/experiments/html_report.h"
#include "gdpn/model/report.h"
#include "gdpn/model/simulation.h"
#include "gdpn/session/breakpoint_syntax.h"
#include "serve.h"

namespace gdpn::app {

namespace {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

/// `gdpn run`'s arguments.
struct RunArgs {
  std::string model;
  std::optional<double> until;
  std::optional<std::int64_t> steps;
  std::optional<std::uint64_t> seed;
  std::string trace;
  std::string report;
  gdpn::script::ScriptLimits limits;  // --script-timeout, --script-memory
  std::string input;
  std::vector<std::string> breaks;
  std::string replay;  // a witness file to play
  bool quiet = false;
  std::vector<std::string> params;  // --param NAME=VALUE
  std::vector<std::string> signals;  // --signal place:P | node:PATH.Q | python:EXPR
  double signal_every = 0.0;         // their period, seconds (0: every step)
  std::string signals_out;           // --signals FILE.csv
  std::string html;                  // --html FILE.html
  ServeArgs serve;        // --modbus, --opcua, --opcua-client, --realtime, --lockstep
};

int run(const RunArgs& a) {
  const std::vector<std::pair<std::string, std::string>> inputs = {{"the model file", modelFile(a.model)},
                                                                    {"the --input file", a.input}};
  auto with_trace = inputs;
  with_trace.emplace_back("the --trace file", a.trace);
  if (overwritesInput("--trace", a.trace, inputs) || overwritesInput("--report", a.report, with_trace) ||
      overwritesInput("--signals", a.signals_out, with_trace) ||
      overwritesInput("--signals", a.signals_out, {{"the --report file", a.report}}) ||
      overwritesInput("--html", a.html, with_trace) ||
      overwritesInput("--html", a.html, {{"the --report file", a.report}, {"the --signals file", a.signals_out}})) {
    return 2;
  }
  std::vector<model::SignalSpec> extra;
  for (const auto& arg : a.signals) {
    std::string why;
    auto spec = model::parseSignalArgument(arg, why);
    if (!spec) {
      std::cerr << "error: --signal: " << why << "\n";
      return 2;
    }
    spec->every = a.signal_every;
    extra.push_back(std::move(*spec));
  }
  if (!extra.empty() && a.signals_out.empty() && a.html.empty()) {
    std::cerr << "error: --signal records into a table or a page: add --signals FILE.csv or --html FILE.html\n";
    return 2;
  }
  // with a report to show or write, its cycles are worked out first and each token with
  // alternative circuits watched, so that each circuit's cycle is measured; the page's plots
  // need every occurrence and every change of tokens (up to a budget)
  session::RunRequest request;
  request.report = !a.quiet || !a.report.empty() || !a.html.empty();
  request.timeline = !a.html.empty();
  request.echo_log = !a.quiet;  // sim.log still goes to the trace
  auto sim = open(a.model, a.seed, a.limits, a.params, request);
  if (!sim) return 1;
  if (!a.signals_out.empty() || !a.html.empty()) {
    Diagnostics diags;
    const bool ok = sim->simulation().recordSignals(extra, diags);
    diags.print(std::cerr);
    if (!ok) return 1;
  }
  for (const auto& spec : a.breaks) {
    const auto bp = session::parseBreakpoint(spec);
    std::string why = bp ? std::string() : bp.error().message;
    if (!bp || !sim->addBreakpoint(*bp, why)) {
      std::cerr << "error: --break " << quoteArg(spec) << ": " << why << "\n";
      return 2;
    }
  }
  if (!a.input.empty()) {
    Diagnostics diags;
    auto events = model::loadInput(a.input, diags);
    diags.print(std::cerr);
    if (!events) return 1;
    sim->setInput(std::move(*events));
  }
  if (!a.replay.empty()) {
    Diagnostics diags;
    const bool ok = sim->replay(a.replay, diags);
    diags.print(std::cerr);
    if (!ok) return 1;
  }
  // the trace is written beside its file and renamed into place when the run ends
  std::unique_ptr<gdpn::core::OutputFile> trace;
  std::string why;
  if (!a.trace.empty()) {
    trace = std::make_unique<gdpn::core::OutputFile>(a.trace);
    if (!trace->open(why)) {
      std::cerr << a.trace << ": error: " << why << "\n";
      return 1;
    }
    sim->traceTo(trace->stream());
  }
  link::Serving serving;
  if (int code = 0; !serving.start(a.serve, sim->simulation(), &g_interrupted, a.quiet, std::cerr, code)) return code;
  std::signal(SIGINT, onSigint);
  std::signal(SIGTERM, onSigint);  // a launcher that stops the run still gets its trace and summary
  model::RunOutcome outcome;
  {
    ProgressBar bar(!a.quiet && isatty(STDERR_FILENO));
    outcome = sim->run({a.until, a.steps}, std::ref(bar), &g_interrupted);
  }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (trace && !trace->commit(why)) {
    std::cerr << a.trace << ": error: " << why << "\n";
    return 1;
  }
  if (outcome.reason == model::StopReason::Breakpoint) std::cerr << "stopped at " << outcome.message << "\n";
  // how far a replay got: every firing started and the witness' marking reached, or not (1)
  int replay_failed = 0;
  if (const auto verdict = sim->replayVerdict()) {
    std::cerr << (verdict->done ? "" : a.replay + ": error: ") << verdict->message << "\n";
    replay_failed = verdict->done ? 0 : 1;
  }
  // the report only when it is shown or written (it works out the cycle bounds)
  if (request.report) {
    const auto report = sim->report(outcome);
    // written as it is made: at 100,000 instances the text alone is 135 MB
    auto json = [&report](std::ostream& out) { model::writeReportJson(out, report); };
    if (!a.report.empty() && !gdpn::core::writeOutput(a.report, json, why)) {
      std::cerr << a.report << ": error: " << why << "\n";
      return 1;
    }
    if (!a.quiet) model::printSummary(std::cout, report);
    if (!a.quiet) serving.finish(sim->simulation(), std::cout);
    if (!a.html.empty()) {
      const auto page = gdpn::experiments::htmlReport(report, sim->simulation().net(), *sim->timeline(),
                                                      sim->simulation().signals(), why, sim->simulation().levels());
      if (!page || !gdpn::core::writeOutput(a.html, *page, why)) {
        std::cerr << a.html << ": error: " << (page ? "" : "the page could not be drawn: ") << why
                  << (why.ends_with('\n') ? "" : "\n");
        return 1;
      }
    }
  }
  if (!a.signals_out.empty()) {
    std::ostringstream csv;
    sim->simulation().signals()->writeCsv(csv);
    if (!gdpn::core::writeOutput(a.signals_out, csv.str(), why)) {
      std::cerr << a.signals_out << ": error: " << why << "\n";
      return 1;
    }
  }
  if (!serving.failure().empty()) {  // the PLC went: the run stopped short
    std::cerr << "error: " << serving.failure() << "\n";
    return 1;
  }
  switch (outcome.reason) {
    case model::StopReason::ScriptError:
    case model::StopReason::PhysicsError:
      std::cerr << outcome.message << (outcome.message.ends_with('\n') ? "" : "\n");
      return 1;
    case model::StopReason::Interrupted:
      if (!outcome.message.empty()) std::cerr << outcome.message << '\n';
      return 130;
    case model::StopReason::Until:
    case model::StopReason::Dead:
    case model::StopReason::Stopped:
    case model::StopReason::Breakpoint:
      return replay_failed;
  }
  return replay_failed;
}

}  // namespace

Subcommand addRun(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* run_cmd = app.add_subcommand("run", "Run a model headless and print a summary");
  run_cmd->add_option("MODEL", args->model, "a .gdpn.yaml file, or a folder holding exactly one")->required();
  auto* until = run_cmd->add_option("--until", args->until, "end time in seconds (default: the model's until)")
                    ->check(number(0.0, kMaxTime, "seconds from 0 to 1e9"));
  run_cmd->add_option("--steps", args->steps, "number of steps to run")
      ->check(number<std::int64_t>(0, 1'000'000'000'000, "a whole number of steps from 0 to 10^12"))
      ->excludes(until);
  run_cmd->add_option("--seed", args->seed, "seed of the random generator (default: the model's seed)")
      ->check(seedCheck());
  run_cmd->add_option("--trace", args->trace, "write every event as JSON Lines to FILE.jsonl");
  run_cmd->add_option("--report", args->report, "write the figures as JSON to FILE.json");
  addScriptLimitOptions(run_cmd, args->limits);
  run_cmd->add_option("--input", args->input,
                      "input events for keyboard and mouse sensors: a YAML list of {t, key | click | viewpoint}");
  run_cmd->add_option("--break", args->breaks,
                      "stop the run at the end of the step where start:TRANSITION or complete:TRANSITION "
                      "happens, PLACE>=N holds (or <, <=, ==, !=, >; a continuous place's amount: main/tank>=2.5), or "
                      "when:PYTHON is true (repeatable)");
  run_cmd->add_option("--replay", args->replay,
                      "play the firing sequence of a witness (gdpn analyze --witness): only its transitions "
                      "start, in its order, each as soon as it can");
  addParamOption(run_cmd, args->params);
  run_cmd->add_option("--html", args->html,
                      "write a self-contained HTML page of the run to FILE.html: the summary tables and plots "
                      "(tokens over time, occurrences, throughput, cycles beside their bounds, signals)");
  run_cmd->add_option("--signals", args->signals_out,
                      "write the model's signals (its signals section and each --signal) over time to FILE.csv");
  run_cmd->add_option("--signal", args->signals,
                      "record one more signal: place:NAME (its tokens), place:NAME=VALUE (a value slot's tokens of "
                      "that value), node:PATH.QUANTITY (position, velocity, "
                      "angle, rate, reading or a number field), python:EXPRESSION (repeatable)")
      ->allow_extra_args(false);
  run_cmd->add_option("--signal-every", args->signal_every,
                      "the --signal signals' sampling period in seconds (default: every step)")
      ->check(number(0.0, kMaxTime, "seconds above 0, at most 1e9", true));
  addServeOptions(*run_cmd, args->serve);
  run_cmd->add_flag("--quiet,-q", args->quiet,
                    "print no summary, no progress and no sim.log lines (they still go to the --trace)");
  setExamples(run_cmd, {"gdpn run examples/factory --until 120 --html factory.html   # summary; a page of plots",
               "gdpn run examples/basics/producer_consumer --seed 7 --trace run.jsonl --report run.json"});
  return {run_cmd, [args] { return run(*args); }};
}

}  // namespace gdpn::app
