// The I/O list: every part's inputs and outputs as a PLC programmer's watch and force table,
// in the inspector's panel (its tab). Live values during a run, forces and releases through the
// run's parts (applied at the next step boundary, traced), the `io` section's addresses, the
// constructs that use each, and one button per part that maps its I/O for a PLC.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

#include "../views.h"
#include "gdpn/ide/io_list.h"

namespace gdpn::ide {

namespace {

constexpr float kTabsHeight = 25.0F;  // the tab strip over the panel: the inspector's fields stay where its heading left them
constexpr float kHeadingWidth = 520.0F;  // a part's name and type in its heading row, at most (px)
constexpr float kFixedWidth = 740.0F;    // the columns before "used by", with their padding (px)
constexpr float kUsesWidth = 200.0F;     // "used by" at least (px)
const ImVec4 kHeading{0.62F, 0.72F, 0.86F, 1.0F};   // the panels' headings
const ImVec4 kForced{1.0F, 0.72F, 0.1F, 1.0F};      // amber, as PLCs mark forced values
const ImVec4 kPending{1.0F, 0.85F, 0.5F, 1.0F};     // a force or release waiting for the next step
const ImVec4 kOn{0.3F, 0.88F, 0.38F, 1.0F};         // a bit that is 1
const ImVec4 kFaint{0.55F, 0.55F, 0.58F, 1.0F};     // what is said in passing

/// The value as the list writes it: a bit's 1 or 0; a number to four digits with its unit.
std::string valueText(const IoListRow& row, double v) {
  if (row.io.signal == model::IoSignal::Digital) return v != 0.0 ? "1" : "0";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return row.io.unit.empty() ? std::string(buf) : std::string(buf) + " " + row.io.unit;
}

/// A lamp: a filled circle in `colour` when on, an outline when off, on the current line.
void lamp(bool on, const ImVec4& colour) {
  const float h = ImGui::GetTextLineHeight();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const ImVec2 centre{at.x + h / 2, at.y + h / 2};
  auto* draw = ImGui::GetWindowDrawList();
  const ImU32 c = ImGui::GetColorU32(colour);
  if (on) draw->AddCircleFilled(centre, h * 0.32F, c);
  else draw->AddCircleFilled(centre, h * 0.32F, ImGui::GetColorU32(ImVec4{0.18F, 0.18F, 0.2F, 1}));
  draw->AddCircle(centre, h * 0.32F, on ? c : ImGui::GetColorU32(ImVec4{0.5F, 0.5F, 0.52F, 1}), 0, 1.5F);
  ImGui::Dummy({h, h});
  ImGui::SameLine(0, 4);
}

/// The value cell: a lamp and 0 or 1, or a number with its unit; forced in amber; a force or
/// release waiting for the next step shown after an arrow.
void valueCell(const IoListRow& row, const IoLive* live) {
  const bool digital = row.io.signal == model::IoSignal::Digital;
  if (live == nullptr) {
    if (digital) lamp(false, kOn);
    ImGui::TextDisabled("\xE2\x80\x94");  // an em dash: no run, no value
    return;
  }
  const ImVec4 colour = live->forced ? kForced : digital && live->value != 0.0 ? kOn : ImGui::GetStyleColorVec4(ImGuiCol_Text);
  if (digital) lamp(live->value != 0.0, live->forced ? kForced : kOn);
  ImGui::TextColored(colour, "%s", valueText(row, live->value).c_str());
  if (live->pending) {
    ImGui::SameLine(0, 6);
    const std::string next = live->asked ? "\xE2\x86\x92 " + valueText(row, *live->asked) : "\xE2\x86\x92 free";
    ImGui::TextColored(kPending, "%s", next.c_str());
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s at the next step", live->asked ? "forced" : "released");
    }
  } else if (live->forced) {
    ImGui::SameLine(0, 6);
    ImGui::TextColored(kForced, "forced");
  }
}

/// Says what came of a force or release in the message line.
void tell(App& app, const std::string& why, const std::string& done) { app.message = why.empty() ? done : why; }

/// The force cell: Force 1 and Force 0 (digital) or a value typed and Force (analogue), and
/// Release while forced; faded outside a run.
void forceCell(App& app, const IoListRow& row, const IoLive* live, bool running, nlohmann::json& at) {
  const auto key = row.key();
  ImGui::BeginDisabled(!running);
  if (row.io.signal == model::IoSignal::Digital) {
    for (const int bit : {1, 0}) {
      const std::string label = "Force " + std::to_string(bit);
      if (ImGui::SmallButton(label.c_str())) {
        const auto why = forceIo(app.run(), row.part, row.io.name, bit);
        tell(app, why, key + " forced to " + std::to_string(bit) + " at the next step");
      }
      if (ImGui::IsItemVisible()) noteItem("force" + std::to_string(bit), at);
      ImGui::SameLine(0, 4);
    }
  } else {
    auto& text = app.io_list.typed[key];
    ImGui::SetNextItemWidth(64);
    const bool entered = ImGui::InputTextWithHint("##value", "value", &text, ImGuiInputTextFlags_EnterReturnsTrue |
                                                                               ImGuiInputTextFlags_CharsScientific);
    if (ImGui::IsItemVisible()) noteItem("field", at);
    ImGui::SameLine(0, 4);
    const bool pressed = ImGui::SmallButton("Force");
    if (ImGui::IsItemVisible()) noteItem("force", at);
    if ((entered || pressed) && running) {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end == text.c_str() || *end != '\0' || !std::isfinite(v)) {
        app.message = "'" + text + "' is not a number: type the value to force " + key + " to";
      } else {
        tell(app, forceIo(app.run(), row.part, row.io.name, v), key + " forced to " + valueText(row, v) + " at the next step");
      }
    }
    ImGui::SameLine(0, 4);
  }
  const bool releasable = live != nullptr && (live->forced || (live->pending && live->asked));
  ImGui::BeginDisabled(!releasable);
  if (ImGui::SmallButton("Release")) tell(app, releaseIo(app.run(), row.part, row.io.name), key + " released at the next step");
  if (ImGui::IsItemVisible()) noteItem("release", at);
  ImGui::EndDisabled();
  ImGui::EndDisabled();
  if (!running && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Run or Step first: forces need a run");
  }
}

