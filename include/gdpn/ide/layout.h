#pragma once
/// \file
/// The IDE's layout: where each view goes in the window, from a few splitter positions the
/// user drags, the world and net views' places (swapped, or one filling the window), remembered
/// between sessions in a small settings file with the recent files. Pure arithmetic and file
/// reading; no ImGui.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gdpn::ide {

/// A rectangle in window pixels (top-left origin).
struct Rect {
  float x = 0, y = 0, w = 0, h = 0;  ///< left, top, width, height, pixels
  /// True when (`px`, `py`) lies inside.
  [[nodiscard]] bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

/// A view that fills the window below the toolbar, the others hidden.
enum class FullView : std::uint8_t {
  None,   ///< every view in its panel
  World,  ///< the world view alone
  Net,    ///< the net view alone
};

/// The splitter positions, in pixels, and where the world and net views go.
struct Splitters {
  float tree_width = 260.0F;       ///< the Tree view's width
  float bottom_height = 230.0F;    ///< the Inspector and Diagnostics' height
  float net_width = 420.0F;        ///< the width of the panel right of the big one (the Net view's, or the World view's when swapped)
  float diagnostics_width = 420.0F;///< the Diagnostics' width (right of the Inspector)
  bool swapped = false;            ///< the net view takes the big panel, the world view the one at its right
  float palette_height = 380.0F;   ///< the Parts palette's height, under the Tree view
  bool show_palette = true;        ///< the Parts palette is shown (View > Parts Palette)
  FullView full = FullView::None;  ///< a view filling the window
  friend bool operator==(const Splitters&, const Splitters&) = default;
};

/// What the settings file keeps: the layout and the files opened last.
struct Settings {
  Splitters splitters;               ///< the layout
  std::vector<std::string> recent;   ///< model files opened, the latest first (at most kRecentFiles)
  friend bool operator==(const Settings&, const Settings&) = default;
};

/// How many recent files the settings keep.
inline constexpr std::size_t kRecentFiles = 10;

/// `recent` with `path` first (once), cut to kRecentFiles.
[[nodiscard]] std::vector<std::string> withRecent(std::vector<std::string> recent, const std::string& path);

/// Which splitter a handle moves.
enum class Splitter : int { Tree, Bottom, Net, Diagnostics, Palette };

/// The views' rectangles in a window.
struct Layout {
  Rect toolbar, tree, world, net, inspector, diagnostics, status;  ///< each view's place
  Rect palette;     ///< the Parts palette's place, under the tree (empty while hidden)
  Rect handles[5];  ///< the splitters' handles, by Splitter

  /// Places the views in a `width` x `height` window; the splitters are first clamped so
  /// every view keeps a usable size (written back into `s`). A view filling the window gets
  /// the whole body; the others get empty rectangles, as do the handles.
  static Layout of(Splitters& s, float width, float height);
};

/// Toolbar height, pixels.
inline constexpr float kToolbarHeight = 36.0F;
/// Status bar height, pixels.
inline constexpr float kStatusHeight = 26.0F;
/// A splitter handle's thickness, pixels.
inline constexpr float kHandle = 6.0F;

/// The settings file: $XDG_CONFIG_HOME/gdpn/ide.ini, or ~/.config/gdpn/ide.ini ("" when
/// neither variable is set).
[[nodiscard]] std::string settingsPath();
/// The settings saved in `path`, or nullopt when there is no such file (unknown or bad lines
/// are passed over).
[[nodiscard]] std::optional<Settings> loadSettingsFile(const std::string& path);
/// Saves the settings to `path` (written beside it, then renamed; its folder made when
/// needed); false when it could not.
bool saveSettingsFile(const std::string& path, const Settings& s);

}  // namespace gdpn::ide
