#pragma once
// The two platforms of the IDE: headless (EGL surfaceless) and a GLFW window.

#include <memory>
#include <vector>

#include "gdpn/ide/document.h"
#include "gdpn/ide/ide.h"
#include "gdpn/ide/replay.h"

namespace gdpn::ide {

/// Runs the IDE headless over `doc`, performing `actions`; the exit code.
int runHeadless(const IdeOptions& options, std::unique_ptr<Document> doc, const std::vector<Action>& actions);
/// Runs the IDE in a window over `doc` until it is closed (or options.quit_after); the exit code.
int runWindow(const IdeOptions& options, std::unique_ptr<Document> doc);

}  // namespace gdpn::ide
