// How parts show what they are (issue 54): a conveyor's arrows on the top face of the Cubes
// it drives, pointing where it carries things and moved on by its speed over model time; a
// Region marked `visible` drawn with no sensor overlay asked for, a ray as a red beam that
// turns green while something breaks it. Pictures taken headless (EGL surfaceless) looking
// straight down, read pixel by pixel: no golden pictures, and no test measures time.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "gdpn/capture/capture.h"
#include "gdpn/capture/sensor_imager.h"
#include "gdpn/model/model.h"
#include "gdpn/platform/headless_context.h"
#include "gdpn/platform/png.h"
#include "gdpn/platform/target.h"
#include "gdpn/render/renderer.h"

namespace gdpn::render {
namespace {

namespace fs = std::filesystem;

/// An RGB picture, top row first.
struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  [[nodiscard]] std::array<int, 3> at(int x, int y) const {
    const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  /// How many pixels of rows `y0` to `y1` (inclusive) are `like`.
  template <class Like>
  [[nodiscard]] int count(Like like, int y0 = 0, int y1 = -1) const {
    int n = 0;
    for (int y = y0; y <= (y1 < 0 ? height - 1 : y1); ++y) {
      for (int x = 0; x < width; ++x) n += like(at(x, y)) ? 1 : 0;
    }
    return n;
  }
};

/// The arrows' safety yellow; the beam's red and, while active, green (against the grey-blue
/// background and the dark belt).
bool yellow(std::array<int, 3> c) { return c[0] > 150 && c[1] > 110 && c[2] < 90; }
bool red(std::array<int, 3> c) { return c[0] > 150 && c[1] < 90 && c[2] < 90; }
bool green(std::array<int, 3> c) { return c[1] > 150 && c[0] < 110 && c[2] < 130; }

/// Pixels per metre on the plane at height `z` (m) seen straight down from `eye` m up by a
/// camera of `fov` degrees (vertical) over `height` pixels.
double pixelsPerMetre(double eye, double z, double fov, int height) {
  return 0.5 * height / ((eye - z) * std::tan(fov * std::numbers::pi / 360.0));
}

/// A model's scene drawn straight down from `eye` m above the origin (+x to the right, +y up
/// in the picture) by the renderer itself, with no shadow, sky or grid.
struct TopView {
  static constexpr double kFov = 40.0;
  std::unique_ptr<model::Simulation> sim;
  std::unique_ptr<platform::GlContext> context;
  std::unique_ptr<platform::Target> target;
  std::unique_ptr<Renderer> renderer;
  DrawOptions options;
  Camera camera;

  TopView(const std::string& scene, double eye, int width, int height) {
    core::Diagnostics diags;
    auto m = model::parseModel("gdpn: 1\nscene:\n" + scene, "parts.gdpn.yaml", diags);
    EXPECT_TRUE(m) << diags.str();
    if (m) sim = model::Simulation::create(*m, diags);
    EXPECT_TRUE(sim) << diags.str();
    std::string why;
    context = platform::createHeadlessContext(why);
    EXPECT_TRUE(context) << why;
    if (!sim || !context) return;
    target = std::make_unique<platform::Target>(width, height, 1);
    renderer = std::make_unique<Renderer>(".");
    options.width = width;
    options.height = height;
    options.shadows = options.sky = options.grid = false;
    camera.eye = {0, 0, eye};
    camera.target = {0, 0, 0};
    camera.up = {0, 1, 0};
    camera.fov = kFov;
  }
  [[nodiscard]] bool ready() const { return renderer != nullptr; }
  /// The picture at model time `t` (s).
  Picture draw(double t) {
    options.time = t;
    target->bind();
    renderer->draw(*sim->plant(), camera, options);
    return {options.width, options.height, target->readRgb()};
  }
};

/// A belt 4 m long along x, 0.6 m wide, its top face at z = 0.1, driven by `conveyor`.
std::string belt(const std::string& conveyor) {
  return R"(  - Material: {diffuse: [0.1, 0.1, 0.1]}
  - Transform:
      name: belt
      translation: [0, 0, 0.05]
      children:
        - Cube: {size: [4, 0.6, 0.1]}
        - )" + conveyor + "\n";
}

/// Yellow pixels per column over the rows of the belt (the profile of its arrows).
std::vector<int> arrowProfile(const Picture& p) {
  std::vector<int> columns(static_cast<std::size_t>(p.width), 0);
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < p.width; ++x) columns[static_cast<std::size_t>(x)] += yellow(p.at(x, y)) ? 1 : 0;
  }
  return columns;
}

