// gdpn ide: open the model, then the window or the headless IDE.

#include "gdpn/ide/ide.h"

#include <iostream>

#include "detail/platforms.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {

int runIde(const IdeOptions& o) {
  core::Diagnostics diags;
  const auto path = model::resolveModelPath(o.model, diags);
  std::unique_ptr<Document> doc;
  if (path) doc = Document::open(*path, diags);
  if (!doc) {
    diags.print(std::cerr);
    return 1;
  }
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
