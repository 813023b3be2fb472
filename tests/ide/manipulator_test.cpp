// The manipulators' geometry: a drag along an axis, about an axis, snapping, the projection
// that places the handles (the inverse of the pick ray), a box's scale tabs and a spot light's
// aim and cone, each against known answers and degenerate rays.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "gdpn/ide/manipulator.h"
#include "gdpn/ide/orbit.h"

namespace gdpn::ide {
namespace {

TEST(Manipulator, AlongAxisIsTheNearestPointOfTheAxisToTheRay) {
  // a ray straight down at x = 2.5 crosses the x axis through (0, 0, 1) at t = 2.5
  const core::Ray down{{2.5, 0, 10}, {0, 0, -1}};
  EXPECT_NEAR(*alongAxis(down, {0, 0, 1}, {1, 0, 0}), 2.5, 1e-12);
  // a ray that passes 1 m beside the axis: the nearest point still counts
  const core::Ray beside{{-1.5, 1, 10}, {0, 0, -1}};
  EXPECT_NEAR(*alongAxis(beside, {0, 0, 1}, {1, 0, 0}), -1.5, 1e-12);
  // a ray along the axis has no nearest point
  EXPECT_FALSE(alongAxis({{0, 0, 1}, {1, 0, 0}}, {0, 0, 0}, {1, 0, 0}));
}

TEST(Manipulator, AngleAboutIsMeasuredFromTheReferenceRightHanded) {
  // about z from x: the ray hits the ground at (0, 2, 0), 90 degrees round
  const core::Ray down{{0, 2, 5}, {0, 0, -1}};
  EXPECT_NEAR(*angleAbout(down, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}), 90.0, 1e-9);
  const core::Ray behind{{-1, -1, 5}, {0, 0, -1}};
  EXPECT_NEAR(*angleAbout(behind, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}), -135.0, 1e-9);
  EXPECT_FALSE(angleAbout({{0, 0, 1}, {1, 0, 0}}, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}));
}

TEST(Manipulator, SnappingRoundsToWholeStepsWithoutBinaryNoise) {
  EXPECT_EQ(snapTo(0.8712, 0.05), 0.85);
  EXPECT_EQ(snapTo(-0.9896, 0.05), -1.0);
  EXPECT_EQ(snapTo(0.01, 0.05), 0.0);
  EXPECT_FALSE(std::signbit(snapTo(-0.01, 0.05)));
  EXPECT_EQ(snapTo(12.3, 5.0), 10.0);
  EXPECT_EQ(snapTo(0.8712, 0.0), 0.8712);  // off
}

TEST(Manipulator, ATurnComposesWithTheRotationItStartsFrom) {
  // 30 degrees about z, then 60 more about z: 90 about z
  const auto r = turned({0, 0, 1, 30}, {0, 0, 1}, 60);
  EXPECT_NEAR(r[2], 1.0, 1e-12);
  EXPECT_NEAR(r[3], 90.0, 1e-9);
  // from none, 90 about x
  const auto x = turned({0, 0, 1, 0}, {1, 0, 0}, 90);
  EXPECT_NEAR(x[0], 1.0, 1e-12);
  EXPECT_NEAR(x[3], 90.0, 1e-9);
  // turned back to nothing: the field's plain form
  const auto none = turned({1, 0, 0, 45}, {1, 0, 0}, -45);
  EXPECT_EQ(none, (std::array<double, 4>{0, 0, 1, 0}));
}

TEST(Manipulator, AReferenceIsPerpendicularToItsAxis) {
  for (const core::Vec3 axis : {core::Vec3{1, 0, 0}, core::Vec3{0, 1, 0}, core::Vec3{0, 0, 1},
                                core::Vec3{0.6, 0, 0.8}}) {
    const auto r = perpendicular(axis);
    EXPECT_NEAR(r.dot(axis), 0.0, 1e-12);
    EXPECT_NEAR(r.length(), 1.0, 1e-12);
  }
}

TEST(Manipulator, AProjectedPointLiesOnThePickRayOfItsPixel) {
  OrbitCamera view;
  view.target = {1, 2, 0.5};
  view.distance = 7;
  view.yaw = -30;
  view.pitch = 25;
  for (const core::Vec3 p : {core::Vec3{0, 0, 0}, core::Vec3{2, -1, 1.5}, core::Vec3{1, 2, 0.5}}) {
    const auto px = view.project(p, 800, 600);
    ASSERT_TRUE(px);
    const auto ray = view.ray((*px)[0], (*px)[1], 800, 600);
    const auto to = p - ray.origin;
    EXPECT_NEAR((to - ray.direction * to.dot(ray.direction)).length(), 0.0, 1e-9);
  }
  EXPECT_FALSE(view.project(view.eye() - (view.target - view.eye()), 800, 600)) << "behind the eye";
}