/// A list of texts joined by ", ".
std::string joined(const std::vector<std::string>& list) {
  std::string out;
  for (const auto& s : list) out += (out.empty() ? "" : ", ") + s;
  return out;
}

/// The uses as the cell shows them: the constructs relative to the part's page and without the
/// scripts' kinds, one of the same instance as the one before by its name alone
/// (`lamp1_control/light, dark`); the tooltip and the report have them whole.
std::string usesText(const IoListRow& row) {
  std::string out, last_owner;
  std::vector<std::string> shown;
  for (const auto& use : row.uses) {
    const auto space = use.rfind(' ');
    std::string construct = space == std::string::npos ? use : use.substr(0, space);
    if (!row.page.empty() && construct.starts_with(row.page + "/")) construct.erase(0, row.page.size() + 1);
    if (std::find(shown.begin(), shown.end(), construct) != shown.end()) continue;
    shown.push_back(construct);
    const auto slash = construct.rfind('/');
    const std::string owner = slash == std::string::npos ? std::string() : construct.substr(0, slash);
    const bool same = !out.empty() && !owner.empty() && owner == last_owner;
    out += (out.empty() ? "" : ", ") + (same ? construct.substr(slash + 1) : construct);
    last_owner = owner;
  }
  return out;
}

/// The part's heading row: its name and type, and Map for PLC (edit mode) while some of its
/// I/O has no address.
void partRow(App& app, const IoListRow& first, std::size_t count, std::size_t unmapped, nlohmann::json& report) {
  ImGui::TableNextRow();
  ImGui::PushID(first.part.c_str());
  ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(ImVec4{0.22F, 0.26F, 0.34F, 1}));
  ImGui::TableSetColumnIndex(0);
  // its name and type run on over the empty cells of the row, up to the address
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::PushClipRect(at, {at.x + kHeadingWidth, at.y + ImGui::GetTextLineHeightWithSpacing()}, false);
  if (app.fonts.bold != nullptr) ImGui::PushFont(app.fonts.bold);
  ImGui::TextUnformatted(first.part.c_str());
  if (app.fonts.bold != nullptr) ImGui::PopFont();
  ImGui::SameLine(0, 10);
  ImGui::TextColored(kFaint, "%s, %zu I/O", first.type.c_str(), count);
  ImGui::PopClipRect();
  ImGui::TableSetColumnIndex(6);
  report = {{"type", first.type}, {"io", count}, {"unmapped", unmapped}};
  if (first.page.empty() || unmapped == 0) {
    // a part inside another instance is mapped by hand (`part: main/cell/pusher1`)
    if (unmapped == 0) ImGui::TextColored(kFaint, "mapped");
    ImGui::PopID();
    return;
  }
  const bool editing = app.run().mode() == RunMode::Edit;
  ImGui::BeginDisabled(!editing);
  if (ImGui::SmallButton("Map for PLC")) {
    auto command = std::make_unique<MapPartIoCommand>(first.page, first.instance);
    const auto* map = command.get();  // kept on the undo stack when it succeeds
    const auto why = app.document().execute(std::move(command));
    std::vector<std::string> addresses;
    if (why.empty()) {
      for (const auto& e : map->added()) addresses.push_back(model::ioAddressName(e.table, e.address));
    }
    app.message = why.empty() ? "mapped " + first.part + ": " + joined(addresses) : why;
  }
  if (ImGui::IsItemVisible()) noteItem("map", report);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip(editing ? "Add its I/O to the io section at free addresses, for a PLC over Modbus (one step of undo)"
                              : "An edit of the model: Reset to edit it");
  }
  ImGui::PopID();
}

}  // namespace

