// gdpn: the command-line program. Every rule lives in the library; each subcommand lives in
// its own file (commands.h) and parses its arguments, calls into the library and prints; this
// file only dispatches.

#include <CLI/CLI.hpp>

#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "commands.h"

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
  // in the order --help lists them
  const std::vector<gdpn::app::Subcommand> subcommands = {
      gdpn::app::addCheck(app),  gdpn::app::addRun(app),    gdpn::app::addSweep(app),   gdpn::app::addAnalyze(app),
      gdpn::app::addRender(app), gdpn::app::addRecord(app), gdpn::app::addConvert(app), gdpn::app::addParts(app),
      gdpn::app::addIde(app),    gdpn::app::addReference(app)};
  // every mistake on the command line exits 2, after CLI11's message (help and version exit 0)
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  for (const auto& subcommand : subcommands) {
    if (subcommand.app->parsed()) return subcommand.run();
  }
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
