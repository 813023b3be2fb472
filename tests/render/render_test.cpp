// Headless rendering (EGL surfaceless, Mesa's llvmpipe): golden images compared with a
// tolerance, what each picture must show whatever the golden says, terrain level of detail,
// and a movie through ffmpeg. GDPN_UPDATE_GOLDEN=1 rewrites the golden pictures.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "gdpn/capture/capture.h"
#include "gdpn/model/model.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/platform/png.h"
#include "gdpn/platform/target.h"
#include "gdpn/render/renderer.h"
#include "support/golden.h"

namespace gdpn::render {
namespace {

using capture::CaptureOptions;
using capture::parseSize;
using capture::record;
using capture::RecordResult;
using capture::renderAt;
using platform::createHeadlessContext;
using platform::readPng;
using platform::Target;
using platform::writePng;

namespace fs = std::filesystem;
const fs::path kData = fs::path(GDPN_SOURCE_DIR) / "tests" / "data";

std::unique_ptr<model::Simulation> open(const std::string& name) {
  core::Diagnostics diags;
  auto m = model::loadModel((kData / "render" / (name + ".gdpn.yaml")).string(), diags);
  std::unique_ptr<model::Simulation> sim;
  if (m) sim = model::Simulation::create(*m, diags);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::array<int, 3> at(int x, int y) const {
    const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

/// Renders model `name` at t = 0, 320 x 240, and compares it with its golden picture.
Picture renderAndCompare(const std::string& name) {
  auto sim = open(name);
  if (!sim) return {};
  CaptureOptions o;
  o.width = 320;
  o.height = 240;
  const auto out = (fs::temp_directory_path() / ("gdpn_render_" + name + ".png")).string();
  std::string error;
  EXPECT_TRUE(renderAt(*sim, 0.0, o, out, error)) << error;
  Picture p;
  EXPECT_TRUE(readPng(out, p.width, p.height, p.rgb, error)) << error;
  fs::remove(out);
  gdpn::testing::expectLikeGolden(p.width, p.height, p.rgb, (kData / "golden" / (name + ".png")).string());
  return p;
}

int brightness(std::array<int, 3> c) { return c[0] + c[1] + c[2]; }

TEST(Render, ACubeLitFromOneSide) {
  const Picture p = renderAndCompare("cube_lit");
  ASSERT_EQ(p.width, 320);
  // the cube is turned 45 degrees: the face towards +x (right in the picture) takes the
  // light, the face towards -x stays dark but not black (ambient), the corner is at x = 160
  const auto lit = p.at(200, 130), unlit = p.at(120, 130);
  EXPECT_GT(brightness(lit), brightness(unlit) + 150);
  EXPECT_GT(brightness(unlit), 0);
  EXPECT_EQ(lit[0], lit[1]);  // a grey material under a white light
}

TEST(Render, ATransparentSphereInFrontOfABox) {
  const Picture p = renderAndCompare("transparent");
  ASSERT_EQ(p.width, 320);
  // through the sphere's middle, both the blue sphere and the red box behind it show
  const auto mid = p.at(160, 120);
  EXPECT_GT(mid[0], 60);
  EXPECT_GT(mid[2], 60);
  // beside the sphere, only the box: red
  const auto box = p.at(160 + 70, 120);
  EXPECT_GT(box[0], 2 * box[2]);
}

TEST(Render, FogHidesTheFarCubeMoreThanTheNearOne) {
  const Picture p = renderAndCompare("fog");
  ASSERT_EQ(p.width, 320);
  const std::array<int, 3> fog = {230, 230, 242};
  auto distance = [&](std::array<int, 3> c) {
    return std::abs(c[0] - fog[0]) + std::abs(c[1] - fog[1]) + std::abs(c[2] - fog[2]);
  };
  const auto near = p.at(95, 120), far = p.at(185, 110);
  EXPECT_LT(distance(far), distance(near) / 2) << far[0] << " " << near[0];
  EXPECT_LT(distance(p.at(5, 5)), 6);  // the background is the fog's colour
}

TEST(Render, ATerrain) {
  const Picture p = renderAndCompare("terrain");
  ASSERT_EQ(p.width, 320);
  const auto ground = p.at(160, 150);
  EXPECT_GT(ground[1], ground[2]);  // green hills
}

TEST(Render, TerrainLevelOfDetailDropsTrianglesWithDistance) {
  auto sim = open("terrain");
  ASSERT_TRUE(sim);
  std::string why;
  auto context = createHeadlessContext(why);
  ASSERT_TRUE(context) << why;
  Target target(320, 240, 1);
  Renderer renderer((kData / "render").string());
  DrawOptions o;
  o.width = 320;
  o.height = 240;
  Camera near;
  near.eye = {0, -120, 40};
  Camera far = near;
  far.eye = {0, -1200, 400};
  far.far = 5000;
  const auto full = 2u * 128u * 128u;  // every cell, two triangles
  const auto n = renderer.draw(*sim->plant(), near, o).triangles;
  const auto f = renderer.draw(*sim->plant(), far, o).triangles;
  EXPECT_GT(n, 0u);
  EXPECT_LT(f, n / 4) << "far " << f << ", near " << n;
  EXPECT_LT(f, full / 8);
  // looking away, nothing of it is drawn
  Camera away = near;
  away.target = {0, -1000, 40};
  EXPECT_EQ(renderer.draw(*sim->plant(), away, o).triangles, 0u);
  EXPECT_TRUE(renderer.problems().empty());
}

/// A model given as text, with a headless context, a `width` x `height` target and a renderer
/// to draw it on: the set-up of the tests that call the renderer directly.
struct DirectDraw {
  std::unique_ptr<model::Simulation> sim;
  std::unique_ptr<platform::GlContext> context;
  std::unique_ptr<Target> target;
  std::unique_ptr<Renderer> renderer;
  DrawOptions options;
  Camera camera;

  DirectDraw(const std::string& yaml, const std::string& name, int width, int height) {
    core::Diagnostics diags;
    auto m = model::parseModel(yaml, name, diags);
    EXPECT_TRUE(m) << diags.str();
    if (m) sim = model::Simulation::create(*m, diags);
    EXPECT_TRUE(sim) << diags.str();
    std::string why;
    context = createHeadlessContext(why);
    EXPECT_TRUE(context) << why;
    if (!sim || !context) return;
    target = std::make_unique<Target>(width, height, 1);
    renderer = std::make_unique<Renderer>(".");
    options.width = width;
    options.height = height;
    camera = chooseCamera(*sim->plant(), "", 0, why);
  }
  [[nodiscard]] bool ready() const { return renderer != nullptr; }
  DrawStats draw() { return renderer->draw(*sim->plant(), camera, options); }
};

TEST(Render, SensorsJointsAndTheSelectionAreDrawnOnlyWhenAsked) {
  DirectDraw d(R"(gdpn: 1
scene:
  - Camera: {position: [0, -4, 0], target: [0, 0, 0]}
  - Region: {name: r, shape: box, size: [1, 1, 1]}
  - Joint:
      kind: hinge
      children: [{Body: {name: b, children: [{Sphere: {radius: 0.2}}]}}]
)", "overlay.gdpn.yaml", 160, 120);
  ASSERT_TRUE(d.ready());
  auto& sim = d.sim;
  auto& renderer = *d.renderer;
  auto& o = d.options;
  const Camera cam = d.camera;
  const auto plain = renderer.draw(*sim->plant(), cam, o);
  o.sensors = true;
  const auto sensors = renderer.draw(*sim->plant(), cam, o);
  o.joints = true;
  const auto joints = renderer.draw(*sim->plant(), cam, o);
  o.selection = {sim->plant()->find("#2/b")->handle()};
  const auto selected = renderer.draw(*sim->plant(), cam, o);
  EXPECT_EQ(sensors.triangles, plain.triangles + 2 * 12);  // the region's box: far side, then near side
  EXPECT_GT(joints.triangles, sensors.triangles);      // an axis and an anchor
  EXPECT_GT(selected.draw_calls, joints.draw_calls);   // the sphere outlined again
  // the renderer reads the scene and changes nothing
  auto copy = sim->plant()->clone();
  renderer.draw(*sim->plant(), cam, o);
  EXPECT_TRUE(copy->sameAs(*sim->plant()));
}

TEST(Render, ACameraSensorShowsItsViewAndALaserScanItsFanWhenSensorsAreDrawn) {
  // with sensors drawn, a RangeFinder is one ray; a camera sensor its axis and the four edges
  // of its picture; a 360-ray LaserScan 36 of its rays, one in ten
  const auto added = [](const std::string& sensor) {
    DirectDraw d("gdpn: 1\nscene:\n  - Camera: {position: [0, -4, 2], target: [0, 0, 0]}\n  - " + sensor + "\n",
                 "sensors.gdpn.yaml", 160, 120);
    EXPECT_TRUE(d.ready());
    if (!d.ready()) return std::size_t{0};
    const auto plain = d.renderer->draw(*d.sim->plant(), d.camera, d.options);
    d.options.sensors = true;
    const auto drawn = d.renderer->draw(*d.sim->plant(), d.camera, d.options);
    return drawn.triangles - plain.triangles;
  };
  const std::size_t ray = added("RangeFinder: {length: 2}");
  ASSERT_GT(ray, 0u);
  EXPECT_EQ(added("ColorCamera: {width: 64, height: 48}"), 5 * ray);
  EXPECT_EQ(added("DepthCamera: {}"), 5 * ray);
  EXPECT_EQ(added("LaserScan: {count: 360}"), 36 * ray);
  EXPECT_EQ(added("LaserScan: {count: 7, min_angle: -30, max_angle: 30}"), 7 * ray);
}

TEST(Render, APictureFromADepthCameraIsItsDepthInGreyNearWhiteFarBlack) {
  // a DepthCamera with near 0.5 m and far 10.5 m looks along +x at a wall whose face is 3 m
  // away, with a box whose face is 1.5 m away in the middle: grey 255 (1 - (d - near) / (far -
  // near)), 191 for the wall, 230 for the box; nothing of the colour view (the sky, the box's
  // red, the light)
  core::Diagnostics diags;
  auto m = model::parseModel(R"(gdpn: 1
scene:
  - Light: {kind: directional, direction: [1, 0.2, -0.3]}
  - Material: {diffuse: [0.9, 0.05, 0.05]}
  - Transform: {translation: [3.5, 0, 0], children: [{Cube: {size: [1, 40, 40]}}]}
  - Transform: {translation: [2, 0, 0], children: [{Cube: {size: [1, 0.6, 0.6]}}]}
  - DepthCamera: {name: eye, width: 64, height: 48, fov: 60, near: 0.5, far: 10.5}
)", (kData / "depth_camera.gdpn.yaml").string(), diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = model::Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  CaptureOptions o;
  o.camera = "eye";
  o.width = 64;
  o.height = 48;
  const auto out = (fs::temp_directory_path() / "gdpn_render_depth_camera.png").string();
  std::string error;
  ASSERT_TRUE(renderAt(*sim, 0.0, o, out, error)) << error;
  Picture p;
  ASSERT_TRUE(readPng(out, p.width, p.height, p.rgb, error)) << error;
  fs::remove(out);
  ASSERT_EQ(p.width, 64);
  ASSERT_EQ(p.height, 48);
  const auto grey = [](double d) { return static_cast<int>(255.0 * (1.0 - (d - 0.5) / 10.0) + 0.5); };
  // the box: 0.6 m at 1.5 m over 60 degrees spans about 12 pixels about the middle
  for (int y = 20; y < 28; ++y) {
    for (int x = 28; x < 36; ++x) {
      const auto c = p.at(x, y);
      ASSERT_NEAR(c[0], grey(1.5), 1) << x << ", " << y;
      ASSERT_EQ(c[1], c[0]);
      ASSERT_EQ(c[2], c[0]);
    }
  }
  // the wall beside it; its far ends are farther off the axis, but the depth is along it
  for (int y = 0; y < 48; ++y) {
    for (int x : {0, 1, 10, 53, 62, 63}) {
      const auto c = p.at(x, y);
      ASSERT_NEAR(c[0], grey(3.0), 1) << x << ", " << y;
      ASSERT_EQ(c[1], c[0]);
      ASSERT_EQ(c[2], c[0]);
    }
  }
}

TEST(Render, ATemplateIsNotDrawnNorItsLightsAndCameras) {
  DirectDraw d(R"(gdpn: 1
scene:
  - Group:
      name: store
      template: true
      children:
        - Light: {kind: point, location: [0, -1, 0], intensity: 5}
        - Camera: {name: inside, position: [0, 4, 0], target: [0, 0, 0]}
        - Cube: {size: [1, 1, 1]}
  - Camera: {name: front, position: [0, -4, 0], target: [0, 0, 0]}
  - Sphere: {radius: 0.2}
)", "template.gdpn.yaml", 160, 120);
  ASSERT_TRUE(d.ready());
  auto& scene = *d.sim->plant();
  const auto with = d.renderer->draw(scene, d.camera, d.options);
  // the first camera is the first that is no template's
  std::string error;
  EXPECT_EQ(chooseCamera(scene, "", 0, error).eye.y, -4.0);
  EXPECT_NE(cameraProblem(scene, "fornt").find("the scene's cameras: front"), std::string::npos);
  EXPECT_NE(cameraProblem(scene, "store/inside").find("'store/inside' is a Camera in a template"), std::string::npos);
  scene.find("store")->is_template = false;
  const auto without = d.renderer->draw(scene, d.camera, d.options);
  EXPECT_EQ(without.triangles, with.triangles + 12);  // the cube's, drawn once it is no template
  EXPECT_EQ(chooseCamera(scene, "", 0, error).eye.y, 4.0);
}

TEST(Render, TheDirectionalLightCastsAShadowOnTheSideItShinesTowards) {
  // a cube 1 m above a plane, the light shining down and towards +x: its shadow falls on the
  // plane at x = +1 (right of the cube in the picture), and nowhere else
  DirectDraw d(R"(gdpn: 1
scene:
  - Camera: {position: [0, -6, 5], target: [0.5, 0, 0], fov: 40}
  - Light: {kind: directional, direction: [1, 0, -1]}
  - Material: {diffuse: [0.8, 0.8, 0.8], ambient: [0.2, 0.2, 0.2]}
  - Plane: {}
  - Transform: {translation: [0, 0, 1.2], children: [{Cube: {size: [0.6, 0.6, 0.6]}}]}
)", "shadow.gdpn.yaml", 320, 240);
  ASSERT_TRUE(d.ready());
  d.options.shadows = false;
  d.draw();
  const auto plain = d.target->readRgb();
  d.options.shadows = true;
  d.draw();
  const auto shaded = d.target->readRgb();
  ASSERT_EQ(plain.size(), shaded.size());
  // pixels the shadow darkens, and where they are
  int darker = 0, brighter = 0;
  double x_sum = 0;
  for (std::size_t i = 0; i < plain.size(); i += 3) {
    const int before = plain[i] + plain[i + 1] + plain[i + 2], after = shaded[i] + shaded[i + 1] + shaded[i + 2];
    if (after < before - 60) {
      ++darker;
      x_sum += static_cast<double>((i / 3) % 320);
    }
    if (after > before + 3) ++brighter;
  }
  EXPECT_GT(darker, 400) << "a shadow about the cube's size";
  EXPECT_LT(darker, 320 * 240 / 8) << "and not the whole plane";
  EXPECT_EQ(brighter, 0) << "a shadow only takes light away";
  EXPECT_GT(x_sum / darker, 160.0) << "the shadow lies towards +x, right of the middle";
}

TEST(Render, AMovieOfTwoSecondsHasItsFrames) {
  auto sim = open("cube_lit");
  ASSERT_TRUE(sim);
  CaptureOptions o;
  o.width = 160;
  o.height = 120;
  o.samples = 1;
  o.fps = 30;
  const auto out = (fs::temp_directory_path() / "gdpn_movie_test.mp4").string();
  RecordResult result;
  std::string error;
  ASSERT_TRUE(record(*sim, 2.0, o, out, {}, nullptr, result, error)) << error;
  EXPECT_EQ(result.frames, 60);
  // ffprobe decodes the whole file: a playable movie with the right number of frames
  const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                          "stream=nb_read_frames,width,height,codec_name -of csv=p=0 '" + out + "'";
  std::FILE* probe = ::popen(cmd.c_str(), "r");
  ASSERT_NE(probe, nullptr);
  char buf[256] = {};
  const std::string text = std::fgets(buf, sizeof buf, probe) != nullptr ? buf : "";
  EXPECT_EQ(::pclose(probe), 0);
  EXPECT_EQ(text, "h264,160,120,60\n");
  fs::remove(out);
}

TEST(Render, SizesAreParsed) {
  EXPECT_EQ(parseSize("1280x720"), (std::pair{1280, 720}));
  EXPECT_FALSE(parseSize("1280"));
  EXPECT_FALSE(parseSize("x720"));
  EXPECT_FALSE(parseSize("12a0x720"));
  EXPECT_FALSE(parseSize("0x720"));
  EXPECT_FALSE(parseSize("1280x720x3"));
}

}  // namespace
}  // namespace gdpn::render
