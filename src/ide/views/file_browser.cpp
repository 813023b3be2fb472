// The IDE's own file browser (Open, Save As) and the "save changes?" question.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "../views.h"

namespace gdpn::ide {

namespace {

namespace fs = std::filesystem;

constexpr const char* kModelSuffix = ".gdpn.yaml";
constexpr std::size_t kMostEntries = 2000;  // a folder's entries listed at most

/// A folder's subfolders and model files (hidden ones left out), each group sorted by name.
struct Listing {
  std::vector<std::string> folders, files;
  bool cut = false;  ///< more than kMostEntries
};

Listing list(const std::string& folder) {
  Listing l;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const auto name = it->path().filename().string();
    if (name.empty() || name.front() == '.') continue;
    if (l.folders.size() + l.files.size() >= kMostEntries) {
      l.cut = true;
      break;
    }
    std::error_code type_ec;
    if (it->is_directory(type_ec)) l.folders.push_back(name);
    else if (name.size() > std::string_view(kModelSuffix).size() && name.ends_with(kModelSuffix)) l.files.push_back(name);
  }
  std::sort(l.folders.begin(), l.folders.end());
  std::sort(l.files.begin(), l.files.end());
  return l;
}

/// Opens or saves as the browser's folder/name; false (with the browser's error) when refused.
bool choose(App& app) {
  auto& b = app.browser;
  std::string name = b.name;
  if (name.empty()) {
    b.error = "type a file name or click a file";
    return false;
  }
  switch (b.mode) {
    case BrowseFor::Open: {
      const fs::path path = fs::path(b.folder) / name;
      std::error_code ec;
      if (!fs::is_regular_file(path, ec)) {
        b.error = "no file " + path.string();
        return false;
      }
      b.open = false;
      app.openModel(path.string());
      return true;
    }
    case BrowseFor::SaveAs: {
      if (!name.ends_with(kModelSuffix)) name += kModelSuffix;
      const fs::path path = fs::path(b.folder) / name;
      std::error_code ec;
      if (fs::exists(path, ec) && b.replacing != path.string() &&
          fs::absolute(path, ec) != fs::absolute(app.document().model().path, ec)) {
        b.replacing = path.string();
        b.error = path.filename().string() + " exists: Save again to replace it";
        b.name = name;
        return false;
      }
      b.open = false;
      app.saveAs(path.string());
      return true;
    }
  }
  return false;
}

}  // namespace

