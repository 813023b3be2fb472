#pragma once
/// \file
/// The meshes that primitive shapes are drawn from: one cube, sphere, cylinder, cone and plane
/// each, stretched to each node's size when drawn.

#include <glm/glm.hpp>

#include "gdpn/core/math.h"
#include "gpu_mesh.h"

namespace gdpn::render::detail {

/// A mesh of one size and that size: what primitive shapes are drawn from, stretched to each
/// node's extent.
struct UnitShape {
  GpuMesh gpu;
  core::Vec3 extent;  ///< the mesh's size along x, y, z
  /// `at` scaled so that the mesh takes up `size` (m along x, y, z, as scene::shapeExtent gives it).
  [[nodiscard]] glm::mat4 fit(const glm::mat4& at, core::Vec3 size) const;
};

/// A cube of edge 1.
UnitShape unitCube();
/// A sphere of radius 1.
UnitShape unitSphere();
/// A cylinder (top radius 1) or cone (top radius 0) of radius 1 and height 1 along z.
UnitShape unitRound(bool cone);
/// "Endless" ground facing +z: a 2 km square.
GpuMesh unitPlane();
/// A flat chevron facing +z and pointing +x: 1 long (x) and 1 wide (y), centred on the
/// origin, its two arms 0.45 thick along x (a conveyor's arrow, stretched to its size).
GpuMesh unitChevron();

}  // namespace gdpn::render::detail
