#pragma once
/// \file
/// The convex hull of a cloud of points, in the form ODE's convex geometry reads. Private to
/// src/physics; it knows nothing of ODE itself.

#include <vector>

namespace gdpn::physics {

/// The convex hull of `points` (x y z each, metres) as ODE's convex geometry wants it:
/// `planes` (a b c d per face: a unit outward normal and its offset in metres), the hull's
/// own points (`out_points`, x y z each, metres) and `polygons` (3 i j k per face, indices
/// into out_points). Incremental: each point outside the hull so far replaces the faces it
/// sees. Appends nothing when the points are flat (fewer than four, or all in one plane).
void convexHull(const std::vector<double>& points, std::vector<double>& planes, std::vector<double>& out_points,
                std::vector<unsigned>& polygons);

}  // namespace gdpn::physics