void drawFileBrowser(App& app, nlohmann::json& report) {
  auto& b = app.browser;
  const char* title = b.mode == BrowseFor::Open ? "Open a model###file_browser" : "Save the model as###file_browser";
  report = {{"open", b.open}};
  if (b.open && !ImGui::IsPopupOpen("###file_browser")) ImGui::OpenPopup("###file_browser");
  const auto& io = ImGui::GetIO();
  ImGui::SetNextWindowSize({620, 470}, ImGuiCond_Appearing);
  ImGui::SetNextWindowPos({io.DisplaySize.x / 2, io.DisplaySize.y / 2}, ImGuiCond_Appearing, {0.5F, 0.5F});
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return;
  nlohmann::json entries = nlohmann::json::object(), buttons = nlohmann::json::object();

  // the folder: typed, or one up
  if (ImGui::Button("Up")) b.folder = fs::path(b.folder).parent_path().string();
  noteItem("up", buttons);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  std::string typed = b.folder;
  if (ImGui::InputText("##folder", &typed, ImGuiInputTextFlags_EnterReturnsTrue)) {
    std::error_code ec;
    if (fs::is_directory(typed, ec)) b.folder = fs::absolute(typed, ec).lexically_normal().string();
    else b.error = "no folder " + typed;
  }

  // its subfolders and model files: a click on a folder goes in, on a file takes its name
  const Listing listing = list(b.folder);
  // room under the list for the name row, and the error's line when there is one
  const float rows = b.error.empty() ? 1.0F : 2.0F;
  const float list_h = ImGui::GetContentRegionAvail().y - rows * ImGui::GetFrameHeightWithSpacing() - 4;
  ImGui::BeginChild("##entries", {0, std::max(list_h, 80.0F)}, true);
  std::string enter;
  for (const auto& f : listing.folders) {
    if (ImGui::Selectable((f + "/").c_str())) enter = f;
    noteItem(f, entries);
  }
  for (const auto& f : listing.files) {
    if (ImGui::Selectable(f.c_str(), f == b.name, ImGuiSelectableFlags_AllowDoubleClick)) {
      b.name = f;
      b.error.clear();
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) (void)choose(app);
    }
    noteItem(f, entries);
  }
  if (listing.folders.empty() && listing.files.empty()) ImGui::TextDisabled("(no folders or model files here)");
  if (listing.cut) ImGui::TextDisabled("(the first %zu entries)", kMostEntries);
  ImGui::EndChild();
  if (!enter.empty()) {
    b.folder = (fs::path(b.folder) / enter).string();
    b.error.clear();
  }

  // the name, and the choice
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 170);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  const bool entered = ImGui::InputTextWithHint("##name", "file name (.gdpn.yaml)", &b.name, ImGuiInputTextFlags_EnterReturnsTrue);
  noteItem("name", buttons);
  ImGui::SameLine();
  const bool go = ImGui::Button(b.mode == BrowseFor::Open ? "Open" : "Save", {75, 0});
  noteItem(b.mode == BrowseFor::Open ? "open" : "save", buttons);
  ImGui::SameLine();
  if (ImGui::Button("Cancel", {75, 0}) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    b.open = false;
    if (app.question.then != AfterQuestion::None) app.answer(SaveAnswer::Cancel);  // a Save As the question asked for
  }
  noteItem("cancel", buttons);
  if (go || entered) (void)choose(app);
  if (!b.error.empty()) ImGui::TextColored({1.0F, 0.55F, 0.45F, 1.0F}, "%s", b.error.c_str());
  report = {{"open", b.open},
            {"mode", b.mode == BrowseFor::Open ? "open" : "save-as"},
            {"folder", b.folder},
            {"name", b.name},
            {"error", b.error},
            {"entries", entries},
            {"buttons", buttons}};
  if (!b.open) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

void drawSaveQuestion(App& app, nlohmann::json& report) {
  report = {{"open", app.question.then != AfterQuestion::None}};
  if (app.question.then == AfterQuestion::None || app.browser.open) return;
  if (!ImGui::IsPopupOpen("Save changes?")) ImGui::OpenPopup("Save changes?");
  const auto& io = ImGui::GetIO();
  ImGui::SetNextWindowPos({io.DisplaySize.x / 2, io.DisplaySize.y / 2}, ImGuiCond_Appearing, {0.5F, 0.5F});
  if (!ImGui::BeginPopupModal("Save changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    return;
  }
  const auto name = fs::path(app.document().model().path).filename().string();
  ImGui::Text("%s has changes that are not saved.", name.c_str());
  ImGui::TextDisabled("Save them first? The edits not saved are lost otherwise.");
  ImGui::Spacing();
  nlohmann::json buttons = nlohmann::json::object();
  std::optional<SaveAnswer> answer;
  if (ImGui::Button("Save", {110, 0})) answer = SaveAnswer::Save;
  noteItem("save", buttons);
  ImGui::SameLine();
  if (ImGui::Button("Don't Save", {110, 0})) answer = SaveAnswer::DontSave;
  noteItem("dont-save", buttons);
  ImGui::SameLine();
  if (ImGui::Button("Cancel", {110, 0}) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) answer = SaveAnswer::Cancel;
  noteItem("cancel", buttons);
  report = {{"open", true}, {"file", name}, {"buttons", buttons}};
  if (answer) {
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    app.answer(*answer);
    return;
  }
  ImGui::EndPopup();
}

}  // namespace gdpn::ide
