// gdpn: the command-line program. Every rule lives in the library; this file only parses
// arguments, calls into model and net, and prints.

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <iostream>
#include <new>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "gdpn/core/file.h"
#include "gdpn/core/memory.h"
#include "gdpn/core/output_file.h"
#include "gdpn/model/analysis.h"
#include "gdpn/model/model.h"
#include "gdpn/model/report.h"
#include "gdpn/experiments/html_report.h"
#include "gdpn/net/timeline.h"
#include "cli_checks.h"
#include "serve.h"
#include "sweep_command.h"
#include "gdpn/model/simulation.h"
#include "gdpn/model/witness.h"
#include <nlohmann/json.hpp>

#include "gdpn/net/analysis.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/graph_export.h"
#include "gdpn/net/pnml.h"
#include "gdpn/capture/capture.h"
#include "gdpn/capture/sensor_imager.h"
#ifdef GDPN_WITH_IDE
#include "gdpn/ide/ide.h"
#endif
#include "gdpn/scene/mesh.h"
#include "gdpn/script/engine.h"
#include "gdpn/session/session.h"

namespace {

using gdpn::core::Diagnostics;
namespace model = gdpn::model;

std::atomic<bool> g_interrupted{false};

void onSigint(int) {
  g_interrupted.store(true);
  gdpn::script::requestInterrupt();  // a script running now raises KeyboardInterrupt
}

using gdpn::app::number;
using gdpn::app::quoteArg;

/// The model file that MODEL names (a file, or the one in a folder); MODEL when there is none.
std::string modelFile(const std::string& arg) {
  Diagnostics ignored;  // the run itself reports a missing model
  return model::resolveModelPath(arg, ignored).value_or(arg);
}

/// True (after saying so) when the output `out`, given as `option`, would write over one of
/// `inputs` (what each is, and its path), before anything is written. A device or a pipe
/// (/dev/stdout) is never refused.
bool overwritesInput(const std::string& option, const std::string& out,
                     const std::vector<std::pair<std::string, std::string>>& inputs) {
  std::error_code ec;
  if (out.empty() || (std::filesystem::exists(out, ec) && !std::filesystem::is_regular_file(out, ec))) return false;
  for (const auto& [what, path] : inputs) {
    if (path.empty() || !gdpn::core::sameFile(out, path)) continue;
    std::cerr << "error: " << option << " '" << out << "' is " << what << "; gdpn writes no output over it\n";
    return true;
  }
  return false;
}

/// Longest model time a run, picture or movie may ask for, seconds (about 31 years).
constexpr double kMaxTime = 1e9;

class ProgressBar {
 public:
  explicit ProgressBar(bool on) : on_(on) {}
  void operator()(std::int64_t done, std::int64_t total) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100) && done != total) return;
    last_ = now;
    if (total > 0) {
      const int width = 30;
      const double f = std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
      const int filled = static_cast<int>(f * width);
      std::fprintf(stderr, "\r[%s%s] %5.1f%%  step %lld/%lld", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                   std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), 100.0 * f,
                   static_cast<long long>(done), static_cast<long long>(total));
    } else {
      std::fprintf(stderr, "\rstep %lld", static_cast<long long>(done));
    }
    drawn_ = true;
  }
  ~ProgressBar() {
    if (drawn_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool on_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

/// The --param arguments (NAME=VALUE each, checked by the option's validator).
std::vector<model::ParamOverride> paramOverrides(const std::vector<std::string>& args) {
  std::vector<model::ParamOverride> out;
  for (const auto& a : args) {
    if (auto o = model::parseParamArgument(a)) out.push_back(std::move(*o));
  }
  return out;
}

/// `--param NAME=VALUE` on `cmd` (repeatable), into `out`.
void addParamOption(CLI::App* cmd, std::vector<std::string>& out) {
  cmd->add_option("--param", out, "set a parameter of the model's params section: NAME=VALUE (repeatable)")
      ->allow_extra_args(false)
      ->check(CLI::Validator(
          [](std::string& s) {
            return model::parseParamArgument(s) ? std::string() : "expects NAME=VALUE, got '" + s + "'";
          },
          "NAME=VALUE"));
}

/// Loads and compiles MODEL (file or folder), printing diagnostics; nullptr on error.
std::unique_ptr<gdpn::session::Session> open(const std::string& arg, std::optional<std::uint64_t> seed,
                                             double script_timeout_s, const std::vector<std::string>& params) {
  Diagnostics diags;
  std::unique_ptr<gdpn::session::Session> sim;
  if (auto path = model::resolveModelPath(arg, diags)) {
    if (auto m = model::loadModel(*path, diags, paramOverrides(params))) {
      sim = gdpn::session::Session::create(std::move(*m), diags, {seed, script_timeout_s, gdpn::capture::makeSensorImager});
    }
  }
  diags.print(std::cerr);
  if (!sim && diags.errorCount() > 1) std::cerr << diags.errorCount() << " errors\n";
  return sim;
}

int check(const std::string& arg, double script_timeout_s, const std::vector<std::string>& params) {
  Diagnostics diags;
  auto path = model::resolveModelPath(arg, diags);
  std::optional<model::Model> m;
  if (path) m = model::loadModel(*path, diags, paramOverrides(params));
  std::shared_ptr<const gdpn::net::Net> net;
  // scripts, the plant and the signals are checked too: scripts compiled, their files and
  // functions found, globals run (under the script timeout); bodies, joints and mesh files made
  // ready; what each signal names found
  if (m) net = model::checkModel(*m, diags, script_timeout_s);
  diags.print(std::cerr);
  if (diags.hasErrors()) {
    std::cerr << diags.errorCount() << (diags.errorCount() == 1 ? " error\n" : " errors\n");
    return 1;
  }
  // "1 place", "2 places"
  const auto counted = [](std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
  std::cout << *path << ": ok (" << counted(net->places().size(), "place") << ", "
            << counted(net->transitions().size(), "transition") << ", " << counted(net->terms().size(), "arc term")
            << ")\n";
  return 0;
}

struct CaptureArgs {
  std::string model;
  std::string out;
  std::string size = "1280x720";
  double at = 0.0;
  double until = 10.0;
  std::optional<std::uint64_t> seed;
  gdpn::capture::CaptureOptions options;
  bool net = false;         // render --net: the net of a page rather than the plant
  std::string page;         // render --net --page
  bool at_given = false;    // --at was on the command line
  bool size_given = false;  // --size was on the command line
  bool quiet = false;       // no sim.log lines, no progress
  std::vector<std::string> params;  // --param NAME=VALUE
};

/// The --size argument as width and height in pixels; nullopt after saying what is wrong.
std::optional<std::pair<int, int>> sizeArg(const std::string& text) {
  auto size = gdpn::capture::parseSize(text);
  if (!size) {
    std::cerr << "error: --size " << quoteArg(text) << " is not WIDTHxHEIGHT (for example 1280x720), each side "
              << gdpn::capture::kMinSide << " to " << gdpn::capture::kMaxSide << " pixels\n";
  }
  return size;
}

/// `gdpn render --net`: the net of one page with its marking at --at (the initial marking
/// without it), as SVG or PNG.
int renderNet(const CaptureArgs& a) {
  gdpn::capture::NetPictureOptions o;
  o.page = a.page;
  if (a.at_given) o.at = a.at;
  if (a.size_given) {
    const auto size = sizeArg(a.size);
    if (!size) return 2;
    o.width = size->first;
    o.height = size->second;
  }
  if (!a.out.ends_with(".svg") && !a.out.ends_with(".png")) {
    std::cerr << "error: -o " << quoteArg(a.out) << ": a net picture is written as .svg or .png\n";
    return 2;
  }
  if (overwritesInput("-o", a.out, {{"the model file", modelFile(a.model)}})) return 2;
  auto session = open(a.model, a.seed, 0.0, a.params);
  if (!session) return 1;
  std::string error;
  Diagnostics warnings;
  const bool ok = gdpn::capture::renderNetAt(session->simulation(), o, a.out, warnings, error);
  warnings.print(std::cerr);
  if (!ok) {
    std::cerr << (error.starts_with("--page") || error.find(": error: ") != std::string::npos ? "error: " : a.out + ": error: ")
              << error << (error.ends_with('\n') ? "" : "\n");
    return 1;
  }
  std::cout << a.out << ": the net of " << (a.page.empty() ? "the first page" : "'" + a.page + "'") << " at t = "
            << session->simulation().kernel().now() << " s\n";
  return 0;
}

/// The size of a movie is even on each side (ffmpeg's yuv420p); otherwise says so. `source`
/// says where the size came from.
bool evenSize(const gdpn::capture::CaptureOptions& o, const std::string& source) {
  if (o.width % 2 == 0 && o.height % 2 == 0) return true;
  std::cerr << "error: a movie needs an even width and height, not " << o.width << "x" << o.height << " (" << source
            << ")\n";
  return false;
}

/// `gdpn render` (movie = false) and `gdpn record` (movie = true). Without --size, a picture
/// from a camera sensor takes the camera's own width and height, any other 1280x720.
int capture(CaptureArgs a, bool movie) {
  const auto size = sizeArg(a.size);
  if (!size) {
    return 2;
  }
  a.options.width = size->first;
  a.options.height = size->second;
  if (movie && a.size_given && !evenSize(a.options, "--size " + quoteArg(a.size))) return 2;
  if (overwritesInput("-o", a.out, {{"the model file", modelFile(a.model)}})) return 2;
  if (!movie && !a.out.ends_with(".png")) {
    std::cerr << "error: -o " << quoteArg(a.out) << ": a picture of the plant is written as .png (PNG data in a file "
              << "named otherwise would mislead)\n";
    return 2;
  }
  auto session = open(a.model, a.seed, 0.0, a.params);
  if (!session) return 1;
  if (const auto* plant = session->simulation().plant(); plant != nullptr && !a.size_given) {
    if (const auto own = gdpn::capture::cameraSensorSize(*plant, a.options.camera)) {
      std::tie(a.options.width, a.options.height) = *own;
      if (movie && !evenSize(a.options, "the size of camera '" + a.options.camera + "'; give --size")) return 2;
    }
  }
  model::Simulation* sim = &session->simulation();
  if (a.quiet) sim->setLogEcho(false);
  std::string error;
  bool ok = false;
  if (!movie) {
    ok = gdpn::capture::renderAt(*sim, a.at, a.options, a.out, error);
    if (ok) std::cout << a.out << ": " << a.options.width << "x" << a.options.height << " at t = " << sim->kernel().now() << " s\n";
  } else {
    std::signal(SIGINT, onSigint);
    gdpn::capture::RecordResult result;
    {
      ProgressBar bar(!a.quiet && isatty(STDERR_FILENO));
      ok = gdpn::capture::record(*sim, a.until, a.options, a.out, std::ref(bar), &g_interrupted, result, error);
    }
    std::signal(SIGINT, SIG_DFL);
    if (ok) {
      std::cout << a.out << ": " << result.frames << " frames of " << a.options.width << "x" << a.options.height
                << " at " << a.options.fps << " fps (" << result.outcome.steps << " steps, "
                << model::stopReasonName(result.outcome.reason) << ")\n";
    }
  }
  if (!ok) {
    std::cerr << (error.find(": error: ") != std::string::npos ? "" : a.out + ": error: ") << error
              << (error.ends_with('\n') ? "" : "\n");
    return 1;
  }
  return 0;
}

struct AnalyzeArgs {
  std::string model;
  bool json = false;
  bool progress = false;
  std::uint64_t max_states = 20'000'000;
  double max_memory_mib = 0.0;
  double time_limit_s = 0.0;
  unsigned threads = 1;
  bool shortest_path = false;
  std::vector<std::string> queries;  // formulas, or files of them
  std::string witness;               // where to write the first answer's witness
  bool reduction = true;             // stubborn sets in the searches on the fly
  std::string graph;                 // write the reachability graph here (.dot or .aut) instead
  std::vector<std::string> params;   // --param NAME=VALUE
};

/// Reads the --query arguments: each is a file of formulas (one per line; blank lines and
/// lines starting with # skipped) when such a file exists, else a formula itself. Mistakes
/// go to `err` located (file:line:col, or the argument's number and column) with the line
/// and a caret; nullopt when there was one.
std::optional<std::vector<model::QueryResult>> readQueries(const gdpn::net::Net& net,
                                                          const std::vector<std::string>& args, std::ostream& err) {
  std::vector<model::QueryResult> out;
  bool ok = true;
  auto read = [&](const std::string& where, const std::string& text) {
    gdpn::net::QueryError e;
    if (auto f = gdpn::net::parseQuery(net, text, e)) {
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
      auto properties = gdpn::net::readMccProperties(net, *text, args[i], diags);
      diags.print(err);
      if (!properties) {
        ok = false;
        continue;
      }
      for (auto& p : *properties) {
        model::QueryResult r;
        r.text = gdpn::net::formulaText(net, p.formula);
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

int analyze(const AnalyzeArgs& a) {
  Diagnostics diags;
  std::optional<gdpn::net::NetSpec> spec;
  std::string path = a.model;
  model::AnalysisOptions options;
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
      options.dt = m->settings.dt;
    }
  }
  std::shared_ptr<const gdpn::net::Net> net;
  if (spec) net = gdpn::net::compile(*spec, diags);
  diags.print(std::cerr);
  if (!net) return 1;
  options.explore.max_states = a.max_states;
  options.explore.max_bytes = static_cast<std::uint64_t>(a.max_memory_mib * 1024.0 * 1024.0);
  // none given: 3/4 of the memory the system has to give now, so that a state space too big
  // for the machine ends in a partial answer rather than in the system's out-of-memory kill
  const bool default_memory = a.max_memory_mib <= 0.0;
  if (default_memory) {
    options.explore.max_bytes = gdpn::core::availableMemory() / 4 * 3;
    options.explore.max_bytes_guard = true;
  }
  options.explore.threads = a.threads;
  options.explore.shortest_path = a.shortest_path;
  options.explore.reduction = a.reduction;
  options.time_limit_s = a.time_limit_s;
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
    gdpn::net::ExploreOptions limits = options.explore;
    if (a.time_limit_s > 0.0) {
      limits.deadline = gdpn::net::deadlineAfter(a.time_limit_s);
    }
    const auto stop = gdpn::net::writeStateGraph(*net, dot ? gdpn::net::GraphFormat::Dot : gdpn::net::GraphFormat::Aldebaran,
                                                 file.stream(), limits);
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
    auto queries = readQueries(*net, a.queries, std::cerr);
    if (!queries) return 1;
    gdpn::net::ExploreOptions limits = options.explore;
    if (a.time_limit_s > 0.0) {
      limits.deadline = gdpn::net::deadlineAfter(a.time_limit_s);
    }
    std::vector<gdpn::net::Formula> formulas;
    for (const auto& q : *queries) formulas.push_back(q.formula);
    const auto answers = gdpn::net::answerQueries(*net, formulas, limits);
    bool decided = true;
    for (std::size_t i = 0; i < answers.size(); ++i) {
      (*queries)[i].answer = answers[i];
      decided = decided && answers[i].verdict != gdpn::net::Verdict::Unknown;
    }
    if (a.json) {
      std::cout << model::queriesJson(*net, *queries);
    } else {
      model::printQueries(std::cout, *net, *queries);
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
  options.progress = [&](const char* phase, const gdpn::net::InvariantProgress& p) {
    if (!due(phase)) return;
    std::fprintf(stderr, "%s%s: column %zu of %zu, %zu candidate rows, %.1f MiB%s", a.progress ? "" : "\r\033[K", phase,
                 p.round, p.columns, p.rows, static_cast<double>(p.bytes) / (1024.0 * 1024.0), a.progress ? "\n" : "");
  };
  options.explore.progress = [&](const gdpn::net::ExploreProgress& p) {
    if (!due("state space")) return;
    const auto now = std::chrono::steady_clock::now();
    const double secs = std::max(1e-6, std::chrono::duration<double>(now - start).count());
    std::fprintf(stderr, "%s%llu states, %llu edges, %.2fM states/s, %.1f MiB", a.progress ? "" : "\r",
                 static_cast<unsigned long long>(p.states), static_cast<unsigned long long>(p.edges),
                 static_cast<double>(p.states) / secs / 1e6, static_cast<double>(p.bytes) / (1024.0 * 1024.0));
    std::fputs(a.progress ? "\n" : "", stderr);
  };
  const auto result = model::analyze(*net, path, options);
  if (drawn) std::fprintf(stderr, "\r\033[K");
  const auto stopped = model::stoppedPhases(result);
  if (default_memory && std::any_of(stopped.begin(), stopped.end(),
                                    [](const auto& p) { return p.second == gdpn::net::ExploreStop::MaxMemory; })) {
    std::fprintf(stderr, "note: stopped at the default --max-memory, 3/4 of the memory available at the start (%.0f MiB)\n",
                 static_cast<double>(options.explore.max_bytes) / (1024.0 * 1024.0));
  }
  if (a.json) {
    std::cout << model::analysisJson(*net, result);
  } else {
    model::printAnalysis(std::cout, *net, result);
  }
  return result.complete() ? 0 : 3;
}

int convert(const std::string& in, const std::string& out) {
  // the format follows the output's extension; an input is never written over
  const bool to_pnml = out.ends_with(".pnml");
  if (!to_pnml && !out.ends_with(model::kModelSuffix)) {
    std::cerr << "error: OUT '" << out << "' must end in .pnml (a PNML net) or " << model::kModelSuffix
              << " (a model)\n";
    return 2;
  }
  const bool mesh = gdpn::scene::isMeshFile(in);
  if (mesh && to_pnml) {
    std::cerr << "error: a mesh converts to a model (" << model::kModelSuffix << "), not to PNML\n";
    return 2;
  }
  const std::string in_file = mesh || in.ends_with(".pnml") ? in : modelFile(in);
  if (overwritesInput("OUT", out, {{"the input file", in_file}})) return 2;
  Diagnostics diags;
  std::optional<model::Model> m;
  if (mesh) {
    m = model::meshModel(in, out, diags);
  } else if (in.ends_with(".pnml")) {
    if (auto spec = gdpn::net::loadPnml(in, diags); spec && gdpn::net::compile(*spec, diags)) {
      m.emplace();
      m->net = std::move(*spec);
      m->description = "converted from " + std::filesystem::path(in).filename().string();
    }
  } else if (auto path = model::resolveModelPath(in, diags)) {
    m = model::loadModel(*path, diags);
    if (m && !gdpn::net::compile(m->net, diags)) m.reset();
    // a model's files (scripts, meshes) are named relative to its folder
    const auto folder = [](const std::string& file) { return std::filesystem::absolute(file).parent_path().string(); };
    if (m && !to_pnml && !gdpn::core::sameFile(folder(*path), folder(out))) {
      diags.error({out, 0, 0}, "a model is rewritten only in its own folder (its files are named relative to it)");
      m.reset();
    }
  }
  if (m && to_pnml) {
    std::string why;
    auto text = gdpn::net::writePnml(m->net, why);
    if (!text) {
      diags.error({in, 0, 0}, "cannot write PNML: " + why);
    } else if (!gdpn::core::writeOutput(out, *text, why)) {
      diags.error({out, 0, 0}, why);
    }
  } else if (m) {
    model::saveModel(*m, out, diags);
  }
  diags.print(std::cerr);
  return diags.hasErrors() ? 1 : 0;
}

struct RunArgs {
  std::string model;
  std::optional<double> until;
  std::optional<std::int64_t> steps;
  std::optional<std::uint64_t> seed;
  std::string trace;
  std::string report;
  double script_timeout = 0.0;
  std::string input;
  std::vector<std::string> breaks;
  std::string replay;  // a witness file to play
  bool quiet = false;
  std::vector<std::string> params;  // --param NAME=VALUE
  std::vector<std::string> signals;  // --signal place:P | node:PATH.Q | python:EXPR
  double signal_every = 0.0;         // their period, seconds (0: every step)
  std::string signals_out;           // --signals FILE.csv
  std::string html;                  // --html FILE.html
  gdpn::app::ServeArgs serve;        // --modbus, --realtime, --lockstep
};

/// A breakpoint written on the command line: "start:T", "complete:T", "PLACE OP N" (OP one
/// of < <= == != >= >) or "when:EXPRESSION". Nullopt with `why` when it is none of these.
std::optional<gdpn::session::Breakpoint> parseBreakpoint(const std::string& spec, std::string& why) {
  using gdpn::session::Breakpoint;
  if (spec.starts_with("start:")) return Breakpoint::starts(spec.substr(6));
  if (spec.starts_with("complete:")) return Breakpoint::completes(spec.substr(9));
  if (spec.starts_with("when:")) return Breakpoint::predicate(spec.substr(5));
  // PLACE OP N: the operator is the first run of <, =, !, >
  const auto op = spec.find_first_of("<=!>");
  const auto end = spec.find_first_not_of("<=!>", op);
  const auto how = op == std::string::npos ? std::nullopt : gdpn::session::parseCompare(spec.substr(op, end - op));
  std::int64_t value = 0;
  const std::string number = end == std::string::npos ? "" : spec.substr(end);
  const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (!how || number.empty() || ec != std::errc() || ptr != number.data() + number.size()) {
    why = "expected start:TRANSITION, complete:TRANSITION, PLACE>=N (or <, <=, ==, !=, >) or when:EXPRESSION";
    return std::nullopt;
  }
  return Breakpoint::marking(spec.substr(0, op), *how, value);
}

/// Says how far a replay got: every firing started and the witness' marking reached (0), or
/// where it stopped and why, or how the marking differs (1).
int reportReplay(const model::Witness& w, const model::Simulation& sim, const std::string& file) {
  const std::size_t total = w.path.size() + w.cycle.size();
  const std::string loop = w.lasso ? " (its cycle once)" : "";
  const std::string all = total == 1 ? "the 1 firing" : "all " + std::to_string(total) + " firings";
  if (sim.replayed() < total) {
    std::cerr << file << ": error: replay stopped after " << sim.replayed() << " of " << total << " firings" << loop
              << " at t = " << sim.kernel().now() << " s: "
              << (sim.replayBlocked().empty() ? "the run ended first" : sim.replayBlocked()) << "\n";
    return 1;
  }
  if (sim.kernel().occurringCount() != 0) {
    std::cerr << file << ": error: replay: " << all << " started" << loop << ", but "
              << sim.kernel().occurringCount() << " still occur at t = " << sim.kernel().now()
              << " s (a later --until lets them complete)\n";
    return 1;
  }
  if (const std::string differs = model::witnessMismatch(sim.net(), sim.kernel(), w); !differs.empty()) {
    std::cerr << file << ": error: replay: " << all << " done" << loop
              << ", but the marking is not the witness': " << differs << "\n";
    return 1;
  }
  std::cerr << "replay: " << all << " done" << loop << " by t = " << sim.kernel().now()
            << " s; the marking is the witness'" << (w.query.empty() ? "" : " (" + w.query + ")") << "\n";
  return 0;
}

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
  auto sim = open(a.model, a.seed, a.script_timeout, a.params);
  if (!sim) return 1;
  if (!a.signals_out.empty() || !a.html.empty()) {
    Diagnostics diags;
    const bool ok = sim->simulation().recordSignals(extra, diags);
    diags.print(std::cerr);
    if (!ok) return 1;
  }
  if (a.quiet) sim->simulation().setLogEcho(false);  // sim.log still goes to the trace
  for (const auto& spec : a.breaks) {
    std::string why;
    const auto bp = parseBreakpoint(spec, why);
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
  std::optional<model::Witness> witness;
  if (!a.replay.empty()) {
    Diagnostics diags;
    witness = model::loadWitness(sim->simulation().net(), a.replay, diags);
    diags.print(std::cerr);
    if (!witness) return 1;
    auto sequence = witness->path;
    sequence.insert(sequence.end(), witness->cycle.begin(), witness->cycle.end());
    sim->simulation().replay(std::move(sequence));
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
  // with a report to show or write, its cycles are worked out first and each token with
  // alternative circuits watched, so that each circuit's cycle is measured
  const bool reporting = !a.quiet || !a.report.empty() || !a.html.empty();
  if (reporting) model::watchRoundTrips(sim->simulation());
  if (!reporting) sim->simulation().dropStatistics();  // no report: its figures are not collected
  // the page's plots need every occurrence and every change of tokens (up to a budget)
  std::unique_ptr<gdpn::net::Timeline> timeline;
  if (!a.html.empty()) {
    timeline = std::make_unique<gdpn::net::Timeline>(sim->simulation().net());
    sim->simulation().kernel().addObserver(timeline.get());
  }
  gdpn::app::Serving serving;
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
  int replay_failed = 0;
  if (witness) replay_failed = reportReplay(*witness, sim->simulation(), a.replay);
  // the report only when it is shown or written (it works out the cycle bounds)
  if (reporting) {
    const auto report = model::makeReport(sim->simulation(), outcome);
    // written as it is made: at 100,000 instances the text alone is 135 MB
    auto json = [&report](std::ostream& out) { model::writeReportJson(out, report); };
    if (!a.report.empty() && !gdpn::core::writeOutput(a.report, json, why)) {
      std::cerr << a.report << ": error: " << why << "\n";
      return 1;
    }
    if (!a.quiet) model::printSummary(std::cout, report);
    if (!a.quiet) serving.finish(sim->simulation(), std::cout);
    if (!a.html.empty()) {
      const auto page = gdpn::experiments::htmlReport(report, sim->simulation().net(), *timeline,
                                                      sim->simulation().signals(), why);
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
  switch (outcome.reason) {
    case model::StopReason::ScriptError:
    case model::StopReason::PhysicsError:
      std::cerr << outcome.message << (outcome.message.ends_with('\n') ? "" : "\n");
      return 1;
    case model::StopReason::Interrupted:
      if (!outcome.message.empty()) std::cerr << outcome.message << '\n';
      return 130;
    default:
      return replay_failed;
  }
}

/// `gdpn ide`'s arguments.
struct IdeArgs {
  std::string model, size = "1600x900", replay, screenshot, report;
  bool headless = false;
  double quit_after = 0;
  double autosave = 60;
};

/// `gdpn ide`: the IDE when it was built in (GDPN_IDE), else a message.
int ide(const IdeArgs& a) {
#ifdef GDPN_WITH_IDE
  const auto size = sizeArg(a.size);
  if (!size) return 2;
  if (!a.headless && !a.replay.empty()) {
    std::cerr << "error: --replay needs --headless\n";
    return 2;
  }
  gdpn::ide::IdeOptions o;
  o.model = a.model;
  o.headless = a.headless;
  o.width = size->first;
  o.height = size->second;
  o.replay = a.replay;
  o.screenshot = a.screenshot;
  o.report = a.report;
  o.quit_after = a.quit_after;
  o.autosave = a.autosave;
  return gdpn::ide::runIde(o);
#else
  (void)a;
  std::cerr << "error: this gdpn was built without the IDE (configure with -DGDPN_IDE=ON)\n";
  return 1;
#endif
}

}  // namespace

namespace {

int command(int argc, char** argv) {
  CLI::App app{"gdpn: geometry-driven Petri nets. Model, run and analyse control logic against a virtual plant."};
  app.set_version_flag("--version", std::string("gdpn ") + GDPN_VERSION);
  app.require_subcommand(1);
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    std::string msg = std::string("gdpn: error: ") + e.what() + "\n";
    msg += "Run '" + a->get_name() + " --help' for usage.\n";
    return msg;
  });

  std::string check_model;
  double check_timeout = 0.0;
  auto* check_cmd = app.add_subcommand("check", "Check a model and print its diagnostics; exit 0 when clean");
  check_cmd->add_option("MODEL", check_model, "a .gdpn.yaml file, or a folder holding exactly one")->required();
  check_cmd->add_option("--script-timeout", check_timeout,
                        "report an error when the globals script (or a script file's top level) runs longer than SECONDS")
      ->check(CLI::PositiveNumber);
  std::vector<std::string> check_params;
  addParamOption(check_cmd, check_params);

  const auto kSeed = number<std::uint64_t>(0, UINT64_MAX, "a whole number from 0 to 2^64-1");
  RunArgs run_args;
  auto* run_cmd = app.add_subcommand("run", "Run a model headless and print a summary");
  run_cmd->add_option("MODEL", run_args.model, "a .gdpn.yaml file, or a folder holding exactly one")->required();
  auto* until = run_cmd->add_option("--until", run_args.until, "end time in seconds (default: the model's until)")
                    ->check(number(0.0, kMaxTime, "seconds from 0 to 1e9"));
  run_cmd->add_option("--steps", run_args.steps, "number of steps to run")
      ->check(number<std::int64_t>(0, 1'000'000'000'000, "a whole number of steps from 0 to 10^12"))
      ->excludes(until);
  run_cmd->add_option("--seed", run_args.seed, "seed of the random generator (default: the model's seed)")
      ->check(kSeed);
  run_cmd->add_option("--trace", run_args.trace, "write every event as JSON Lines to FILE.jsonl");
  run_cmd->add_option("--report", run_args.report, "write the figures as JSON to FILE.json");
  run_cmd->add_option("--script-timeout", run_args.script_timeout,
                      "stop the run when one script call runs longer than SECONDS")
      ->check(number(0.0, 1e6, "seconds above 0, at most 1e6", true));
  run_cmd->add_option("--input", run_args.input,
                      "input events for keyboard and mouse sensors: a YAML list of {t, key | click | viewpoint}");
  run_cmd->add_option("--break", run_args.breaks,
                      "stop the run at the end of the step where start:TRANSITION or complete:TRANSITION "
                      "happens, PLACE>=N holds (or <, <=, ==, !=, >), or when:PYTHON is true (repeatable)");
  run_cmd->add_option("--replay", run_args.replay,
                      "play the firing sequence of a witness (gdpn analyze --witness): only its transitions "
                      "start, in its order, each as soon as it can");
  addParamOption(run_cmd, run_args.params);
  run_cmd->add_option("--html", run_args.html,
                      "write a self-contained HTML page of the run to FILE.html: the summary tables and plots "
                      "(tokens over time, occurrences, throughput, cycles beside their bounds, signals)");
  run_cmd->add_option("--signals", run_args.signals_out,
                      "write the model's signals (its signals section and each --signal) over time to FILE.csv");
  run_cmd->add_option("--signal", run_args.signals,
                      "record one more signal: place:NAME (its tokens), node:PATH.QUANTITY (position, velocity, "
                      "angle, rate, reading or a number field), python:EXPRESSION (repeatable)")
      ->allow_extra_args(false);
  run_cmd->add_option("--signal-every", run_args.signal_every,
                      "the --signal signals' sampling period in seconds (default: every step)")
      ->check(number(0.0, kMaxTime, "seconds above 0, at most 1e9", true));
  gdpn::app::addServeOptions(*run_cmd, run_args.serve);
  run_cmd->add_flag("--quiet,-q", run_args.quiet,
                    "print no summary, no progress and no sim.log lines (they still go to the --trace)");

  gdpn::app::SweepArgs sweep_args;
  auto* sweep_cmd = gdpn::app::addSweepCommand(app, sweep_args);

  AnalyzeArgs analyze_args;
  auto* analyze_cmd = app.add_subcommand(
      "analyze", "State space (deadlocks, bounds, liveness), invariants and cycle-time bounds of the untimed net");
  analyze_cmd->add_option("MODEL", analyze_args.model, "a .gdpn.yaml file (or a folder holding one), or a .pnml net")
      ->required();
  addParamOption(analyze_cmd, analyze_args.params);
  analyze_cmd->add_flag("--json", analyze_args.json, "print the results as JSON");
  analyze_cmd->add_option("--max-states", analyze_args.max_states, "stop after this many states (the answer is then partial)")
      ->check(number<std::uint64_t>(1, 1'000'000'000'000, "a whole number of states from 1 to 10^12"));
  analyze_cmd->add_option("--max-memory", analyze_args.max_memory_mib,
                          "stop when the search holds this many MiB (the answer is then partial; default: 3/4 of the memory available at the start)")
      ->check(number(0.0, 1e9, "MiB above 0, at most 1e9", true));
  analyze_cmd->add_option("--time-limit", analyze_args.time_limit_s,
                          "stop every phase after this many seconds in all (the answer is then partial)")
      ->check(number(0.0, 1e9, "seconds above 0, at most 1e9", true));
  analyze_cmd->add_option("--threads", analyze_args.threads,
                          "threads for the search (1: one depth-first walk, the least memory; more keep the graph)")
      ->check(number(1u, 256u, "a whole number of threads from 1 to 256"));
  analyze_cmd->add_option("--query", analyze_args.queries,
                          "answer this formula instead (repeatable), or each line of this file: 'EF (buffer >= 3 and "
                          "fireable(consume))', 'AG not deadlock' (docs/queries.md)");
  analyze_cmd->add_option("--witness", analyze_args.witness,
                          "with --query: write the firing sequence that shows the first answer shown by one "
                          "(and its marking) as JSON, for gdpn run --replay");
  analyze_cmd->add_option("--graph", analyze_args.graph,
                          "write the reachability graph to FILE.dot (Graphviz: markings on the nodes) or FILE.aut "
                          "(Aldebaran, for CADP and mCRL2) instead of the analysis");
  analyze_cmd->add_flag("!--no-reduction", analyze_args.reduction,
                        "with --query: search reachability without stubborn sets (every enabled transition fires)");
  analyze_cmd->add_flag("--shortest-path", analyze_args.shortest_path,
                        "give a shortest path to a deadlock (a second pass over the states)");
  analyze_cmd->add_flag("--progress", analyze_args.progress,
                        "print a progress line every 250 ms even when stderr is not a terminal");

  CaptureArgs render_args;
  auto* render_cmd =
      app.add_subcommand("render", "Run a model headless to a time and save a picture of its plant (or, with --net, of its net)");
  render_cmd->add_option("MODEL", render_args.model, "a .gdpn.yaml file, or a folder holding one")->required();
  render_cmd->add_option("--at", render_args.at, "model time of the picture, seconds")
      ->check(number(0.0, kMaxTime, "seconds from 0 to 1e9"));
  auto add_look = [&kSeed](CLI::App* cmd, CaptureArgs& args) {
    cmd->add_option("--camera", args.options.camera, "path of the Camera node (default: the scene's first, or a framing view)");
    cmd->add_option("--size", args.size,
                    "WIDTHxHEIGHT in pixels, each side 16 to 16384 (default 1280x720, or a camera sensor's own size)");
    cmd->add_option("--samples", args.options.samples, "samples per pixel for anti-aliasing (default 4)")
        ->check(number(1, 16, "a whole number of samples from 1 to 16"));
    cmd->add_flag("--sensors", args.options.sensors, "draw sensor volumes and rays");
    cmd->add_flag("--joints", args.options.joints, "draw joint axes");
    cmd->add_flag("!--no-shadows", args.options.shadows, "no shadows (they cost about half a frame more on a software renderer)");
    cmd->add_flag("!--no-ground", args.options.ground, "no sky and no ground grid: the background in one colour");
    cmd->add_option("--seed", args.seed, "the random seed (default: the model's)")->check(kSeed);
    cmd->add_option("-o,--output", args.out, "the file to write")->required();
    cmd->add_flag("--quiet,-q", args.quiet, "no sim.log lines and no progress on stderr");
    addParamOption(cmd, args.params);
  };
  add_look(render_cmd, render_args);
  render_cmd->add_flag("--net", render_args.net, "draw the net of a page with its marking (.svg or .png) instead of the plant; without --size, as large as the page needs");
  render_cmd->add_option("--page", render_args.page,
                         "with --net: the page, page type or instance path (page/instance/...) to draw (default: the first page)");
  CaptureArgs record_args;
  auto* record_cmd = app.add_subcommand("record", "Run a model headless and encode a movie of its plant (through ffmpeg)");
  record_cmd->add_option("MODEL", record_args.model, "a .gdpn.yaml file, or a folder holding one")->required();
  record_cmd->add_option("--until", record_args.until, "model time at which the movie ends, seconds (default 10)")
      ->check(number(0.0, kMaxTime, "seconds above 0, at most 1e9", true));
  record_cmd->add_option("--fps", record_args.options.fps, "frames per second of model time (default 30)")
      ->check(number(0.0, 1000.0, "frames per second above 0, at most 1000", true));
  add_look(record_cmd, record_args);

  std::string convert_in, convert_out;
  auto* convert_cmd = app.add_subcommand(
      "convert", "Convert a PNML net to a model file (and back), or a mesh file to a model holding it as a subtree");
  convert_cmd->add_option("IN", convert_in, "a .pnml file, a .gdpn.yaml model, or a mesh (obj stl 3ds gltf glb dae ply wrl iv)")
      ->required();
  convert_cmd->add_option("OUT", convert_out, "the .gdpn.yaml or .pnml to write")->required();

  IdeArgs ide_args;
  auto* ide_cmd = app.add_subcommand("ide", "Open a model in the IDE (a window; --headless for none)");
  ide_cmd->add_option("MODEL", ide_args.model,
                      "a .gdpn.yaml file, or a folder holding one; a new or empty .gdpn.yaml starts a new model")
      ->required();
  ide_cmd->add_flag("--headless", ide_args.headless, "no window: draw on an EGL surfaceless context");
  ide_cmd->add_option("--size", ide_args.size, "WIDTHxHEIGHT of the window or frame in pixels (default 1600x900)");
  ide_cmd->add_option("--replay", ide_args.replay, "headless: perform the actions in ACTIONS.yaml (docs/ide.md)");
  ide_cmd->add_option("--screenshot", ide_args.screenshot, "save the last frame as a PNG");
  ide_cmd->add_option("--report", ide_args.report, "save what the views showed in the last frame as JSON");
  ide_cmd->add_option("--quit-after", ide_args.quit_after,
                      "window: run in real time and quit after SECONDS (with the screenshot and report)")
      ->check(number(0.0, 1e6, "seconds above 0, at most 1e6", true));
  ide_cmd->add_option("--autosave", ide_args.autosave,
                      "save unsaved edits into the user's state folder after SECONDS (default 60; 0: never)")
      ->check(number(0.0, 1e6, "seconds from 0 to 1e6", false));

  // every mistake on the command line exits 2, after CLI11's message (help and version exit 0)
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (convert_cmd->parsed()) return convert(convert_in, convert_out);
  if (analyze_cmd->parsed()) return analyze(analyze_args);
  if (render_cmd->parsed()) {
    // the plant's options and the net's do not mix
    for (const char* plant_only : {"--camera", "--samples", "--sensors", "--joints", "--no-shadows", "--no-ground"}) {
      if (render_args.net && render_cmd->get_option(plant_only)->count() > 0) {
        std::cerr << "error: " << plant_only << " draws the plant; it does not go with --net\n";
        return 2;
      }
    }
    if (!render_args.net && render_cmd->get_option("--page")->count() > 0) {
      std::cerr << "error: --page chooses the page of the net: add --net\n";
      return 2;
    }
  }
  if (render_cmd->parsed() && render_args.net) {
    render_args.at_given = render_cmd->get_option("--at")->count() > 0;
    render_args.size_given = render_cmd->get_option("--size")->count() > 0;
    return renderNet(render_args);
  }
  if (render_cmd->parsed()) {
    render_args.size_given = render_cmd->get_option("--size")->count() > 0;
    return capture(render_args, false);
  }
  if (record_cmd->parsed()) {
    record_args.size_given = record_cmd->get_option("--size")->count() > 0;
    return capture(record_args, true);
  }
  if (check_cmd->parsed()) return check(check_model, check_timeout, check_params);
  if (run_cmd->parsed()) return run(run_args);
  if (sweep_cmd->parsed()) {
    sweep_args.scheduler_given = sweep_cmd->get_option("--scheduler")->count() > 0;
    return gdpn::app::sweep(sweep_args);
  }
  if (ide_cmd->parsed()) return ide(ide_args);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  // memory that no limit foresaw (a model too big for the machine, --max-memory set past
  // what it has): a message and a non-zero exit rather than an abort
  try {
    return command(argc, argv);
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory (gdpn analyze: --max-memory sets a limit at which the search stops with a "
                 "partial answer)\n";
    return 1;
  }
}
