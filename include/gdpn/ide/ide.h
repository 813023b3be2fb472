#pragma once
/// \file
/// `gdpn ide`: the IDE in a window (GLFW), or headless (EGL surfaceless, no window) with
/// replayed actions, a screenshot and a report of what the views show.

#include <string>

namespace gdpn::ide {

/// How the IDE is started.
struct IdeOptions {
  std::string model;       ///< the model file (or a folder holding one)
  bool headless = false;   ///< no window: EGL surfaceless, the same frame code
  int width = 1600;        ///< window or frame width, pixels
  int height = 900;        ///< window or frame height, pixels
  std::string replay;      ///< actions to perform (replay.h); "" for none
  std::string screenshot;  ///< PNG of the last frame; "" for none
  std::string report;      ///< JSON of what the views showed in the last frame; "" for none
  double quit_after = 0;   ///< window: quit after this many real seconds, running (0: never)
  double autosave = 60;    ///< unsaved edits are autosaved after this many seconds (0: never)
};

/// Runs the IDE; the process's exit code (0 when it ended well, 1 on an error it printed).
int runIde(const IdeOptions& options);

}  // namespace gdpn::ide