/// The shift in pixels (within +-`most`) that lays profile `before` best on `after`, compared
/// over the columns from `lo` to `hi` (away from the belt's ends, where arrows come and go).
int bestShift(const std::vector<int>& before, const std::vector<int>& after, int lo, int hi, int most) {
  int best = 0;
  long best_error = -1;
  for (int s = -most; s <= most; ++s) {
    long error = 0;
    for (int x = lo; x <= hi; ++x) {
      error += std::abs(before[static_cast<std::size_t>(x)] - after[static_cast<std::size_t>(x + s)]);
    }
    if (best_error < 0 || error < best_error) {
      best_error = error;
      best = s;
    }
  }
  return best;
}

/// Where the arrows point along x: the mean column of their pixels on the belt's middle row
/// less that of their pixels near its edges (positive: towards +x). A chevron's middle is
/// its tip, its edges its back.
double pointing(const Picture& p, int edge_rows) {
  const int mid = p.height / 2;
  double middle = 0, edges = 0;
  int n_middle = 0, n_edges = 0;
  for (int x = 0; x < p.width; ++x) {
    if (yellow(p.at(x, mid))) {
      middle += x;
      ++n_middle;
    }
    for (const int y : {mid - edge_rows, mid + edge_rows}) {
      if (yellow(p.at(x, y))) {
        edges += x;
        ++n_edges;
      }
    }
  }
  EXPECT_GT(n_middle, 0);
  EXPECT_GT(n_edges, 0);
  return n_middle == 0 || n_edges == 0 ? 0.0 : middle / n_middle - edges / n_edges;
}

// the belt seen from 3 m up, 640 x 160: 76 pixels a metre on its top face, the belt from
// column 168 to 472 and from row 57 to 103; an arrow 0.36 m wide is 27 rows tall
constexpr int kWidth = 640, kHeight = 160;
constexpr double kEye = 3.0;

TEST(Parts, AConveyorsArrowsLieOnTheTopFaceOfItsBeltAndPointWhereItCarries) {
  TopView v(belt("Conveyor: {speed: 0.5, direction: [1, 0, 0]}"), kEye, kWidth, kHeight);
  ASSERT_TRUE(v.ready());
  const Picture p = v.draw(0);
  const double ppm = pixelsPerMetre(kEye, 0.1, TopView::kFov, kHeight);
  // arrows along the belt, and none off it
  const int left = static_cast<int>(kWidth / 2 - 2 * ppm), right = static_cast<int>(kWidth / 2 + 2 * ppm);
  const int top = static_cast<int>(kHeight / 2 - 0.3 * ppm), bottom = static_cast<int>(kHeight / 2 + 0.3 * ppm);
  int on = 0, off = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (!yellow(p.at(x, y))) continue;
      (x > left && x < right && y > top && y < bottom ? on : off) += 1;
    }
  }
  EXPECT_GT(on, 1000) << "a belt 4 m long has several arrows";
  EXPECT_EQ(off, 0);
  // with its arrows in each quarter of its length
  const auto columns = arrowProfile(p);
  for (int q = 0; q < 4; ++q) {
    int in_quarter = 0;
    for (int x = left + q * (right - left) / 4; x < left + (q + 1) * (right - left) / 4; ++x) {
      in_quarter += columns[static_cast<std::size_t>(x)];
    }
    EXPECT_GT(in_quarter, 0) << "quarter " << q;
  }
  // they point along +x, where it carries things
  EXPECT_GT(pointing(p, 10), 2.0);
  // turned round by the direction, or by a negative speed
  TopView back(belt("Conveyor: {speed: 0.5, direction: [-1, 0, 0]}"), kEye, kWidth, kHeight);
  ASSERT_TRUE(back.ready());
  EXPECT_LT(pointing(back.draw(0), 10), -2.0);
  TopView reverse(belt("Conveyor: {speed: -0.5, direction: [1, 0, 0]}"), kEye, kWidth, kHeight);
  ASSERT_TRUE(reverse.ready());
  EXPECT_LT(pointing(reverse.draw(0), 10), -2.0);
}

