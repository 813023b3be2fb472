// The library's newer versions of the model's parts: found when a model is opened and after a
// Rescan (model::partUpdates), noted in the palette, listed in a popup (the I/O and parameters
// each adds, removes and changes, the io section's uses of removed I/O) and taken as one step
// of undo (UpdatePartsCommand, one model::applyPartUpdate a part).

#include <imgui.h>

#include <string>
#include <vector>

#include "../action_run.h"
#include "../views.h"
#include "palette_state.h"

namespace gdpn::ide {

namespace {

constexpr const char* kUpdatesPopup = "Update Parts###parts_update";
const ImVec4 kRemovedColour{1.0F, 0.55F, 0.45F, 1.0F};  // what goes: removed I/O, errors
const ImVec4 kNoticeColour{0.95F, 0.75F, 0.3F, 1.0F};   // amber, as the palette's warnings

/// "1 part has a newer version", "2 parts have newer versions".
std::string newerVersions(std::size_t n) {
  return n == 1 ? std::string("1 part has a newer version") : std::to_string(n) + " parts have newer versions";
}

/// `names` joined by ", ".
std::string commaList(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// One line of what an update changes: "I/O removed: seen", in `colour` (none: the text's).
void changeLine(const char* what, const std::vector<std::string>& names, const ImVec4* colour = nullptr) {
  if (names.empty()) return;
  ImGui::TextDisabled("%s", what);
  ImGui::SameLine(150);
  if (colour != nullptr) ImGui::TextColored(*colour, "%s", commaList(names).c_str());
  else ImGui::TextUnformatted(commaList(names).c_str());
}

/// What the report says of an update.
nlohmann::json updateJson(const model::PartUpdate& u) {
  return {{"name", u.name},       {"from", u.from},
          {"to", u.to},           {"file", u.file},
          {"added", u.added},     {"removed", u.removed},
          {"changed", u.changed}, {"params_added", u.params_added},
          {"params_removed", u.params_removed}};
}

/// Takes the updates the popup lists as one step, then the run is made again so that the
/// uses of removed I/O show as located errors in the Diagnostics view.
void applyUpdates(App& app) {
  auto& st = app.part_updates;
  auto command = std::make_unique<UpdatePartsCommand>(st.offered);
  const auto* updating = command.get();  // kept on the undo stack when it succeeds
  const auto why = app.document().execute(std::move(command));
  if (!why.empty()) {
    st.error = why;
    return;
  }
  const auto uses = updating->uses().size();
  std::string text = updating->label();
  core::Diagnostics diags;
  (void)app.run().reset(diags);
  if (uses > 0) {
    text += "; " + std::to_string(uses) + (uses == 1 ? " use" : " uses") +
            " of removed I/O: errors in Diagnostics";
  }
  app.message = text;
  st.open = false;
  st.error.clear();
}

}  // namespace

void refreshPartUpdates(App& app) {
  auto& st = app.part_updates;
  const auto& m = app.document().model();
  // a model without parts has nothing to update: the library is not read for it
  if (m.parts.empty()) {
    st.updates.clear();
    return;
  }
  scanLibrary(app);
  const auto& palette = app.palette();
  if (st.revision == app.document().revision() && st.scans == palette.scans) return;
  st.updates = model::partUpdates(m, palette.parts);
  st.revision = app.document().revision();
  st.scans = palette.scans;
}

void openPartUpdates(App& app) {
  auto& st = app.part_updates;
  st.offered = st.updates;
  st.error.clear();
  // the uses the updates will leave without their I/O, found on a copy of the model
  st.uses = removedIoUses(app.document().model(), st.offered, st.error);
  st.open = true;
}

void drawPartUpdateNotice(App& app, nlohmann::json& report) {
  const auto& updates = app.part_updates.updates;
  report = {{"count", updates.size()}};
  if (updates.empty()) return;
  std::vector<std::string> names;
  for (const auto& u : updates) names.push_back(u.name);
  const std::string text = newerVersions(updates.size()) + ":";
  ImGui::TextColored(kNoticeColour, "%s", text.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", commaList(names).c_str());
  const float button = ImGui::CalcTextSize("Update...").x + 2 * ImGui::GetStyle().FramePadding.x;
  // beside the text where it fits, else under it
  if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + button <=
      ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
    ImGui::SameLine();
  }
  if (ImGui::SmallButton("Update...")) {
    const auto why = performAction(app, ActionId::UpdateParts);
    if (!why.empty()) app.message = app.run().mode() == RunMode::Edit ? why : "the model is not edited while it runs: Reset first";
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("List what the newer versions change, and take them");
  noteItem("update", report);
  report["text"] = text;
  report["parts"] = names;
}

void drawPartUpdates(App& app, nlohmann::json& report) {
  auto& st = app.part_updates;
  report = {{"open", st.open}};
  if (!st.open) return;
  if (!ImGui::IsPopupOpen(kUpdatesPopup)) ImGui::OpenPopup(kUpdatesPopup);
  const auto& io = ImGui::GetIO();
  ImGui::SetNextWindowPos({io.DisplaySize.x / 2, io.DisplaySize.y / 2}, ImGuiCond_Appearing, {0.5F, 0.5F});
  ImGui::SetNextWindowSizeConstraints({420, 0}, {io.DisplaySize.x * 0.9F, io.DisplaySize.y * 0.9F});
  if (!ImGui::BeginPopupModal(kUpdatesPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    return;
  }
  ImGui::TextUnformatted("The library holds newer versions of parts this model uses.");
  ImGui::TextDisabled("The model keeps its own copy of each until it takes the new one.");
  nlohmann::json parts = nlohmann::json::array();
  for (const auto& u : st.offered) {
    ImGui::Spacing();
    ImGui::Separator();
    ImGui::Text("%s", u.name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("version %d \xe2\x86\x92 %d", u.from, u.to);  // an arrow
    ImGui::TextDisabled("from %s", u.file.c_str());
    ImGui::Indent();
    changeLine("I/O added", u.added);
    changeLine("I/O removed", u.removed, &kRemovedColour);
    changeLine("I/O changed", u.changed);
    changeLine("params added", u.params_added);
    changeLine("params removed", u.params_removed, &kRemovedColour);
    if (u.added.empty() && u.removed.empty() && u.changed.empty() && u.params_added.empty() && u.params_removed.empty()) {
      ImGui::TextDisabled("its I/O and parameters stay as they are");
    }
    ImGui::Unindent();
    parts.push_back(updateJson(u));
  }
  ImGui::Spacing();
  ImGui::Separator();
  if (!st.uses.empty()) {
    ImGui::TextUnformatted("These uses of removed I/O become errors, listed in Diagnostics:");
    for (const auto& use : st.uses) ImGui::TextColored(kNoticeColour, "  %s", use.c_str());
  } else {
    ImGui::TextDisabled("Nothing in the model uses the I/O they remove.");
  }
  ImGui::TextDisabled("Update is one step: Undo gives the model back as it was.");
  ImGui::Spacing();
  nlohmann::json buttons = nlohmann::json::object();
  ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  const bool update = ImGui::Button("Update", {110, 0});
  ImGui::PopStyleColor();
  noteItem("update", buttons);
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel", {110, 0}) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  noteItem("cancel", buttons);
  if (!st.error.empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 600);
    ImGui::TextColored(kRemovedColour, "%s", st.error.c_str());
    ImGui::PopTextWrapPos();
  }
  report = {{"open", true}, {"parts", parts}, {"uses", st.uses}, {"error", st.error}, {"buttons", buttons}};
  if (update) applyUpdates(app);
  if (cancel) st.open = false;
  if (!st.open) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace gdpn::ide
