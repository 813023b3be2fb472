// `gdpn analyze`: the untimed analysis of a model or a PNML net (session::AnalysisRequest),
// the answers to queries, or the reachability graph.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_checks.h"
#include "commands.h"
#include "gdpn/core/file.h"
#include "gdpn/core/output_file.h"
#include "gdpn/model/analysis.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/unfold.h"
#include "gdpn/session/analysis_request.h"

namespace gdpn::app {

namespace {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

/// `gdpn analyze`'s arguments: the request (limits and search), and what the command line
/// alone adds.
struct AnalyzeArgs {
  std::string model;
  session::AnalysisRequest request;  // --max-states, --max-memory, --time-limit, --threads, ...
  bool json = false;
  bool progress = false;
  std::vector<std::string> queries;  // formulas, or files of them
  std::string witness;               // where to write the first answer's witness
  std::string graph;                 // write the reachability graph here (.dot or .aut) instead
  std::vector<std::string> params;   // --param NAME=VALUE
  std::string colours = "auto";      // --colours: auto, unfold or native
};

/// Reads the --query arguments: each is a file of formulas (one per line; blank lines and
/// lines starting with # skipped) when such a file exists, else a formula itself. Mistakes
/// go to `err` located (file:line:col, or the argument's number and column) with the line
/// and a caret; nullopt when there was one.
std::optional<std::vector<model::QueryResult>> readQueries(const gdpn::net::Net& net,
                                                          const std::vector<std::string>& args, std::ostream& err,
                                                          const gdpn::net::NameExpansion* names) {
  std::vector<model::QueryResult> out;
  bool ok = true;
  auto read = [&](const std::string& where, const std::string& text) {
    gdpn::net::QueryError e;
    if (auto f = gdpn::net::parseQuery(net, text, e, names)) {
      model::QueryResult r;
      r.text = text;
      r.formula = std::move(*f);
      out.push_back(std::move(r));
      return;
    }
    ok = false;
    err << where << ":" << e.column << ": error: " << e.message << "\n  " << text << "\n  "
        << std::string(e.column - 1, ' ') << "^\n";
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    // a path that exists is a file of queries (readFile says what is wrong with one that is
    // not a regular file); anything else is a formula
    std::error_code ec;
    if (!std::filesystem::exists(args[i], ec)) {
      read("--query " + std::to_string(i + 1) + ":1", args[i]);
      continue;
    }
    Diagnostics diags;
    const auto text = gdpn::core::readFile(args[i], diags);
    if (!text) {
      diags.print(err);
      ok = false;
      continue;
    }
    if (args[i].ends_with(".xml")) {
      // the Model Checking Contest's property file
      auto properties = gdpn::net::readMccProperties(net, *text, args[i], diags, names);
      diags.print(err);
      if (!properties) {
        ok = false;
        continue;
      }
      for (auto& p : *properties) {
        model::QueryResult r;
        r.text = gdpn::net::formulaText(net, p.formula, names);
        r.formula = std::move(p.formula);
        r.id = p.id;
        out.push_back(std::move(r));
      }
      continue;
    }
    // one formula per line; blank lines and # comments skipped
    std::istringstream in(*text);
    std::string line;
    for (std::size_t n = 1; std::getline(in, line); ++n) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const auto first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line[first] == '#') continue;
      read(args[i] + ":" + std::to_string(n), line);
    }
  }
  if (!ok) return std::nullopt;
  return out;
}