Rect drawInspectorTabs(App& app, const Rect& at, nlohmann::json& report) {
  // three tabs where the panel's heading would be: the inspector, the I/O list, the colour sets
  auto* draw = ImGui::GetWindowDrawList();
  float x = at.x + 4;
  const char* shown = app.io_list.shown ? "I/O" : app.colour_sets.shown ? "Colour Sets" : "Inspector";
  for (const char* label : {"Inspector", "I/O", "Colour Sets"}) {
    const bool active = std::string_view(label) == shown;
    const ImVec2 text = ImGui::CalcTextSize(label);
    const ImVec2 lo{x, at.y + 3}, hi{x + text.x + 20, at.y + kTabsHeight};
    ImGui::SetCursorScreenPos(lo);
    ImGui::PushID(label);
    if (ImGui::InvisibleButton("##tab", {hi.x - lo.x, hi.y - lo.y})) {
      app.io_list.shown = std::string_view(label) == "I/O";
      app.colour_sets.shown = std::string_view(label) == "Colour Sets";
    }
    ImGui::PopID();
    noteItem(label, report);
    const ImGuiCol fill = active ? ImGuiCol_TabActive : ImGui::IsItemHovered() ? ImGuiCol_TabHovered : ImGuiCol_Tab;
    draw->AddRectFilled(lo, hi, ImGui::GetColorU32(fill), 4.0F, ImDrawFlags_RoundCornersTop);
    draw->AddText({lo.x + 10, lo.y + (hi.y - lo.y - text.y) / 2}, ImGui::GetColorU32(active ? kHeading : kFaint), label);
    x = hi.x + 2;
  }
  report["active"] = shown;
  return {at.x, at.y + kTabsHeight, at.w, at.h - kTabsHeight};
}

