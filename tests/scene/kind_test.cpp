// Node kinds and field ids: each kind registered once, ids bound to their descriptions, the
// words of Enum fields in the order of their C++ enums, one field check, one shape extent.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/scene/actions.h"
#include "gdpn/scene/node.h"
#include "gdpn/scene/sensor_rules.h"

namespace gdpn::scene {
namespace {

TEST(NodeKinds, EveryKindHasItsTypeAndItsName) {
  const char* names[] = {"Group",    "Transform", "Material",      "Light",         "Camera",      "Fog",
                         "Cube",     "Sphere",    "Cylinder",      "Cone",          "Plane",       "Mesh",
                         "Terrain",  "World",     "Body",          "Joint",         "Conveyor",    "GradientField",
                         "Region",   "RangeFinder", "GradientSensor", "KeyboardSensor", "MouseSensor", "TimeSensor",
                         "ColorCamera", "DepthCamera", "LaserScan", "Imu", "Gps", "Contact", "ForceTorque"};
  static_assert(std::size(names) == kNodeKinds);
  for (std::size_t k = 0; k < kNodeKinds; ++k) {
    const NodeType* t = builtinTypes().find(static_cast<NodeKind>(k));
    ASSERT_NE(t, nullptr) << names[k];
    EXPECT_EQ(t->name, names[k]);
    EXPECT_EQ(builtinTypes().find(names[k]), t);
  }
}

TEST(FieldIds, NameTheFieldsTheyStandFor) {
  const auto& joint = *builtinTypes().find(NodeKind::Joint);
  EXPECT_EQ(joint.fields[static_cast<std::size_t>(field::Joint::Vel1)]->name, "vel1");
  EXPECT_EQ(joint.fields[static_cast<std::size_t>(field::Joint::ServoTime)]->name, "servo_time");
  const auto& world = *builtinTypes().find(NodeKind::World);
  EXPECT_EQ(world.fields[static_cast<std::size_t>(field::World::AutoDisable)]->name, "auto_disable");
  Scene s;
  Node* j = s.create(joint, "j", s.root());
  j->setValue(field::Joint::Vel1, 2.5);
  EXPECT_EQ(j->number(field::Joint::Vel1), 2.5);
  EXPECT_EQ(j->value(static_cast<std::size_t>(joint.fieldIndex("vel1"))), FieldValue(2.5));
}

TEST(FieldIds, EnumWordsFollowTheirCxxEnums) {
  Scene s;
  Node* j = s.create(*builtinTypes().find(NodeKind::Joint), "j", s.root());
  const std::pair<const char*, JointKind> kinds[] = {{"hinge", JointKind::Hinge},   {"slider", JointKind::Slider},
                                                     {"ball", JointKind::Ball},     {"universal", JointKind::Universal},
                                                     {"hinge2", JointKind::Hinge2}, {"fixed", JointKind::Fixed}};
  for (const auto& [word, kind] : kinds) {
    j->setValue(field::Joint::Kind, std::string(word));
    EXPECT_EQ(j->choice<JointKind>(field::Joint::Kind), kind) << word;
  }
  j->setValue(field::Joint::Control, std::string("position"));
  EXPECT_EQ(j->choice<JointControl>(field::Joint::Control), JointControl::Position);
  Node* r = s.create(*builtinTypes().find(NodeKind::Region), "r", s.root());
  const std::pair<const char*, RegionShape> shapes[] = {{"box", RegionShape::Box},           {"sphere", RegionShape::Sphere},
                                                        {"cylinder", RegionShape::Cylinder}, {"cone", RegionShape::Cone},
                                                        {"ray", RegionShape::Ray}};
  for (const auto& [word, shape] : shapes) {
    r->setValue(field::Region::Shape, std::string(word));
    EXPECT_EQ(r->choice<RegionShape>(field::Region::Shape), shape) << word;
  }
  Node* g = s.create(*builtinTypes().find(NodeKind::Gps), "g", s.root());
  g->setValue(field::Gps::Frame, std::string("geodetic"));
  EXPECT_EQ(g->choice<GpsFrame>(field::Gps::Frame), GpsFrame::Geodetic);
  // a DepthCamera reads the fields it takes from ColorCamera through their ids
  Node* d = s.create(*builtinTypes().find(NodeKind::DepthCamera), "d", s.root());
  EXPECT_EQ(d->number(field::ColorCamera::Far), 100.0);
  EXPECT_EQ(builtinTypes().find(NodeKind::LaserScan)->fields[static_cast<std::size_t>(field::LaserScan::Resolution)]->name,
            "resolution");
  const std::pair<const char*, Scope> scopes[] = {{"world", Scope::World}, {"siblings", Scope::Siblings}, {"parent", Scope::Parent}};
  for (const auto& [word, scope] : scopes) {
    r->setValue(field::Region::Scope, std::string(word));
    EXPECT_EQ(r->choice<Scope>(field::Region::Scope), scope) << word;
  }
  Node* m = s.create(*builtinTypes().find(NodeKind::Mesh), "m", s.root());
  m->setValue(field::Mesh::Collision, std::string("convex"));
  EXPECT_EQ(m->choice<MeshCollision>(field::Mesh::Collision), MeshCollision::Convex);
  Node* l = s.create(*builtinTypes().find(NodeKind::Light), "l", s.root());
  l->setValue(field::Light::Kind, std::string("spot"));
  EXPECT_EQ(l->choice<LightKind>(field::Light::Kind), LightKind::Spot);
  Node* c = s.create(*builtinTypes().find(NodeKind::Camera), "c", s.root());
  c->setValue(field::Camera::Kind, std::string("orbit"));
  EXPECT_EQ(c->choice<CameraKind>(field::Camera::Kind), CameraKind::Orbit);
  Node* f = s.create(*builtinTypes().find(NodeKind::Fog), "f", s.root());
  f->setValue(field::Fog::Kind, std::string("exponential"));
  EXPECT_EQ(f->choice<FogKind>(field::Fog::Kind), FogKind::Exponential);
}

TEST(FieldIdsDeathTest, AFieldOfAnotherKindIsAProgrammingError) {
  Scene s;
  Node* cube = s.create(*builtinTypes().find(NodeKind::Cube), "c", s.root());
  EXPECT_DEATH((void)cube->number(field::Sphere::Radius), "a field is read from a node of the kind that declares it");
  EXPECT_DEATH(cube->setValue(field::Cube::Size, 1.0), "a field is set to a value of its own kind");
}

const FieldDesc& fieldOf(NodeKind kind, const char* name) {
  const auto& t = *builtinTypes().find(kind);
  return *t.fields[static_cast<std::size_t>(t.fieldIndex(name))];
}

TEST(FieldCheck, OneRuleForEveryKindOfValue) {
  const auto& bounce = fieldOf(NodeKind::Material, "bounce");
  EXPECT_FALSE(bounce.check(0.5));
  EXPECT_EQ(bounce.check(1.5)->message, "'bounce' must lie in [0, 1], got 1.5");
  EXPECT_EQ(bounce.check(std::nan(""))->message, "'bounce' must be a finite number, got nan");
  EXPECT_EQ(bounce.check(std::string("x"))->message, "'bounce' expects a float value");
  const auto& diffuse = fieldOf(NodeKind::Material, "diffuse");
  const auto bad = diffuse.check(std::array<double, 3>{0.5, 2.0, 0.5});
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->component, 1);
  EXPECT_EQ(bad->message, "'diffuse' must lie in [0, 1], got 2");
  const auto& rotation = fieldOf(NodeKind::Transform, "rotation");
  EXPECT_FALSE(rotation.check(std::array<double, 4>{0, 0, 0, 0}));
  EXPECT_EQ(rotation.check(std::array<double, 4>{0, 0, 0, 90})->message, "'rotation' needs an axis that is not zero");
  const auto& kind = fieldOf(NodeKind::Joint, "kind");
  EXPECT_FALSE(kind.check(std::string("slider")));
  EXPECT_EQ(kind.check(std::string("slidr"))->message,
            "'kind' is one of hinge, slider, ball, universal, hinge2, fixed, got \"slidr\" (did you mean 'slider'?)");
  const auto& nx = fieldOf(NodeKind::GradientField, "nx");
  EXPECT_EQ(nx.check(std::int64_t{1})->message, "'nx' must lie in [2, 1e+06], got 1");
  const auto& vectors = fieldOf(NodeKind::GradientField, "vectors");
  EXPECT_EQ(vectors.check(std::vector<double>{1, 2, std::numeric_limits<double>::infinity()})->component, 2);
}

TEST(FieldCheck, ShapeDimensionsMustBeAboveZero) {
  // a length of 0 is refused where a shape or a sensor's volume needs one (min_open)
  const auto& size = fieldOf(NodeKind::Cube, "size");
  EXPECT_TRUE(size.min_open);
  const auto flat = size.check(std::array<double, 3>{1, 0, 1});
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->component, 1);
  EXPECT_EQ(flat->message, "'size' must be above 0, got 0");
  EXPECT_FALSE(size.check(std::array<double, 3>{1, 1e-6, 1}));
  EXPECT_EQ(size.rangeText(), "(0, 1e+12]");
  for (const auto& [kind, name] : std::vector<std::pair<NodeKind, const char*>>{
           {NodeKind::Sphere, "radius"}, {NodeKind::Cylinder, "radius"}, {NodeKind::Cylinder, "height"},
           {NodeKind::Cone, "radius"}, {NodeKind::Cone, "height"}, {NodeKind::Region, "radius"},
           {NodeKind::Region, "height"}, {NodeKind::Region, "length"}, {NodeKind::RangeFinder, "length"},
           {NodeKind::LaserScan, "length"}, {NodeKind::Terrain, "width"}, {NodeKind::GradientField, "depth"},
           {NodeKind::TimeSensor, "period"}, {NodeKind::Fog, "visibility"}}) {
    const auto& f = fieldOf(kind, name);
    ASSERT_TRUE(f.check(0.0)) << name;
    EXPECT_EQ(f.check(0.0)->message, "'" + std::string(name) + "' must be above 0, got 0");
    EXPECT_FALSE(f.check(0.25)) << name;
  }
  const auto& region = fieldOf(NodeKind::Region, "size");
  EXPECT_EQ(region.check(std::array<double, 3>{1, 1, -1})->component, 2);
  // a bound that is reached stays a closed one
  EXPECT_FALSE(fieldOf(NodeKind::Material, "friction").check(0.0));
}

