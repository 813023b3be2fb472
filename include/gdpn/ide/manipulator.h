#pragma once
/// \file
/// The manipulators' geometry (dissertation section 2.4): where a drag along an axis, about an
/// axis, or of a joint's limit puts the value it edits. Pure math, no ImGui: the world view
/// draws the handles and turns a drag into field edits with these.

#include <array>
#include <cstdint>
#include <optional>

#include "gdpn/core/math.h"

namespace gdpn::ide {

/// A handle of a manipulator.
enum class Handle : std::uint8_t {
  None,
  MoveX, MoveY, MoveZ,  ///< a Transform's translation, along an axis
  TurnX, TurnY, TurnZ,  ///< a Transform's rotation, about an axis
  Lo1, Hi1,             ///< a Joint's limits on its first axis
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

}  // namespace gdpn::ide
