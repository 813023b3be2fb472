// Where a part dropped from the palette lands: on the floor on the grid, on top of a part it
// fits on, at a part's end, beside its side, on its centre line, turned as the part is; and the
// box of a machine in its own frame.

#include <gtest/gtest.h>

#include "gdpn/ide/part_snap.h"
#include "gdpn/scene/actions.h"

namespace gdpn::ide {
namespace {

using core::Aabb;
using core::Vec3;

/// A ray straight down onto (x, y) from 5 m up.
core::Ray down(double x, double y) { return {{x, y, 5}, {0, 0, -1}}; }

/// A belt's box: 2 m along x, 0.5 m wide, its top at 0.8 m.
const Aabb kBelt{{-1, -0.25, 0}, {1, 0.25, 0.8}};

DropQuery query(const core::Ray& ray, const Aabb& box, std::vector<PartFootprint> neighbours = {}) {
  DropQuery q;
  q.ray = ray;
  q.box = box;
  q.neighbours = std::move(neighbours);
  return q;
}

void expectAt(const std::optional<DropPlace>& place, double x, double y, double z, SnapKind kind,
              const std::string& neighbour = {}, double angle = 0) {
  ASSERT_TRUE(place);
  EXPECT_NEAR(place->translation[0], x, 1e-9);
  EXPECT_NEAR(place->translation[1], y, 1e-9);
  EXPECT_NEAR(place->translation[2], z, 1e-9);
  EXPECT_EQ(place->kind, kind) << snapKindName(place->kind);
  EXPECT_EQ(place->neighbour, neighbour);
  EXPECT_NEAR(place->angle, angle, 1e-9);
}

TEST(PartSnap, OnTheFloorTheOriginGoesOnTheGridUnderTheBoxCentre) {
  expectAt(placeDrop(query(down(1.23, -0.47), kBelt)), 1.25, -0.45, 0, SnapKind::Floor);
  // a box beside its origin: the pointer holds the box's centre
  expectAt(placeDrop(query(down(1.0, 1.0), Aabb{{0, 0, 0}, {0.4, 0.2, 0.3}})), 0.8, 0.9, 0, SnapKind::Floor);
  auto q = query(down(1.23, -0.47), kBelt);
  q.grid = 0;  // snap off
  expectAt(placeDrop(q), 1.23, -0.47, 0, SnapKind::Floor);
  // an oblique ray meets the floor where it comes down
  const auto slanted = placeDrop(query({{0, -4, 4}, Vec3{0, 1, -1}.normalized()}, kBelt));
  expectAt(slanted, 0, 0, 0, SnapKind::Floor);
}

TEST(PartSnap, NothingUnderARayLookingUp) { EXPECT_FALSE(placeDrop(query({{0, 0, 1}, {0, 0.5, 0.5}}, kBelt))); }

TEST(PartSnap, ABeltNearABeltsEndTouchesItEndToEndOnItsCentreLine) {
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  // its near end 0.3 m from the first belt's end, a little aside: captured
  expectAt(placeDrop(query(down(2.3, 0.12), kBelt, belt)), 2, 0, 0, SnapKind::EndPlusX, "belt1");
  // overlapping it, nearer its -x end
  expectAt(placeDrop(query(down(-1.4, -0.05), kBelt, belt)), -2, 0, 0, SnapKind::EndMinusX, "belt1");
  // further than the capture: the floor
  expectAt(placeDrop(query(down(2.4, 0), kBelt, belt)), 2.4, 0, 0, SnapKind::Floor);
}

TEST(PartSnap, ASnappedPartIsTurnedAndRaisedAsItsNeighbour) {
  // a belt at (1, 2, 0.5) turned 90 degrees: its +x end points along +y
  const std::vector<PartFootprint> belt{{"belt1", {1, 2, 0.5}, 90, kBelt}};
  expectAt(placeDrop(query(down(1.05, 4.2), kBelt, belt)), 1, 4, 0.5, SnapKind::EndPlusX, "belt1", 90);
}

TEST(PartSnap, ASideSnapTouchesTheSideAndSlidesAlongOnTheGrid) {
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  const Aabb sensor{{-0.05, -0.05, 0}, {0.05, 0.05, 1}};
  expectAt(placeDrop(query(down(0.32, -0.45), sensor, belt)), 0.3, -0.3, 0, SnapKind::SideMinusY, "belt1");
  expectAt(placeDrop(query(down(-0.52, 0.41), sensor, belt)), -0.5, 0.3, 0, SnapKind::SidePlusY, "belt1");
}

TEST(PartSnap, APartDrawnBesideABeltGoesOntoItsCentreLine) {
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  // a pusher's box ends at the belt's edge (y = -0.25 of its origin): its origin on the line
  const Aabb pusher{{-0.2, -0.8, 0.78}, {0.2, -0.26, 0.92}};
  expectAt(placeDrop(query(down(0.53, -0.7), pusher, belt)), 0.55, 0, 0, SnapKind::CentreLine, "belt1");
  // a pusher pointed at on the belt's top, near its side: beside it all the same
  expectAt(placeDrop(query(down(-0.31, -0.2), pusher, belt)), -0.3, 0, 0, SnapKind::CentreLine, "belt1");
  // at the other side it faces the belt: turned half round
  expectAt(placeDrop(query(down(0.53, 0.7), pusher, belt)), 0.55, 0, 0, SnapKind::CentreLine, "belt1", 180);
  // drawn 0.5 m off its origin: touching, its origin 0.25 m inside the belt's side
  const Aabb far_pusher{{-0.2, -0.9, 0.78}, {0.2, -0.5, 0.92}};
  expectAt(placeDrop(query(down(0.53, 0.6), far_pusher, belt)), 0.55, -0.25, 0, SnapKind::SidePlusY, "belt1", 180);
  expectAt(placeDrop(query(down(0.53, -0.6), far_pusher, belt)), 0.55, 0.25, 0, SnapKind::SideMinusY, "belt1");
  // a through-beam's posts on both sides: pointed at on the belt, across it on its centre line;
  // beside it, beside it
  const Aabb eye{{-0.025, -0.375, 0}, {0.025, 0.375, 0.9}};
  expectAt(placeDrop(query(down(0.4, 0.1), eye, belt)), 0.4, 0, 0, SnapKind::CentreLine, "belt1");
  expectAt(placeDrop(query(down(-0.88, -0.2), eye, belt)), -0.9, 0, 0, SnapKind::CentreLine, "belt1");
  expectAt(placeDrop(query(down(0.4, 0.5), eye, belt)), 0.4, 0.625, 0, SnapKind::SidePlusY, "belt1");
  // beyond the belt's end it is no longer across it
  expectAt(placeDrop(query(down(1.2, 0), eye, belt)), 1.025, 0, 0, SnapKind::EndPlusX, "belt1");
  // a belt as wide as the belt is not across it: end to end
  expectAt(placeDrop(query(down(0.95, 0.1), kBelt, belt)), 2, 0, 0, SnapKind::EndPlusX, "belt1");
}

TEST(PartSnap, APartReachingOverABeltFromItsSideGoesOntoItsCentreLine) {
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  // a proximity sensor: a post 0.4 m off its origin at -y, an arm reaching to its head over
  // the origin (its box passes the origin by 16 mm): pointed at over the belt or at the post's
  // side, its origin on the centre line as drawn; at the other side, turned half round
  const Aabb sensor{{-0.06, -0.46, 0}, {0.06, 0.016, 1.0}};
  expectAt(placeDrop(query(down(0.4, 0.02), sensor, belt)), 0.4, 0, 0, SnapKind::CentreLine, "belt1");
  expectAt(placeDrop(query(down(0.4, -0.5), sensor, belt)), 0.4, 0, 0, SnapKind::CentreLine, "belt1");
  expectAt(placeDrop(query(down(0.4, 0.5), sensor, belt)), 0.4, 0, 0, SnapKind::CentreLine, "belt1", 180);
  // one whose box passes its origin by more than the belt's half width is no such part: it
  // touches the side
  const Aabb wide{{-0.06, -0.46, 0}, {0.06, 0.3, 1.0}};
  expectAt(placeDrop(query(down(0.4, -0.5), wide, belt)), 0.4, -0.55, 0, SnapKind::SideMinusY, "belt1");
}

TEST(PartSnap, APartTurnedWhileDraggedSnapsAsItsTurnedBox) {
  // a gantry 1.6 m long along its x, 0.4 m wide: turned a quarter, it spans the belt and goes
  // across it on its centre line
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  const Aabb gantry{{-0.4, -0.2, 0}, {1.2, 0.2, 1.8}};
  const Aabb turned = turnedAboutZ(gantry, 90);
  EXPECT_NEAR(turned.lo.x, -0.2, 1e-12);
  EXPECT_NEAR(turned.hi.x, 0.2, 1e-12);
  EXPECT_NEAR(turned.lo.y, -0.4, 1e-12);
  EXPECT_NEAR(turned.hi.y, 1.2, 1e-12);
  expectAt(placeDrop(query(down(0.3, 0), turned, belt)), 0.3, 0, 0, SnapKind::CentreLine, "belt1");
  EXPECT_EQ(turnedAboutZ(gantry, 0).hi.x, 1.2);
}

TEST(PartSnap, ThePartNearestTheDropCapturesItTheLargestOfThoseOverlapped) {
  const std::vector<PartFootprint> belts{{"belt1", {0, 0, 0}, 0, kBelt}, {"belt2", {0, 1.2, 0}, 0, kBelt}};
  const Aabb sensor{{-0.05, -0.05, 0}, {0.05, 0.05, 1}};
  expectAt(placeDrop(query(down(0, 0.4), sensor, belts)), 0, 0.3, 0, SnapKind::SidePlusY, "belt1");
  expectAt(placeDrop(query(down(0, 0.8), sensor, belts)), 0, 0.9, 0, SnapKind::SideMinusY, "belt2");
  // a bin beside a belt where a photo-eye stands across it: the belt's side, not the eye's end
  const std::vector<PartFootprint> station{{"eye", {0.5, 0, 0}, 0, {{-0.025, -0.375, 0}, {0.025, 0.375, 0.9}}},
                                           {"belt1", {0, 0, 0}, 0, kBelt}};
  const Aabb bin{{-0.5, -0.4, 0}, {0.5, 0.4, 0.5}};
  expectAt(placeDrop(query(down(0.52, 0.6), bin, station)), 0.5, 0.65, 0, SnapKind::SidePlusY, "belt1");
}

TEST(PartSnap, AnItemOverTheTopOfAPartItFitsOnLandsThereOnTheGrid) {
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  const Aabb box{{-0.1, -0.1, 0}, {0.1, 0.1, 0.2}};
  auto item = [&](const core::Ray& ray) {
    auto q = query(ray, box, belt);
    q.loose = true;
    return placeDrop(q);
  };
  expectAt(item(down(0.42, 0.08)), 0.4, 0.1, 0.8, SnapKind::OnTop, "belt1");
  // kept inside its footprint
  expectAt(item(down(0.98, -0.2)), 0.9, -0.15, 0.8, SnapKind::OnTop, "belt1");
  // a machine (a sensor's post) pointed at on the belt's top stands beside it
  expectAt(placeDrop(query(down(0.42, 0.08), box, belt)), 0.4, 0.35, 0, SnapKind::SidePlusY, "belt1");
  // a belt over a belt does not fit on it: end to end instead
  expectAt(placeDrop(query(down(0.9, 0), kBelt, belt)), 2, 0, 0, SnapKind::EndPlusX, "belt1");
  // seen from the side, the ray enters the belt through its side: not on it, but where the ray
  // meets the floor behind it (1 m past its middle: too far to snap)
  expectAt(item({{0.52, -5, 0.6}, Vec3{0, 1, -0.1}.normalized()}), 0.5, 1, 0, SnapKind::Floor);
}

TEST(PartSnap, AMachinesBoxIsInItsOwnFrame) {
  scene::Scene s;
  const auto& types = s.types();
  auto* frame = s.create(*types.find(scene::NodeKind::Transform), "belt", s.root());
  frame->setValue(scene::field::Transform::Translation, std::array<double, 3>{2, 1, 0});
  frame->setValue(scene::field::Transform::Rotation, std::array<double, 4>{0, 0, 1, 90});
  auto* top = s.create(*types.find(scene::NodeKind::Transform), "top", *frame);
  top->setValue(scene::field::Transform::Translation, std::array<double, 3>{0, 0, 0.75});
  auto* cube = s.create(*types.find(scene::NodeKind::Cube), "surface", *top);
  cube->setValue(scene::field::Cube::Size, std::array<double, 3>{2, 0.5, 0.1});
  scene::updateTransforms(s.root());
  const auto box = localBox(*frame);
  EXPECT_NEAR(box.lo.x, -1, 1e-9);
  EXPECT_NEAR(box.hi.x, 1, 1e-9);
  EXPECT_NEAR(box.lo.y, -0.25, 1e-9);
  EXPECT_NEAR(box.hi.z, 0.8, 1e-9);
  EXPECT_TRUE(localBox(*cube).empty());  // no shape below it
  // a machine, not an item: its shape is in no body
  EXPECT_FALSE(looseMachine(*frame));
  auto* item = s.create(*types.find(scene::NodeKind::Transform), "box", s.root());
  EXPECT_FALSE(looseMachine(*item));  // no shape at all
  auto* body = s.create(*types.find(scene::NodeKind::Body), "body", *item);
  s.create(*types.find(scene::NodeKind::Cube), "look", *body);
  EXPECT_TRUE(looseMachine(*item));
}

TEST(PartSnap, OnlyATurnAboutZIsAnAngle) {
  EXPECT_EQ(angleAboutZ({0, 0, 1, 30}), 30);
  EXPECT_EQ(angleAboutZ({0, 0, -2, 30}), -30);
  EXPECT_EQ(angleAboutZ({1, 0, 0, 30}), 0);
  EXPECT_EQ(angleAboutZ({0, 0, 0, 30}), 0);
}

}  // namespace
}  // namespace gdpn::ide
