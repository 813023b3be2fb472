#pragma once
// The contents view's script editor: a script shown highlighted with its file's line numbers,
// or typed in a field with completion (the names `sim`, `self`, its slots, node tokens and the
// globals offer, under the cursor as one types after a dot, or on Tab), its syntax error and
// the run's error marked on their lines. Private to the ide module.

#include <functional>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "gdpn/ide/script_completion.h"
#include "gdpn/ide/script_places.h"
#include "gdpn/net/spec.h"

namespace gdpn::ide {

class App;
struct CompletionPopup;

/// What may complete the word at byte `cursor` of `text`.
using Completer = std::function<CompletionQuery(std::string_view text, std::size_t cursor)>;

/// A text field `id` (`width` pixels, -1 the whole row; `lines` high) over `buffer` with the
/// completion list of `complete` under the cursor, as the script editor has it: it opens after a
/// dot or from a name's second character (Tab asks), Up and Down choose, Tab or Enter insert.
/// Enter with the list closed is not typed: it sets `popup.enter` (the caller applies the text).
/// The list's state goes into `entry["completion"]`. True when the text changed.
bool completingField(const char* id, std::string& buffer, CompletionPopup& popup, const Completer& complete, float width,
                     int lines, nlohmann::json& entry);

/// The run's last error at a line of the model file (0: none) and its message, while the
/// document is as that run had it: a script's exception, or an error found when the run was
/// made.
std::pair<int, std::string> runError(App& app);

/// One script in the editor, under `heading`: highlighted with its line numbers, its syntax
/// error and the run's error marked, or, after "Edit", a field that takes the typing with
/// completion and is compiled when it loses focus. A script in a .py file is shown, not edited
/// here. `key` names it among the editors, `at` says which script of the model it is (what it
/// sees, where it stands in the file). Calls `store` with the new code when the field was
/// changed.
void scriptEditor(App& app, const std::string& key, const std::string& heading, const net::ScriptSpec& script,
                  bool expression, const ScriptAt& at, const std::function<void(const std::string&)>& store,
                  nlohmann::json& report);

}  // namespace gdpn::ide
