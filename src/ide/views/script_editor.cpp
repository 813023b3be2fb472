// The script editor: highlighted text with the file's line numbers, or a field with completion
// under the cursor; the syntax error and the run's error marked on their lines.

#include "script_editor.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <optional>

#include "../views.h"
#include "gdpn/ide/python_text.h"
#include "gdpn/ide/script_completion.h"

namespace gdpn::ide {
namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
constexpr int kListRows = 10;  // names the completion list shows at once

// ---- where the scripts stand, and the run's error ----

/// The document's net with its scripts on the lines Save gives them (as the run has them),
/// made again when the document changes.
const net::NetSpec& placedNet(App& app) {
  auto& ed = app.inspector.scripts;
  const auto& doc = app.document();
  if (ed.placed_revision != doc.revision()) {
    model::Model m = doc.model();
    placeScripts(m, doc.text());
    ed.placed = std::move(m.net);
    ed.placed_revision = doc.revision();
  }
  return ed.placed;
}

/// An error of the run at a line of a script.
struct RunError {
  int line = 0;       ///< the script's own line, 1 its first
  int file_line = 0;  ///< the model file's
  std::string message;
};

/// The line of the model file `path` that `text` (a located message: "PATH:LINE: error: ...")
/// names first, or 0.
int fileLineIn(const std::string& text, const std::string& path) {
  if (path.empty()) return 0;
  for (std::size_t at = text.find(path + ":"); at != std::string::npos; at = text.find(path + ":", at + 1)) {
    std::size_t i = at + path.size() + 1;
    int line = 0;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) != 0 && line < 100'000'000) {
      line = line * 10 + (text[i++] - '0');
    }
    if (line > 0 && (at == 0 || text[at - 1] == ' ' || text[at - 1] == '\n')) return line;
  }
  return 0;
}

/// The last line of a traceback that says something: the exception.
std::string lastLine(const std::string& text) {
  std::size_t end = text.size();
  while (end > 0) {
    while (end > 0 && (text[end - 1] == '\n' || text[end - 1] == ' ')) --end;
    const auto nl = text.rfind('\n', end == 0 ? 0 : end - 1);
    const auto begin = nl == std::string::npos ? 0 : nl + 1;
    if (end > begin) return text.substr(begin, end - begin);
    end = begin;
  }
  return {};
}

/// Where the run's last error (runError) lies in the script `at`, if it does.
std::optional<RunError> runErrorIn(App& app, const ScriptAt& at) {
  const auto [file_line, message] = runError(app);
  if (file_line == 0) return std::nullopt;
  const auto* script = scriptAt(placedNet(app), at);
  const int line = script != nullptr ? scriptLineOf(*script, file_line) : 0;
  if (line == 0) return std::nullopt;
  return RunError{line, file_line, message};
}

// ---- completion ----

/// What the text field's callback works on.
struct FieldCall {
  CompletionPopup& popup;
  const Completer& complete;
  bool enter_applies = false;  ///< Enter with the list closed is not typed: it sets popup.enter
};

bool nameChar(ImWchar c) { return c < 128 && (std::isalnum(static_cast<int>(c)) != 0 || c == '_'); }

/// Puts the chosen name in place of the word typed so far.
void insertChosen(ImGuiInputTextCallbackData* data, const CompletionQuery& q, int chosen) {
  if (chosen < 0 || chosen >= static_cast<int>(q.names.size())) return;
  const int start = static_cast<int>(q.start);
  if (start > data->CursorPos) return;
  data->DeleteChars(start, data->CursorPos - start);
  data->InsertChars(start, q.names[static_cast<std::size_t>(chosen)].name.c_str());
}