TEST(Parts, AConveyorsArrowsMoveOnBySpeedTimesTime) {
  TopView v(belt("Conveyor: {name: drive, speed: 0.5}"), kEye, kWidth, kHeight);
  ASSERT_TRUE(v.ready());
  const double ppm = pixelsPerMetre(kEye, 0.1, TopView::kFov, kHeight);
  const int lo = static_cast<int>(kWidth / 2 - 1.5 * ppm), hi = static_cast<int>(kWidth / 2 + 1.5 * ppm);
  const auto at0 = arrowProfile(v.draw(0));
  // 0.3 s at 0.5 m/s: 0.15 m (11 pixels) towards +x
  const int shift = bestShift(at0, arrowProfile(v.draw(0.3)), lo, hi, 20);
  EXPECT_NEAR(shift, 0.15 * ppm, 1.5);
  // half as long, half as far: the arrows move steadily (each shift well under half the
  // arrows' spacing, 0.58 m, which looks the same as no shift)
  EXPECT_NEAR(bestShift(at0, arrowProfile(v.draw(0.15)), lo, hi, 20), 0.075 * ppm, 1.5);
  // backwards at a negative speed
  v.sim->plant()->find("belt/drive")->setValue(scene::field::Conveyor::Speed, -0.5);
  EXPECT_NEAR(bestShift(at0, arrowProfile(v.draw(0.3)), lo, hi, 20), -0.15 * ppm, 1.5);
  // a stopped belt's arrows stand still
  v.sim->plant()->find("belt/drive")->setValue(scene::field::Conveyor::Speed, 0.0);
  const Picture still = v.draw(0);
  EXPECT_GT(still.count(yellow), 1000);
  EXPECT_EQ(v.draw(7.3).rgb, still.rgb);
}

TEST(Parts, ATemplateConveyorDrawsNoArrowsNorDoesAPictureWithoutMarkings) {
  TopView v(belt("Conveyor: {speed: 0.5, template: true}"), kEye, kWidth, kHeight);
  ASSERT_TRUE(v.ready());
  EXPECT_EQ(v.draw(0).count(yellow), 0);
  // a template Conveyor after a live one leaves the live one driving (the physics' rule)
  TopView two(belt("Conveyor: {speed: 0.5}\n        - Conveyor: {speed: 0.5, template: true}"), kEye, kWidth, kHeight);
  ASSERT_TRUE(two.ready());
  EXPECT_GT(two.draw(0).count(yellow), 1000);
  // nor are they drawn when the markings are not asked for (camera sensors)
  two.options.markings = false;
  EXPECT_EQ(two.draw(0).count(yellow), 0);
}

// a ray 1 m along +x from the origin, 0.1 m up, seen from 1.6 m up: 1 cm across is 2 pixels
constexpr int kBeamWidth = 480, kBeamHeight = 240;
constexpr double kBeamEye = 1.6;
const std::string kRay = "  - Transform: {translation: [0, 0, 0.1], children: [{Region: {name: eye, shape: ray, length: 1";

