#pragma once
/// \file
/// `gdpn sweep`: every combination of parameter values, each over several seeds, run on Dask
/// (a local cluster, or one at --scheduler); a table of the runs, a summary with 95 %
/// confidence intervals, and a plot.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gdpn::app {

/// `gdpn sweep`'s arguments.
struct SweepArgs {
  std::string model;                ///< the model file or folder
  std::vector<std::string> params;  ///< NAME=VALUES: "0.4,0.5" or "1..3:0.5"
  int seeds = 1;                    ///< replications per combination
  std::uint64_t seed = 1;           ///< the first seed; replication k has seed + k
  std::optional<double> until;      ///< end time of each run, s (default: the model's)
  std::string output;               ///< -o FILE.csv: one row per run
  std::string summary;              ///< --summary FILE.csv: per combination, mean and 95 % interval
  std::string plot;                 ///< --plot FILE.svg|png|pdf
  std::string figure;               ///< --figure: which figure the plot shows
  std::string against;              ///< --against: which parameter it is plotted against
  std::optional<int> workers;       ///< local workers (default: every core; 0: serially, no Dask)
  std::string scheduler;            ///< tcp://HOST:PORT of a running Dask scheduler
  bool scheduler_given = false;     ///< whether --scheduler was given (even empty)
  std::optional<double> timeout;    ///< seconds one run may take (wall-clock)
  bool quiet = false;               ///< no summary table, no progress
};

/// Adds the `sweep` subcommand to `app`, its options into `args`.
CLI::App* addSweepCommand(CLI::App& app, SweepArgs& args);

/// Runs the sweep; 0 when every run succeeded, 1 when one failed or the model has errors
/// (the tables are written all the same), 2 for a mistake in the arguments.
int sweep(const SweepArgs& args);

}  // namespace gdpn::app
