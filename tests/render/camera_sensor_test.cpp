// Camera sensors rendered offscreen during a run: a depth camera reads the distance to a
// wall, a colour camera sees a red cube where it projects, a picture is rendered only once a
// sample and only when read.

#include <gtest/gtest.h>

#include <cmath>

#include "../sensors/rig.h"
#include "gdpn/capture/sensor_imager.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/render/renderer.h"
#include "gdpn/scene/actions.h"

namespace gdpn::sensors {
namespace {

TEST(CameraSensor, ADepthCameraReadsTheDistanceToAWallTwoMetresAway) {
  // the wall's near face lies at x = 2, square to the camera's axis: every pixel reads 2 m
  Rig rig(R"(
  - Transform: {translation: [2.5, 0, 0], children: [{Cube: {size: [1, 20, 20]}}]}
  - DepthCamera: {name: eye, width: 64, height: 48, fov: 60, near: 0.05, far: 100}
)");
  auto imager = std::make_shared<capture::SensorImager>(".");
  rig.hub->setImager(imager);
  rig.hub->update(0);
  std::string why;
  const auto picture = rig.hub->image(rig.handle("eye"), why);
  ASSERT_TRUE(picture) << why;
  ASSERT_EQ(picture->width, 64);
  ASSERT_EQ(picture->height, 48);
  ASSERT_EQ(picture->depth.size(), 64u * 48u);
  EXPECT_NEAR(picture->depth[24 * 64 + 32], 2.0, 1e-3);
  for (float d : picture->depth) ASSERT_NEAR(d, 2.0, 1e-3);
}

TEST(CameraSensor, ADepthCameraReadsItsFarWhereNothingIs) {
  Rig rig("  - DepthCamera: {name: eye, width: 8, height: 6, far: 30}\n");
  rig.hub->setImager(std::make_shared<capture::SensorImager>("."));
  rig.hub->update(0);
  std::string why;
  const auto picture = rig.hub->image(rig.handle("eye"), why);
  ASSERT_TRUE(picture) << why;
  for (float d : picture->depth) EXPECT_FLOAT_EQ(d, 30.0f);
}

TEST(CameraSensor, AColourCameraSeesARedCubeAsRedPixelsWhereItProjects) {
  // a 0.5 m cube 3 m ahead (near face at 2.75 m): 64 px over 60 degrees puts its edges 5 px
  // from the centre
  Rig rig(R"(
  - Light: {kind: directional, direction: [1, 0.2, -0.3]}
  - Transform:
      translation: [3, 0, 0]
      children: [{Material: {diffuse: [0.9, 0.05, 0.05]}}, {Cube: {size: [0.5, 0.5, 0.5]}}]
  - ColorCamera: {name: eye, width: 64, height: 48, fov: 60}
)");
  auto imager = std::make_shared<capture::SensorImager>(".");
  rig.hub->setImager(imager);
  rig.hub->update(0);
  std::string why;
  const auto picture = rig.hub->image(rig.handle("eye"), why);
  ASSERT_TRUE(picture) << why;
  ASSERT_EQ(picture->rgb.size(), 64u * 48u * 3u);
  auto at = [&](int x, int y) {
    const auto i = static_cast<std::size_t>((y * 64 + x) * 3);
    return std::array<int, 3>{picture->rgb[i], picture->rgb[i + 1], picture->rgb[i + 2]};
  };
  auto red = [](std::array<int, 3> c) { return c[0] > 60 && c[0] > 3 * c[1] && c[0] > 3 * c[2]; };
  int inside = 0, outside = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      const double dx = std::abs(x + 0.5 - 32), dy = std::abs(y + 0.5 - 24);
      if (dx < 4 && dy < 4) inside += red(at(x, y)) ? 0 : 1;     // every pixel well inside: red
      if (dx > 6.5 || dy > 6.5) outside += red(at(x, y)) ? 1 : 0;  // every pixel well outside: not
    }
  }
  EXPECT_EQ(inside, 0);
  EXPECT_EQ(outside, 0);
  // read again in the same sample: the same picture, not rendered again
  EXPECT_EQ(rig.hub->image(rig.handle("eye"), why), picture);
  EXPECT_EQ(imager->pictures(), 1u);
}

TEST(CameraSensor, APictureIsRenderedOnlyWhenReadAndOncePerSample) {
  Rig rig("  - ColorCamera: {name: eye, width: 16, height: 12, rate: 10}\n");
  auto imager = std::make_shared<capture::SensorImager>(".");
  rig.hub->setImager(imager);
  std::string why;
  for (int i = 0; i <= 100; ++i) rig.hub->update(i * 0.01);  // 11 samples, none read
  EXPECT_EQ(imager->pictures(), 0u);
  for (int i = 101; i <= 200; ++i) {
    rig.hub->update(i * 0.01);
    ASSERT_TRUE(rig.hub->image(rig.handle("eye"), why)) << why;  // read every step
  }
  EXPECT_EQ(imager->pictures(), 11u);  // one per sample: 1.0 (first read at 1.01 s) to 2.0 s
}

