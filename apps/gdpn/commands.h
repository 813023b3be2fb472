#pragma once
/// \file
/// gdpn's subcommands, each in its own file (check.cpp, run.cpp, analyze.cpp, render.cpp,
/// convert.cpp, ide.cpp, sweep_command.cpp): each adds itself to the program with its options
/// and runs when it was parsed. main.cpp only dispatches.

#include <CLI/CLI.hpp>

#include "cli_support.h"

namespace gdpn::app {

/// `gdpn check MODEL`: the model's diagnostics; exit 0 when clean, 1 with errors.
Subcommand addCheck(CLI::App& app);
/// `gdpn run MODEL`: a headless run (session::RunRequest) with its summary, report, trace,
/// signals, HTML page, breakpoints, witness replay and Modbus serving.
Subcommand addRun(CLI::App& app);
/// `gdpn sweep MODEL`: parameter sweeps (sweep_command.h).
Subcommand addSweep(CLI::App& app);
/// `gdpn analyze MODEL`: the untimed analysis (session::AnalysisRequest), queries or the
/// reachability graph.
Subcommand addAnalyze(CLI::App& app);
/// `gdpn render MODEL -o FILE`: a picture of the plant, or with --net of the net.
Subcommand addRender(CLI::App& app);
/// `gdpn record MODEL -o FILE`: a movie of the plant.
Subcommand addRecord(CLI::App& app);
/// `gdpn convert IN OUT`: PNML to a model and back, or a mesh to a model.
Subcommand addConvert(CLI::App& app);
/// `gdpn parts`: the parts library; a model's parts added, mapped and updated.
Subcommand addParts(CLI::App& app);
/// `gdpn ide MODEL`: the IDE, when it was built in.
Subcommand addIde(CLI::App& app);
/// `gdpn reference`: the command-line reference from these definitions (docs/cli.md, gdpn.1);
/// hidden from --help.
Subcommand addReference(CLI::App& app);

}  // namespace gdpn::app