/// The columns (of `p`'s middle rows) that hold a pixel `like`, from the first to the last.
template <class Like>
std::pair<int, int> span(const Picture& p, Like like) {
  int first = -1, last = -1;
  for (int x = 0; x < p.width; ++x) {
    for (int y = p.height / 2 - 3; y <= p.height / 2 + 3; ++y) {
      if (!like(p.at(x, y))) continue;
      if (first < 0) first = x;
      last = x;
    }
  }
  return {first, last};
}

TEST(Parts, AVisibleRayRegionIsARedBeamAlongItsLengthGreenWhileActive) {
  const double ppm = pixelsPerMetre(kBeamEye, 0.1, TopView::kFov, kBeamHeight);
  TopView v(kRay + ", visible: true}}]}", kBeamEye, kBeamWidth, kBeamHeight);
  ASSERT_TRUE(v.ready());
  const Picture p = v.draw(0);
  // red from the sensor's origin (the middle column) to 1 m along +x, and only there
  const auto [first, last] = span(p, red);
  EXPECT_NEAR(first, kBeamWidth / 2, 2);
  EXPECT_NEAR(last, kBeamWidth / 2 + ppm, 2);
  EXPECT_EQ(p.count(red), p.count(red, kBeamHeight / 2 - 3, kBeamHeight / 2 + 3));
  int gaps = 0;
  for (int x = first; x <= last; ++x) {
    bool any = false;
    for (int y = kBeamHeight / 2 - 3; y <= kBeamHeight / 2 + 3; ++y) any = any || red(p.at(x, y));
    gaps += any ? 0 : 1;
  }
  EXPECT_EQ(gaps, 0) << "the beam is drawn whole";
  EXPECT_EQ(p.count(green), 0);
  // while it holds something: green, not red
  v.options.active = [](const scene::Node& n) { return n.name() == "eye"; };
  const Picture active = v.draw(0);
  EXPECT_EQ(active.count(red), 0);
  EXPECT_NEAR(span(active, green).first, first, 1);
  EXPECT_NEAR(span(active, green).second, last, 1);
  // not visible: nothing, unless the sensor volumes are asked for (then the overlay's yellow)
  TopView hidden(kRay + "}}]}", kBeamEye, kBeamWidth, kBeamHeight);
  ASSERT_TRUE(hidden.ready());
  const Picture none = hidden.draw(0);
  EXPECT_EQ(none.count(red), 0);
  const auto background = none.at(0, 0);
  EXPECT_EQ(none.count([&](std::array<int, 3> c) { return c != background; }), 0) << "only the background";
  hidden.options.sensors = true;
  EXPECT_EQ(hidden.draw(0).count(red), 0);
  // nor is a visible one drawn where the markings are not asked for
  v.options.markings = false;
  EXPECT_EQ(v.draw(0).count(red) + v.draw(0).count(green), 0);
}

TEST(Parts, AVisibleVolumeRegionIsTranslucentRed) {
  TopView v("  - Region: {shape: box, size: [0.5, 0.5, 0.2], visible: true}\n", kBeamEye, kBeamWidth, kBeamHeight);
  ASSERT_TRUE(v.ready());
  const auto middle = v.draw(0).at(kBeamWidth / 2, kBeamHeight / 2);
  // reddened, and the background still shows through (its blue)
  EXPECT_GT(middle[0], middle[1] + 40);
  EXPECT_GT(middle[2], 60);
  EXPECT_LT(middle[0], 250);
}