/// The field's callback: characters first (a dot or a name's character opens or follows the
/// list; Tab and Enter take the chosen name while it shows), then once a frame with the text:
/// the list found again for the word at the cursor.
int fieldCallback(ImGuiInputTextCallbackData* data) {
  auto& call = *static_cast<FieldCall*>(data->UserData);
  auto& p = call.popup;
  if (data->EventFlag == ImGuiInputTextFlags_CallbackCharFilter) {
    const ImWchar c = data->EventChar;
    if (p.open && (c == '\t' || c == '\n')) {
      p.accept = true;
      return 1;
    }
    if (!p.open && c == '\n' && call.enter_applies) {
      p.enter = true;
      return 1;
    }
    if (!p.open && c == '\t' && p.cursor > 0 && p.cursor >= static_cast<int>(p.query.start) &&
        (!p.query.prefix.empty() || p.query.member)) {
      p.ask = true;  // Tab after a name or a dot: complete, not indent
      return 1;
    }
    if (c == '.' || nameChar(c)) p.typed = true;
    return 0;
  }
  // where the text begins on screen: the callback runs inside the field's own window
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  p.text_x = origin.x;
  p.text_y = origin.y;
  const bool up = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow));
  const bool down = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow));
  if ((up || down) && p.open && !p.query.names.empty()) {
    // Up and Down choose in the list; the text cursor stays where it was
    const int n = static_cast<int>(p.query.names.size());
    p.selected = (p.selected + (up ? n - 1 : 1)) % n;
    data->CursorPos = data->SelectionStart = data->SelectionEnd = std::min(p.cursor, data->BufTextLen);
    return 0;
  }
  if (p.accept && p.open) {
    insertChosen(data, p.query, p.selected);
    p.open = false;
  }
  p.accept = false;
  const std::string_view code(data->Buf, static_cast<std::size_t>(data->BufTextLen));
  auto q = call.complete(code, static_cast<std::size_t>(data->CursorPos));
  const bool whole = q.names.size() == 1 && q.names.front().name == q.prefix;  // nothing left to complete
  if (p.ask) {
    if (q.names.size() == 1) {
      insertChosen(data, q, 0);
      q = call.complete(std::string_view(data->Buf, static_cast<std::size_t>(data->BufTextLen)),
                        static_cast<std::size_t>(data->CursorPos));
      p.open = false;
    } else {
      p.open = !q.names.empty();
      p.selected = 0;
    }
  } else if (p.typed) {
    // after a dot the list opens; a name typed at the start of a word opens it from its second
    // character; it follows the typing while it shows
    const bool was_open = p.open;
    p.open = !q.names.empty() && !whole && (q.member || q.prefix.size() >= 2 || was_open);
    if (!was_open || q.start != p.query.start) p.selected = 0;
  } else if (p.open) {
    // the cursor left the word (arrows, a click) or the word was deleted: the list goes
    if (q.start != p.query.start || q.member != p.query.member || q.names.empty() || whole) p.open = false;
  }
  if (p.open && p.selected < static_cast<int>(p.query.names.size())) {
    // the chosen name stays chosen while the list narrows
    const auto& was = p.query.names[static_cast<std::size_t>(p.selected)].name;
    const auto it = std::find_if(q.names.begin(), q.names.end(), [&](const auto& c) { return c.name == was; });
    p.selected = it == q.names.end() ? 0 : static_cast<int>(it - q.names.begin());
  }
  p.ask = p.typed = false;
  p.query = std::move(q);
  p.cursor = data->CursorPos;
  return 0;
}

/// The list under the word being completed: up to kListRows names around the chosen one, each
/// with what it is, and the chosen one's line below.
void drawCompletion(const CompletionPopup& p, std::string_view code, nlohmann::json& entry) {
  nlohmann::json names = nlohmann::json::array();
  for (const auto& c : p.query.names) names.push_back(c.name);
  entry["completion"] = {{"open", p.open},      {"context", p.query.context}, {"prefix", p.query.prefix},
                         {"member", p.query.member}, {"names", names}};
  if (!p.open || p.query.names.empty()) return;
  const auto& chosen = p.query.names[static_cast<std::size_t>(std::clamp(p.selected, 0, static_cast<int>(p.query.names.size()) - 1))];
  entry["completion"]["selected"] = chosen.name;
  entry["completion"]["detail"] = chosen.detail;
  entry["completion"]["signature"] = chosen.signature;
  // under the word's first character
  const std::size_t start = std::min(p.query.start, code.size());
  const auto line_start = code.rfind('\n', start == 0 ? 0 : start - 1);
  const std::size_t from = line_start == std::string_view::npos || start == 0 ? 0 : line_start + 1;
  const auto row = static_cast<float>(std::count(code.begin(), code.begin() + static_cast<std::ptrdiff_t>(start), '\n'));
  const auto before = code.substr(from, start - from);
  const float x = p.text_x + ImGui::CalcTextSize(before.data(), before.data() + before.size()).x;
  const float line = ImGui::GetTextLineHeight();
  float y = p.text_y + (row + 1) * line + 2;
  const float rows = static_cast<float>(std::min<std::size_t>(p.query.names.size(), kListRows)) + 3.5f;
  const float height = rows * ImGui::GetTextLineHeightWithSpacing();
  const auto& io = ImGui::GetIO();
  if (y + height > io.DisplaySize.y) y = std::max(0.0f, y - line - 4 - height);  // above the line when it would not fit below
  ImGui::SetNextWindowPos({std::min(x, std::max(0.0f, io.DisplaySize.x - 440)), y});
  ImGui::SetNextWindowSizeConstraints({260, 0}, {440, height + 40});
  ImGui::PushStyleColor(ImGuiCol_PopupBg, {0.13f, 0.14f, 0.17f, 0.98f});
  ImGui::PushStyleColor(ImGuiCol_Border, {0.45f, 0.55f, 0.75f, 1.0f});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 1.0f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##completion", nullptr, flags)) {
    const int n = static_cast<int>(p.query.names.size());
    const int first = std::clamp(p.selected - kListRows / 2, 0, std::max(0, n - kListRows));
    const int last = std::min(n, first + kListRows);
    if (ImGui::BeginTable("##names", 2, ImGuiTableFlags_SizingFixedFit)) {
      for (int i = first; i < last; ++i) {
        const auto& c = p.query.names[static_cast<std::size_t>(i)];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Selectable(c.name.c_str(), i == p.selected, ImGuiSelectableFlags_SpanAllColumns);
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", c.kind.c_str());
      }
      ImGui::EndTable();
    }
    if (n > last - first) ImGui::TextDisabled("%d of %d; Up and Down choose", last - first, n);
    ImGui::Separator();
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 420);
    ImGui::TextColored({0.6f, 0.75f, 1.0f, 1.0f}, "%s%s", chosen.name.c_str(), chosen.signature.c_str());
    ImGui::SameLine();
    ImGui::TextWrapped("%s", chosen.detail.empty() ? "" : chosen.detail.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextDisabled("Tab or Enter: insert");
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor(2);
}