TEST(FieldUnits, AJointsAxisOneFieldsFollowItsKind) {
  Scene s;
  Node& joint = *s.create(*builtinTypes().find(NodeKind::Joint), "j", s.root());
  const auto unit = [&](const char* name) { return unitOf(joint, static_cast<std::size_t>(joint.type().fieldIndex(name))); };
  // a hinge turns: degrees
  EXPECT_EQ(unit("lo1"), "deg");
  EXPECT_EQ(unit("hi1"), "deg");
  EXPECT_EQ(unit("target1"), "deg");
  EXPECT_EQ(unit("vel1"), "deg/s");
  EXPECT_EQ(unit("fmax1"), "N m");
  EXPECT_TRUE(isAngular(joint, static_cast<std::size_t>(joint.type().fieldIndex("lo1"))));
  // a slider slides: metres
  joint.setValue(field::Joint::Kind, std::string("slider"));
  EXPECT_EQ(unit("lo1"), "m");
  EXPECT_EQ(unit("hi1"), "m");
  EXPECT_EQ(unit("target1"), "m");
  EXPECT_EQ(unit("vel1"), "m/s");
  EXPECT_EQ(unit("fmax1"), "N");
  EXPECT_FALSE(isAngular(joint, static_cast<std::size_t>(joint.type().fieldIndex("vel1"))));
  // axis 2 is always angular; other fields keep their one unit
  EXPECT_EQ(unit("vel2"), "deg/s");
  EXPECT_EQ(unit("anchor"), "m");
  for (const auto* f : joint.type().fields) {
    EXPECT_EQ(f->unit.find(" or "), std::string::npos) << f->name << ": a unit is one unit";
  }
}

