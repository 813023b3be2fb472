#pragma once
/// \file
/// The manipulators' geometry (dissertation section 2.4, its Figure 2.2): where a drag along an
/// axis, about an axis, of a joint's limit, of a box's scale tab or of a spot light's aim and
/// cone puts the value it edits. Pure math, no ImGui: the world view draws the handles and
/// turns a drag into field edits with these.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "gdpn/core/math.h"

namespace gdpn::ide {

/// A handle of a manipulator.
enum class Handle : std::uint8_t {
  None,
  MoveX, MoveY, MoveZ,  ///< a Transform's translation, along an axis
  TurnX, TurnY, TurnZ,  ///< a Transform's rotation, about an axis
  Lo1, Hi1,             ///< a Joint's limits on its first axis
  Scale,                ///< a tab of a box's scale manipulator (which one: a ScaleTab)
  Aim,                  ///< a spot light's direction
  Cone,                 ///< a spot light's cone (its cutoff half-angle)
};

/// "move x", "turn z", "lo1", ... ("" for None).
const char* handleName(Handle handle);

/// The parameter t (m along unit `axis`) of the point `origin + axis * t` nearest to `ray`;
/// nullopt when the ray runs along the axis.
std::optional<double> alongAxis(const core::Ray& ray, const core::Vec3& origin, const core::Vec3& axis);

/// The angle (degrees in (-180, 180]) about unit `axis`, from `reference` (a unit vector
/// perpendicular to it), of the point where `ray` meets the plane through `origin` normal to
/// `axis`; nullopt when the ray runs along that plane.
std::optional<double> angleAbout(const core::Ray& ray, const core::Vec3& origin, const core::Vec3& axis,
                                 const core::Vec3& reference);

/// `value` rounded to a whole number of `step`s; unchanged when `step` <= 0.
double snapTo(double value, double step);

/// A unit vector perpendicular to unit `axis`: where angles about it are measured from.
core::Vec3 perpendicular(const core::Vec3& axis);

/// A rotation field (axis x, y, z and an angle in degrees) turned further by `degrees` about
/// unit `axis` of the frame the rotation is given in (the node's parent).
std::array<double, 4> turned(const std::array<double, 4>& rotation, const core::Vec3& axis, double degrees);

/// The faces a scale tab sits on: -1, 0 or +1 along the box's own x, y and z. One axis not 0:
/// the tab in the middle of a face, which scales that axis; two: the middle of the edge where
/// two faces meet (a corner of the box's outline seen across the third axis), which scales both.
using ScaleTab = std::array<int, 3>;

/// The eighteen tabs of a box: six faces, then twelve edges.
const std::array<ScaleTab, 18>& scaleTabs();

/// "scale +x", "scale -y", "scale +x-y", ...: a tab's name in the report.
std::string scaleTabName(const ScaleTab& tab);

/// Whether `tab` of a box turned by `rotation` (its frame in the world) is offered to a view
/// looking along unit `forward` (world): not when all its faces look away from the view, nor
/// when its drag would run nearly along the line of sight (a face tab whose axis points at the
/// eye, an edge tab whose plane is seen edge on). Seen from straight above, a box offers the
/// eight tabs of a rectangle: four scale one axis, its corners two.
bool scaleTabShown(const ScaleTab& tab, const core::Quat& rotation, const core::Vec3& forward);

/// Where `ray` meets the plane through `point` normal to unit `normal` (world, m); nullopt when
/// it runs along the plane or meets it behind its origin.
std::optional<core::Vec3> onPlane(const core::Ray& ray, const core::Vec3& point, const core::Vec3& normal);

/// The edge lengths (m, along the box's x, y, z, before the scale above it) of a box of
/// `size` centred on its origin, after its `tab` was dragged by `moved` (world metres,
/// expressed along the box's own axes) under the scale `scale` of its parents. The box stays
/// centred, so the dragged faces follow the pointer: an axis the tab scales grows by twice the
/// move along the tab's side (a +x tab moved by d along +x: size x + 2 d; a -x tab moved
/// along -x grows it too); the other axes keep their size. With `step` > 0 (m) each changed
/// length is a whole number of steps and at least one step; without, at least 1 mm.
std::array<double, 3> scaledSize(const std::array<double, 3>& size, const ScaleTab& tab, const core::Vec3& moved,
                                 const core::Vec3& scale, double step);

/// The unit direction from `apex` (a spot light, world, m) toward the point where `ray` meets
/// the plane through `point` normal to unit `normal` (the aim handle's plane, facing the view);
/// nullopt when the ray runs along that plane, meets it behind its origin, or there at `apex`.
std::optional<core::Vec3> aimAt(const core::Ray& ray, const core::Vec3& apex, const core::Vec3& point,
                                const core::Vec3& normal);

/// The unit direction from `apex` (a spot light, world, m) toward `target` (world, m: what is
/// under the pointer); nullopt when the two are one point.
std::optional<core::Vec3> aimToward(const core::Vec3& apex, const core::Vec3& target);

/// Unit `direction` with its heading (about z, from x) and its elevation (from the xy plane)
/// each rounded to a whole number of `step` degrees; normalised only when `step` <= 0.
core::Vec3 snapDirection(const core::Vec3& direction, double step);

/// The unit vector perpendicular to unit `axis` (a spot light's) and to the view's unit
/// `forward`: the side of the cone seen as its outline, where the cone's handle sits;
/// perpendicular(axis) when the view looks along the axis.
core::Vec3 coneSide(const core::Vec3& axis, const core::Vec3& forward);

/// The angle (degrees in [0, 180]) from unit `axis` of the point where `ray` meets the plane
/// through `apex` spanned by `axis` and unit `side` (the cone's half-angle there; the side
/// across the axis counts the same); nullopt when the ray runs along that plane or meets it
/// behind its origin or at the apex.
std::optional<double> coneAngle(const core::Ray& ray, const core::Vec3& apex, const core::Vec3& axis,
                                const core::Vec3& side);

}  // namespace gdpn::ide