TEST(ScaleManipulator, ABoxHasSixFaceTabsAndTwelveEdgeTabsEachNamedByItsSides) {
  std::set<std::string> names;
  int faces = 0, edges = 0;
  for (const auto& tab : scaleTabs()) {
    names.insert(scaleTabName(tab));
    const int axes = (tab[0] != 0) + (tab[1] != 0) + (tab[2] != 0);
    faces += axes == 1;
    edges += axes == 2;
  }
  EXPECT_EQ(names.size(), 18U);
  EXPECT_EQ(faces, 6);
  EXPECT_EQ(edges, 12);
  EXPECT_EQ(scaleTabName({1, 0, 0}), "scale +x");
  EXPECT_EQ(scaleTabName({0, -1, 0}), "scale -y");
  EXPECT_EQ(scaleTabName({1, -1, 0}), "scale +x-y");
  EXPECT_EQ(scaleTabName({-1, 0, 1}), "scale -x+z");
  EXPECT_STREQ(handleName(Handle::Aim), "aim");
  EXPECT_STREQ(handleName(Handle::Cone), "cone");
}

TEST(ScaleManipulator, AFaceTabDraggedByDAlongItsSideGrowsItsAxisByTwiceD) {
  // the box stays centred, so both faces move by d and the dragged one follows the pointer
  const std::array<double, 3> size = {0.4, 0.6, 0.2};
  const core::Vec3 one{1, 1, 1};
  EXPECT_EQ(scaledSize(size, {1, 0, 0}, {0.2, 0.3, 0.1}, one, 0), (std::array<double, 3>{0.8, 0.6, 0.2}))
      << "the move across the tab's axis counts for nothing";
  const auto out = scaledSize(size, {-1, 0, 0}, {-0.1, 0, 0}, one, 0);  // the -x face outward
  EXPECT_NEAR(out[0], 0.6, 1e-12);
  EXPECT_EQ(out[1], 0.6);
  const auto in = scaledSize(size, {0, 0, 1}, {0, 0, -0.05}, one, 0);  // the +z face inward
  EXPECT_NEAR(in[2], 0.1, 1e-12);
  EXPECT_EQ(scaledSize(size, {0, 1, 0}, {0, 0, 0}, one, 0), size) << "no move, no change";
}

TEST(ScaleManipulator, AnEdgeTabScalesItsTwoAxes) {
  const auto out = scaledSize({0.4, 0.6, 0.2}, {1, -1, 0}, {0.1, -0.15, 0.4}, {1, 1, 1}, 0);
  EXPECT_NEAR(out[0], 0.6, 1e-12);
  EXPECT_NEAR(out[1], 0.9, 1e-12);
  EXPECT_EQ(out[2], 0.2);
}

TEST(ScaleManipulator, SnappingChangesTheSizeInWholeStepsAndLeavesAtLeastOne) {
  const std::array<double, 3> size = {0.4, 0.6, 0.2};
  const core::Vec3 one{1, 1, 1};
  // 2 x 0.071 = 0.142: three steps of 0.05
  EXPECT_EQ(scaledSize(size, {1, 0, 0}, {0.071, 0, 0}, one, 0.05)[0], 0.55);
  EXPECT_EQ(scaledSize(size, {1, 1, 0}, {0.071, 0.1, 0}, one, 0.05), (std::array<double, 3>{0.55, 0.8, 0.2}));
  EXPECT_EQ(scaledSize(size, {1, 0, 0}, {0.01, 0, 0}, one, 0.05)[0], 0.4) << "less than half a step";
  // dragged through the box: one step is left; without snapping 1 mm
  EXPECT_EQ(scaledSize(size, {1, 0, 0}, {-1, 0, 0}, one, 0.05)[0], 0.05);
  EXPECT_EQ(scaledSize(size, {1, 0, 0}, {-1, 0, 0}, one, 0)[0], 0.001);
  // a box already thinner than a step is not grown by a press
  EXPECT_EQ(scaledSize({0.02, 1, 1}, {1, 0, 0}, {0, 0, 0}, one, 0.05)[0], 0.02);
}

