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
  // a through-beam's posts on both sides: across the belt, on its centre line
  const Aabb eye{{-0.025, -0.375, 0}, {0.025, 0.375, 0.9}};
  expectAt(placeDrop(query(down(0.4, 0.5), eye, belt)), 0.4, 0, 0, SnapKind::CentreLine, "belt1");
}

TEST(PartSnap, ThePartNearestTheDropCapturesIt) {
  const std::vector<PartFootprint> belts{{"belt1", {0, 0, 0}, 0, kBelt}, {"belt2", {0, 1.2, 0}, 0, kBelt}};
  const Aabb sensor{{-0.05, -0.05, 0}, {0.05, 0.05, 1}};
  expectAt(placeDrop(query(down(0, 0.4), sensor, belts)), 0, 0.3, 0, SnapKind::SidePlusY, "belt1");
  expectAt(placeDrop(query(down(0, 0.8), sensor, belts)), 0, 0.9, 0, SnapKind::SideMinusY, "belt2");
}

TEST(PartSnap, OverTheTopOfAPartItFitsOnItLandsThereOnTheGrid) {
  const std::vector<PartFootprint> belt{{"belt1", {0, 0, 0}, 0, kBelt}};
  const Aabb box{{-0.1, -0.1, 0}, {0.1, 0.1, 0.2}};
  expectAt(placeDrop(query(down(0.42, 0.08), box, belt)), 0.4, 0.1, 0.8, SnapKind::OnTop, "belt1");
  // kept inside its footprint
  expectAt(placeDrop(query(down(0.98, -0.2), box, belt)), 0.9, -0.15, 0.8, SnapKind::OnTop, "belt1");
  // a belt over a belt does not fit on it: end to end instead
  expectAt(placeDrop(query(down(0.9, 0), kBelt, belt)), 2, 0, 0, SnapKind::EndPlusX, "belt1");
  // seen from the side, the ray enters the belt through its side: the floor behind it
  const auto behind = placeDrop(query({{0.5, -5, 0.6}, Vec3{0, 1, -0.1}.normalized()}, box, belt));
  ASSERT_TRUE(behind);
  EXPECT_NE(behind->kind, SnapKind::OnTop);
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
}

TEST(PartSnap, OnlyATurnAboutZIsAnAngle) {
  EXPECT_EQ(angleAboutZ({0, 0, 1, 30}), 30);
  EXPECT_EQ(angleAboutZ({0, 0, -2, 30}), -30);
  EXPECT_EQ(angleAboutZ({1, 0, 0, 30}), 0);
  EXPECT_EQ(angleAboutZ({0, 0, 0, 30}), 0);
}

}  // namespace
}  // namespace gdpn::ide