/// A faint red band over line `line` (1 its first) of the text of the field just drawn, where
/// the field shows it.
void markFieldLine(const CompletionPopup& p, int line) {
  if (line <= 0) return;
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const float h = ImGui::GetTextLineHeight();
  const float y = p.text_y + static_cast<float>(line - 1) * h;
  if (y < lo.y || y + h > hi.y) return;
  ImGui::GetForegroundDrawList()->AddRectFilled({lo.x + 2, y}, {hi.x - 2, y + h}, IM_COL32(220, 60, 50, 70));
}

/// "line 3 (file line 15)".
std::string whereText(int line, int file_line) {
  return "line " + std::to_string(line) + (file_line > 0 ? " (file line " + std::to_string(file_line) + ")" : "");
}

}  // namespace

bool completingField(const char* id, std::string& buffer, CompletionPopup& popup, const Completer& complete, float width,
                     int lines, nlohmann::json& entry) {
  FieldCall call{popup, complete, true};
  const bool changed = ImGui::InputTextMultiline(
      id, &buffer, {width, ImGui::GetTextLineHeight() * static_cast<float>(std::max(1, lines)) + 8},
      ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackCharFilter | ImGuiInputTextFlags_CallbackAlways,
      &fieldCallback, &call);
  if (ImGui::IsItemActive()) drawCompletion(popup, buffer, entry);
  else popup.open = false;
  return changed;
}

std::pair<int, std::string> runError(App& app) {
  auto& ed = app.inspector.scripts;
  const auto& doc = app.document();
  if (app.run().revision() == doc.revision()) {
    // a run of the document as it is: its error in the model file, found when it was made or
    // where a script stopped it
    const auto& path = doc.model().path;
    for (const auto& d : app.runDiagnostics().all()) {
      if (d.severity != core::Severity::Error || d.loc.file != path || d.loc.line <= 0) continue;
      ed.error_line = d.loc.line;
      ed.error_message = lastLine(d.message);
      ed.error_revision = doc.revision();
      break;
    }
    const auto& message = app.run().message();
    if (const int line = fileLineIn(message, path); line > 0) {
      ed.error_line = line;
      ed.error_message = lastLine(message);
      ed.error_revision = doc.revision();
    }
  }
  if (ed.error_revision != doc.revision()) ed.error_line = 0;  // an edit since: the line may be another
  return {ed.error_line, ed.error_line > 0 ? ed.error_message : std::string()};
}

