#pragma once
/// \file
/// Where a part dropped from the palette lands: on the floor or on top of the part under the
/// pointer, on the grid, and snapped to the parts near it by their bounding boxes (a belt to a
/// belt's end, a sensor or a pusher to a belt's side). Pure geometry, no ImGui: the world view
/// calls it each frame of a drag and once at the drop (docs/ide.md, "The parts palette").

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/math.h"
#include "gdpn/scene/node.h"

namespace gdpn::ide {

/// A part instance as snapping sees it: where its frame stands and the box of its machine.
struct PartFootprint {
  std::string name;        ///< the instance ("belt_conveyor1")
  core::Vec3 position;     ///< its frame's origin, world, m
  double angle = 0;        ///< its turn about z, degrees
  core::Aabb box;          ///< its machine's shapes in its frame, m (empty: nothing to snap to)
};

/// How a drop was placed.
enum class SnapKind : std::uint8_t {
  Floor,       ///< on the floor (z = 0) under the pointer, on the grid
  OnTop,       ///< on top of the part under the pointer (it fits there)
  EndPlusX,    ///< touching the +x end of a part, centre lines aligned (belt after belt)
  EndMinusX,   ///< touching its -x end
  SidePlusY,   ///< touching its +y side, along it on the grid
  SideMinusY,  ///< touching its -y side
  CentreLine,  ///< beside it with its origin on the part's centre line (y = 0 of its frame)
};

/// "floor", "on top", "end +x", "end -x", "side +y", "side -y", "centre line".
[[nodiscard]] const char* snapKindName(SnapKind kind);

/// What placeDrop() is asked.
struct DropQuery {
  core::Ray ray;                          ///< the pick ray under the pointer, world
  core::Aabb box;                         ///< the dropped part's machine in its own frame, m
  bool loose = false;                     ///< its shapes all move with bodies (an item): it may go on top of a part
  std::vector<PartFootprint> neighbours;  ///< the parts already placed
  double grid = 0.05;                     ///< the grid step, m (0: none)
  double capture = 0.3;                   ///< how near a neighbour's box must come to snap to it, m
  double centre_line = 0.06;              ///< a side snap within this of the centre line goes onto it, m
};

/// Where the dropped part goes.
struct DropPlace {
  std::array<double, 3> translation{0, 0, 0};  ///< its frame's origin, world, m
  double angle = 0;                            ///< its turn about z, degrees
  SnapKind kind = SnapKind::Floor;             ///< how it was placed
  std::string neighbour;                       ///< the part it snapped to or stands on ("" on the floor)
};

/// Where a part with machine box `q.box` lands when dropped along `q.ray`: nullopt when the ray
/// meets neither the floor nor a part. The rules (docs/ide.md):
/// - a loose part (an item) over the top face of the part the ray meets first, when its
///   footprint fits inside that part's: on top of it, turned as it is, on the grid of its frame;
/// - else the point under the pointer (on the top face of the part the ray meets, else on the
///   floor) holds the dropped box's centre, and a part whose box comes within `capture` of that
///   box captures it: the nearest, and of those as near (overlapping), the one of the largest
///   footprint (a belt rather than the photo-eye across it). A box wider than the part by a
///   centimetre on both sides, pointed at on the part, goes across it with its origin on the
///   part's centre line (y = 0 of its frame: a photo-eye's posts, a portal over a belt). Else
///   the side of the part's box nearest the pointer (its ends along x, its sides along y: the
///   one the pointer lies beyond, else the nearest) is touched: at an
///   end the centre lines line up; at a side the drop slides along on the grid, its origin
///   going onto the centre line when that is within `centre_line`, and a part drawn on one side
///   of its origin (a pusher, a diffuse photo-eye) faces the part: at its other side it is
///   turned half round. A snapped part stands at the part's height and is turned as it is;
/// - else the origin goes on the floor, on the grid.
[[nodiscard]] std::optional<DropPlace> placeDrop(const DropQuery& q);

/// True when every shape below `frame` lies in a Body (the part is an item that moves as a
/// whole, not a machine standing on the floor); false when it holds no shape.
[[nodiscard]] bool looseMachine(const scene::Node& frame);

/// The box of the shapes below `frame` in the frame it sets up for them (a Transform's own
/// translation and rotation included), from the last updateTransforms(), templates left out;
/// empty when it holds no shape with a size.
[[nodiscard]] core::Aabb localBox(const scene::Node& frame);

/// The turn about z, in degrees, of a rotation (axis and degrees) about ±z; 0 for another axis.
[[nodiscard]] double angleAboutZ(const std::array<double, 4>& rotation);

/// The pose of a frame at `position` turned `angle` degrees about z.
[[nodiscard]] core::Pose poseAboutZ(const core::Vec3& position, double angle);
/// The box holding `box` turned by `angle` degrees about z (the dropped part's box when the
/// user turns it while dragging).
[[nodiscard]] core::Aabb turnedAboutZ(const core::Aabb& box, double angle);

}  // namespace gdpn::ide