/// A picture of model `yaml` at `t` seconds through `gdpn render`'s path (capture::renderAt):
/// the run's own time and sensors.
Picture renderedAt(const std::string& yaml, double t, int width, int height) {
  core::Diagnostics diags;
  auto m = model::parseModel(yaml, "parts.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return {};
  auto sim = model::Simulation::create(*m, diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  capture::CaptureOptions o;
  o.width = width;
  o.height = height;
  o.samples = 1;
  o.ground = false;
  const auto out = (fs::temp_directory_path() / "gdpn_parts_test.png").string();
  std::string error;
  EXPECT_TRUE(capture::renderAt(*sim, t, o, out, error)) << error;
  Picture p;
  EXPECT_TRUE(platform::readPng(out, p.width, p.height, p.rgb, error)) << error;
  fs::remove(out);
  return p;
}

TEST(Parts, APictureOfARunShowsTheArrowsWhereItsTimeMovedThemAndTheBeamBrokenByABox) {
  // gdpn render at 0 and at 0.3 s: the arrows 0.15 m on
  const std::string camera = "  - Camera: {position: [0, 0, 3], target: [0, 0, 0], up: [0, 1, 0], fov: 40}\n";
  const std::string model = "gdpn: 1\nsettings: {dt: 0.01}\nscene:\n" + camera + belt("Conveyor: {speed: 0.5}");
  const double ppm = pixelsPerMetre(kEye, 0.1, TopView::kFov, kHeight);
  const int lo = static_cast<int>(kWidth / 2 - 1.5 * ppm), hi = static_cast<int>(kWidth / 2 + 1.5 * ppm);
  const auto at0 = arrowProfile(renderedAt(model, 0, kWidth, kHeight));
  ASSERT_EQ(at0.size(), static_cast<std::size_t>(kWidth));
  EXPECT_NEAR(bestShift(at0, arrowProfile(renderedAt(model, 0.3, kWidth, kHeight)), lo, hi, 20), 0.15 * ppm, 1.5);
  // a box resting across a visible beam: the beam is green where it shows; red with no box
  const std::string beam = R"(gdpn: 1
settings: {dt: 0.01}
scene:
  - World: {}
  - Camera: {position: [0, 0, 1.6], target: [0, 0, 0], up: [0, 1, 0], fov: 40}
  - Plane: {}
  - Transform: {translation: [0, 0, 0.1], children: [{Region: {name: eye, shape: ray, length: 1, visible: true}}]}
)";
  const std::string box = "  - Transform: {translation: [0.5, 0, 0.1], children: [{Body: {children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}\n";
  const Picture broken = renderedAt(beam + box, 0.05, kBeamWidth, kBeamHeight);
  EXPECT_GT(broken.count(green), 100);
  EXPECT_EQ(broken.count(red), 0);
  const Picture clear = renderedAt(beam, 0.05, kBeamWidth, kBeamHeight);
  EXPECT_GT(clear.count(red), 100);
  EXPECT_EQ(clear.count(green), 0);
}

TEST(Parts, ACameraSensorSeesNoMarkings) {
  // a colour camera looking down at a driven belt and a visible beam: the belt, not the
  // arrows nor the beam (what the plant is, not how people are shown it works)
  core::Diagnostics diags;
  auto m = model::parseModel("gdpn: 1\nscene:\n" + belt("Conveyor: {speed: 0.5}") + kRay + ", visible: true}}]}\n" +
                                 "  - Transform: {translation: [0, 0, 2], rotation: [0, 1, 0, 90], children: "
                                 "[{ColorCamera: {name: cam, width: 160, height: 120, fov: 90}}]}\n",
                             "camera.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = model::Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  capture::SensorImager imager(".");
  sensors::Image image;
  std::string why;
  ASSERT_TRUE(imager.render(*sim->plant(), *sim->plant()->find("#3/cam"), image, why)) << why;
  const Picture seen{image.width, image.height, image.rgb};
  ASSERT_EQ(seen.rgb.size(), 160u * 120u * 3u);
  EXPECT_EQ(seen.count(yellow), 0);
  EXPECT_EQ(seen.count(red), 0);
  // the belt is in view: dark pixels in the middle
  const auto middle = seen.at(80, 60);
  EXPECT_LT(middle[0] + middle[1] + middle[2], 150);
}

}  // namespace
}  // namespace gdpn::render