int analyze(AnalyzeArgs a) {
  Diagnostics diags;
  std::optional<gdpn::net::NetSpec> spec;
  std::string path = a.model;
  session::AnalysisRequest& request = a.request;
  if (a.model.ends_with(".pnml")) {
    if (!a.params.empty()) {
      std::cerr << "error: --param sets a parameter of a model file's params section; a PNML net has none\n";
      return 2;
    }
    spec = gdpn::net::loadPnml(a.model, diags);
  } else if (auto resolved = model::resolveModelPath(a.model, diags)) {
    path = *resolved;
    if (auto m = model::loadModel(path, diags, paramOverrides(a.params))) {
      spec = std::move(m->net);
      request.dt = m->settings.dt;
    }
  }
  // queries and graphs name the unfolded net's markings: a coloured net is unfolded for them
  const bool unfolded_only = !a.queries.empty() || !a.graph.empty();
  if (unfolded_only && a.colours == "native") {
    std::cerr << "error: --colours native: queries and graphs need the net unfolded (--colours unfold or auto)\n";
    return 2;
  }
  const auto how = a.colours == "native" ? session::ColourSearch::Native
                   : a.colours == "unfold" || unfolded_only ? session::ColourSearch::Unfold
                                                            : session::ColourSearch::Auto;
  std::optional<session::AnalysedNet> analysed;
  if (spec) analysed = session::analysedNet(*spec, diags, how);
  spec.reset();  // the compiled net is all that is read from here on: the spec's memory goes back
                 // before the search (explore() returns it to the system)
  diags.print(std::cerr);
  if (!analysed) return 1;
  const gdpn::net::NameExpansion* expansion = analysed->expansion();
  const std::shared_ptr<const gdpn::net::Net> net = analysed->net;
  if (!a.graph.empty()) {
    // the graph alone, written beside its file and renamed into place when complete
    const bool dot = a.graph.ends_with(".dot"), aut = a.graph.ends_with(".aut");
    if (!dot && !aut) {
      std::cerr << "error: --graph " << quoteArg(a.graph) << ": the file must end in .dot or .aut\n";
      return 2;
    }
    if (overwritesInput("--graph", a.graph, {{"the model file", path}})) return 2;
    gdpn::core::OutputFile file(a.graph);
    std::string why;
    if (!file.open(why)) {
      std::cerr << a.graph << ": error: " << why << "\n";
      return 1;
    }
    const auto stop = session::writeStateGraph(*net, dot ? gdpn::net::GraphFormat::Dot : gdpn::net::GraphFormat::Aldebaran,
                                               file.stream(), request);
    if (stop != gdpn::net::ExploreStop::Done) {
      std::cerr << a.graph << ": error: nothing written: the graph is not whole (" << gdpn::net::stopReason(stop) << ")\n";
      return 3;
    }
    if (!file.commit(why)) {
      std::cerr << a.graph << ": error: " << why << "\n";
      return 1;
    }
    return 0;
  }
  if (!a.queries.empty()) {
    // only the questions asked, each answered as soon as a search decides it
    auto queries = readQueries(*net, a.queries, std::cerr, expansion);
    if (!queries) return 1;
    std::vector<gdpn::net::Formula> formulas;
    for (const auto& q : *queries) formulas.push_back(q.formula);
    const auto answers = session::answerQueries(*net, formulas, request);
    bool decided = true;
    for (std::size_t i = 0; i < answers.size(); ++i) {
      (*queries)[i].answer = answers[i];
      decided = decided && answers[i].verdict != gdpn::net::Verdict::Unknown;
    }
    if (a.json) {
      std::cout << model::queriesJson(*net, *queries, expansion);
    } else {
      model::printQueries(std::cout, *net, *queries, expansion, analysed->notes);
    }
    if (!a.witness.empty()) {
      const auto shown = std::find_if(queries->begin(), queries->end(), [](const auto& q) { return q.answer.has_marking; });
      std::string why;
      if (shown == queries->end()) {
        std::cerr << "error: --witness " << quoteArg(a.witness)
                  << ": no answer here is shown by a firing sequence (an answer that rests on every reachable "
                     "marking has none); nothing written\n";
        return 1;
      }
      if (!gdpn::core::writeOutput(a.witness, model::witnessJson(*net, *shown, path), why)) {
        std::cerr << a.witness << ": error: " << why << "\n";
        return 1;
      }
    }
    return decided ? 0 : 3;
  }
  // a progress line on a terminal: states, states per second, memory (the invariants: rows)
  const bool show = a.progress || isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  auto last = start - std::chrono::seconds(1);  // the first call prints
  bool drawn = false;
  std::string shown_phase;  // a new phase prints at once
  auto due = [&](const char* phase) {
    const auto now = std::chrono::steady_clock::now();
    if (!show || (phase == shown_phase && now - last < std::chrono::milliseconds(250))) return false;
    last = now;
    shown_phase = phase;
    drawn = !a.progress;
    return true;
  };
  request.phase_progress = [&](const char* phase, const gdpn::net::InvariantProgress& p) {
    if (!due(phase)) return;
    std::fprintf(stderr, "%s%s: column %zu of %zu, %zu candidate rows, %.1f MiB%s", a.progress ? "" : "\r\033[K", phase,
                 p.round, p.columns, p.rows, static_cast<double>(p.bytes) / (1024.0 * 1024.0), a.progress ? "\n" : "");
  };
  request.progress = [&](const gdpn::net::ExploreProgress& p) {
    if (!due("state space")) return;
    const auto now = std::chrono::steady_clock::now();
    const double secs = std::max(1e-6, std::chrono::duration<double>(now - start).count());
    std::fprintf(stderr, "%s%llu states, %llu edges, %.2fM states/s, %.1f MiB", a.progress ? "" : "\r",
                 static_cast<unsigned long long>(p.states), static_cast<unsigned long long>(p.edges),
                 static_cast<double>(p.states) / secs / 1e6, static_cast<double>(p.bytes) / (1024.0 * 1024.0));
    std::fputs(a.progress ? "\n" : "", stderr);
  };
  const auto answer = session::analyze(*analysed, path, request);
  const model::Analysis& result = answer.analysis;
  if (drawn) std::fprintf(stderr, "\r\033[K");
  if (answer.stoppedAtGuard()) std::cerr << "note: " << answer.guardNote("--max-memory") << "\n";
  if (a.json) {
    std::cout << model::analysisJson(*net, result);
  } else {
    model::printAnalysis(std::cout, *net, result);
  }
  return result.complete() ? 0 : 3;
}

}  // namespace

