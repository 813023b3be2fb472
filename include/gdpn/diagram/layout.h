#pragma once
/// \file
/// Where each construct of one page (or page type) is drawn: places, transitions, instance
/// boxes and the polyline of each arc, in layout units. A page whose constructs all carry an
/// editor position (`at:` in the model file, PNML graphics) is drawn where they say; a page
/// with any construct lacking one is laid out by Graphviz (`dot`, left to right).
///
/// Layout units: 1 layout unit = 1 point (1/72 inch), x right and y down. One editor unit
/// (`at: [1, 0]`) is kEditorUnit layout units. The same spec always gives the same layout.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/diagram/geometry.h"
#include "gdpn/net/spec.h"

namespace gdpn::diagram {

/// Layout units per editor unit: neighbours one editor unit apart stand an inch apart.
inline constexpr double kEditorUnit = 72.0;
/// Radius of a place's circle, layout units.
inline constexpr double kPlaceRadius = 18.0;
/// Width of a transition's bar, layout units.
inline constexpr double kBarWidth = 8.0;
/// Height of a transition's bar, layout units.
inline constexpr double kBarHeight = 36.0;
/// Width of a continuous transition's box (hybrid nets: hollow, double-bordered), layout units.
inline constexpr double kFlowWidth = 16.0;
/// The inner outline of a continuous place (hybrid nets: a double circle), its radius as a
/// share of kPlaceRadius.
inline constexpr double kInnerCircle = 0.78;
/// Height of an instance box, layout units (its width follows its name).
inline constexpr double kInstanceHeight = 40.0;
/// The most constructs Graphviz lays out on one page (about 1.5 s at 4,000 on one core); a
/// larger page without positions is put in columns by distance from its sources instead.
inline constexpr std::size_t kGraphvizLimit = 2000;

/// What a laid-out item is.
enum class ItemKind : std::uint8_t {
  Place,       ///< a place (index into NetLayout::places)
  Transition,  ///< a transition (index into NetLayout::transitions)
  Instance,    ///< an instance box (index into NetLayout::instances)
  Arc,         ///< an arc (index into NetLayout::arcs)
};

/// One item of a layout: what it is and its index in the vector of its kind.
struct ItemRef {
  ItemKind kind = ItemKind::Place;  ///< which vector
  std::uint32_t index = 0;          ///< position in it
  friend auto operator<=>(const ItemRef&, const ItemRef&) = default;
};

/// What the picture shows of a continuous place or transition (hybrid nets) without a run:
/// the spec's.
struct FluidLook {
  double amount = 0.0;              ///< a place's initial amount, in its unit
  std::optional<double> capacity{}; ///< a place's capacity, in its unit (none: unbounded)
  /// A place's unit ("L", "" for none); a transition's rate's unit: its first output's (else
  /// input's) continuous place's unit per second, "L/s", else "/s".
  std::string unit{};
};

/// A place, a transition or an instance box: its centre and its box, layout units.
struct NodeLayout {
  std::string name;  ///< the construct's name on the page
  Point centre;      ///< centre, layout units
  Box box;           ///< what it covers, layout units (the circle's square for a place)
  /// A place's tag, drawn beside it as CPN Tools draws port and fusion tags: "port" for a
  /// place its page type publishes, "fusion NAME" for a member of a fusion set, both joined by
  /// ", "; a transition's: its condition in brackets, "[x > 1]"; "" for none.
  std::string tag{};
  /// Set for a continuous place or transition (hybrid nets): drawn as such.
  std::optional<FluidLook> fluid{};
};

/// An instance box: the instance's name and its page type.
struct InstanceLayout : NodeLayout {
  std::string type;  ///< the page type it instantiates
};

/// An arc: its polyline from the source's outline to the target's outline, layout units.
struct ArcLayout {
  ItemRef from;                  ///< the source item (a place, transition or instance)
  ItemRef to;                    ///< the target item
  std::string link;              ///< for an arc to or from an instance: the reference's name, else ""
  net::ArcKind kind = net::ArcKind::Normal;  ///< normal, test or inhibitor
  std::int64_t weight = 1;       ///< total weight over its slots, tokens
  /// What the arc's label says: "" for weight 1 on a0, "3" for weight 3 on a0, else its slots
  /// ("b0..b4", "2·a1+c0"); a real weight on a continuous place as amountText() writes it ("2.5").
  std::string inscription;
  std::uint32_t spec_index = 0;  ///< the arc's index in PageSpec::arcs (NetState::arcs is indexed by it)
  std::vector<Point> points;     ///< at least two points: start, bends, end (the end touches the target)
  /// True when the bends (points[1 .. size-2]) are the spec's `via`, one for one; false for a
  /// straight arc, one bent apart from its twin, or Graphviz's route.
  bool follows_via = false;
  std::optional<Point> label_at;  ///< where the inscription's centre stands when the spec says (`label_at`), layout units
  Box box;                       ///< the polyline's bounding box (and the label's point)
};

/// A page drawn on the plane. Items keep the spec's order: places[i] is the page's i-th place.
struct NetLayout {
  std::string page;                         ///< the page's name
  std::vector<NodeLayout> places;           ///< in the spec's order
  std::vector<NodeLayout> transitions;      ///< in the spec's order
  std::vector<InstanceLayout> instances;    ///< in the spec's order
  std::vector<ArcLayout> arcs;              ///< in the spec's order (arcs naming nothing on the page are left out)
  Box bounds;                               ///< everything, layout units
  bool from_graphviz = false;               ///< true when Graphviz placed the nodes