TEST(ScaleManipulator, TheScaleAboveTheBoxIsTakenOut) {
  // under a scale of 2 along x a world move of 0.2 m is 0.1 m of the box's own size a face
  EXPECT_NEAR(scaledSize({0.4, 0.6, 0.2}, {1, 0, 0}, {0.2, 0, 0}, {2, 1, 1}, 0)[0], 0.6, 1e-12);
}

/// The names of the tabs a box turned by `rotation` offers a view looking along `forward`.
std::set<std::string> shownTabs(const core::Quat& rotation, const core::Vec3& forward) {
  std::set<std::string> out;
  for (const auto& tab : scaleTabs()) {
    if (scaleTabShown(tab, rotation, forward.normalized())) out.insert(scaleTabName(tab));
  }
  return out;
}

TEST(ScaleManipulator, SeenFromAboveABoxOffersTheTabsOfARectangle) {
  const std::set<std::string> rectangle = {"scale +x",   "scale -x",   "scale +y",   "scale -y",
                                           "scale +x+y", "scale +x-y", "scale -x+y", "scale -x-y"};
  EXPECT_EQ(shownTabs({}, {0, 0, -1}), rectangle);
  // the IDE's top view is tilted by a degree: the same
  EXPECT_EQ(shownTabs({}, {0, std::cos(89 * std::numbers::pi / 180), -std::sin(89 * std::numbers::pi / 180)}), rectangle);
  // turned a quarter about z, its own x and y still make the rectangle
  EXPECT_EQ(shownTabs(core::Quat::axisAngle({0, 0, 1}, std::numbers::pi / 2), {0, 0, -1}), rectangle);
  // from the front (looking along +y) the rectangle of x and z
  EXPECT_EQ(shownTabs({}, {0, 1, 0}), (std::set<std::string>{"scale +x", "scale -x", "scale +z", "scale -z",
                                                             "scale +x+z", "scale +x-z", "scale -x+z", "scale -x-z"}));
}

TEST(ScaleManipulator, SeenAslantABoxOffersTheTabsOfItsThreeNearFacesAndTheirEdges) {
  // from (+, +, +): the faces +x, +y, +z and the nine edges one of them touches
  const auto shown = shownTabs({}, {-1, -1, -1});
  EXPECT_EQ(shown.size(), 12U);
  for (const char* name : {"scale +x", "scale +y", "scale +z", "scale +x+y", "scale +x-y", "scale -x+y"}) {
    EXPECT_TRUE(shown.count(name)) << name;
  }
  for (const char* name : {"scale -x", "scale -y", "scale -z", "scale -x-y", "scale -y-z", "scale -x-z"}) {
    EXPECT_FALSE(shown.count(name)) << name;
  }
}

TEST(ScaleManipulator, APlaneIsMetWhereTheRayCrossesItNeverBehindNorAlongIt) {
  const auto hit = onPlane({{1, 2, 5}, {0, 0, -1}}, {0, 0, 1}, {0, 0, 1});
  ASSERT_TRUE(hit);
  EXPECT_EQ(*hit, (core::Vec3{1, 2, 1}));
  EXPECT_FALSE(onPlane({{1, 2, 5}, {1, 0, 0}}, {0, 0, 1}, {0, 0, 1})) << "along the plane";
  EXPECT_FALSE(onPlane({{1, 2, 5}, {0, 0, 1}}, {0, 0, 1}, {0, 0, 1})) << "behind the ray";
}

TEST(SpotManipulator, TheLightPointsTowardThePointerOnTheHandlesPlane) {
  // a spot at (0, 0, 2); the view looks along +y; the aim handle's plane is y = 0
  const core::Vec3 apex{0, 0, 2}, plane{0, 0, 1}, facing{0, 1, 0};
  const auto d = aimAt({{1, -10, 1}, {0, 1, 0}}, apex, plane, facing);
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(d->y, 0.0, 1e-12);
  EXPECT_NEAR(d->z, -std::sqrt(0.5), 1e-12);
  const auto right = aimAt({{3, -10, 2}, {0, 1, 0}}, apex, plane, facing);
  ASSERT_TRUE(right);
  EXPECT_EQ(*right, (core::Vec3{1, 0, 0}));
  // degenerate: a ray along the plane; the pointer on the light itself
  EXPECT_FALSE(aimAt({{1, 0, 1}, {1, 0, 0}}, apex, plane, facing));
  EXPECT_FALSE(aimAt({{0, -10, 2}, {0, 1, 0}}, apex, plane, facing));
}

