#pragma once
/// \file
/// Where the model's inline scripts stand in its file. A script typed in the IDE keeps the
/// location it had when the file was read (or none, when it is new), and every line the edits
/// added above it moves it; the run compiles the scripts with their file lines (net::ScriptSpec
/// `loc`, `lines`), so the IDE gives them the lines they have in the text that Save writes, and
/// an error is reported at the line it will have in the file. No ImGui.

#include <functional>
#include <string>

#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"
#include "gdpn/net/spec.h"

namespace gdpn::model {
struct Model;
}

namespace gdpn::ide {

/// Which script of a net: its page (or page type), its construct ("" for the globals), its
/// kind, and for a place slot's script its slot (for an arc's, the slot of its predicate or
/// condition, and `arc` its index on the page).
struct ScriptAt {
  std::string page;                    ///< "" for the globals
  std::string construct;               ///< the place or transition; an arc's transition
  net::ScriptKind kind = net::ScriptKind::Globals;  ///< which of its scripts
  net::SlotId slot = net::kDefaultSlot;  ///< a place slot's, a predicate's or a condition's slot
  int arc = -1;                        ///< an arc's index on its page (-1: no arc)
  friend bool operator==(const ScriptAt&, const ScriptAt&) = default;
};

/// Calls `visit` for every script of `net` (inline or in a file, empty ones left out), in one
/// fixed order: the globals, then each page and page type's places, transitions and arcs.
void forEachScript(const net::NetSpec& net, const std::function<void(const ScriptAt&, const net::ScriptSpec&)>& visit);

/// The script at `at` in `net`, or null.
const net::ScriptSpec* scriptAt(const net::NetSpec& net, const ScriptAt& at);

/// Gives every script of `model` the location it has in `text` (the model as Save writes it:
/// Document::text()), read back as the file `model.path`: its first line, its lines and its
/// indent. Nothing changes where `text` does not read back as the same net. Python's tracebacks
/// then quote `text`'s lines for that file (script::quoteSourceAs).
void placeScripts(model::Model& model, const std::string& text);

/// The line of `script`'s own text (1 its first) that the model file's line `file_line` is, or
/// 0 when the script does not cover that line.
int scriptLineOf(const net::ScriptSpec& script, int file_line);

}  // namespace gdpn::ide