TEST(CameraSensor, TheCallersContextIsCurrentAgainAfterAPicture) {
  // `gdpn render` and `gdpn record` draw in a context of their own while the run they film
  // renders camera pictures in the imager's: a picture must not take the caller's away
  std::string why;
  auto caller = platform::createHeadlessContext(why);
  ASSERT_TRUE(caller) << why;
  platform::Target target(8, 8, 1);
  render::Renderer renderer(".");
  render::DrawOptions o;
  o.width = o.height = 8;
  o.sky = o.grid = o.shadows = false;
  Rig rig("  - ColorCamera: {name: eye, width: 8, height: 6}\n");
  rig.hub->setImager(std::make_shared<capture::SensorImager>("."));
  rig.hub->update(0);
  ASSERT_TRUE(rig.hub->image(rig.handle("eye"), why)) << why;
  target.bind();
  renderer.draw(*rig.scene, render::Camera{}, o);
  const auto rgb = target.readRgb();
  EXPECT_EQ(rgb[0], 158);  // the background, 0.62 0.70 0.80
  EXPECT_EQ(rgb[1], 178);
  EXPECT_EQ(rgb[2], 204);
}

TEST(CameraSensor, AContextDrawsOnAfterAnotherOnItsDisplayIsGone) {
  // the imager's context and a picture's share EGL's one surfaceless display: whichever
  // goes first must leave the display to the other
  std::string why;
  auto first = platform::createHeadlessContext(why);
  ASSERT_TRUE(first) << why;
  Rig rig("  - ColorCamera: {name: eye, width: 8, height: 6}\n");
  auto imager = std::make_shared<capture::SensorImager>(".");
  rig.hub->setImager(imager);
  rig.hub->update(0);
  const auto before = rig.hub->image(rig.handle("eye"), why);  // the imager's context is made
  ASSERT_TRUE(before) << why;
  const std::vector<std::uint8_t> sky = before->rgb;
  ASSERT_NE(sky[0] + sky[1] + sky[2], 0);
  first.reset();
  rig.hub->update(1);
  const auto after = rig.hub->image(rig.handle("eye"), why);
  ASSERT_TRUE(after) << why;
  EXPECT_EQ(after->rgb, sky);  // the same empty sky, not black
  EXPECT_EQ(imager->pictures(), 2u);
}

TEST(CameraSensor, AMeshThatCannotBeDrawnFailsOnlyThePicturesThatDrawIt) {
  // a Mesh whose file is not there (no physics read it first): the picture with it fails,
  // saying where the file is named and which node; a picture without it, later, is drawn
  core::Diagnostics diags;
  auto model = model::parseModel(R"(gdpn: 1
scene:
  - Transform: {translation: [2.5, 0, 0], children: [{Cube: {size: [1, 20, 20]}}]}
  - Mesh: {name: broken, file: nowhere.obj}
  - DepthCamera: {name: eye, width: 16, height: 12}
)", "broken.gdpn.yaml", diags);
  ASSERT_TRUE(model) << diags.str();
  auto scene = model->scene->clone();
  scene::updateTransforms(scene->root());
  capture::SensorImager imager(".");
  Image picture;
  std::string why;
  EXPECT_FALSE(imager.render(*scene, *scene->find("eye"), picture, why));
  EXPECT_NE(why.find("broken.gdpn.yaml:4:"), std::string::npos) << why;
  EXPECT_NE(why.find("'broken'"), std::string::npos) << why;
  EXPECT_NE(why.find("nowhere.obj"), std::string::npos) << why;
  // the mesh deleted: the same camera's next picture is drawn, and so is another scene's
  scene->destroy(*scene->find("broken"));
  why.clear();
  ASSERT_TRUE(imager.render(*scene, *scene->find("eye"), picture, why)) << why;
  for (float d : picture.depth) ASSERT_NEAR(d, 2.0, 1e-3);
  Rig rig("  - ColorCamera: {name: eye, width: 8, height: 6}\n");
  ASSERT_TRUE(imager.render(*rig.scene, *rig.scene->find("eye"), picture, why)) << why;
  EXPECT_EQ(imager.pictures(), 2u);
}

TEST(CameraSensor, WithoutAnImagerReadingAPictureSaysWhy) {
  Rig rig("  - ColorCamera: {name: eye}\n");
  rig.hub->update(0);
  std::string why;
  EXPECT_FALSE(rig.hub->image(rig.handle("eye"), why));
  EXPECT_NE(why.find("renders no camera pictures"), std::string::npos);
}

}  // namespace
}  // namespace gdpn::sensors
