// "Save as Part": the selected scene node, with what it holds, written to the user's parts
// folder as a new part (savePartOfNode: model::partFromNodes, then a file written beside and
// renamed), after which the palette scans the library again and lists it.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <filesystem>
#include <string>

#include "../views.h"
#include "gdpn/core/text.h"
#include "palette_state.h"

namespace gdpn::ide {

namespace {

constexpr const char* kSavePartPopup = "Save as Part###save_as_part";
const ImVec4 kSavePartError{1.0F, 0.42F, 0.38F, 1.0F};  // red, as the Diagnostics' errors

/// Writes the part the popup describes; closes it when written, else says why in it.
void savePart(App& app) {
  auto& st = app.save_part;
  const auto folder = userPartsFolder();
  const auto file = (std::filesystem::path(folder) / (st.name + model::kModelSuffix)).string();
  const bool replace = !st.replacing.empty() && st.replacing == file;
  const auto saved = savePartOfNode(app.document().model(), st.node, st.name, st.group, folder, replace);
  if (!saved.error.empty()) {
    st.error = saved.error;
    st.replacing = saved.exists ? saved.file : std::string();
    return;
  }
  app.message = "saved the part " + st.name + " to " + saved.file + ": the palette lists it";
  app.palette().scanned_for.reset();  // scanned again at the next frame
  st.open = false;
  st.error.clear();
  st.replacing.clear();
}

}  // namespace

void openSaveAsPart(App& app) {
  auto& st = app.save_part;
  const auto& sel = app.document().selection();
  st.open = true;
  st.focus = true;
  st.node = sel.name;
  st.error.clear();
  st.replacing.clear();
  // the node's own name, when it is a part's name
  const auto slash = sel.name.rfind('/');
  const std::string leaf = sel.name.substr(slash == std::string::npos ? 0 : slash + 1);
  st.name = core::isIdentifier(leaf) ? leaf : std::string();
}

void drawSaveAsPart(App& app, nlohmann::json& report) {
  auto& st = app.save_part;
  report = {{"open", st.open}};
  if (!st.open) return;
  if (!ImGui::IsPopupOpen(kSavePartPopup)) ImGui::OpenPopup(kSavePartPopup);
  const auto& io = ImGui::GetIO();
  ImGui::SetNextWindowPos({io.DisplaySize.x / 2, io.DisplaySize.y / 2}, ImGuiCond_Appearing, {0.5F, 0.5F});
  ImGui::SetNextWindowSizeConstraints({460, 0}, {io.DisplaySize.x * 0.9F, io.DisplaySize.y * 0.9F});
  if (!ImGui::BeginPopupModal(kSavePartPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    return;
  }
  const std::string folder = userPartsFolder();
  ImGui::Text("A new part made of %s and what it holds, for the palette.", st.node.c_str());
  const auto* s = app.document().scene();
  const auto* node = s != nullptr ? s->find(st.node) : nullptr;
  if (node != nullptr && node->kind() == scene::NodeKind::Transform) {
    ImGui::TextDisabled("Where it stands becomes the part's origin.");
  }
  ImGui::TextDisabled("The model's parameters that its fields name become the part's.");
  ImGui::Spacing();
  nlohmann::json fields = nlohmann::json::object(), buttons = nlohmann::json::object();
  const float label = ImGui::CalcTextSize("Group").x + 2 * ImGui::GetStyle().ItemSpacing.x;
  const float field = 420;
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Name");
  ImGui::SameLine(label);
  ImGui::SetNextItemWidth(field);
  if (st.focus) {
    ImGui::SetKeyboardFocusHere();
    st.focus = false;
  }
  const auto flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll;
  bool entered = ImGui::InputTextWithHint("##part_name", "a word: letters, digits and _", &st.name, flags);
  noteItem("name", fields);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Group");
  ImGui::SameLine(label);
  ImGui::SetNextItemWidth(field);
  entered = ImGui::InputTextWithHint("##part_group", "the palette's group (none: Other)", &st.group, flags) || entered;
  noteItem("group", fields);
  const std::string file = st.name.empty() ? std::string() : st.name + model::kModelSuffix;
  ImGui::TextDisabled("Written to %s/%s", folder.empty() ? "(no parts folder)" : folder.c_str(),
                      file.empty() ? "NAME.gdpn.yaml" : file.c_str());
  // a part of that name elsewhere in the library: the palette shows one of the two
  if (const auto* other = model::findLibraryPart(app.palette().parts, st.name);
      other != nullptr && std::filesystem::path(other->file).parent_path() != std::filesystem::path(folder)) {
    ImGui::TextDisabled("The library has a part %s already (%s, version %d).", st.name.c_str(), other->file.c_str(),
                        other->spec.version);
  }
  ImGui::Spacing();
  ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  const bool save = ImGui::Button("Save", {110, 0});
  ImGui::PopStyleColor();
  noteItem("save", buttons);
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel", {110, 0}) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  noteItem("cancel", buttons);
  if (!st.error.empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + label + field);
    ImGui::TextColored(kSavePartError, "%s", st.error.c_str());
    ImGui::PopTextWrapPos();
  }
  report = {{"open", true},    {"node", st.node},   {"name", st.name},           {"group", st.group},
            {"folder", folder}, {"error", st.error}, {"replacing", st.replacing}, {"fields", fields},
            {"buttons", buttons}};
  if (save || entered) savePart(app);
  if (cancel) st.open = false;
  if (!st.open) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace gdpn::ide