TEST(FieldCheck, ASensorsFieldsKeepTheirRulesWhenOneIsSetFromOutside) {
  // the rules between fields hold for a value set at run time as at load (sensor_rules.h)
  Scene s;
  Node* cam = s.create(*builtinTypes().find(NodeKind::DepthCamera), "cam", s.root());
  const std::size_t far = cam->slot(field::ColorCamera::Far), near = cam->slot(field::ColorCamera::Near);
  EXPECT_EQ(refusal(*cam, far, 20.0, AngleUnit::Degrees), "");
  EXPECT_EQ(refusal(*cam, far, 0.01, AngleUnit::Degrees), "far (0.01 m) must lie beyond near (0.05 m)");
  EXPECT_EQ(refusal(*cam, near, 1e-4, AngleUnit::Degrees),
            "far (100 m) is more than 100,000 times near (1e-04 m), which leaves the depth buffer too few steps to "
            "tell distances apart: raise near");
  EXPECT_EQ(sensorRule(*cam, near, 1e-4).field, near);
  Node* lidar = s.create(*builtinTypes().find(NodeKind::LaserScan), "lidar", s.root());
  const std::size_t lo = lidar->slot(field::LaserScan::MinAngle);
  EXPECT_EQ(refusal(*lidar, lo, 180.0, AngleUnit::Degrees), "has 360 rays but no angle between min_angle and max_angle");
  EXPECT_EQ(refusal(*lidar, lo, std::numbers::pi, AngleUnit::Radians),
            "has 360 rays but no angle between min_angle and max_angle");
  EXPECT_EQ(refusal(*lidar, lo, -90.0, AngleUnit::Degrees), "");
  EXPECT_EQ(sensorRule(*lidar, kAsItIs, {}).message, "");
}

