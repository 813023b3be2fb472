// The scene tree: type descriptions, paths, handles, copies, transforms, bounds, picking.

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "gdpn/scene/actions.h"
#include "gdpn/scene/node.h"

namespace gdpn::scene {
namespace {

const NodeType& T(const char* name) { return *builtinTypes().find(name); }

TEST(NodeTypes, EveryBuiltinTypeIsDescribedOnce) {
  for (const char* name : {"Group", "Transform", "Material", "Light", "Camera", "Fog", "Cube", "Sphere", "Cylinder",
                           "Cone", "Plane", "Mesh", "World", "Body", "Joint", "Conveyor"}) {
    const NodeType* t = builtinTypes().find(name);
    ASSERT_NE(t, nullptr) << name;
    EXPECT_FALSE(t->doc.empty()) << name;
    for (const auto* f : t->fields) {
      EXPECT_FALSE(f->doc.empty()) << name << "." << f->name;
      if (f->kind == FieldKind::Enum) {
        EXPECT_FALSE(f->choices.empty()) << name << "." << f->name;
      }
    }
  }
  // Transform inherits nothing but is a Group; fields come with units
  EXPECT_TRUE(T("Transform").is(T("Group")));
  EXPECT_EQ(T("Transform").fields[0]->unit, "m");
  const auto& joint = T("Joint");
  EXPECT_GE(joint.fieldIndex("vel1"), 0);
  EXPECT_GE(joint.fieldIndex("fmax1"), 0);
  EXPECT_EQ(joint.fields[static_cast<std::size_t>(joint.fieldIndex("kind"))]->choices.size(), 6u);
}

TEST(SceneTree, PathsNamesAndSiblings) {
  Scene s;
  Node* line = s.create(T("Transform"), "line", s.root());
  Node* station = s.create(T("Group"), "stationA", *line);
  Node* rod = s.create(T("Body"), "rod", *station);
  Node* shape = s.create(T("Cube"), "", *rod);
  EXPECT_EQ(rod->path(), "line/stationA/rod");
  EXPECT_EQ(shape->path(), "line/stationA/rod/#0");
  EXPECT_EQ(s.find("line/stationA/rod"), rod);
  EXPECT_EQ(s.find("line/stationA/rod/#0"), shape);
  EXPECT_EQ(rod->find("../.."), line);
  EXPECT_EQ(s.find("line/nowhere"), nullptr);
  EXPECT_EQ(s.find("line/#9"), nullptr);
  // siblings: unique names; shapes take no children
  EXPECT_EQ(s.create(T("Group"), "stationA", *line), nullptr);
  EXPECT_EQ(s.create(T("Cube"), "x", *shape), nullptr);
  Node* stationB = s.create(T("Group"), "stationB", *line);
  EXPECT_EQ(station->next(), stationB);
  EXPECT_EQ(stationB->prev(), station);
  EXPECT_EQ(station->prev(), nullptr);
  EXPECT_EQ(s.size(), 6u);
}

TEST(SceneTree, ARenameKeepsTheNodesPlaceAndItsSubtree) {
  Scene s;
  Node* line = s.create(T("Transform"), "line", s.root());
  Node* a = s.create(T("Group"), "a", *line);
  Node* b = s.create(T("Group"), "b", *line);
  s.create(T("Body"), "rod", *a);
  ASSERT_TRUE(s.rename(*a, "first"));
  EXPECT_EQ(s.find("line/first/rod")->parent(), a);
  EXPECT_EQ(s.find("line/a"), nullptr);
  EXPECT_EQ(a->next(), b);  // still before b
  EXPECT_FALSE(s.rename(*b, "first"));
  EXPECT_EQ(b->name(), "b");
  EXPECT_FALSE(s.rename(s.root(), "top"));
}

TEST(SceneTree, HandlesStopResolvingWhenTheirNodeIsDeleted) {
  Scene s;
  Node* a = s.create(T("Group"), "a", s.root());
  Node* b = s.create(T("Cube"), "b", *a);
  const NodeHandle ha = a->handle(), hb = b->handle();
  EXPECT_EQ(s.resolve(hb), b);
  s.destroy(*a);
  EXPECT_EQ(s.resolve(ha), nullptr);
  EXPECT_EQ(s.resolve(hb), nullptr);
  EXPECT_EQ(s.size(), 1u);
  // the slot is reused with a new generation: the old handle still resolves to nothing
  Node* c = s.create(T("Sphere"), "c", s.root());
  EXPECT_EQ(s.resolve(hb), nullptr);
  EXPECT_EQ(s.resolve(c->handle()), c);
  EXPECT_EQ(s.resolve(0), nullptr);
}

TEST(SceneTree, CopyAndCloneKeepTheSubtree) {
  Scene s;
  Node* cell = s.create(T("Transform"), "cell", s.root());
  cell->setValue(0, std::array<double, 3>{1, 2, 3});
  s.create(T("Cube"), "box", *cell);
  Node* copy = s.copy(*cell, s.root(), "cell2");
  ASSERT_NE(copy, nullptr);
  EXPECT_EQ(copy->vec3(field::Transform::Translation), (core::Vec3{1, 2, 3}));
  EXPECT_NE(s.find("cell2/box"), nullptr);
  EXPECT_EQ(s.copy(*cell, s.root(), "cell2"), nullptr);  // name taken
  auto clone = s.clone();
  EXPECT_TRUE(clone->sameAs(s));
  clone->find("cell2/box")->setValue(0, std::array<double, 3>{9, 9, 9});
  EXPECT_FALSE(clone->sameAs(s));
}

TEST(Actions, TransformsComposeFromTheRoot) {
  Scene s;
  Node* outer = s.create(T("Transform"), "outer", s.root());
  outer->setValue(0, std::array<double, 3>{1, 0, 0});
  outer->setValue(1, std::array<double, 4>{0, 0, 1, 90});  // quarter turn about z
  Node* inner = s.create(T("Transform"), "inner", *outer);
  inner->setValue(0, std::array<double, 3>{2, 0, 0});
  Node* cube = s.create(T("Cube"), "cube", *inner);
  updateTransforms(s.root());
  // (2, 0, 0) turned a quarter about z is (0, 2, 0); plus (1, 0, 0)
  EXPECT_NEAR(cube->world.position.x, 1.0, 1e-12);
  EXPECT_NEAR(cube->world.position.y, 2.0, 1e-12);
  EXPECT_NEAR(cube->world.position.z, 0.0, 1e-12);
  const core::Vec3 x_axis = cube->world.rotation.rotate({1, 0, 0});
  EXPECT_NEAR(x_axis.y, 1.0, 1e-12);
}

TEST(Actions, ScaleScalesTranslationsAndShapes) {
  Scene s;
  Node* t = s.create(T("Transform"), "t", s.root());
  t->setValue(2, std::array<double, 3>{2, 2, 2});
  Node* inner = s.create(T("Transform"), "inner", *t);
  inner->setValue(0, std::array<double, 3>{1, 0, 0});
  Node* cube = s.create(T("Cube"), "c", *inner);
  updateTransforms(s.root());
  EXPECT_NEAR(cube->world.position.x, 2.0, 1e-12);
  const core::Aabb box = boundingBox(*cube);
  EXPECT_NEAR(box.lo.x, 1.0, 1e-12);
  EXPECT_NEAR(box.hi.x, 3.0, 1e-12);
}

TEST(Actions, BoundingBoxOfASubtree) {
  Scene s;
  Node* g = s.create(T("Group"), "g", s.root());
  Node* a = s.create(T("Transform"), "a", *g);
  a->setValue(0, std::array<double, 3>{-2, 0, 0});
  s.create(T("Sphere"), "ball", *a);  // radius 0.5
  Node* b = s.create(T("Transform"), "b", *g);
  b->setValue(0, std::array<double, 3>{3, 1, 0});
  Node* cyl = s.create(T("Cylinder"), "c", *b);
  cyl->setValue(1, 4.0);  // height
  updateTransforms(s.root());
  const core::Aabb box = boundingBox(*g);
  EXPECT_NEAR(box.lo.x, -2.5, 1e-12);
  EXPECT_NEAR(box.hi.x, 3.5, 1e-12);
  EXPECT_NEAR(box.lo.z, -2.0, 1e-12);
  EXPECT_NEAR(box.hi.z, 2.0, 1e-12);
  EXPECT_NEAR(box.hi.y, 1.5, 1e-12);
}

TEST(Actions, PickFindsTheNearestShapeOnTheRay) {
  Scene s;
  Node* near_t = s.create(T("Transform"), "near", s.root());
  near_t->setValue(0, std::array<double, 3>{3, 0, 0});
  Node* near_box = s.create(T("Cube"), "box", *near_t);
  Node* far_t = s.create(T("Transform"), "far", s.root());
  far_t->setValue(0, std::array<double, 3>{10, 0, 0});
  s.create(T("Cube"), "box", *far_t);
  updateTransforms(s.root());
  const Pick hit = pick(s.root(), {{0, 0, 0}, {1, 0, 0}});
  EXPECT_EQ(hit.shape, near_box);
  EXPECT_NEAR(hit.distance, 2.5, 1e-12);  // the near face of a unit cube at x = 3
  EXPECT_EQ(pick(s.root(), {{0, 0, 0}, {0, 1, 0}}).shape, nullptr);
}

TEST(Actions, AMaterialHoldsForTheShapesAfterIt) {
  Scene s;
  Node* g = s.create(T("Group"), "g", s.root());
  Node* before = s.create(T("Cube"), "before", *g);
  Node* red = s.create(T("Material"), "red", *g);
  Node* after = s.create(T("Cube"), "after", *g);
  std::map<Node*, const Node*> seen;
  traverse(s.root(), [&](Node& n, const TraversalState& st) { seen[&n] = st.material; });
  EXPECT_EQ(seen[before], nullptr);
  EXPECT_EQ(seen[after], red);
}

}  // namespace
}  // namespace gdpn::scene
