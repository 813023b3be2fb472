// The parts palette: the library's parts by group with their pictures and names, searched; a
// part dragged into the world view shows where it will land (a ghost, snapped by
// gdpn/ide/part_snap.h) and is placed there by one library call; a part with a control pattern
// is offered it. Also the edit scene: the document's scene with the part instances' machines,
// which the views show in edit mode.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "../detail/picture_texture.h"
#include "../views.h"
#include "gdpn/core/text.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/ide/tile_label.h"
#include "gdpn/platform/png.h"
#include "gdpn/scene/actions.h"
#include "net_view_state.h"
#include "palette_state.h"

namespace gdpn::ide {

namespace {

namespace fs = std::filesystem;

constexpr float kPicture = 56.0F;   // a part's picture in the palette, pixels
constexpr float kTileWidth = 70.0F;
constexpr const char* kGhostName = "palette_ghost";
constexpr double kBeyond = 0.1;     // the report's points beside a part: this far beyond its sides, m

/// `text` in lower case.
std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// How the palette writes a part's name: its words apart ("belt conveyor").
std::string shownName(const std::string& name) {
  std::string out = name;
  std::replace(out.begin(), out.end(), '_', ' ');
  return out;
}

}  // namespace

void scanLibrary(App& app) {
  auto& st = app.palette();
  const auto& path = app.document().model().path;
  if (st.scanned_for && *st.scanned_for == path) return;
  st.scanned_for = path;
  ++st.scans;
  std::error_code ec;
  const auto dir = path.empty() ? fs::path() : fs::absolute(path, ec).parent_path();
  st.folders = model::partSearchPath(dir.string());
  core::Diagnostics diags;
  st.parts.clear();
  for (auto& p : model::scanParts(st.folders, diags, path)) {
    if (!p.pattern) st.parts.push_back(std::move(p));  // patterns come with their parts
  }
  st.warnings.clear();
  for (const auto& d : diags.all()) st.warnings.push_back(d.str());
  st.pictures.clear();
  st.machines.clear();
}

namespace {

/// The picture of `part`, made `kPicture` pixels at most on a side by averaging (so that it
/// shows sharp at that size); null when it has none or it cannot be read.
PictureTexture* pictureOf(PaletteState& st, const model::LibraryPart& part) {
  auto [it, fresh] = st.pictures.try_emplace(part.name);
  if (!fresh || part.picture.empty()) return it->second.get();
  int w = 0, h = 0;
  std::vector<std::uint8_t> rgb;
  std::string why;
  if (!platform::readPng(part.picture, w, h, rgb, why) || w <= 0 || h <= 0) return nullptr;
  const int side = static_cast<int>(kPicture);
  const double shrink = std::max({1.0, static_cast<double>(w) / side, static_cast<double>(h) / side});
  auto image = std::make_shared<sensors::Image>();
  image->width = std::max(1, static_cast<int>(std::lround(w / shrink)));
  image->height = std::max(1, static_cast<int>(std::lround(h / shrink)));
  image->rgb.assign(static_cast<std::size_t>(image->width) * static_cast<std::size_t>(image->height) * 3, 0);
  const auto sw = static_cast<std::size_t>(w), sh = static_cast<std::size_t>(h);
  const auto dw = static_cast<std::size_t>(image->width), dh = static_cast<std::size_t>(image->height);
  for (std::size_t y = 0; y < dh; ++y) {
    for (std::size_t x = 0; x < dw; ++x) {
      // the mean of the source pixels under this one
      const auto from = [&](std::size_t i) { return static_cast<std::size_t>(static_cast<double>(i) * shrink); };
      const std::size_t x0 = from(x), x1 = std::min(sw, std::max(x0 + 1, from(x + 1)));
      const std::size_t y0 = from(y), y1 = std::min(sh, std::max(y0 + 1, from(y + 1)));
      for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0;
        std::size_t n = 0;
        for (std::size_t sy = y0; sy < y1; ++sy) {
          for (std::size_t sx = x0; sx < x1; ++sx, ++n) sum += rgb[(sy * sw + sx) * 3 + c];
        }
        image->rgb[(y * dw + x) * 3 + c] = static_cast<std::uint8_t>(n > 0 ? sum / static_cast<double>(n) + 0.5 : 0.0);
      }
    }
  }
  it->second = std::make_unique<PictureTexture>();
  it->second->show(image, 0.0, 1.0);
  return it->second.get();
}

/// The machine of library part `part` at its type's parameters: its type's scene and box.
const PartMachine& machineOf(PaletteState& st, const model::LibraryPart& part) {
  auto [it, fresh] = st.machines.try_emplace(part.name);
  if (!fresh) return it->second;
  core::Diagnostics diags;
  const auto file = model::loadModel(part.file, diags);
  if (!file) {
    it->second.error = diags.all().empty() ? part.file + ": cannot be read" : diags.all().front().str();
    return it->second;
  }
  const auto own = file->type_scenes.find(part.name);
  if (own == file->type_scenes.end()) return it->second;
  it->second.scene = own->second;
  // its box in its own frame: the machine under a frame at the origin
  scene::Scene s(own->second->types());
  auto* frame = s.create(*s.types().find(scene::NodeKind::Transform), "part", s.root());
  for (const auto& c : own->second->root().children()) s.copy(*c, *frame);
  scene::updateTransforms(s.root());
  it->second.box = localBox(*frame);
  it->second.loose = looseMachine(*frame);
  return it->second;
}

/// The parts placed, for snapping: where each stands and its machine's box.
std::vector<PartFootprint> footprints(const App& app) {
  const auto& st = app.palette();
  std::vector<PartFootprint> out;
  if (!st.edit_scene) return out;
  for (const auto& [path, at] : st.frames) {
    const auto* inst = instanceAt(app.document().model(), at);
    const auto* frame = st.edit_scene->find(path);
    if (inst == nullptr || frame == nullptr) continue;
    out.push_back({at.name, {inst->translation[0], inst->translation[1], inst->translation[2]}, angleAboutZ(inst->rotation),
                   localBox(*frame)});
  }
  return out;
}

/// The page a drop goes to: the net view's page when it shows a page, else the first page, else
/// "main".
std::string dropPage(App& app) {
  const auto& pages = app.document().model().net.pages;
  const auto& path = app.netView().path;
  const std::string first = path.substr(0, path.find('/'));
  for (const auto& p : pages) {
    if (!first.empty() && p.name == first) return p.name;
  }
  return pages.empty() ? std::string("main") : pages.front().name;
}

/// Where world point `p` is in window pixels, the view's picture at `at` (nullopt: behind the eye).
std::optional<ImVec2> onScreen(const OrbitCamera& view, const core::Vec3& p, ImVec2 at, float w, float h) {
  const auto q = view.project(p, static_cast<double>(w), static_cast<double>(h));
  if (!q) return std::nullopt;
  return ImVec2{at.x + static_cast<float>((*q)[0]), at.y + static_cast<float>((*q)[1])};
}

/// Places part `name` where `place` says (one step of undo), selects it and offers its control.
void placeDropped(App& app, const std::string& name, const DropPlace& place, ImVec2 pointer) {
  auto& st = app.palette();
  if (app.run().mode() != RunMode::Edit) {
    app.message = "the run's plant is not edited: Reset to place parts";
    return;
  }
  const auto* part = model::findLibraryPart(st.parts, name);
  if (part == nullptr) return;
  const auto page = dropPage(app);
  auto command = std::make_unique<PlacePartCommand>(*part, page, place.translation, place.angle);
  const auto* placing = command.get();  // kept on the undo stack when it succeeds
  const auto why = app.document().execute(std::move(command));
  if (!why.empty()) {
    app.message = why;
    return;
  }
  const auto made = placing->made().front();
  app.selectNode(made);
  std::ostringstream text;
  text << "placed " << made << " at (" << core::formatDouble(place.translation[0]) << ", "
       << core::formatDouble(place.translation[1]) << ", " << core::formatDouble(place.translation[2]) << ") m";
  if (!place.neighbour.empty()) text << ", " << snapKindName(place.kind) << " of " << place.neighbour;
  app.message = text.str();
  // a part with control patterns is offered them at the drop
  const auto& m = app.document().model();
  std::vector<OfferedPattern> offered;
  for (const auto& pattern : model::controlPatterns(m, part->name)) {
    OfferedPattern o{pattern, {}, {}, {}};
    for (const auto& t : m.net.page_types) {
      if (t.name == pattern) o.description = t.description;
    }
    for (const auto& u : model::fillRoles(m, page, made, pattern, {}, o.unfilled)) {
      o.uses += (o.uses.empty() ? "" : ", ") + u.role + ": " + u.part;
    }
    offered.push_back(std::move(o));
  }
  if (!offered.empty()) st.offer = {true, true, {page, made}, std::move(offered), pointer.x, pointer.y};
}

/// A part's tile: its picture (or its group's initial) over its name in one or two lines.
void tile(PaletteState& st, const model::LibraryPart& part, nlohmann::json& items, nlohmann::json& list) {
  ImGui::PushID(part.name.c_str());
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float line = ImGui::GetTextLineHeight();
  const ImVec2 size{kTileWidth, kPicture + 2 * line + 8};
  ImGui::InvisibleButton("##tile", size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (hovered || ImGui::IsItemActive()) {
    draw->AddRectFilled(at, {at.x + size.x, at.y + size.y}, ImGui::GetColorU32(ImGuiCol_HeaderHovered), 4.0F);
  }
  const ImVec2 pic{at.x + (size.x - kPicture) / 2, at.y + 3};
  PictureTexture* picture = pictureOf(st, part);
  if (picture != nullptr) {
    draw->AddImage(reinterpret_cast<ImTextureID>(picture->texture()), pic, {pic.x + kPicture, pic.y + kPicture}, {0, 0}, {1, 1});
  } else {
    // no picture: the group's initial on a plain square
    draw->AddRectFilled(pic, {pic.x + kPicture, pic.y + kPicture}, IM_COL32(70, 76, 88, 255), 6.0F);
    const std::string initial(1, static_cast<char>(std::toupper(static_cast<unsigned char>(part.spec.group.empty() ? part.name[0] : part.spec.group[0]))));
    const ImVec2 t = ImGui::CalcTextSize(initial.c_str());
    draw->AddText({pic.x + (kPicture - t.x) / 2, pic.y + (kPicture - t.y) / 2}, IM_COL32(220, 224, 232, 255), initial.c_str());
  }
  // the name in two centred lines at most, broken where it must be (tile_label.h)
  const std::string name = shownName(part.name);
  const auto lines = tileLabel(name, size.x - 4, [](std::string_view text) {
    const std::string s(text);
    return ImGui::CalcTextSize(s.c_str()).x;
  });
  float y = pic.y + kPicture + 3;
  for (const auto& l : lines) {
    const float tw = ImGui::CalcTextSize(l.c_str()).x;
    draw->PushClipRect(at, {at.x + size.x, at.y + size.y}, true);
    draw->AddText({at.x + std::max(2.0F, (size.x - tw) / 2), y}, ImGui::GetColorU32(ImGuiCol_Text), l.c_str());
    draw->PopClipRect();
    y += line;
  }
  // dragged into the world view, it is placed there
  if (ImGui::BeginDragDropSource()) {
    ImGui::SetDragDropPayload(kPartPayload, part.name.data(), part.name.size());
    if (picture != nullptr) ImGui::Image(reinterpret_cast<ImTextureID>(picture->texture()), {kPicture / 2, kPicture / 2});
    ImGui::SameLine();
    ImGui::TextUnformatted(name.c_str());
    ImGui::EndDragDropSource();
  } else if (hovered) {
    std::size_t inputs = 0, outputs = 0;
    for (const auto& io : part.spec.io) (io.direction == model::IoDirection::Input ? inputs : outputs)++;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 26);
    ImGui::Text("%s  (%s, version %d)", part.name.c_str(), part.spec.group.c_str(), part.spec.version);
    if (!part.description.empty()) ImGui::TextUnformatted(part.description.c_str());
    using core::counted;
    const std::string io = std::to_string(part.spec.io.size()) + " I/O (" + counted(inputs, "input") + ", " +
                           counted(outputs, "output") + "), " + counted(part.spec.params.size(), "parameter") +
                           (part.spec.control.empty() ? "" : "; comes with its control (" + part.spec.control + ")");
    ImGui::TextDisabled("%s", io.c_str());
    ImGui::TextDisabled("Drag it into the world view to place it.");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  // where a replay can drag it from: the middle of what is in sight of it, at least 8 pixels
  // high (scroll or search to bring it)
  const ImVec2 clip_lo = draw->GetClipRectMin(), clip_hi = draw->GetClipRectMax();
  const ImVec2 lo{std::max(at.x, clip_lo.x), std::max(at.y, clip_lo.y)};
  const ImVec2 hi{std::min(at.x + size.x, clip_hi.x), std::min(at.y + size.y, clip_hi.y)};
  const bool visible = hi.x - lo.x >= 8 && hi.y - lo.y >= 8;
  nlohmann::json entry = {{"name", part.name}, {"group", part.spec.group}, {"version", part.spec.version},
                          {"picture", picture != nullptr}, {"visible", visible}};
  if (visible) {
    items[part.name] = {std::lround((lo.x + hi.x) / 2), std::lround((lo.y + hi.y) / 2)};
    entry["at"] = items[part.name];
  }
  list.push_back(std::move(entry));
  ImGui::PopID();
}

/// True when `part` answers the search `words`: each found in its name or group, or with
/// `described`, in its description too.
bool matches(const model::LibraryPart& part, const std::string& search, bool described) {
  const std::string hay = lower(part.name + " " + shownName(part.name) + " " + part.spec.group +
                                (described ? " " + part.description : std::string()));
  std::istringstream words(lower(search));
  std::string w;
  while (words >> w) {
    if (hay.find(w) == std::string::npos) return false;
  }
  return true;
}

}  // namespace

void drawPalette(App& app, const Rect& at, nlohmann::json& report) {
  auto& st = app.palette();
  scanLibrary(app);
  beginPanel("##palette", at, "Parts");
  nlohmann::json items = nlohmann::json::object(), list = nlohmann::json::array(), groups = nlohmann::json::array();
  ImGui::SetNextItemWidth(-70);
  ImGui::InputTextWithHint("##part_search", "search parts", &st.search);
  nlohmann::json controls = nlohmann::json::object();
  noteItem("search", controls);
  ImGui::SameLine();
  if (ImGui::Button("Rescan")) st.scanned_for.reset();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Look for part files again along the search path");
  noteItem("rescan", controls);
  nlohmann::json updates;
  drawPartUpdateNotice(app, updates);
  {
    // the list's middle: where a replay's wheel scrolls it
    const ImVec2 c = ImGui::GetCursorScreenPos(), room = ImGui::GetContentRegionAvail();
    controls["list"] = {std::lround(c.x + room.x / 2), std::lround(c.y + room.y / 2)};
  }
  ImGui::BeginChild("##palette_scroll", {0, 0}, false);
  if (st.parts.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("No parts found. Part files (*.gdpn.yaml with a part section) are looked for in:");
    for (const auto& f : st.folders) ImGui::BulletText("%s", f.c_str());
    ImGui::PopTextWrapPos();
  }
  // the parts a search names (by name or group); when it names none, those it describes
  const bool described = std::none_of(st.parts.begin(), st.parts.end(),
                                      [&](const model::LibraryPart& p) { return matches(p, st.search, false); });
  std::size_t shown = 0;
  for (std::size_t i = 0; i < st.parts.size();) {
    // a group: its parts that answer the search, in tiles as many to a row as fit
    const std::string group = st.parts[i].spec.group;
    std::vector<const model::LibraryPart*> found;
    for (; i < st.parts.size() && st.parts[i].spec.group == group; ++i) {
      if (matches(st.parts[i], st.search, described)) found.push_back(&st.parts[i]);
    }
    if (found.empty()) continue;
    const std::string heading = (group.empty() ? std::string("Other") : group) + "  (" + std::to_string(found.size()) + ")";
    groups.push_back(group);
    if (!ImGui::CollapsingHeader(heading.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
    const float room = ImGui::GetContentRegionAvail().x;
    const int per_row = std::max(1, static_cast<int>((room + ImGui::GetStyle().ItemSpacing.x) / (kTileWidth + ImGui::GetStyle().ItemSpacing.x)));
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (k % static_cast<std::size_t>(per_row) != 0) ImGui::SameLine();
      tile(st, *found[k], items, list);
      ++shown;
    }
  }
  if (!st.parts.empty() && shown == 0) ImGui::TextDisabled("No part answers '%s'.", st.search.c_str());
  for (const auto& w : st.warnings) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored({0.95F, 0.75F, 0.3F, 1.0F}, "%s", w.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndChild();
  endPanel();
  report = {{"shown", true},   {"count", st.parts.size()}, {"listed", shown},        {"search", st.search},
            {"groups", groups}, {"items", items},           {"list", list},          {"folders", st.folders},
            {"warnings", st.warnings}, {"controls", controls}, {"dragging", st.dragged}};
  report["updates"] = updates;
}

void drawDropOffer(App& app, nlohmann::json& report) {
  auto& offer = app.palette().offer;
  if (!report.is_object()) report = nlohmann::json::object();
  report["offer"] = {{"open", offer.open}};
  if (!offer.open) return;
  constexpr const char* kId = "##control_offer";
  if (offer.appearing) {
    ImGui::SetNextWindowPos({offer.x + 12, offer.y + 12});
    ImGui::OpenPopup(kId);
    offer.appearing = false;
  }
  if (!ImGui::BeginPopup(kId, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    offer.open = false;  // closed by a click elsewhere: no
    return;
  }
  ImGui::Text("Add a control for %s?", offer.at.name.c_str());
  ImGui::TextDisabled("A net in the model that runs it through its I/O:");
  nlohmann::json buttons = nlohmann::json::object(), patterns = nlohmann::json::array();
  std::string chosen;  // the pattern clicked ("": none yet)
  const OfferedPattern* first = nullptr;  // the first that can be added: Enter's
  const float wrap = ImGui::GetFontSize() * 34;
  // the buttons as wide as the longest pattern's name (pick_and_place_control), and at least 9 ems
  float button = ImGui::GetFontSize() * 9;
  for (const auto& o : offer.patterns) {
    button = std::max(button, ImGui::CalcTextSize(o.name.c_str()).x + ImGui::GetStyle().FramePadding.x * 2);
  }
  for (const auto& o : offer.patterns) {
    if (first == nullptr && o.unfilled.empty()) first = &o;
    ImGui::BeginDisabled(!o.unfilled.empty());
    if (&o == first) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(o.name.c_str(), {button, 0})) chosen = o.name;
    if (&o == first) ImGui::PopStyleColor();
    ImGui::EndDisabled();
    noteItem(o.name, buttons);
    ImGui::SameLine();
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
    if (!o.unfilled.empty()) {
      ImGui::TextColored({1.0F, 0.55F, 0.35F, 1.0F}, "%s", o.unfilled.c_str());
    } else {
      ImGui::TextDisabled("%s%s", o.description.c_str(), o.uses.empty() ? "" : ("\nwith " + o.uses).c_str());
    }
    ImGui::PopTextWrapPos();
    patterns.push_back({{"name", o.name}, {"uses", o.uses}, {"unfilled", o.unfilled}});
  }
  const bool no = ImGui::Button("No", {button, 0});
  noteItem("no", buttons);
  if (first != nullptr) {
    ImGui::SameLine();
    ImGui::TextDisabled("Enter: %s", first->name.c_str());
  }
  const bool enter = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                     ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter));
  const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  if (enter && first != nullptr) chosen = first->name;
  report["offer"] = {{"open", true}, {"part", offer.at.name}, {"patterns", patterns}, {"buttons", buttons}};
  if (!chosen.empty() || no || escape || enter) {
    const auto at = offer.at;
    offer.open = false;
    ImGui::CloseCurrentPopup();
    if (!chosen.empty()) {
      auto command = std::make_unique<AddPartControlCommand>(at, chosen);
      const auto* adding = command.get();
      const auto why = app.document().execute(std::move(command));
      app.message = why.empty() ? "added " + adding->made() + ", the control of " + at.name : why;
    }
  }
  ImGui::EndPopup();
}

void refreshEditScene(App& app) {
  auto& st = app.palette();
  const auto& doc = app.document();
  const auto& m = doc.model();
  const bool edit = app.run().mode() == RunMode::Edit;
  // the part instances as the run builds their machines: types and parameters
  std::string placed;
  bool machines = false;
  for (const auto& page : m.net.pages) {
    for (const auto& inst : page.instances) {
      const auto own = m.type_scenes.find(inst.type);
      const bool owns = own != m.type_scenes.end() && !own->second->root().children().empty();
      if (!owns && !m.parts.contains(inst.type)) continue;
      machines = machines || owns;
      placed += page.name + "/" + inst.name + ":" + inst.type;
      for (const auto& p : inst.params) placed += "," + p.name + "=" + core::formatDouble(p.value);
      placed += ";";
    }
  }
  // the machines are the run's: it follows an edit of them at once, not a quarter second later
  if (edit && placed != st.followed) {
    st.followed = placed;
    if (app.run().revision() != doc.revision()) {
      core::Diagnostics diags;
      (void)app.run().reset(diags);
    }
  }
  if (!edit || !(machines || doc.scene() == nullptr)) {
    if (st.edit_scene) {
      ++st.generation;
      ++st.builds;
    }
    st.edit_scene.reset();
    st.frames.clear();
    st.built_revision = ~std::uint64_t{0};
    return;
  }
  const auto* plant = app.run().session() != nullptr ? app.run().session()->simulation().plant() : nullptr;
  if (st.edit_scene && st.built_revision == doc.revision() && st.built_run == app.run().revision() && st.built_session == plant) {
    return;
  }
  // the document's scene, and each part instance's machine under a Transform named after it:
  // the run's (its parameters applied), else its type's as it is
  auto s = doc.scene() != nullptr ? doc.scene()->clone() : std::make_unique<scene::Scene>();
  const auto& transform = *s->types().find(scene::NodeKind::Transform);
  st.frames.clear();
  for (const auto& page : m.net.pages) {
    for (const auto& inst : page.instances) {
      const auto own = m.type_scenes.find(inst.type);
      if (own == m.type_scenes.end() || own->second->root().children().empty() || s->find(inst.name) != nullptr) continue;
      const scene::Node* made = plant != nullptr ? plant->find(inst.name) : nullptr;
      scene::Node* frame = nullptr;
      if (made != nullptr && made->kind() == scene::NodeKind::Transform) {
        frame = s->copy(*made, s->root());
      } else if ((frame = s->create(transform, inst.name, s->root())) != nullptr) {
        for (const auto& c : own->second->root().children()) s->copy(*c, *frame);
      }
      if (frame == nullptr) continue;
      frame->setValue(scene::field::Transform::Translation, inst.translation);
      frame->setValue(scene::field::Transform::Rotation, inst.rotation);
      if (m.parts.contains(inst.type)) st.frames[frame->path()] = {page.name, inst.name};
    }
  }
  scene::updateTransforms(s->root());
  st.edit_scene = std::move(s);
  st.built_revision = doc.revision();
  st.built_run = app.run().revision();
  st.built_session = plant;
  ++st.generation;
  ++st.builds;
}

PaletteGhost paletteGhost(App& app, const OrbitCamera& view, ImVec2 at, float w, float h) {
  auto& st = app.palette();
  const ImGuiPayload* payload = ImGui::GetDragDropPayload();
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const bool over = mouse.x >= at.x && mouse.y >= at.y && mouse.x < at.x + w && mouse.y < at.y + h;
  const auto* part = payload != nullptr && payload->IsDataType(kPartPayload) && over && app.run().mode() == RunMode::Edit
                         ? model::findLibraryPart(st.parts, std::string(static_cast<const char*>(payload->Data),
                                                                        static_cast<std::size_t>(payload->DataSize)))
                         : nullptr;
  if (part == nullptr) {
    if (!st.dragged.empty()) ++st.generation;
    st.dragged.clear();
    st.drag_turn = 0;
    st.ghost.reset();
    st.ghost_scene.reset();
    return {};
  }
  const auto& machine = machineOf(st, *part);
  DropQuery q;
  q.ray = view.ray(static_cast<double>(mouse.x - at.x), static_cast<double>(mouse.y - at.y), static_cast<double>(w),
                   static_cast<double>(h));
  // turned while dragging: it snaps as the turned box it is
  if (st.dragged != part->name) st.drag_turn = 0;
  q.box = turnedAboutZ(machine.box, st.drag_turn);
  q.loose = machine.loose;
  q.neighbours = footprints(app);
  q.grid = app.world.snap ? app.world.move_step : 0.0;
  auto place = placeDrop(q);
  if (place) place->angle = std::fmod(place->angle + st.drag_turn, 360.0);

  const bool moved = st.dragged != part->name || !st.ghost || !place || place->translation != st.ghost->translation ||
                     place->angle != st.ghost->angle;
  st.dragged = part->name;
  st.ghost = place;
  // the scene shown with the ghost in it: made again when the scene under it or the part changed
  if (!st.ghost_scene || st.ghost_builds != st.builds || st.ghost_revision != app.document().sceneRevision() ||
      st.ghost_part != part->name) {
    auto* base = app.shownScene();
    st.ghost_scene = base != nullptr ? base->clone() : std::make_unique<scene::Scene>();
    auto* frame = st.ghost_scene->create(*st.ghost_scene->types().find(scene::NodeKind::Transform), kGhostName,
                                         st.ghost_scene->root());
    if (frame != nullptr && machine.scene) {
      for (const auto& c : machine.scene->root().children()) st.ghost_scene->copy(*c, *frame);
    }
    st.ghost_node = frame != nullptr ? frame->handle() : 0;
    st.ghost_part = part->name;
    st.ghost_builds = st.builds;
    st.ghost_revision = app.document().sceneRevision();
    ++st.generation;
  } else if (moved) {
    ++st.generation;
  }
  auto* frame = st.ghost_scene->resolve(st.ghost_node);
  if (frame == nullptr) return {};
  // where it would land; nowhere (looking up into the sky): not drawn
  frame->is_template = !place;
  if (place) {
    frame->setValue(scene::field::Transform::Translation, place->translation);
    frame->setValue(scene::field::Transform::Rotation, std::array<double, 4>{0, 0, 1, place->angle});
  }
  scene::updateTransforms(st.ghost_scene->root());
  return {st.ghost_scene.get(), {frame->handle()}};
}

void paletteDrop(App& app, const OrbitCamera& view, ImVec2 at, float w, float h, nlohmann::json& report) {
  auto& st = app.palette();
  // a part dropped here is placed where its ghost stands
  if (ImGui::BeginDragDropTarget()) {
    if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kPartPayload, ImGuiDragDropFlags_AcceptNoDrawDefaultRect)) {
      const std::string name(static_cast<const char*>(payload->Data), static_cast<std::size_t>(payload->DataSize));
      if (st.ghost && st.dragged == name) {
        placeDropped(app, name, *st.ghost, ImGui::GetIO().MousePos);
      } else {
        app.message = "'" + name + "' cannot land there: point at the floor or at a part";
      }
      st.dragged.clear();
      st.ghost.reset();
      st.ghost_scene.reset();
      ++st.generation;
    }
    ImGui::EndDragDropTarget();
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  // the footprint where the dragged part would land, and how it snapped
  if (st.ghost && !st.dragged.empty()) {
    const auto* part = model::findLibraryPart(st.parts, st.dragged);
    const auto box = part != nullptr ? machineOf(st, *part).box : core::Aabb{};
    const auto pose = poseAboutZ({st.ghost->translation[0], st.ghost->translation[1], st.ghost->translation[2]}, st.ghost->angle);
    const bool snapped = !st.ghost->neighbour.empty();
    const ImU32 colour = snapped ? IM_COL32(80, 230, 120, 255) : IM_COL32(120, 190, 255, 255);
    if (!box.empty()) {
      std::vector<ImVec2> outline;
      for (const auto& c : {core::Vec3{box.lo.x, box.lo.y, 0}, core::Vec3{box.hi.x, box.lo.y, 0}, core::Vec3{box.hi.x, box.hi.y, 0},
                            core::Vec3{box.lo.x, box.hi.y, 0}}) {
        if (const auto p = onScreen(view, pose.apply(c), at, w, h)) outline.push_back(*p);
      }
      if (outline.size() == 4) {
        draw->AddPolyline(outline.data(), 4, IM_COL32(10, 10, 10, 160), ImDrawFlags_Closed, 4.0F);
        draw->AddPolyline(outline.data(), 4, colour, ImDrawFlags_Closed, 2.0F);
      }
    }
    std::string label = shownName(st.dragged) + ": ";
    label += snapped ? std::string(snapKindName(st.ghost->kind)) + " of " + st.ghost->neighbour : "on the floor";
    label += "  (" + core::formatDouble(st.ghost->translation[0]) + ", " + core::formatDouble(st.ghost->translation[1]) + ")";
    // above the pointer: the drag's own preview is below it
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    const ImVec2 corner{std::clamp(mouse.x + 12, at.x + 4, std::max(at.x + 4, at.x + w - size.x - 12)),
                        std::max(at.y + 4, mouse.y - 16 - size.y)};
    draw->AddRectFilled(corner, {corner.x + size.x + 8, corner.y + size.y + 6}, IM_COL32(20, 22, 26, 220), 4.0F);
    draw->AddText({corner.x + 4, corner.y + 3}, colour, label.c_str());
    report["drop"] = {{"part", st.dragged},
                      {"translation", st.ghost->translation},
                      {"angle", st.ghost->angle},
                      {"snap", snapKindName(st.ghost->kind)},
                      {"neighbour", st.ghost->neighbour}};
  }
  // where a replay can drop beside each part: its top's centre and just beyond each side
  nlohmann::json parts = nlohmann::json::object();
  if (st.edit_scene) {
    for (const auto& [path, inst] : st.frames) {
      const auto* frame = st.edit_scene->find(path);
      if (frame == nullptr) continue;
      const auto box = localBox(*frame);
      if (box.empty()) continue;
      const core::Vec3 c = (box.lo + box.hi) * 0.5;
      nlohmann::json points = nlohmann::json::object();
      const double quarter = (box.hi.x - box.lo.x) / 4;
      const std::pair<const char*, core::Vec3> named[] = {{"center", {c.x, c.y, box.hi.z}},
                                                          {"top -x", {c.x - quarter, c.y, box.hi.z}},
                                                          {"top +x", {c.x + quarter, c.y, box.hi.z}},
                                                          {"+x", {box.hi.x + kBeyond, c.y, 0}},
                                                          {"-x", {box.lo.x - kBeyond, c.y, 0}},
                                                          {"+y", {c.x, box.hi.y + kBeyond, 0}},
                                                          {"-y", {c.x, box.lo.y - kBeyond, 0}}};
      for (const auto& [key, local] : named) {
        if (const auto p = onScreen(view, frame->framePose().apply(local), at, w, h)) {
          points[key] = {std::lround(p->x), std::lround(p->y)};
        }
      }
      parts[inst.name] = points;
    }
  }
  report["parts"] = parts;
}

