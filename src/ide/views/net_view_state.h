#pragma once
// What the net view keeps between frames: the page shown, its layout and index (made again
// only when the page or the document changes), and the viewport. Private to the ide module.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gdpn/net/spec.h"

#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/net_state.h"
#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/spatial_index.h"

namespace gdpn::ide {

/// The overview's grid: columns and rows over the page's bounds.
inline constexpr int kOverviewCols = 72;
inline constexpr int kOverviewRows = 44;

/// What a left click or drag on the net view's paper does.
enum class NetTool : std::uint8_t {
  Select,      ///< a click selects, a drag moves the selection or draws a rubber band
  Place,       ///< a click on paper adds a place there
  Transition,  ///< a click on paper adds a transition there
  Arc,         ///< a drag (or two clicks) from one end to the other adds an arc
};

/// A drag of a selected arc's bend or label (or of its path, which adds a bend).
struct ArcDrag {
  std::uint32_t arc = 0;  ///< the arc's index in the layout
  net::ArcSpec spec;      ///< the arc as it was when the drag began
  int bend = -1;          ///< the index in `via` of the bend dragged; -1: the label
  bool fresh = false;     ///< the bend is new: it goes into `via` at `bend` with the first move
};

/// The net view's own state.
struct NetViewState {
  std::string path;                  ///< the page or instance shown (diagram::findView's path; "" the first page)
  diagram::PageView view;            ///< what `path` named when laid out
  diagram::NetLayout layout;         ///< the page laid out
  bool positioned = false;           ///< every construct of the page had its position when laid out
  std::unique_ptr<diagram::SpatialIndex> index;  ///< over `layout`
  diagram::Viewport viewport;        ///< pan and zoom
  bool fit = true;                   ///< fit the page into the view at the next frame
  std::size_t laid_out_items = 0;    ///< places, transitions and instances when last laid out
  bool fitted = true;                ///< the view shows the fit (no zoom or pan since): a new size fits again
  int fitted_w = 0, fitted_h = 0;    ///< the canvas's size when it was fitted, pixels
  std::string error;                 ///< why the page cannot be shown ("" when it can)
  std::string laid_out_path = "\x01";  ///< `path` when the layout was made
  std::uint64_t laid_out_revision = ~std::uint64_t{0};  ///< the document's revision then
  diagram::PageBinding binding;      ///< where `view`'s constructs are in the run's net
  const void* bound_net = nullptr;   ///< the net `binding` was made for (null: none yet)
  std::string bound_path = "\x01";  ///< `path` then
  std::optional<diagram::NetState> state;  ///< the run's marking as last read
  std::int64_t state_steps = -1;     ///< the kernel's steps plus starts then
  const void* state_kernel = nullptr;  ///< and its kernel
  std::vector<diagram::ItemRef> holding;  ///< the places and transitions holding the selected node as a token
  std::string holding_node;          ///< that node's path ("" : none)
  std::int64_t holding_steps = -1;   ///< state_steps when `holding` was found
  NetTool tool = NetTool::Select;    ///< what a left click or drag does
  /// Every place, transition and instance of the layout by name, and every arc by the name
  /// arcName() gives it after the prefix ("infeed -> load_a"), made with the layout.
  std::unordered_map<std::string, diagram::ItemRef> by_name;
  std::string moving;                ///< the construct a left drag began on ("" : none)
  /// A drag moving the selection: each construct's name and where it stood at the start, editor units.
  std::vector<std::pair<std::string, net::EditorPos>> moving_from;
  diagram::Point moving_origin;      ///< where that drag began, layout units
  net::EditorPos moved_by{0, 0};     ///< how far the last move edit took them, editor units
  std::optional<diagram::Point> band_from;  ///< a rubber band's first corner, layout units (none: no band)
  bool band_adds = false;            ///< the band adds to the selection (Shift or Ctrl held)
  std::optional<diagram::ItemRef> toggling;  ///< a Shift- or Ctrl-click's item, toggled unless it becomes a drag
  std::optional<diagram::ItemRef> alone;     ///< a click on one of a group: selected alone unless it becomes a drag
  bool panning = false;              ///< an Alt+left drag pans
  std::optional<ArcDrag> arc_drag;   ///< a bend or label being dragged
  /// The overview of a page larger than the view: how many constructs fall in each cell of a
  /// kOverviewCols x kOverviewRows grid over the page's bounds (made with the layout).
  std::vector<std::uint32_t> density;
  bool overview_drag = false;        ///< a drag in the overview moves the view
  bool overview_hot = false;         ///< the mouse is over the overview (or drags in it): it takes the left button
  std::string port_instance;         ///< an arc ended at (or began from) this instance: its ports' menu opens
  std::string port_other;            ///< that arc's other end
  bool port_into = true;             ///< the arc runs into the instance (else out of it)
  bool port_open = false;            ///< the ports' menu was opened
  std::string arc_from;              ///< an arc begun from this construct, waiting for its other end
  net::ArcKind arc_kind = net::ArcKind::Normal;  ///< that arc's kind
  std::optional<diagram::ItemRef> menu_item;     ///< what the open menu is about (none: the paper)
  diagram::Point menu_at;            ///< where it was opened, layout units
  std::string rename;                ///< the menu's rename field
};

class App;

/// Lays out the page `s` shows again when the page or the document changed.
void ensureLayout(App& app, NetViewState& s);
/// A layout point in editor units (`at:`), on a grid of a quarter unit (never -0).
inline net::EditorPos editorAt(diagram::Point p) { return diagram::editorPosition(p); }
/// The pins of a page some of whose constructs lack a position (laid out by Graphviz or in
/// columns): where each construct is drawn now, so that a move keeps the page's look (none for
/// a page with positions throughout).
std::vector<std::pair<std::string, net::EditorPos>> pinsOf(const NetViewState& s);
/// "select", "place", "transition", "arc".
const char* netToolName(NetTool tool);

}  // namespace gdpn::ide
