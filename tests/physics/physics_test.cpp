// Rigid-body physics against analytic answers, each within a stated tolerance.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gdpn/model/model.h"
#include "gdpn/physics/world.h"

namespace gdpn::physics {
namespace {

constexpr double g = 9.81;

/// A scene parsed from the `scene:` section text, and its physics.
struct Plant {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<World> world;
  explicit Plant(const std::string& scene_text, std::uint64_t seed = 1, const std::string& dir = ".") {
    core::Diagnostics diags;
    auto m = model::parseModel("gdpn: 1\nscene:\n" + scene_text, "plant.gdpn.yaml", diags);
    EXPECT_TRUE(m) << diags.str();
    if (!m) return;
    scene = m->scene->clone();
    world = World::create(*scene, dir, seed, diags);
    EXPECT_TRUE(world) << diags.str();
  }
  scene::Node& node(const char* path) const {
    auto* n = scene->find(path);
    EXPECT_NE(n, nullptr) << path;
    return *n;
  }
  void run(double seconds, double dt) {
    const auto steps = static_cast<int>(std::lround(seconds / dt));
    for (int i = 0; i < steps; ++i) world->step(dt);
  }
};

const std::string kMeshes = std::string(GDPN_SOURCE_DIR) + "/tests/data/physics";

TEST(Physics, ABallComesToRestOnATriangleMeshGround) {
  Plant p(R"(
  - Mesh: {file: ground.obj, collision: trimesh}
  - Transform:
      translation: [1.5, -2, 1]
      children:
        - Body: {name: ball, mass: 1, children: [{Sphere: {radius: 0.1}}]}
)", 1, kMeshes);
  p.run(3.0, 1.0 / 240);
  const auto& ball = p.node("#1/ball");
  EXPECT_NEAR(ball.world.position.z, 0.1, 0.005);
  EXPECT_NEAR(ball.world.position.x, 1.5, 1e-6);
}

TEST(Physics, ASlidingBoxTouchesTheGroundAtItsCornersWhenAsked) {
  const char* scene = R"(
  - Plane: {}
  - Transform:
      translation: [2, 3, 0.25]
      children:
        - Body: {name: box, mass: 1, children: [{Cube: {size: [1, 1, 0.5]}}]}
)";
  // pushed along x, it slides (and stays awake: a resting body sleeps and makes no contacts)
  Plant unasked(scene);
  unasked.world->setVelocity(unasked.node("#1/box"), {2, 0, 0});
  unasked.run(0.1, 1.0 / 240);
  EXPECT_TRUE(unasked.world->contacts().empty());  // not recorded until asked for
  Plant p(scene);
  const auto& box = p.node("#1/box");
  p.world->setVelocity(box, {2, 0, 0});
  p.world->recordContacts(true);
  p.run(0.1, 1.0 / 240);
  const auto& touching = p.world->contacts();
  ASSERT_EQ(touching.size(), 4u);  // a box on a plane: its four lower corners
  for (const auto& c : touching) {
    EXPECT_NEAR(std::abs(c.position.x - box.world.position.x), 0.5, 0.01);
    EXPECT_NEAR(std::abs(c.position.y - 3), 0.5, 1e-3);
    EXPECT_NEAR(c.position.z, 0.0, 5e-3);
    EXPECT_NEAR(std::abs(c.normal.z), 1.0, 1e-9);
    EXPECT_GE(c.depth, 0.0);
    EXPECT_LT(c.depth, 5e-3);
  }
  p.world->recordContacts(false);
  EXPECT_TRUE(p.world->contacts().empty());
}

TEST(Physics, AMeshBodyRestsOnItsHullItsBoxOrItsTriangles) {
  // a unit cube from a file, dropped on the ground: its centre comes to rest 0.5 m up whatever
  // the model chooses to collide with; its mass is its box's (density 1000: 1000 kg)
  for (const char* collision : {"convex", "box", "trimesh"}) {
    Plant p(R"(
  - Plane: {}
  - Transform:
      translation: [0, 0, 2]
      children:
        - Body: {name: cube, children: [{Mesh: {file: cube.obj, collision: )" + std::string(collision) + R"(}}]}
)", 1, kMeshes);
    p.run(3.0, 1.0 / 240);
    const auto& cube = p.node("#1/cube");
    EXPECT_NEAR(cube.world.position.z, 0.5, 0.01) << collision;
    EXPECT_NEAR(p.world->mass(cube), 1000.0, 1e-6) << collision;
  }
}

TEST(Physics, FreeFallFollowsHalfGTSquared) {
  Plant p(R"(
  - Transform:
      translation: [0, 0, 10]
      children:
        - Body: {name: ball, mass: 1, children: [{Sphere: {radius: 0.1}}]}
)");
  const double dt = 1.0 / 240;
  p.run(1.0, dt);
  const auto& ball = p.node("#0/ball");
  // semi-implicit Euler: the velocity is exact; the position is off by at most g t dt
  EXPECT_NEAR(p.world->velocity(ball).z, -g * 1.0, 1e-9);
  EXPECT_NEAR(ball.world.position.z, 10 - g / 2, g * 1.0 * dt);
  EXPECT_NEAR(ball.world.position.x, 0.0, 1e-12);
}

TEST(Physics, PendulumHasTheSmallAnglePeriod) {
  // a 1 m pendulum released 5 degrees out: T = 2 pi sqrt(L / g) = 2.0061 s (the 5 degree
  // amplitude lengthens it by 0.05 %); tolerance 0.5 %
  const double L = 1.0, theta = core::radians(5);
  const std::string x = std::to_string(L * std::sin(theta)), z = std::to_string(-L * std::cos(theta));
  Plant p(R"(
  - World: {auto_disable: false}
  - Joint:
      name: pivot
      kind: hinge
      axis1: [0, 1, 0]
      children:
        - Transform:
            translation: [)" + x + ", 0, " + z + R"(]
            children:
              - Body: {name: bob, mass: 1, children: [{Sphere: {radius: 0.01}}]}
)");
  const double dt = 1.0 / 1000;
  const auto& bob = p.node("pivot/#0/bob");
  // time the upward zero crossings of x
  std::vector<double> crossings;
  double last = bob.world.position.x;
  for (int i = 1; i <= 10000; ++i) {
    p.world->step(dt);
    const double now = bob.world.position.x;
    if (last < 0 && now >= 0) crossings.push_back(i * dt - dt * now / (now - last));
    last = now;
  }
  ASSERT_GE(crossings.size(), 4u);
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double expected = 2 * M_PI * std::sqrt(L / g);
  EXPECT_NEAR(period, expected, 0.005 * expected);
}

TEST(Physics, ABlockSlidesDownAnInclineAtGTimesSinMinusMuCos) {
  // 30 degree incline, friction 0.3 on both materials: a = g (sin 30 - 0.3 cos 30) = 2.356 m/s^2;
  // the speed after 1 s within 3 %
  Plant p(R"(
  - World: {auto_disable: false}
  - Transform:
      rotation: [0, -1, 0, 30]
      children:
        - Material: {friction: 0.3}
        - Cube: {size: [20, 2, 0.2]}
        - Transform:
            translation: [0, 0, 0.2]
            children:
              - Body: {name: block, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
)");
  const double dt = 1.0 / 500;
  p.run(0.2, dt);  // settle onto the surface
  const auto& block = p.node("#1/#2/block");
  const double v0 = p.world->velocity(block).length();
  p.run(1.0, dt);
  const double a = g * (0.5 - 0.3 * std::cos(core::radians(30)));
  EXPECT_NEAR(p.world->velocity(block).length() - v0, a * 1.0, 0.03 * a);
  // it slides down the slope: towards -x, and down
  EXPECT_LT(p.world->velocity(block).x, 0.0);
}

TEST(Physics, ABoxOnAConveyorReachesTheBeltSpeed) {
  // 0.1 m box of 0.5 kg dropped on a 1 m/s belt: after 2 s it moves with the belt (within 1 %)
  Plant p(R"(
  - Transform:
      name: belt
      children:
        - Conveyor: {speed: 1, direction: [1, 0, 0]}
        - Cube: {size: [10, 1, 0.1]}
  - Transform:
      translation: [-4, 0, 0.12]
      children:
        - Body: {name: box, mass: 0.5, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
)");
  p.run(2.0, 1.0 / 500);
  const auto& box = p.node("#1/box");
  EXPECT_NEAR(p.world->velocity(box).x, 1.0, 0.01);
  EXPECT_NEAR(p.world->velocity(box).y, 0.0, 0.01);
  EXPECT_GT(box.world.position.x, -4 + 1.0);  // it has travelled along +x
}

/// A scene of one hinge, "shoulder", at the origin with the joint fields `fields` (YAML, flow
/// style), turning a 1 m arm of 2 kg that reaches out along +x.
std::string armOnAHinge(const std::string& fields) {
  return "  - Joint: {name: shoulder, kind: hinge, " + fields +
         ", children: [{Body: {name: arm, mass: 2, children: [{Transform: {translation: [0.5, 0, 0], "
         "children: [{Cube: {size: [1, 0.1, 0.1]}}]}}]}}]}\n";
}

TEST(Physics, AHingeMotorReachesItsTargetVelocity) {
  Plant p(armOnAHinge("axis1: [0, 0, 1], vel1: 90, fmax1: 50"));
  p.run(1.0, 1.0 / 500);
  const auto& shoulder = p.node("shoulder");
  EXPECT_NEAR(p.world->jointRate(shoulder), core::radians(90), 0.01 * core::radians(90));
  // it reached the speed almost at once: the angle is close to 90 degrees after 1 s
  EXPECT_NEAR(p.world->jointPosition(shoulder), core::radians(90), core::radians(2));
}

TEST(Physics, APositionControlledHingeClosesItsErrorExponentiallyAndHoldsAgainstGravity) {
  // a horizontal arm about a horizontal axis, so gravity pulls it off its target; a strong
  // motor, no speed cap: the error shrinks as exp(-t / servo_time) (less a small sag)
  Plant p(armOnAHinge("axis1: [0, 1, 0], control: position, target1: -30, servo_time: 0.2, fmax1: 500"));
  const auto& shoulder = p.node("shoulder");
  p.run(0.2, 1.0 / 500);
  // after one servo time: e^-1 of the 30 degrees left
  EXPECT_NEAR(p.world->jointPosition(shoulder), core::radians(-30 * (1 - std::exp(-1.0))), core::radians(1.5));
  p.run(0.4, 1.0 / 500);
  EXPECT_NEAR(p.world->jointPosition(shoulder), core::radians(-30 * (1 - std::exp(-3.0))), core::radians(1.5));
  p.run(2.0, 1.0 / 500);
  // it holds: gravity's torque (2 kg at 0.5 m, about 10 N m) leaves it within a degree
  EXPECT_NEAR(p.world->jointPosition(shoulder), core::radians(-30), core::radians(1));
  EXPECT_NEAR(p.world->jointRate(shoulder), 0.0, 0.01);
}

TEST(Physics, APositionControlledSliderMovesNoFasterThanVel1AndStopsAtItsTarget) {
  Plant p(R"(
  - World: {gravity: [0, 0, 0]}
  - Joint:
      name: rail
      kind: slider
      axis1: [1, 0, 0]
      control: position
      target1: 0.8
      vel1: 0.5
      fmax1: 1000
      children:
        - Body: {name: cart, mass: 5, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
)");
  const auto& rail = p.node("rail");
  p.run(1.0, 1.0 / 500);
  // far from the target the cap holds it to 0.5 m/s: 0.5 m in the first second
  EXPECT_NEAR(p.world->jointRate(rail), 0.5, 0.01);
  EXPECT_NEAR(p.world->jointPosition(rail), 0.5, 0.02);
  p.run(2.0, 1.0 / 500);
  EXPECT_NEAR(p.world->jointPosition(rail), 0.8, 0.002);
  EXPECT_NEAR(p.world->jointRate(rail), 0.0, 0.01);
}

TEST(Physics, AJointSwitchedToPositionControlByAScriptServoesToItsTarget) {
  // a hinge about the vertical axis runs at vel1 (90 deg/s) past its target (30 degrees) in
  // velocity control; switched to position control (as a script does: set the field, then
  // tell the world), it turns back to the target and holds there, vel1 now capping its speed
  Plant p(armOnAHinge("axis1: [0, 0, 1], vel1: 90, fmax1: 50, target1: 30, servo_time: 0.1"));
  auto& shoulder = p.node("shoulder");
  p.run(0.6, 1.0 / 500);
  // velocity control: it ignores the target
  EXPECT_NEAR(p.world->jointRate(shoulder), core::radians(90), 0.01 * core::radians(90));
  EXPECT_GT(p.world->jointPosition(shoulder), core::radians(45));
  shoulder.setValue(scene::field::Joint::Control, std::string("position"));
  EXPECT_EQ(p.world->fieldChanged(shoulder), "");
  p.run(0.2, 1.0 / 500);
  // on its way back, no faster than vel1
  EXPECT_LT(p.world->jointRate(shoulder), 0.0);
  EXPECT_GE(p.world->jointRate(shoulder), -core::radians(90) * 1.01);
  p.run(1.5, 1.0 / 500);
  EXPECT_NEAR(p.world->jointPosition(shoulder), core::radians(30), core::radians(0.5));
  EXPECT_NEAR(p.world->jointRate(shoulder), 0.0, 0.01);
}

/// The bodies a sensor feels now, by name.
std::vector<std::string> felt(World& world, const scene::Scene& scene, const scene::Node& sensor) {
  std::vector<std::pair<scene::NodeHandle, World::Feel>> out;
  world.sense(out);
  std::vector<std::string> names;
  for (const auto& [handle, feel] : out) {
    if (handle != sensor.handle()) continue;
    for (auto item : feel.items) names.push_back(scene.resolve(item)->name());
  }
  return names;
}

TEST(Physics, ARegionWhoseScopeOrSizeAScriptChangesFeelsWhatItSaysAfterwards) {
  // two boxes float inside a 1 m region: one beside it in its cell, one from elsewhere
  Plant p(R"(
  - World: {gravity: [0, 0, 0]}
  - Transform:
      name: cell
      children:
        - Region: {name: eye, size: [1, 1, 1], scope: siblings}
        - Transform: {translation: [-0.2, 0, 0], children: [{Body: {name: mine, mass: 1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
  - Transform:
      translation: [0.3, 0, 0]
      children:
        - Body: {name: stranger, mass: 1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
)");
  auto& eye = p.node("cell/eye");
  p.run(0.1, 1.0 / 500);
  EXPECT_EQ(felt(*p.world, *p.scene, eye), std::vector<std::string>{"mine"});
  // the whole world in scope: the stranger is felt too
  eye.setValue(scene::field::Region::Scope, std::string("world"));
  EXPECT_EQ(p.world->fieldChanged(eye), "");
  EXPECT_EQ(felt(*p.world, *p.scene, eye), (std::vector<std::string>{"stranger", "mine"}));  // by path
  // a volume 0.2 m across, which neither box reaches
  eye.setValue(scene::field::Region::Size, std::array<double, 3>{0.2, 0.2, 0.2});
  EXPECT_EQ(p.world->fieldChanged(eye), "");
  EXPECT_TRUE(felt(*p.world, *p.scene, eye).empty());
}

TEST(Physics, AShelfAScriptMovesCarriesWhatFallsOnItThereAndItsSensorGoesWithIt) {
  // a static shelf (a box 1 m across, its top at 1 m) with a region over it, moved 3 m along
  // x as a script sets its Transform's translation; a ball dropped over the new place lands on
  // it (its centre at 1.1 m), and the region there feels the ball
  Plant p(R"(
  - World: {}
  - Transform:
      name: shelf
      children:
        - Transform: {name: board, translation: [0, 0, 0.95], children: [{Cube: {size: [1, 1, 0.1]}}]}
        - Transform: {name: above, translation: [0, 0, 1.2], children: [{Region: {name: eye, size: [0.8, 0.8, 0.3]}}]}
  - Transform:
      name: drop
      translation: [3, 0, 1.6]
      children: [{Body: {name: ball, mass: 1, children: [{Sphere: {radius: 0.1}}]}}]
)");
  auto& shelf = p.node("shelf");
  ASSERT_EQ(assignField(shelf, static_cast<std::size_t>(shelf.type().fieldIndex("translation")),
                        std::array<double, 3>{3, 0, 0}, scene::AngleUnit::Degrees, p.world.get()),
            "");
  EXPECT_NEAR(p.node("shelf/board").world.position.x, 3.0, 1e-12) << "the poses below it follow at once";
  p.run(1.0, 1.0 / 500);
  EXPECT_NEAR(p.node("drop/ball").framePose().position.z, 1.1, 0.005) << "it lies on the moved shelf";
  EXPECT_EQ(felt(*p.world, *p.scene, p.node("shelf/above/eye")), std::vector<std::string>{"ball"});
  // turned a quarter about x, the shelf stands on its edge: the ball falls past it to the floor
  ASSERT_EQ(assignField(shelf, static_cast<std::size_t>(shelf.type().fieldIndex("rotation")),
                        std::array<double, 4>{0, 1, 0, 90}, scene::AngleUnit::Degrees, p.world.get()),
            "");
  p.run(1.0, 1.0 / 500);
  EXPECT_LT(p.node("drop/ball").framePose().position.z, 0.5);
}

TEST(Physics, AnAttachedBoxFollowsTheArmThenFallsWhenDetached) {
  Plant p(R"(
  - World: {auto_disable: false}
  - Joint:
      name: rail
      kind: slider
      axis1: [1, 0, 0]
      fmax1: 1000
      children:
        - Transform:
            translation: [0, 0, 1]
            children:
              - Body: {name: arm, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
  - Transform:
      translation: [0, 0, 0.8]
      children:
        - Body: {name: box, mass: 0.2, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
)");
  auto& rail = p.node("rail");
  const auto& box = p.node("#2/box");
  const auto& arm = p.node("rail/#0/arm");
  ASSERT_TRUE(p.world->attach(arm, box));
  EXPECT_FALSE(p.world->attach(arm, box));  // already
  rail.setValue(scene::field::Joint::Vel1, 0.5);  // m/s
  p.run(1.0, 1.0 / 500);
  // the box went along with the arm, and did not fall
  EXPECT_NEAR(box.world.position.x, 0.5, 0.02);
  EXPECT_NEAR(box.world.position.z, 0.8, 0.02);
  ASSERT_TRUE(p.world->detach(arm, box));
  EXPECT_FALSE(p.world->detach(arm, box));
  p.run(0.3, 1.0 / 500);
  // free now: it falls (and keeps the arm's speed for a while)
  EXPECT_LT(box.world.position.z, 0.8 - 0.5 * g * 0.3 * 0.3 + 0.02);
  EXPECT_GT(box.world.position.x, 0.55);
}

TEST(Physics, StaticShapesDoNotMoveAndBodiesRestOnThem) {
  Plant p(R"(
  - Plane: {}
  - Transform:
      translation: [0, 0, 0.3]
      children:
        - Body: {name: box, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}
)");
  p.run(3.0, 1.0 / 250);
  const auto& box = p.node("#1/box");
  EXPECT_NEAR(box.world.position.z, 0.1, 0.005);
  // at rest, auto-disable put it to sleep
  EXPECT_FALSE(p.world->awake(box));
  EXPECT_EQ(p.world->awakeCount(), 0u);
}

TEST(Physics, ABodyThatRunsAwayFaultsTheWorldWhichThenKeepsItsLastGoodPlacement) {
  // the largest force a script may apply, on 1 kg: beyond 1e12 m/s in the first step
  Plant p(R"(
  - Transform:
      translation: [0, 0, 1]
      children:
        - Body: {name: rocket, mass: 1, children: [{Sphere: {radius: 0.1}}]}
)");
  auto& rocket = p.node("#0/rocket");
  p.world->step(0.01);
  EXPECT_EQ(p.world->fault(), "");
  const core::Pose good = rocket.world;
  p.world->setForce(rocket, {kMaxForce, 0, 0});
  p.world->step(0.01);
  EXPECT_EQ(p.world->fault().rfind("body '#0/rocket' ran away: its position became (", 0), 0u) << p.world->fault();
  // the scene keeps the placement of the last good step, and the world steps no more
  EXPECT_EQ(rocket.world.position.x, good.position.x);
  EXPECT_TRUE(std::isfinite(rocket.world.position.z));
  p.world->step(0.01);
  EXPECT_EQ(rocket.world.position.x, good.position.x);
}

}  // namespace
}  // namespace gdpn::physics