std::optional<PartInstanceAt> partAtPath(const App& app, const std::string& path) {
  // a top-level node named after a part instance that places a machine, which the document's
  // own scene does not hold (the edit scene's and the run's plant's alike)
  if (path.empty() || path.find('/') != std::string::npos) return std::nullopt;
  const auto& m = app.document().model();
  const auto at = findPartInstance(m, path);
  if (!at) return std::nullopt;
  const auto* inst = instanceAt(m, *at);
  const auto own = m.type_scenes.find(inst->type);
  if (own == m.type_scenes.end() || own->second->root().children().empty()) return std::nullopt;
  if (const auto* s = app.document().scene(); s != nullptr && s->find(path) != nullptr) return std::nullopt;
  return at;
}

std::string partPathOf(const App& app, const std::string& path) {
  const auto top = path.substr(0, path.find('/'));
  return partAtPath(app, top) ? top : path;
}

std::unique_ptr<Command> manipulatorCommand(const App& app, const std::string& path, const std::string& field,
                                            const scene::FieldValue& value, std::uint64_t merge) {
  const auto at = partAtPath(app, path);
  const auto* inst = at ? instanceAt(app.document().model(), *at) : nullptr;
  if (inst != nullptr && (field == "translation" || field == "rotation")) {
    // a part's Transform stands for its instance: the instance moves and turns
    auto translation = inst->translation;
    auto rotation = inst->rotation;
    if (const auto* t = std::get_if<std::array<double, 3>>(&value); t != nullptr && field == "translation") translation = *t;
    if (const auto* r = std::get_if<std::array<double, 4>>(&value); r != nullptr && field == "rotation") rotation = *r;
    return SetInstanceCommand::placement(*at, translation, rotation, merge);
  }
  return std::make_unique<SetFieldCommand>(path, field, value, merge);
}

}  // namespace gdpn::ide
