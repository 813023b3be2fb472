// gdpn ide: open the model, then the window or the headless IDE.

#include "gdpn/ide/ide.h"

#include <iostream>

#include "detail/platforms.h"
#include "detail/termination.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {

int runIde(const IdeOptions& o) {
  // SIGTERM, SIGINT and SIGHUP end the IDE between two frames, even where a launcher left them
  // ignored
  catchTermination();
  core::Diagnostics diags;
  std::unique_ptr<Document> doc;
  if (model::startsNewModel(o.model)) {
    doc = Document::create(o.model);
  } else if (const auto path = model::resolveModelPath(o.model, diags)) {
    doc = Document::open(*path, diags);
  }
  if (!doc) {
    diags.print(std::cerr);
    return 1;
  }
  if (terminationFlag().load()) endByTermination();
  if (!o.headless) return runWindow(o, std::move(doc));
  std::vector<Action> actions;
  if (!o.replay.empty()) {
    core::Diagnostics replay_diags;
    auto loaded = loadReplay(o.replay, replay_diags);
    if (!loaded) {
      replay_diags.print(std::cerr);
      return 1;
    }
    actions = std::move(*loaded);
  }
  return runHeadless(o, std::move(doc), actions);
}

}  // namespace gdpn::ide
