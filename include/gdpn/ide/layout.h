#pragma once
/// \file
/// The IDE's fixed layout: where each view goes in the window, from a few splitter positions
/// the user drags, remembered between sessions in a small settings file. Pure arithmetic and
/// file reading; no ImGui.

#include <optional>
#include <string>

namespace gdpn::ide {

/// A rectangle in window pixels (top-left origin).
struct Rect {
  float x = 0, y = 0, w = 0, h = 0;  ///< left, top, width, height, pixels
  /// True when (`px`, `py`) lies inside.
  [[nodiscard]] bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

/// The splitter positions, in pixels.
struct Splitters {
  float tree_width = 260.0F;       ///< the Tree view's width
  float bottom_height = 230.0F;    ///< the Inspector and Diagnostics' height
  float net_width = 420.0F;        ///< the Net view's width (right of the World view)
  float diagnostics_width = 420.0F;///< the Diagnostics' width (right of the Inspector)
  friend bool operator==(const Splitters&, const Splitters&) = default;
};

/// Which splitter a handle moves.
enum class Splitter : int { Tree, Bottom, Net, Diagnostics };

/// The views' rectangles in a window.
struct Layout {
  Rect toolbar, tree, world, net, inspector, diagnostics, status;  ///< each view's place
  Rect handles[4];  ///< the splitters' handles, by Splitter

  /// Places the views in a `width` x `height` window; the splitters are first clamped so
  /// every view keeps a usable size (written back into `s`).
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
/// The splitters saved in `path`, or nullopt when there is no such file (unknown or bad lines
/// are passed over).
[[nodiscard]] std::optional<Splitters> loadSplitters(const std::string& path);
/// Saves the splitters to `path` (its folder made when needed); false when it could not.
bool saveSplitters(const std::string& path, const Splitters& s);

}  // namespace gdpn::ide