TEST(SpotManipulator, TheLightPointsTowardAPointOfAShapeUnderThePointer) {
  // from (0, 0, 2) toward (3, 4, 2): along (0.6, 0.8, 0); toward (0, 0, 0): straight down
  const auto d = aimToward({0, 0, 2}, {3, 4, 2});
  ASSERT_TRUE(d);
  EXPECT_NEAR((*d - core::Vec3{0.6, 0.8, 0}).length(), 0.0, 1e-15);
  EXPECT_EQ(*aimToward({0, 0, 2}, {0, 0, 0}), (core::Vec3{0, 0, -1}));
  EXPECT_FALSE(aimToward({0, 0, 2}, {0, 0, 2})) << "the light itself has no direction";
}

TEST(SpotManipulator, ASnappedDirectionHasWholeStepsOfHeadingAndElevation) {
  // heading 1.1 degrees, elevation -44.6: snapped to 0 and -45
  const auto d = snapDirection({1, 0.02, -1}, 5);
  EXPECT_NEAR(d.x, std::sqrt(0.5), 1e-12);
  EXPECT_EQ(d.y, 0.0);
  EXPECT_NEAR(d.z, -std::sqrt(0.5), 1e-12);
  // heading 30, elevation 0
  const auto h = snapDirection({std::cos(0.53), std::sin(0.53), 0.01}, 5);
  EXPECT_NEAR(h.x, std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(h.y, 0.5, 1e-12);
  EXPECT_EQ(h.z, 0.0);
  EXPECT_EQ(snapDirection({0, 0, -3}, 5), (core::Vec3{0, 0, -1})) << "straight down stays so";
  const auto free = snapDirection({1, 0.02, -1}, 0);
  EXPECT_NEAR(free.length(), 1.0, 1e-12);
  EXPECT_NEAR(free.y / free.x, 0.02, 1e-12) << "not snapped, only made unit";
}

TEST(SpotManipulator, TheConesHandleSitsOnItsOutlineAsSeen) {
  // looking along +y at a spot pointing down: its outline is to the sides, along x
  const auto side = coneSide({0, 0, -1}, {0, 1, 0});
  EXPECT_NEAR(std::abs(side.x), 1.0, 1e-12);
  for (const core::Vec3 axis : {core::Vec3{0, 0, -1}, core::Vec3{0.6, 0, -0.8}}) {
    const auto s = coneSide(axis, core::Vec3{1, 1, -1}.normalized());
    EXPECT_NEAR(s.dot(axis), 0.0, 1e-12);
    EXPECT_NEAR(s.length(), 1.0, 1e-12);
  }
  // looking along the beam: any side across it
  const auto along = coneSide({0, 0, -1}, {0, 0, -1});
  EXPECT_NEAR(along.dot({0, 0, -1}), 0.0, 1e-12);
  EXPECT_NEAR(along.length(), 1.0, 1e-12);
}

TEST(SpotManipulator, TheConeAngleIsThatOfThePointerFromTheAxis) {
  // a spot at (0, 0, 2) pointing down, its handle on the side +x: the plane y = 0
  const core::Vec3 apex{0, 0, 2}, axis{0, 0, -1}, side{1, 0, 0};
  EXPECT_NEAR(*coneAngle({{1, -10, 1}, {0, 1, 0}}, apex, axis, side), 45.0, 1e-9);
  EXPECT_NEAR(*coneAngle({{-1, -10, 2 - std::sqrt(3.0)}, {0, 1, 0}}, apex, axis, side), 30.0, 1e-9)
      << "across the axis counts the same";
  EXPECT_NEAR(*coneAngle({{1, -10, 3}, {0, 1, 0}}, apex, axis, side), 135.0, 1e-9) << "behind the light";
  EXPECT_NEAR(*coneAngle({{0, -10, 0}, {0, 1, 0}}, apex, axis, side), 0.0, 1e-9) << "on the axis";
  // degenerate: a ray in the plane; the pointer on the light
  EXPECT_FALSE(coneAngle({{-5, 0, 1}, {1, 0, 0}}, apex, axis, side));
  EXPECT_FALSE(coneAngle({{0, -10, 2}, {0, 1, 0}}, apex, axis, side));
}

}  // namespace
}  // namespace gdpn::ide
