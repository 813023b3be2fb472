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
  double script_timeout = 0.0;      ///< --script-timeout, seconds (0: none)
  std::vector<std::string> params;  ///< --param NAME=VALUE
};

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
  using gdpn::core::counted;
  std::cout << *path << ": ok (" << counted(net->places().size(), "place") << ", "
            << counted(net->transitions().size(), "transition") << ", " << counted(net->terms().size(), "arc term")
            << ")\n";
  return 0;
}

}  // namespace

Subcommand addCheck(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  auto* check_cmd = app.add_subcommand("check", "Check a model and print its diagnostics; exit 0 when clean");
  check_cmd->add_option("MODEL", args->model, "a .gdpn.yaml file, or a folder holding exactly one")->required();
  check_cmd->add_option("--script-timeout", args->script_timeout,
                        "report an error when the globals script (or a script file's top level) runs longer than SECONDS")
      ->check(CLI::PositiveNumber);
  addParamOption(check_cmd, args->params);
  return {check_cmd, [args] { return check(args->model, args->script_timeout, args->params); }};
}

}  // namespace gdpn::app