TEST(ShapeExtent, IsTheOneSizeOfEveryPrimitive) {
  Scene s;
  auto make = [&](NodeKind kind) { return s.create(*builtinTypes().find(kind), "", s.root()); };
  Node* cube = make(NodeKind::Cube);
  cube->setValue(field::Cube::Size, std::array<double, 3>{1, 2, 3});
  EXPECT_EQ(shapeExtent(*cube), (core::Vec3{1, 2, 3}));
  Node* ball = make(NodeKind::Sphere);
  ball->setValue(field::Sphere::Radius, 0.25);
  EXPECT_EQ(shapeExtent(*ball), (core::Vec3{0.5, 0.5, 0.5}));
  Node* can = make(NodeKind::Cylinder);
  can->setValue(field::Cylinder::Radius, 0.5);
  can->setValue(field::Cylinder::Height, 2.0);
  EXPECT_EQ(shapeExtent(*can), (core::Vec3{1, 1, 2}));
  Node* cone = make(NodeKind::Cone);
  EXPECT_EQ(shapeExtent(*cone), (core::Vec3{1, 1, 1}));
  Node* region = make(NodeKind::Region);
  region->setValue(field::Region::Shape, std::string("sphere"));
  region->setValue(field::Region::Radius, 2.0);
  EXPECT_EQ(shapeExtent(*region), (core::Vec3{4, 4, 4}));
  region->setValue(field::Region::Shape, std::string("ray"));
  EXPECT_EQ(shapeExtent(*region), (core::Vec3{0, 0, 0}));
  EXPECT_EQ(shapeExtent(*make(NodeKind::Plane)), (core::Vec3{0, 0, 0}));
  // bounds and the extent agree
  const core::Aabb box = shapeBounds(*can);
  EXPECT_EQ(box.hi - box.lo, shapeExtent(*can));
}

}  // namespace
}  // namespace gdpn::scene
