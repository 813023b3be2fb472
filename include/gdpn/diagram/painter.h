#pragma once
/// \file
/// Draws a page's layout, with or without its state, onto a Canvas within a viewport. The
/// look (the dissertation's scheme, close to CPN Tools and TAPAAL):
/// - places are circles with their tokens as dots coloured by slot kind (control black, node
///   blue, sensor orange), or as numbers when there are more than kMaxDots;
/// - transitions are bars: enabled green (the last firing phase found it able to start),
///   occurring red, idle dark grey; amber with a green outline when its marking suffices but
///   its guard, a predicate, a condition or its probability draw held it back; dark grey with
///   a green outline while its arcs allow it but no firing phase has tried it yet;
/// - normal arcs end in an arrowhead, inhibitor arcs in a small circle; test arcs are dashed
///   with no arrowhead (they take nothing); an arc is green while its condition holds and
///   grey while not; inscriptions (weights above 1, or the slots: "b0..b4") stand beside
///   the arc's middle;
/// - hybrid nets: a continuous place is a double circle filled from the bottom in
///   colours::kContinuous up to its level (amount over capacity; no fill when unbounded),
///   its amount and unit written inside ("12.5 L"; beside it when too small to read); a
///   continuous transition is a hollow box with a double border, green while it flows (its
///   effective rate beside it: "0.3 L/s") and dark grey while it does not; without a run,
///   the spec's initial amounts;
/// - names stand under places and above transitions; instance boxes show the instance's
///   name and its type, and arcs to them the reference's name.
/// Text is never drawn below kMinFontPx: when zoomed out that far, names are left out.

#include <cstddef>

#include "gdpn/diagram/canvas.h"
#include "gdpn/diagram/layout.h"
#include "gdpn/diagram/net_state.h"
#include "gdpn/diagram/spatial_index.h"

namespace gdpn::diagram {

/// Smallest text drawn, pixels.
inline constexpr double kMinFontPx = 8.0;
/// Largest text drawn, pixels (names do not grow past it when zoomed in).
inline constexpr double kMaxFontPx = 18.0;
/// Names whose zoom would draw them this small or larger are drawn at Viewport::min_label_px
/// when it is larger (below, the shapes are too close for names to find room), pixels.
inline constexpr double kReadableFromPx = 5.0;
/// Most tokens drawn as dots in one place; more are shown as numbers.
inline constexpr std::int64_t kMaxDots = 5;

/// Colours of the net view.
namespace colours {
inline constexpr Rgba kBackground{255, 255, 255, 255};  ///< the page
inline constexpr Rgba kOutline{34, 34, 34, 255};        ///< places' circles, names
inline constexpr Rgba kEnabled{44, 160, 44, 255};       ///< enabled transitions, arcs that hold
inline constexpr Rgba kOccurring{214, 39, 40, 255};     ///< occurring transitions
inline constexpr Rgba kHeldBack{230, 171, 2, 255};      ///< transitions whose marking suffices but something held back
inline constexpr Rgba kIdle{68, 68, 68, 255};           ///< idle transitions, arcs with no state
inline constexpr Rgba kArcOff{160, 160, 160, 255};      ///< arcs that do not hold
inline constexpr Rgba kControl{20, 20, 20, 255};        ///< control tokens
inline constexpr Rgba kNode{31, 119, 180, 255};         ///< node tokens
inline constexpr Rgba kSensor{255, 127, 14, 255};       ///< sensor variables
inline constexpr Rgba kValue{148, 103, 189, 255};       ///< value tokens
inline constexpr Rgba kContinuous{23, 190, 207, 255};   ///< a continuous place's amount (hybrid nets)
inline constexpr Rgba kInstanceFill{232, 238, 246, 255};  ///< instance boxes
inline constexpr Rgba kInstanceLine{80, 96, 128, 255};    ///< instance boxes' outlines, link names
inline constexpr Rgba kInscription{70, 70, 110, 255};     ///< arc inscriptions (weights, slots)
}  // namespace colours

struct Viewport;
/// The height the names of constructs are drawn at through `v`, pixels; 0 when the zoom is
/// too small for names (they are left out).
[[nodiscard]] double labelPx(const Viewport& v);

/// How layout units map to the canvas: screen = (layout - origin) * zoom.
struct Viewport {
  Point origin;       ///< the layout point at the canvas' top-left corner, layout units
  double zoom = 1.0;  ///< pixels per layout unit (> 0)
  /// The least height of names, pixels, where the zoom would draw them smaller but still at
  /// kReadableFromPx or more (0: names scale with the zoom alone). An editor's view asks for
  /// names it can read; a rendered picture keeps them in proportion.
  double min_label_px = 0;

  /// A layout point on the canvas, pixels.
  [[nodiscard]] Point toScreen(Point p) const { return (p - origin) * zoom; }
  /// A canvas point in the layout, layout units.
  [[nodiscard]] Point toLayout(Point s) const { return origin + s * (1.0 / zoom); }
  /// The viewport zoomed by `factor` (> 0) about canvas point `anchor` (pixels): the layout
  /// point under the anchor stays under it (a mouse wheel over the net view).
  [[nodiscard]] Viewport zoomedAbout(Point anchor, double factor) const {
    const Point fixed = toLayout(anchor);
    const double zoomed = zoom * factor;
    return {fixed - anchor * (1.0 / zoomed), zoomed};
  }
  /// The viewport moved so that the picture follows a drag of `delta` pixels.
  [[nodiscard]] Viewport panned(Point delta) const { return {origin - delta * (1.0 / zoom), zoom}; }
  /// What a canvas of `width` x `height` pixels shows, layout units.
  [[nodiscard]] Box visible(int width, int height) const {
    return {origin, toLayout({static_cast<double>(width), static_cast<double>(height)})};
  }
};

/// The viewport that shows all of `layout` (names included) centred on a canvas of `width`
/// x `height` pixels, with `margin` pixels around it, zoomed in at most to `max_zoom`.
[[nodiscard]] Viewport fitViewport(const NetLayout& layout, int width, int height, double margin = 16.0,
                                   double max_zoom = 2.0);

/// The layout's bounds grown by the room its names take, layout units.
[[nodiscard]] Box drawnBounds(const NetLayout& layout);

/// Clears `canvas` and draws the items of `layout` that `index` finds in the viewport, with
/// `state` (may be null: a static picture, every transition idle, the arcs dark grey).
/// Returns how many items it drew.
std::size_t paintNet(const NetLayout& layout, const SpatialIndex& index, const NetState* state,
                     const Viewport& view, Canvas& canvas);

}  // namespace gdpn::diagram
