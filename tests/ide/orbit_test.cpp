// The world view's orbit camera: pure math.

#include <gtest/gtest.h>

#include "gdpn/ide/orbit.h"

namespace gdpn::ide {
namespace {

TEST(OrbitCamera, TakesTheViewOfASceneCamera) {
  render::Camera c;
  c.eye = {-3, -11, 8};
  c.target = {-1.5, 0.5, 0.5};
  c.fov = 50;
  const auto o = OrbitCamera::from(c);
  const auto back = o.camera();
  EXPECT_NEAR(back.eye.x, -3, 1e-9);
  EXPECT_NEAR(back.eye.y, -11, 1e-9);
  EXPECT_NEAR(back.eye.z, 8, 1e-9);
  EXPECT_DOUBLE_EQ(back.fov, 50);
}

TEST(OrbitCamera, OrbitKeepsTheDistanceAndPitchStaysBelowTheZenith) {
  OrbitCamera o;
  const double d = (o.eye() - o.target).length();
  o.orbit(200, 1000);
  EXPECT_NEAR((o.eye() - o.target).length(), d, 1e-9);
  EXPECT_LE(o.pitch, 89.0);
}

TEST(OrbitCamera, ZoomInComesNearer) {
  OrbitCamera o;
  o.zoom(2);
  EXPECT_LT(o.distance, 10.0);
  o.zoom(-4);
  EXPECT_GT(o.distance, 10.0);
}

TEST(OrbitCamera, PanMovesTheTargetSideways) {
  OrbitCamera o;
  o.look(StandardView::Front);  // looking along +y: right is +x
  o.pan(-100, 0, 500);
  EXPECT_GT(o.target.x, 0.0);
  EXPECT_NEAR(o.target.y, 0.0, 1e-9);
}

TEST(OrbitCamera, FrameFillsTheViewWithTheBox) {
  OrbitCamera o;
  core::Aabb box;
  box.add(core::Vec3{1, 1, 1});
  box.add(core::Vec3{3, 3, 3});
  o.frame(box);
  EXPECT_NEAR(o.target.x, 2, 1e-9);
  EXPECT_GT(o.distance, std::sqrt(3.0));
  EXPECT_LT(o.distance, 10.0);
}

TEST(OrbitCamera, TheRayThroughTheCentreHitsTheTarget) {
  OrbitCamera o;
  o.target = {1, 2, 3};
  const auto r = o.ray(320, 240, 640, 480);
  const auto to = (o.target - r.origin).normalized();
  EXPECT_NEAR(r.direction.dot(to), 1.0, 1e-9);
  // a pixel right of the centre looks to the right
  const auto right = o.ray(600, 240, 640, 480);
  EXPECT_LT(right.direction.dot(to), 1.0 - 1e-6);
}

TEST(OrbitCamera, StandardViewsHaveNames) {
  EXPECT_EQ(parseStandardView("top"), StandardView::Top);
  EXPECT_FALSE(parseStandardView("sideways"));
  OrbitCamera o;
  o.look(StandardView::Top);
  EXPECT_GT(o.eye().z, o.target.z + 0.99 * o.distance);
}

}  // namespace
}  // namespace gdpn::ide
