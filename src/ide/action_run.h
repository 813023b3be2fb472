#pragma once
// What each action of the table (gdpn/ide/actions.h) does in the App: whether it can be done,
// whether a toggle is on, doing it, and the shortcuts pressed in a frame. Private to the ide
// module: the menus, the toolbar, the shortcuts and the replay's `press:` all come here.

#include <string>

#include "gdpn/ide/actions.h"

namespace gdpn::ide {

class App;

/// True when `id` can be done now (Undo with nothing to undo cannot).
[[nodiscard]] bool actionEnabled(const App& app, ActionId id);
/// For a toggle, whether it is on now (false for the other actions).
[[nodiscard]] bool actionChecked(const App& app, ActionId id);
/// Does `id`; "" when done, else why not (it was not enabled).
std::string performAction(App& app, ActionId id);
/// Does the actions whose shortcuts were pressed in this frame (call inside the frame, before
/// the views: a text field being typed in keeps the keys of the actions marked text_first).
void handleShortcuts(App& app);

}  // namespace gdpn::ide
