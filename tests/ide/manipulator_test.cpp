// The manipulators' geometry: a drag along an axis, about an axis, snapping, and the
// projection that places the handles (the inverse of the pick ray).

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace gdpn::ide
