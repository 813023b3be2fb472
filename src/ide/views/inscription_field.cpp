// A field of the inscription language: typed with completion, checked as typed against the
// model's colour sets and variables, applied only once it checks.

#include <imgui.h>

#include <algorithm>

#include "../views.h"
#include "gdpn/ide/colour_edit.h"
#include "script_editor.h"

namespace gdpn::ide {
namespace {

const ImVec4 kInscriptionErrorColour{1.0f, 0.45f, 0.4f, 1.0f};

/// A red line under column `column` of line `line` of the text of the field just drawn (both
/// from 1), where the field shows it.
void markInscriptionColumn(std::string_view text, int line, int column) {
  if (line <= 0 || column <= 0) return;
  std::size_t from = 0;
  for (int l = 1; l < line; ++l) {
    const auto nl = text.find('\n', from);
    if (nl == std::string_view::npos) return;
    from = nl + 1;
  }
  const auto eol = text.find('\n', from);
  const auto row = text.substr(from, eol == std::string_view::npos ? std::string_view::npos : eol - from);
  const auto at = std::min(static_cast<std::size_t>(column - 1), row.size());
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const auto& style = ImGui::GetStyle();
  const float x0 = lo.x + style.FramePadding.x + ImGui::CalcTextSize(row.data(), row.data() + at).x;
  const float w = at < row.size() ? ImGui::CalcTextSize(row.data() + at, row.data() + at + 1).x : 6.0f;
  const float y = lo.y + style.FramePadding.y + static_cast<float>(line) * ImGui::GetTextLineHeight() + 1;
  if (y > hi.y || x0 > hi.x) return;
  ImGui::GetWindowDrawList()->AddLine({x0, y}, {std::min(x0 + std::max(w, 4.0f), hi.x), y}, IM_COL32(240, 80, 70, 255), 2.0f);
}

}  // namespace

void inscriptionField(App& app, const std::string& key, const std::string& label, const std::string& current,
                      const std::string& set, InscriptionRole role, const std::function<void(const std::string&)>& store,
                      nlohmann::json& report) {
  auto& ed = app.inspector.inscriptions;
  const auto scope = colourScopeOf(app.document().model().net);
  const auto typed_it = ed.typed.find(key);
  std::string text = typed_it != ed.typed.end() ? typed_it->second : current;
  ImGui::PushID(key.c_str());
  ImGui::TextUnformatted(label.c_str());
  ImGui::SameLine(150);
  const bool typing = ed.key == key;
  CompletionPopup idle;
  auto& popup = typing ? ed.completion : idle;
  const Completer completer = [&scope](std::string_view t, std::size_t cursor) { return completeInscription(scope, t, cursor); };
  nlohmann::json entry = {{"text", current}};
  const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  (void)completingField("##inscription", text, popup, completer, -1, std::min(lines, 6), entry);
  noteItem(label, report["fields"]);
  const bool activated = ImGui::IsItemActivated();
  const bool active = ImGui::IsItemActive();
  const bool left = ImGui::IsItemDeactivated();
  if (activated) {
    ed.key = key;
    ed.completion = {};
  }
  // what the text says now, checked as it stands
  const bool blank = text.find_first_not_of(" \t\r\n") == std::string::npos;
  const auto problem = blank ? std::nullopt : checkInscriptionText(scope, text, set, role);
  if (problem) markInscriptionColumn(text, problem->line, problem->column);
  const bool apply = (typing && popup.enter) || (left && text != current);
  popup.enter = false;
  if (text != current) ed.typed[key] = text;
  else ed.typed.erase(key);
  if (apply && !problem) {
    std::string clean = text;
    while (!clean.empty() && (clean.back() == ' ' || clean.back() == '\n' || clean.back() == '\t')) clean.pop_back();
    ed.typed.erase(key);
    if (clean != current) store(blank ? std::string() : clean);
  }
  if (left && ed.key == key) ed.key.clear();
  if (problem) {
    const std::string where = problem->column > 0 ? (lines > 1 ? "line " + std::to_string(problem->line) + ", " : std::string()) +
                                                        "column " + std::to_string(problem->column) + ": "
                                                  : std::string();
    ImGui::Dummy({140, 0});
    ImGui::SameLine(150);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kInscriptionErrorColour, "%s%s", where.c_str(), problem->message.c_str());
    ImGui::PopTextWrapPos();
    if (text != current) {
      ImGui::SameLine();
      ImGui::TextDisabled(current.empty() ? "(not applied)" : "(not applied: the old text stays in force)");
    }
    entry["problem"] = {{"line", problem->line}, {"column", problem->column}, {"message", problem->message}};
  }
  if (text != current) entry["typed"] = text;
  entry["editing"] = active;
  report["inscriptions"][label] = entry;
  ImGui::PopID();
}

}  // namespace gdpn::ide
