// `gdpn check`: a model's diagnostics, and its size when clean.

#include <iostream>

#include "commands.h"
#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/net.h"

namespace gdpn::app {

namespace {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

/// `gdpn check`'s arguments.
struct CheckArgs {
  std::string model;                ///< the model file or folder
  gdpn::script::ScriptLimits limits;  ///< --script-timeout, --script-memory
  std::vector<std::string> params;  ///< --param NAME=VALUE
};

int check(const std::string& arg, gdpn::script::ScriptLimits limits, const std::vector<std::string>& params) {
  Diagnostics diags;
  auto path = model::resolveModelPath(arg, diags);
  std::optional<model::Model> m;
  if (path) m = model::loadModel(*path, diags, paramOverrides(params));
  std::shared_ptr<const gdpn::net::Net> net;
  // scripts, the plant and the signals are checked too: scripts compiled, their files and
  // functions found, globals run (under the script timeout); bodies, joints and mesh files made
  // ready; what each signal names found
  if (m) net = model::checkModel(*m, diags, limits);
  diags.print(std::cerr);
  if (diags.hasErrors()) {
    std::cerr << diags.errorCount() << (diags.errorCount() == 1 ? " error\n" : " errors\n");
    return 1;
  }
  using gdpn::core::counted;
  std::cout << core::escapeInvalidUtf8(*path) << ": ok (" << counted(net->places().size(), "place") << ", "
            << counted(net->transitions().size(), "transition") << ", " << counted(net->terms().size(), "arc term")
            << ")\n";
  return 0;
}

}  // namespace

Subcommand addCheck(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  auto* check_cmd = app.add_subcommand("check", "Check a model and print its diagnostics; exit 0 when clean");
  check_cmd->add_option("MODEL", args->model, "a .gdpn.yaml file, or a folder holding exactly one")->required();
  addScriptLimitOptions(check_cmd, args->limits);
  addParamOption(check_cmd, args->params);
  setExamples(check_cmd, {"gdpn check examples/basics/two_cells        # the diagnostics; exit 0 when clean"});
  return {check_cmd, [args] { return check(args->model, args->limits, args->params); }};
}

}  // namespace gdpn::app
