// The fixed layout from the splitters, and the settings file that remembers them.

#include "gdpn/ide/layout.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gdpn::ide {

namespace {

constexpr float kMinView = 120.0F;  // the least a view keeps, pixels

float clampSplit(float v, float lo, float hi) { return std::max(lo, std::min(v, std::max(lo, hi))); }

}  // namespace

Layout Layout::of(Splitters& s, float width, float height) {
  const float body_top = kToolbarHeight;
  const float body_h = std::max(height - kToolbarHeight - kStatusHeight, 0.0F);
  // every splitter leaves its neighbours kMinView
  s.tree_width = clampSplit(s.tree_width, kMinView, width - 2 * kMinView - kHandle);
  const float right_x = s.tree_width + kHandle;
  const float right_w = std::max(width - right_x, 0.0F);
  s.bottom_height = clampSplit(s.bottom_height, 60.0F, body_h - kMinView - kHandle);
  const float top_h = std::max(body_h - s.bottom_height - kHandle, 0.0F);
  s.net_width = clampSplit(s.net_width, kMinView, right_w - kMinView - kHandle);
  s.diagnostics_width = clampSplit(s.diagnostics_width, kMinView, right_w - kMinView - kHandle);

  Layout l;
  l.toolbar = {0, 0, width, kToolbarHeight};
  l.status = {0, height - kStatusHeight, width, kStatusHeight};
  switch (s.full) {
    case FullView::None: break;
    case FullView::World: l.world = {0, body_top, width, body_h}; return l;
    case FullView::Net: l.net = {0, body_top, width, body_h}; return l;
  }
  l.tree = {0, body_top, s.tree_width, body_h};
  if (s.show_palette) {
    // the Parts palette under the tree, as a catalogue under a scene graph
    s.palette_height = clampSplit(s.palette_height, kMinView, body_h - kMinView - kHandle);
    l.tree.h = std::max(body_h - s.palette_height - kHandle, 0.0F);
    l.palette = {0, body_top + l.tree.h + kHandle, s.tree_width, s.palette_height};
    l.handles[static_cast<int>(Splitter::Palette)] = {0, body_top + l.tree.h, s.tree_width, kHandle};
  }
  const float big_w = std::max(right_w - s.net_width - kHandle, 0.0F);
  const Rect big{right_x, body_top, big_w, top_h};
  const Rect side{right_x + big_w + kHandle, body_top, s.net_width, top_h};
  l.world = s.swapped ? side : big;
  l.net = s.swapped ? big : side;
  const float bottom_y = body_top + top_h + kHandle;
  const float inspector_w = std::max(right_w - s.diagnostics_width - kHandle, 0.0F);
  l.inspector = {right_x, bottom_y, inspector_w, s.bottom_height};
  l.diagnostics = {right_x + inspector_w + kHandle, bottom_y, s.diagnostics_width, s.bottom_height};
  l.handles[static_cast<int>(Splitter::Tree)] = {s.tree_width, body_top, kHandle, body_h};
  l.handles[static_cast<int>(Splitter::Bottom)] = {right_x, body_top + top_h, right_w, kHandle};
  l.handles[static_cast<int>(Splitter::Net)] = {right_x + big_w, body_top, kHandle, top_h};
  l.handles[static_cast<int>(Splitter::Diagnostics)] = {right_x + inspector_w, bottom_y, kHandle, s.bottom_height};
  return l;
}

std::string settingsPath() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg != nullptr && *xdg != '\0') {
    return (std::filesystem::path(xdg) / "gdpn" / "ide.ini").string();
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return (std::filesystem::path(home) / ".config" / "gdpn" / "ide.ini").string();
  }
  return {};
}

std::vector<std::string> withRecent(std::vector<std::string> recent, const std::string& path) {
  std::erase(recent, path);
  recent.insert(recent.begin(), path);
  if (recent.size() > kRecentFiles) recent.resize(kRecentFiles);
  return recent;
}

std::optional<Settings> loadSettingsFile(const std::string& path) {
  std::ifstream in(path);
  if (path.empty() || !in) return std::nullopt;
  Settings settings;
  Splitters& s = settings.splitters;
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const auto key = line.substr(0, eq);
    const auto text = line.substr(eq + 1);
    if (key == "recent") {
      if (!text.empty() && settings.recent.size() < kRecentFiles) settings.recent.push_back(text);
      continue;
    }
    if (key == "swapped") s.swapped = text == "1";
    if (key == "palette") s.show_palette = text == "1";
    if (key == "full") s.full = text == "world" ? FullView::World : text == "net" ? FullView::Net : FullView::None;
    float v = 0;
    std::istringstream value(text);
    if (!(value >> v) || !(v > 0 && v < 1e5F)) continue;
    if (key == "tree_width") s.tree_width = v;
    if (key == "bottom_height") s.bottom_height = v;
    if (key == "net_width") s.net_width = v;
    if (key == "diagnostics_width") s.diagnostics_width = v;
    if (key == "palette_height") s.palette_height = v;
  }
  return settings;
}

bool saveSettingsFile(const std::string& path, const Settings& settings) {
  if (path.empty()) return false;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  const auto tmp = path + ".tmp";
  const Splitters& s = settings.splitters;
  const char* full = "none";
  switch (s.full) {
    case FullView::None: break;
    case FullView::World: full = "world"; break;
    case FullView::Net: full = "net"; break;
  }
  {
    std::ofstream out(tmp);
    out << "# gdpn ide: splitter positions (pixels), the views' places, the files opened last\n"
        << "tree_width=" << s.tree_width << "\nbottom_height=" << s.bottom_height << "\nnet_width=" << s.net_width
        << "\ndiagnostics_width=" << s.diagnostics_width << "\nswapped=" << (s.swapped ? 1 : 0) << "\nfull=" << full
        << "\npalette=" << (s.show_palette ? 1 : 0) << "\npalette_height=" << s.palette_height << "\n";
    for (const auto& r : settings.recent) out << "recent=" << r << "\n";
    if (!out) return false;
  }
  std::filesystem::rename(tmp, path, ec);
  return !ec;
}

}  // namespace gdpn::ide
