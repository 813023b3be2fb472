// gdpn ide: open the model, then the window or the headless IDE.

#include "gdpn/ide/ide.h"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "detail/platforms.h"
#include "detail/termination.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {

namespace {

/// True when `path` names a model file that is not there yet, or one that holds nothing but
/// blanks: the IDE starts a new model that saving writes there.
bool newModel(const std::string& path) {
  if (!path.ends_with(model::kModelSuffix)) return false;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return !ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c)) {
    if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return false;
  }
  return true;
}

}  // namespace

int runIde(const IdeOptions& o) {
  // SIGTERM, SIGINT and SIGHUP end the IDE between two frames, even where a launcher left them
  // ignored
  catchTermination();
  core::Diagnostics diags;
  std::unique_ptr<Document> doc;
  if (newModel(o.model)) {
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
