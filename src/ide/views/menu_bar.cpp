// The menus at the toolbar's start and Help's list of keys: both read the table of actions.

#include <imgui.h>

#include <filesystem>
#include <string>

#include "../action_run.h"
#include "../views.h"
#include "gdpn/ide/actions.h"

namespace gdpn::ide {

namespace {

/// The Open Recent submenu: the files opened last, by name, with their folders.
void recentMenu(App& app, nlohmann::json& items, nlohmann::json& report) {
  if (!beginMenu("Open Recent", items)) return;
  std::string chosen;
  for (const auto& path : app.recent) {
    const std::filesystem::path p(path);
    const std::string label = p.filename().string() + "  (" + p.parent_path().string() + ")";
    if (ImGui::MenuItem(label.c_str())) chosen = path;
    noteItem(p.filename().string(), report);
  }
  if (app.recent.empty()) ImGui::TextDisabled("(none yet)");
  ImGui::EndMenu();
  if (!chosen.empty()) app.openModel(chosen);
}

/// The items of `menu`, each an action of the table.
void menuItems(App& app, Menu menu, nlohmann::json& items, nlohmann::json& recent) {
  for (const auto& a : actionInfos()) {
    if (a.menu != menu) continue;
    if (a.separator_before) ImGui::Separator();
    const std::string label(a.label), keys(a.keys);
    const bool enabled = actionEnabled(app, a.id);
    if (ImGui::MenuItem(label.c_str(), keys.empty() ? nullptr : keys.c_str(), actionChecked(app, a.id), enabled)) {
      (void)performAction(app, a.id);
    }
    noteItem(label, items);
    if (ImGui::IsItemHovered() && !a.help.empty()) ImGui::SetTooltip("%s", std::string(a.help).c_str());
    if (a.id == ActionId::Open) recentMenu(app, items, recent);
  }
}

}  // namespace

void actionItems(App& app, std::initializer_list<ActionId> ids, nlohmann::json& positions) {
  for (const ActionId id : ids) {
    if (!actionEnabled(app, id)) continue;
    const auto& a = info(id);
    const std::string label(a.label), keys(a.keys);
    if (ImGui::MenuItem(label.c_str(), keys.empty() ? nullptr : keys.c_str())) (void)performAction(app, id);
    noteItem(label, positions);
    if (ImGui::IsItemHovered() && !a.help.empty()) ImGui::SetTooltip("%s", std::string(a.help).c_str());
  }
}

void drawMenus(App& app, nlohmann::json& report) {
  nlohmann::json items = nlohmann::json::object(), recent = nlohmann::json::object();
  std::string open;
  bool any_open = false;
  for (Menu m : kMenus) any_open = any_open || ImGui::IsPopupOpen((std::string("##menu_") + menuName(m)).c_str());
  for (Menu m : kMenus) {
    const std::string name = menuName(m), popup = "##menu_" + name;
    const bool is_open = ImGui::IsPopupOpen(popup.c_str());
    if (is_open) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    else ImGui::PushStyleColor(ImGuiCol_Button, {0, 0, 0, 0});
    const bool clicked = ImGui::Button(name.c_str());
    ImGui::PopStyleColor();
    noteItem(name, report);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    // a click opens a menu; while one is open, pointing at another opens that one instead
    if (clicked || (any_open && !is_open && ImGui::IsItemHovered())) ImGui::OpenPopup(popup.c_str());
    ImGui::SetNextWindowPos({lo.x, hi.y + 2});
    if (ImGui::BeginPopup(popup.c_str())) {
      open = name;
      menuItems(app, m, items, recent);
      ImGui::EndPopup();
    }
    ImGui::SameLine(0, 2);
  }
  report["open"] = open;
  report["items"] = items;
  report["recent"] = recent;
}

void drawKeys(App& app, nlohmann::json& report) {
  report = {{"open", app.keys_open}};
  if (!app.keys_open) return;
  const auto& io = ImGui::GetIO();
  ImGui::SetNextWindowSize({640, io.DisplaySize.y * 0.8F}, ImGuiCond_Appearing);
  ImGui::SetNextWindowPos({io.DisplaySize.x / 2, io.DisplaySize.y / 2}, ImGuiCond_Appearing, {0.5F, 0.5F});
  if (!ImGui::Begin("Keys and actions", &app.keys_open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  ImGui::TextDisabled("Every action, its key and its name in replay files (press: NAME).");
  nlohmann::json listed = nlohmann::json::array();
  if (ImGui::BeginTable("##keys", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH)) {
    ImGui::TableSetupColumn("Action", ImGuiTableColumnFlags_WidthFixed, 190);
    ImGui::TableSetupColumn("Key", ImGuiTableColumnFlags_WidthFixed, 100);
    ImGui::TableSetupColumn("What it does");
    ImGui::TableHeadersRow();
    for (Menu m : kMenus) {
      for (const auto& a : actionInfos()) {
        if (a.menu != m) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%s: %s", menuName(m), std::string(a.label).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(a.keys.empty() ? "" : std::string(a.keys).c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s (press: %s)", std::string(a.help).c_str(), std::string(a.name).c_str());
        listed.push_back(a.name);
      }
    }
    ImGui::EndTable();
  }
  ImGui::End();
  report["actions"] = listed;
}

}  // namespace gdpn::ide