  /// The box of item `item`, layout units.
  [[nodiscard]] const Box& boxOf(ItemRef item) const;
};

/// Lays out `page`. Positions come from the spec when every place, transition and instance
/// has one; otherwise Graphviz places everything (above kGraphvizLimit constructs, columns
/// by breadth-first distance from the sources, with a warning). A page Graphviz cannot lay
/// out gives an error at the page's location in `diags` and an empty layout.
NetLayout layoutPage(const net::PageSpec& page, core::Diagnostics& diags);

/// Lays out again, in place, the items `moved` (places, transitions, instances) at their
/// positions in `page` and the arcs that touch them, then the bounds: what layoutPage(page)
/// gives, at the cost of what moved. `l` is layoutPage() of `page` as it was before moves alone
/// (positions, and the bends of arcs whose ends moved together) changed it, and not laid out by
/// Graphviz (NetLayout::from_graphviz false).
void relayoutMoved(NetLayout& l, const net::PageSpec& page, const std::vector<ItemRef>& moved);

/// An amount as the net view writes it: at most 4 significant digits, no trailing zeros
/// ("12.5", "0.3", "1e+04"), then " " and `unit` when there is one ("12.5 L").
[[nodiscard]] std::string amountText(double amount, const std::string& unit = {});

/// The unit of continuous transition `name`'s rate on `page` (hybrid nets): its first
/// output's continuous place's unit per second ("L/s"), else its first input's, else "/s".
[[nodiscard]] std::string rateUnit(const net::PageSpec& page, const std::string& name);

/// A rate as the net view writes it: amountText() and its unit ("0.3 L/s", "0.3/s").
[[nodiscard]] std::string rateText(double rate, const std::string& unit);

/// The label of an arc with these weights (see ArcLayout::inscription).
[[nodiscard]] std::string inscription(const std::vector<net::SlotCount>& weights);

/// The point of layout units where editor position `at` stands (`at` times kEditorUnit).
[[nodiscard]] Point layoutPoint(const net::EditorPos& at);

/// The editor position of layout point `p`, as the net editor writes one: editor units rounded
/// to a quarter (so a drag snaps), never -0. layoutPoint() of it is `p` within an eighth of a unit.
[[nodiscard]] net::EditorPos editorPosition(Point p);

/// The middle of a polyline: the point half its length along it (layout units); the first
/// point of one of no length. `points` must not be empty.
[[nodiscard]] Point middleOf(const std::vector<Point>& points);

/// The `label_at` (editor units, an offset from the arc's middle, not rounded) that puts the
/// inscription of `arc` at layout point `p`: what an editor writes when a label is dragged.
[[nodiscard]] net::EditorPos labelOffset(const ArcLayout& arc, Point p);

/// The segment of an arc's polyline nearest a point, and the point of it nearest.
struct SegmentHit {
  std::size_t segment = 0;  ///< from points[segment] to points[segment + 1]
  Point at;                 ///< the nearest point on it, layout units
  double distance = 0.0;    ///< from the point asked about to `at`, layout units
};

/// The segment of `arc`'s polyline nearest `p` (layout units; the first of equally near ones).
/// A bend added at `at` goes into the spec's `via` at index `segment` when the arc follows its
/// `via` (ArcLayout::follows_via). An arc of fewer than two points gives segment 0 at its one
/// point (or at `p` when it has none).
[[nodiscard]] SegmentHit nearestSegment(const ArcLayout& arc, Point p);

/// The index in the spec's `via` of the bend of `arc` within `tolerance` of `p` (layout units;
/// the nearest when several are), for a double-click that removes it; nullopt when none is,
/// or when the arc does not follow its `via`.
[[nodiscard]] std::optional<std::size_t> bendAt(const ArcLayout& arc, Point p, double tolerance);

/// A page to draw, and the prefix that qualifies its constructs' names in the frozen net.
struct PageView {
  const net::PageSpec* page = nullptr;  ///< the page or page type
  std::string prefix;  ///< "line" for page `line`, "line/cellA" inside its instance cellA; "" for a page type alone
};

/// The page a view `path` names: "" is the first page; "line" the page (or else the page
/// type) of that name; "line/cellA/arm" the page type of instance arm inside instance cellA
/// of page line. A path naming nothing gives an error (at `where`) listing the pages and
/// page types, and a view with no page.
PageView findView(const net::NetSpec& spec, const std::string& path, core::Diagnostics& diags,
                  const core::SourceLoc& where = {});

}  // namespace gdpn::diagram