Subcommand addAnalyze(CLI::App& app) {
  auto args = std::make_shared<AnalyzeArgs>();
  auto* analyze_cmd = app.add_subcommand(
      "analyze", "State space (deadlocks, bounds, liveness), invariants and cycle-time bounds of the untimed net");
  analyze_cmd->add_option("MODEL", args->model, "a .gdpn.yaml file (or a folder holding one), or a .pnml net")
      ->required();
  addParamOption(analyze_cmd, args->params);
  analyze_cmd->add_flag("--json", args->json, "print the results as JSON");
  analyze_cmd->add_option("--max-states", args->request.max_states, "stop after this many states (the answer is then partial)")
      ->check(number<std::uint64_t>(1, 1'000'000'000'000, "a whole number of states from 1 to 10^12"));
  analyze_cmd->add_option("--max-memory", args->request.max_memory_mib,
                          "stop when the search holds this many MiB (the answer is then partial; default: 3/4 of the memory available at the start)")
      ->check(number(0.0, 1e9, "MiB above 0, at most 1e9", true));
  analyze_cmd->add_option("--time-limit", args->request.time_limit_s,
                          "stop every phase after this many seconds in all (the answer is then partial)")
      ->check(number(0.0, 1e9, "seconds above 0, at most 1e9", true));
  analyze_cmd->add_option("--threads", args->request.threads,
                          "threads for the search (1: one depth-first walk, the least memory; more keep the graph)")
      ->check(number(1u, 256u, "a whole number of threads from 1 to 256"));
  analyze_cmd->add_option("--query", args->queries,
                          "answer this formula instead (repeatable), or each line of this file: 'EF (buffer >= 3 and "
                          "fireable(consume))', 'AG not deadlock' (docs/queries.md)");
  analyze_cmd->add_option("--witness", args->witness,
                          "with --query: write the firing sequence that shows the first answer shown by one "
                          "(and its marking) as JSON, for gdpn run --replay");
  analyze_cmd->add_option("--graph", args->graph,
                          "write the reachability graph to FILE.dot (Graphviz: markings on the nodes) or FILE.aut "
                          "(Aldebaran, for CADP and mCRL2) instead of the analysis");
  analyze_cmd->add_flag("!--no-reduction", args->request.reduction,
                        "with --query: no simplification and no stubborn sets; the whole graph first (every "
                        "enabled transition fires)");
  analyze_cmd->add_flag("--shortest-path", args->request.shortest_path,
                        "give a shortest path to a deadlock (a second pass over the states)");
  analyze_cmd->add_option("--colours", args->colours,
                          "a coloured net: 'unfold' it into a place/transition net, search it over markings with "
                          "values ('native': the state space, no queries), or 'auto': unfolded where unfolding can")
      ->check(CLI::IsMember({"auto", "unfold", "native"}));
  analyze_cmd->add_flag("--progress", args->progress,
                        "print a progress line every 250 ms even when stderr is not a terminal");

  setExamples(analyze_cmd, {"gdpn analyze examples/basics/producer_consumer   # deadlocks, bounds, invariants",
               "gdpn analyze examples/basics/producer_consumer --query 'AG buffer <= 3'"});
  return {analyze_cmd, [args] { return analyze(*args); }};
}

}  // namespace gdpn::app