void drawIoList(App& app, const Rect& at, nlohmann::json& report) {
  beginPanel("##io_list", at, nullptr);
  auto& st = app.io_list;
  if (st.revision != app.document().revision()) {
    st.rows = ioListRows(app.document().model());
    st.revision = app.document().revision();
  }
  const bool running = app.run().mode() != RunMode::Edit && app.run().session() != nullptr;
  const auto live = ioLiveValues(app.run());
  report = {{"shown", true}, {"running", running}};
  auto& rows = report["rows"] = nlohmann::json::object();
  auto& parts = report["parts"] = nlohmann::json::object();
  auto& order = report["order"] = nlohmann::json::array();

  // what the list holds, and Release all
  std::size_t forced = 0, waiting = 0;
  for (const auto& [key, l] : live) {
    if (l.forced) ++forced;
    if (l.pending) ++waiting;
  }
  std::size_t part_count = 0;
  for (std::size_t i = 0; i < st.rows.size(); ++i) {
    if (i == 0 || st.rows[i].part != st.rows[i - 1].part) ++part_count;
  }
  ImGui::AlignTextToFramePadding();
  if (st.rows.empty()) {
    ImGui::TextDisabled("No parts: a part's inputs and outputs are listed here.");
  } else {
    ImGui::TextColored(kFaint, "%zu inputs and outputs of %zu part%s. %s", st.rows.size(), part_count,
                       part_count == 1 ? "" : "s",
                       running ? "Forces take effect at the next step." : "Values and forcing during a run.");
  }
  ImGui::SameLine();
  if (forced > 0) {
    ImGui::TextColored(kForced, "%zu forced", forced);
    ImGui::SameLine();
  }
  if (waiting > 0) {
    ImGui::TextColored(kPending, "%zu waiting for the next step", waiting);
    ImGui::SameLine();
  }
  ImGui::BeginDisabled(!running || forced + waiting == 0);
  if (ImGui::Button("Release all")) tell(app, releaseAllIo(app.run()), "every force is released at the next step");
  noteItem("release_all", report);
  ImGui::EndDisabled();
  report["forced"] = forced;
  report["waiting"] = waiting;

  // the columns keep their widths and "used by" at least kUsesWidth: a narrower panel scrolls
  constexpr int kColumns = 8;
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_Resizable;
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, {5, 1});
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, {6, 2});
  const ImVec2 room = ImGui::GetContentRegionAvail();
  const float inner = std::max(room.x - ImGui::GetStyle().ScrollbarSize, kFixedWidth + kUsesWidth);
  if (!st.rows.empty() && ImGui::BeginTable("##io", kColumns, flags, room, inner)) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, 120);
    ImGui::TableSetupColumn("dir", ImGuiTableColumnFlags_WidthFixed, 30);
    ImGui::TableSetupColumn("signal", ImGuiTableColumnFlags_WidthFixed, 52);
    ImGui::TableSetupColumn("unit", ImGuiTableColumnFlags_WidthFixed, 36);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, 128);
    ImGui::TableSetupColumn("force", ImGuiTableColumnFlags_WidthFixed, 178);
    ImGui::TableSetupColumn("address, name", ImGuiTableColumnFlags_WidthFixed, 220);
    ImGui::TableSetupColumn("used by", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < st.rows.size(); ++i) {
      const auto& row = st.rows[i];
      if (i == 0 || row.part != st.rows[i - 1].part) {
        std::size_t count = 0, unmapped = 0;
        for (std::size_t j = i; j < st.rows.size() && st.rows[j].part == row.part; ++j) {
          ++count;
          if (st.rows[j].addresses.empty()) ++unmapped;
        }
        partRow(app, row, count, unmapped, parts[row.part]);
      }
      const auto key = row.key();
      const auto found = live.find(key);
      const IoLive* l = found != live.end() ? &found->second : nullptr;
      ImGui::PushID(key.c_str());
      ImGui::TableNextRow();
      if (l != nullptr && (l->forced || l->pending)) {
        // forced rows tinted amber; one waiting for the next step, fainter
        const float alpha = l->forced ? 0.16F : 0.08F;
        ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, ImGui::GetColorU32(ImVec4{kForced.x, kForced.y, kForced.z, alpha}));
      }
      const bool input = row.io.direction == model::IoDirection::Input;
      const bool digital = row.io.signal == model::IoSignal::Digital;
      ImGui::TableSetColumnIndex(0);
      ImGui::Indent(10);
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(row.io.name.c_str());
      ImGui::Unindent(10);
      if (ImGui::IsItemHovered() && !row.io.description.empty()) ImGui::SetTooltip("%s", row.io.description.c_str());
      ImGui::TableSetColumnIndex(1);
      ImGui::TextColored(input ? ImVec4{0.55F, 0.8F, 1.0F, 1} : ImVec4{1.0F, 0.62F, 0.45F, 1}, "%s", input ? "in" : "out");
      ImGui::TableSetColumnIndex(2);
      ImGui::TextUnformatted(digital ? "digital" : "analog");
      ImGui::TableSetColumnIndex(3);
      ImGui::TextUnformatted(row.io.unit.c_str());
      ImGui::TableSetColumnIndex(4);
      valueCell(row, l);
      auto& r = rows[key];
      r = {{"part", row.part},
           {"io", row.io.name},
           {"direction", model::ioDirectionName(row.io.direction)},
           {"signal", model::ioSignalName(row.io.signal)},
           {"unit", row.io.unit},
           {"value", l != nullptr ? nlohmann::json(l->value) : nlohmann::json()},
           {"forced", l != nullptr && l->forced},
           {"pending", l != nullptr && l->pending},
           {"asked", l != nullptr && l->asked ? nlohmann::json(*l->asked) : nlohmann::json()},
           {"addresses", row.addresses},
           {"names", row.names},
           {"uses", row.uses}};
      if (ImGui::IsItemVisible()) noteItem("value_at", r);
      ImGui::TableSetColumnIndex(5);
      forceCell(app, row, l, running, r);
      ImGui::TableSetColumnIndex(6);
      if (row.addresses.empty()) {
        ImGui::TextDisabled("\xE2\x80\x94");
      } else {
        // each address with its point's name, as OPC UA serves it: `coil 3 lamp1_light`
        std::vector<std::string> named;
        for (std::size_t a = 0; a < row.addresses.size(); ++a) named.push_back(row.addresses[a] + " " + row.names[a]);
        ImGui::TextUnformatted(joined(named).c_str());
      }
      ImGui::TableSetColumnIndex(7);
      const auto uses = usesText(row);
      if (uses.empty()) ImGui::TextDisabled("nothing");
      else ImGui::TextUnformatted(uses.c_str());
      if (ImGui::IsItemHovered() && !row.uses.empty()) {
        std::string list;
        for (const auto& u : row.uses) list += u + "\n";
        ImGui::SetTooltip("%s", list.c_str());
      }
      ImGui::PopID();
      order.push_back(key);
    }
    ImGui::EndTable();
  }
  ImGui::PopStyleVar(2);
  endPanel();
}

}  // namespace gdpn::ide
