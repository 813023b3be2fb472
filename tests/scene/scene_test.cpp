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

TEST(Actions, TransformsMadeAgainBelowANodeAreThoseOfTheWholeScene) {
  // outer (at (1, 0, 0), turned a quarter, scaled 2) > inner (at (2, 0, 0)) > cube: inner
  // moved to (3, 0, 0) and made again from inner alone stands where the whole scene's pass
  // puts it (the parent's own placement and scale counted)
  Scene s;
  Node* outer = s.create(T("Transform"), "outer", s.root());
  outer->setValue(0, std::array<double, 3>{1, 0, 0});
  outer->setValue(1, std::array<double, 4>{0, 0, 1, 90});
  outer->setValue(2, std::array<double, 3>{2, 2, 2});
  Node* inner = s.create(T("Transform"), "inner", *outer);
  inner->setValue(0, std::array<double, 3>{2, 0, 0});
  Node* cube = s.create(T("Cube"), "cube", *inner);
  updateTransforms(s.root());
  inner->setValue(0, std::array<double, 3>{3, 0, 0});
  updateTransforms(*inner);
  // (3, 0, 0) scaled 2, turned a quarter: (0, 6, 0); plus (1, 0, 0)
  EXPECT_NEAR(cube->world.position.x, 1.0, 1e-12);
  EXPECT_NEAR(cube->world.position.y, 6.0, 1e-12);
  EXPECT_NEAR(cube->world_scale.x, 2.0, 1e-12);
  const core::Pose alone = cube->world;
  updateTransforms(s.root());
  EXPECT_NEAR(cube->world.position.x, alone.position.x, 1e-12);
  EXPECT_NEAR(cube->world.position.y, alone.position.y, 1e-12);
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

namespace gdpn::scene {
namespace {

TEST(UserData, TextReadsAsABoolANumberOrItself) {
  EXPECT_EQ(datumFromText("true"), FieldValue(true));
  EXPECT_EQ(datumFromText("false"), FieldValue(false));
  EXPECT_EQ(datumFromText("17"), FieldValue(std::int64_t{17}));
  EXPECT_EQ(datumFromText("-3"), FieldValue(std::int64_t{-3}));
  EXPECT_EQ(datumFromText("2.5"), FieldValue(2.5));
  EXPECT_EQ(datumFromText("1e3"), FieldValue(1000.0));
  // what is not exactly one of those stays text
  for (const char* text : {"", "red", "True", "0x10", "+5", "1.5 m", "inf", "nan", "99999999999999999999e999"}) {
    EXPECT_EQ(datumFromText(text), FieldValue(std::string(text))) << text;
  }
  EXPECT_EQ(datumFromText("[1, 2.5]"), FieldValue(std::vector<double>{1, 2.5}));
  EXPECT_EQ(datumFromText("[]"), FieldValue(std::vector<double>{}));
  for (const char* text : {"[1, ]", "[a]", "[1 2]", "[1,,2]", "["}) {
    EXPECT_EQ(datumFromText(text), FieldValue(std::string(text))) << text;
  }
  // a whole number too large for 64 bits is a number
  EXPECT_EQ(datumFromText("99999999999999999999"), FieldValue(1e20));
}

TEST(UserData, TextOfADatumReadsBackAsTheSameDatum) {
  for (const FieldValue& v : {FieldValue(true), FieldValue(std::int64_t{-4}), FieldValue(2.0), FieldValue(0.1),
                              FieldValue(1e300), FieldValue(std::string("crate"))}) {
    EXPECT_EQ(datumFromText(datumText(v)), v) << datumText(v);
  }
  EXPECT_EQ(datumText(FieldValue(2.0)), "2.0");
  EXPECT_EQ(datumText(FieldValue(std::vector<double>{1, 2.5})), "[1, 2.5]");
  EXPECT_EQ(datumFromText(datumText(FieldValue(std::vector<double>{1, 2.5}))), FieldValue(std::vector<double>{1, 2.5}));
  EXPECT_TRUE(datumNeedsQuotes("[1]"));
  EXPECT_TRUE(datumNeedsQuotes("007"));
  EXPECT_TRUE(datumNeedsQuotes("false"));
  EXPECT_TRUE(datumNeedsQuotes(""));
  EXPECT_FALSE(datumNeedsQuotes("crate"));
}

TEST(UserData, ANodeKeepsItsDataInOrderAndACopyTakesThem) {
  Scene s;
  Node* a = s.create(*s.types().find(NodeKind::Group), "a", s.root());
  a->setDatum("kind", std::string("crate"));
  a->setDatum("order", std::int64_t{3});
  a->setDatum("kind", std::string("box"));  // set again: stays first
  ASSERT_EQ(a->data.size(), 2u);
  EXPECT_EQ(a->data[0].first, "kind");
  EXPECT_EQ(*a->datum("kind"), FieldValue(std::string("box")));
  EXPECT_EQ(a->datum("colour"), nullptr);
  a->is_template = true;
  Node* b = s.copy(*a, s.root(), "b");
  EXPECT_TRUE(b->is_template);
  EXPECT_EQ(b->data, a->data);
  auto c = s.clone();
  EXPECT_TRUE(s.sameAs(*c));
  EXPECT_TRUE(b->eraseDatum("order"));
  EXPECT_FALSE(b->eraseDatum("order"));
  EXPECT_FALSE(s.sameAs(*c));  // data count in sameness
  c->find("b")->eraseDatum("order");
  EXPECT_TRUE(s.sameAs(*c));
  c->find("a")->is_template = false;
  EXPECT_FALSE(s.sameAs(*c));  // and so does the template mark
}

TEST(Templates, TraversalsThatSimulateOrDrawSkipThemAndWhatIsBelow) {
  Scene s;
  const auto& group = *s.types().find(NodeKind::Group);
  const auto& cube = *s.types().find(NodeKind::Cube);
  Node* store = s.create(group, "store", s.root());
  store->is_template = true;
  s.create(cube, "box", *store);
  Node* area = s.create(group, "area", s.root());
  s.create(cube, "crate", *area);
  std::vector<std::string> all, live;
  traverse(s.root(), [&](Node& n, const TraversalState&) { all.push_back(n.path()); });
  traverse(s.root(), [&](Node& n, const TraversalState&) { live.push_back(n.path()); }, {}, Templates::Skip);
  EXPECT_EQ(all, (std::vector<std::string>{"", "store", "store/box", "area", "area/crate"}));
  EXPECT_EQ(live, (std::vector<std::string>{"", "area", "area/crate"}));
  // a template is not hit, and the box around the scene leaves it out
  updateTransforms(s.root());
  EXPECT_EQ(pick(s.root(), core::Ray{{0, 0, 5}, {0, 0, -1}}).shape, s.find("area/crate"));
  EXPECT_EQ(boundingBox(s.root()).hi.z, 0.5);
  // unless asked for the template itself
  EXPECT_FALSE(boundingBox(*store).empty());
}

TEST(Templates, TheMaterialInEffectIsTheNearestBeforeAtAnyLevel) {
  Scene s;
  const auto& group = *s.types().find(NodeKind::Group);
  const auto& material = *s.types().find(NodeKind::Material);
  const auto& cube = *s.types().find(NodeKind::Cube);
  Node* outer = s.create(material, "outer", s.root());
  Node* g = s.create(group, "g", s.root());
  Node* first = s.create(cube, "first", *g);
  Node* inner = s.create(material, "inner", *g);
  Node* second = s.create(cube, "second", *g);
  EXPECT_EQ(materialAt(*first), outer);
  EXPECT_EQ(materialAt(*second), inner);
  EXPECT_EQ(materialAt(*outer), nullptr);
  EXPECT_EQ(g->lastChild(NodeKind::Material), inner);
  EXPECT_EQ(g->lastChild(NodeKind::Sphere), nullptr);
}

TEST(Templates, TheShapesAreDrivenByTheLastConveyorBesideThemThatIsNoTemplate) {
  Scene s;
  const auto& group = *s.types().find(NodeKind::Group);
  const auto& conveyor = *s.types().find(NodeKind::Conveyor);
  const auto& cube = *s.types().find(NodeKind::Cube);
  Node* belt = s.create(group, "belt", s.root());
  s.create(cube, "deck", *belt);
  EXPECT_EQ(drivingConveyor(*belt), nullptr);
  Node* first = s.create(conveyor, "first", *belt);
  EXPECT_EQ(drivingConveyor(*belt), first);
  Node* second = s.create(conveyor, "second", *belt);
  EXPECT_EQ(drivingConveyor(*belt), second);
  // a template Conveyor moves nothing: the one before it drives, or none
  second->is_template = true;
  EXPECT_EQ(drivingConveyor(*belt), first);
  first->is_template = true;
  EXPECT_EQ(drivingConveyor(*belt), nullptr);
  // only the children count, not the nodes below them
  EXPECT_EQ(drivingConveyor(s.root()), nullptr);
}

}  // namespace
}  // namespace gdpn::scene
