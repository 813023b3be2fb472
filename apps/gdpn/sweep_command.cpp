#include "sweep_command.h"

#include "cli_checks.h"
#include "commands.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/output_file.h"
#include "gdpn/core/text.h"
#include "gdpn/experiments/python_sources.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/script/call.h"

namespace gdpn::app {

CLI::App* addSweepCommand(CLI::App& app, SweepArgs& a) {
  auto* cmd = app.add_subcommand(
      "sweep", "Run a model for every combination of parameter values and several seeds, on Dask; "
               "tabulate the model's figures with 95 % confidence intervals");
  cmd->add_option("MODEL", a.model, "a .gdpn.yaml file, or a folder holding exactly one")->required();
  cmd->add_option("--param", a.params,
                  "a parameter and its values: NAME=0.4,0.5,0.6 or NAME=1..3:0.5 (FROM..TO:STEP), mixed with "
                  "commas (repeatable; every combination runs)")
      ->allow_extra_args(false);
  cmd->add_option("--seeds", a.seeds, "runs per combination, with seeds --seed, --seed + 1, ... (default 1)")
      ->check(number<int>(1, 1'000'000, "a whole number of runs from 1 to 10^6"));
  cmd->add_option("--seed", a.seed, "the first seed (default 1)")
      ->check(number<std::uint64_t>(0, UINT64_MAX - 1'000'000, "a whole number from 0 to 2^64 - 10^6 - 1"));
  cmd->add_option("--until", a.until, "end time of each run in seconds (default: the model's until)")
      ->check(number(0.0, 1e9, "seconds from 0 to 1e9"));
  cmd->add_option("-o,--output", a.output, "write one row per run to FILE.csv: parameters, seed, every figure, error");
  cmd->add_option("--summary", a.summary,
                  "write per combination the mean and 95 % confidence interval of each figure to FILE.csv");
  cmd->add_option("--plot", a.plot, "plot a figure's mean and interval against a parameter to FILE.svg, .png or .pdf");
  cmd->add_option("--figure", a.figure, "the figure --plot shows (default: the model's first numeric figure)");
  cmd->add_option("--against", a.against, "the parameter --plot puts on its axis (default: the first --param)");
  cmd->add_option("--workers", a.workers,
                  "local Dask workers, each running one model at a time (default: one per core; 0: one run after "
                  "another in this process, without Dask)")
      ->check(number<int>(0, 4096, "a whole number of workers from 0 to 4096"));
  cmd->add_option("--scheduler", a.scheduler,
                  "run on the Dask cluster whose scheduler is at tcp://HOST:PORT (its workers need gdpn and the "
                  "model at the same paths)");
  cmd->add_option("--timeout", a.timeout, "seconds of wall-clock time one run may take before it counts as failed")
      ->check(number(0.0, 1e7, "seconds above 0, at most 1e7", true));
  cmd->add_flag("--quiet,-q", a.quiet, "print no summary table and no progress");
  return cmd;
}

namespace {

/// This program's own path: the workers run it.
std::string selfPath() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? "gdpn" : p.string();
}

}  // namespace

int sweep(const SweepArgs& a) {
  if (a.scheduler_given && a.scheduler.empty()) {
    std::cerr << "error: --scheduler: expected an address like tcp://HOST:PORT, got ''\n";
    return 2;
  }
  if (a.workers && !a.scheduler.empty()) {
    std::cerr << "error: --workers sets the local cluster's size; it does not go with --scheduler\n";
    return 2;
  }
  if ((!a.figure.empty() || !a.against.empty()) && a.plot.empty()) {
    std::cerr << "error: --figure and --against choose what --plot draws: add --plot FILE.svg\n";
    return 2;
  }
  // the model once, before any run: its errors, and each swept parameter's name
  core::Diagnostics diags;
  const auto path = model::resolveModelPath(a.model, diags);
  std::optional<model::Model> m;
  if (path) m = model::loadModel(*path, diags);
  if (m) model::checkModel(*m, diags);
  diags.print(std::cerr);
  if (diags.hasErrors()) return 1;
  // no output over the model, and no two outputs in one file
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"-o", a.output}, {"--summary", a.summary}, {"--plot", a.plot}};
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].second.empty()) continue;
    if (core::sameFile(outputs[i].second, *path)) {
      std::cerr << "error: " << outputs[i].first << " '" << outputs[i].second
                << "' is the model file; gdpn writes no output over it\n";
      return 2;
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].second.empty() &&
          (outputs[j].second == outputs[i].second || core::sameFile(outputs[j].second, outputs[i].second))) {
        std::cerr << "error: " << outputs[j].first << " and " << outputs[i].first << " name one file, '"
                  << outputs[i].second << "'\n";
        return 2;
      }
    }
  }
  std::vector<std::string> declared;
  for (const auto& p : m->params) declared.push_back(p.name);
  for (const auto& arg : a.params) {
    const auto eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    if (eq == std::string::npos || name.empty()) {
      std::cerr << "error: --param: expects NAME=VALUES, got '" << arg << "'\n";
      return 2;
    }
    if (std::find(declared.begin(), declared.end(), name) == declared.end()) {
      const auto near = core::closestMatch(name, declared);
      std::cerr << "--param: error: no parameter '" << name << "' in " << *path
                << (near.empty() ? "" : " (did you mean '" + near + "'?)") << "\n";
      return 2;
    }
  }
  nlohmann::json j;
  j["gdpn"] = selfPath();
  j["model"] = *path;
  j["params"] = a.params;
  auto& units = j["param_units"] = nlohmann::json::object();
  for (const auto& p : m->params) {
    if (!p.unit.empty()) units[p.name] = p.unit;
  }
  j["seeds"] = a.seeds;
  j["seed"] = a.seed;
  j["until"] = a.until ? nlohmann::json(*a.until) : nlohmann::json(nullptr);
  j["output"] = a.output;
  j["summary"] = a.summary;
  j["plot"] = a.plot;
  j["figure"] = a.figure;
  j["against"] = a.against;
  j["workers"] = a.workers ? nlohmann::json(*a.workers) : nlohmann::json(nullptr);
  j["scheduler"] = a.scheduler.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.scheduler);
  j["timeout"] = a.timeout ? nlohmann::json(*a.timeout) : nlohmann::json(nullptr);
  j["quiet"] = a.quiet;
  j["progress"] = !a.quiet && isatty(STDERR_FILENO);
  std::string error;
  std::cout.flush();
  const auto code = script::callPython(experiments::kSweepPy, "sweep.py", "main", j.dump(), error);
  if (!code) {
    std::cerr << "error: the sweep failed:\n" << error;
    return 1;
  }
  return std::stoi(*code);
}

Subcommand addSweep(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  auto* sweep_cmd = addSweepCommand(app, *args);
  setExamples(sweep_cmd, {"gdpn sweep examples/factory --param belt_speed=0.4,0.5,0.6 --seeds 5 --until 120 \\",
               "    -o runs.csv --summary summary.csv --plot painted.svg"});
  return {sweep_cmd, [args, sweep_cmd] {
            args->scheduler_given = sweep_cmd->get_option("--scheduler")->count() > 0;
            return sweep(*args);
          }};
}

}  // namespace gdpn::app
