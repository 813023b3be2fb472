#pragma once
/// \file
/// The scene's double-precision math as the GPU's single-precision glm matrices.

#include <array>

#include <glm/glm.hpp>

#include "gdpn/core/math.h"

namespace gdpn::render::detail {

/// `v` in single precision.
inline glm::vec3 gv(core::Vec3 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
/// `v` (x, y, z) in single precision.
inline glm::vec3 gv(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

/// The model matrix of a node placed at `pose` (world frame, m) with `scale` (along its own
/// axes, applied first).
glm::mat4 placement(const core::Pose& pose, core::Vec3 scale);

/// A rotation taking +z to `dir` (any length but zero).
glm::mat4 alongZ(glm::vec3 dir);

}  // namespace gdpn::render::detail
