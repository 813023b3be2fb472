// `gdpn ide`: the IDE on a model, in a window or headless (when it was built in).

#include <iostream>

#include "cli_checks.h"
#include "commands.h"
#ifdef GDPN_WITH_IDE
#include "gdpn/ide/ide.h"
#endif

namespace gdpn::app {

namespace {

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
  o.model = a.model.empty() ? model::untitledModelPath("") : a.model;
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

Subcommand addIde(CLI::App& app) {
  auto args = std::make_shared<IdeArgs>();
  auto* ide_cmd = app.add_subcommand("ide", "Open a model in the IDE (a window; --headless for none)");
  ide_cmd->add_option("MODEL", args->model,
                      "a .gdpn.yaml file, or a folder holding one; a new or empty .gdpn.yaml starts a new model, "
                      "and so does none (untitled.gdpn.yaml in the current folder)");
  ide_cmd->add_flag("--headless", args->headless, "no window: draw on an EGL surfaceless context");
  ide_cmd->add_option("--size", args->size, "WIDTHxHEIGHT of the window or frame in pixels (default 1600x900)");
  ide_cmd->add_option("--replay", args->replay, "headless: perform the actions in ACTIONS.yaml (docs/ide.md)");
  ide_cmd->add_option("--screenshot", args->screenshot, "save the last frame as a PNG");
  ide_cmd->add_option("--report", args->report, "save what the views showed in the last frame as JSON");
  ide_cmd->add_option("--quit-after", args->quit_after,
                      "window: run in real time and quit after SECONDS (with the screenshot and report)")
      ->check(number(0.0, 1e6, "seconds above 0, at most 1e6", true));
  ide_cmd->add_option("--autosave", args->autosave,
                      "save unsaved edits into the user's state folder after SECONDS (default 60; 0: never)")
      ->check(number(0.0, 1e6, "seconds from 0 to 1e6", false));
  setExamples(ide_cmd, {"gdpn ide examples/factory                 # a window; a new file starts a new model"});
  return {ide_cmd, [args] { return ide(*args); }};
}

}  // namespace gdpn::app
