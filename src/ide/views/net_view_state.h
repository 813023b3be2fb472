#pragma once
// What the net view keeps between frames: the page shown, its layout and index (made again
// only when the page or the document changes), and the viewport. Private to the ide module.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/net_state.h"
#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/spatial_index.h"

namespace gdpn::ide {

/// The net view's own state.
struct NetViewState {
  std::string path;                  ///< the page or instance shown (diagram::findView's path; "" the first page)
  diagram::PageView view;            ///< what `path` named when laid out
  diagram::NetLayout layout;         ///< the page laid out
  std::unique_ptr<diagram::SpatialIndex> index;  ///< over `layout`
  diagram::Viewport viewport;        ///< pan and zoom
  bool fit = true;                   ///< fit the page into the view at the next frame
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
  std::string moving;                ///< the construct a left drag is moving ("" : none)
  std::string arc_from;              ///< an arc begun from this construct, waiting for its other end
  net::ArcKind arc_kind = net::ArcKind::Normal;  ///< that arc's kind
  std::optional<diagram::ItemRef> menu_item;     ///< what the open menu is about (none: the paper)
  diagram::Point menu_at;            ///< where it was opened, layout units
  std::string rename;                ///< the menu's rename field
};

}  // namespace gdpn::ide