void scriptEditor(App& app, const std::string& key, const std::string& heading, const net::ScriptSpec& script,
                  bool expression, const ScriptAt& at, const std::function<void(const std::string&)>& store,
                  nlohmann::json& report) {
  auto& ed = app.inspector.scripts;
  ImGui::PushID(key.c_str());
  ImGui::Separator();
  ImGui::TextColored({0.6f, 0.75f, 1.0f, 1.0f}, "%s", heading.c_str());
  nlohmann::json entry = {{"what", heading}, {"file", script.file}};
  // where the script stands in the file as Save writes it, and the run's error in it
  const auto* placed = scriptAt(placedNet(app), at);
  const int first_line = placed != nullptr && placed->file.empty() && placed->loc.line > 0 ? placed->loc.line : 1;
  const auto run_error = runErrorIn(app, at);
  if (run_error) {
    entry["run_error"] = {{"line", run_error->line}, {"file_line", run_error->file_line}, {"message", run_error->message}};
  }
  const auto problem = ed.problems.find(key);
  const auto showErrors = [&] {
    if (problem != ed.problems.end()) {
      const auto& p = problem->second;
      const int file_line = placed != nullptr && p.line > 0 && first_line > 1 ? first_line + p.line - 1 : 0;
      const std::string where = whereText(p.line, file_line) + (p.column > 0 ? ", column " + std::to_string(p.column) : "");
      ImGui::TextColored(kErrorColour, "%s: %s", where.c_str(), p.message.c_str());
      entry["error"] = {{"line", p.line}, {"column", p.column}, {"message", p.message}};
    }
    if (run_error) {
      ImGui::TextColored(kErrorColour, "the run stopped at %s: %s", whereText(run_error->line, run_error->file_line).c_str(),
                         run_error->message.c_str());
    }
  };
  if (!script.file.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s%s%s (edit the file)", script.file.c_str(), script.function.empty() ? "" : ": ",
                        script.function.c_str());
    entry["lines"] = drawPython(script.code, script.loc.line);
  } else if (ed.key == key) {
    ImGui::SameLine();
    ImGui::TextDisabled(expression ? "an expression; compiled when you leave it; Tab completes"
                                   : "compiled when you leave it; Tab completes");
    if (ed.focus) {
      ImGui::SetKeyboardFocusHere();
      ed.focus = false;
      ed.completion = {};
      ed.scope = scopeOf(app.document().model(), app.tokenTypes(), at.page, at.construct, at.kind, at.slot);
    }
    const int lines = 1 + static_cast<int>(std::count(ed.buffer.begin(), ed.buffer.end(), '\n'));
    const Completer completer = [&ed](std::string_view code, std::size_t cursor) { return complete(ed.scope, code, cursor); };
    FieldCall call{ed.completion, completer};
    ImGui::InputTextMultiline("##code", &ed.buffer,
                              {-1, ImGui::GetTextLineHeight() * static_cast<float>(std::clamp(lines + 1, 3, 16)) + 8},
                              ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackCharFilter |
                                  ImGuiInputTextFlags_CallbackAlways,
                              &fieldCallback, &call);
    noteItem("field", entry);
    entry["editing"] = true;
    entry["lines"] = lines;
    entry["text"] = ed.buffer;
    if (ImGui::IsItemDeactivated()) {
      // compiled now; a syntax error is kept and marked, the text is never thrown away
      std::string code = ed.buffer;
      while (!code.empty() && (code.back() == '\n' || code.back() == ' ')) code.pop_back();
      if (!code.empty() && !expression) code += '\n';
      ed.problems.erase(key);
      if (!code.empty()) {
        if (auto found = script::syntaxProblem(code, expression)) ed.problems[key] = *found;
      }
      ed.key.clear();
      ed.completion = {};
      if (code != script.code) store(code);
    } else {
      if (problem != ed.problems.end()) markFieldLine(ed.completion, std::max(1, problem->second.line));
      if (run_error) markFieldLine(ed.completion, run_error->line);
      drawCompletion(ed.completion, ed.buffer, entry);
      showErrors();
    }
  } else {
    const int error_line = problem != ed.problems.end() ? std::max(1, problem->second.line) : run_error ? run_error->line : 0;
    ImGui::SameLine();
    if (ImGui::SmallButton(script.empty() ? "Add" : "Edit")) {
      ed.key = key;
      ed.buffer = script.code;
      ed.focus = true;
    }
    noteItem("edit", entry);
    entry["lines"] = script.empty() ? 0 : drawPython(script.code, first_line, error_line);
    entry["first_line"] = first_line;
    showErrors();
  }
  if (!script.empty() || entry.contains("editing")) report["scripts"].push_back(entry);
  report["editors"][heading] = entry;
  ImGui::PopID();
}

}  // namespace gdpn::ide
