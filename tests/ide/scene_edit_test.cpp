// Editing the scene tree through commands, on the factory example: adding, renaming (the
// marking follows), duplicating, deleting (refused while the net holds the node, unless its
// marking goes too), and random sequences of scene and net edits that undo to the starting save
// byte for byte and redo to the last.

#include <gtest/gtest.h>

#include <random>

#include "gdpn/ide/document.h"
#include "ide/edit_support.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/scene_edit.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"

namespace gdpn::ide {
namespace {

using testing::openFactory;
using testing::readsBack;
using testing::undoesToStartAndRedoesToEnd;

SceneEdit edit(SceneEditKind kind, std::string path, std::string name = {}, std::string type = {}) {
  SceneEdit e;
  e.kind = kind;
  e.path = std::move(path);
  e.name = std::move(name);
  e.type = std::move(type);
  return e;
}

std::string run(Document& doc, SceneEdit e) { return doc.execute(std::make_unique<SceneEditCommand>(std::move(e))); }

TEST(SceneEdit, ANodeIsAddedUnderItsParentWithAFreshName) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Add, "line", "", "Cube")), "");
  ASSERT_NE(doc->scene()->find("line/cube_1"), nullptr);
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Add, "line", "", "Cube")), "");
  EXPECT_NE(doc->scene()->find("line/cube_2"), nullptr);
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Add, "", "marker", "Sphere")), "");
  EXPECT_NE(doc->scene()->find("marker"), nullptr);
  readsBack(doc->text());
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Add, "line", "", "Teapot")), "no node type 'Teapot'");
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Add, "line", "cube_1", "Cube")), "'line' has a child 'cube_1' already");
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Add, "marker", "", "Cube")), "a Sphere holds no other nodes");
  while (doc->undo()) {
  }
  EXPECT_EQ(doc->text(), before);
}

TEST(SceneEdit, DeletingANodeTheNetHoldsSaysWhereUnlessItsMarkingGoesToo) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  const auto uses = usesOf(doc->model().net, "arm");
  ASSERT_EQ(uses.size(), 3u);
  EXPECT_EQ(uses[0], "factory/P1 (b0)");
  const auto why = run(*doc, edit(SceneEditKind::Delete, "arm"));
  EXPECT_NE(why.find("'arm' is used by the net: factory/P1 (b0), factory/P1 (b1), factory/P1 (b2)"), std::string::npos) << why;
  EXPECT_EQ(doc->text(), before);
  auto both = edit(SceneEditKind::Delete, "arm");
  both.with_marking = true;
  ASSERT_EQ(run(*doc, both), "");
  EXPECT_EQ(doc->scene()->find("arm"), nullptr);
  EXPECT_TRUE(usesOf(doc->model().net, "arm").empty());
  readsBack(doc->text());
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
}

TEST(SceneEdit, ARenameCarriesTheMarkingAndADuplicateStandsBesideItsSource) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Rename, "arm", "robot")), "");
  EXPECT_EQ(usesOf(doc->model().net, "robot").size(), 3u);
  EXPECT_TRUE(usesOf(doc->model().net, "arm").empty());
  EXPECT_NE(doc->text().find("b0: [robot/turn]"), std::string::npos);
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Rename, "robot", "line")), "'line' is taken beside it");
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Rename, "robot", "9lives")),
            "'9lives' is not a name (letters, digits and _, not starting with a digit)");
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Duplicate, "boxes/b00")), "");
  EXPECT_NE(doc->scene()->find("boxes/b00_1"), nullptr);
  readsBack(doc->text());
  // the renamed model still compiles and runs: its net names its nodes by their new paths
  core::Diagnostics diags;
  auto sim = model::Simulation::create(doc->snapshot(), diags);
  EXPECT_TRUE(sim) << diags.str();
}

TEST(SceneEdit, AReparentedSubtreeKeepsItsFieldsAndTheMarkingFollowsIt) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  // the box b05 (a token of factory/buffer) under the line group
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Reparent, "boxes/b05", "line")), "");
  EXPECT_EQ(doc->scene()->find("boxes/b05"), nullptr);
  ASSERT_NE(doc->scene()->find("line/b05/box"), nullptr);
  EXPECT_NE(doc->text().find("line/b05/box"), std::string::npos) << "the marking follows";
  EXPECT_EQ(doc->text().find("boxes/b05/box"), std::string::npos);
  // and to the top of the scene
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Reparent, "line/b05", "")), "");
  EXPECT_NE(doc->scene()->find("b05/box"), nullptr);
  // refused: under itself, under a node that takes no children, where a sibling has its name
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Reparent, "arm", "arm/turn")), "a node cannot go under itself");
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Reparent, "b05", "line/belt1/#0")), "a Cube holds no other nodes");
  ASSERT_EQ(run(*doc, edit(SceneEditKind::Add, "line", "arm", "Group")), "");
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Reparent, "line/arm", "")), "'the scene' has a child 'arm' already");
  EXPECT_EQ(run(*doc, edit(SceneEditKind::Reparent, "arm", "")), "'arm' is there already");
  while (doc->undo()) {
  }
  EXPECT_EQ(doc->text(), before);
}

TEST(SceneEdit, AnySequenceOfSceneAndNetEditsUndoesToTheStartAndRedoesToTheEnd) {
  static const char* kTypes[] = {"Cube", "Sphere", "Group", "Transform", "Body", "Region", "Light"};
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    auto doc = openFactory();
    ASSERT_TRUE(doc);
    const auto start = doc->text();
    std::mt19937 rng(seed);
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    int applied = 0;
    for (int i = 0; i < 80; ++i) {
      // a node of the tree as it is now, by walking down from the root
      std::vector<std::string> paths{""};
      for (const scene::Node* n = &doc->scene()->root(); !n->children().empty();) {
        n = n->children()[pick(n->children().size())].get();
        paths.push_back(n->path());
      }
      std::string why;
      if (pick(4) == 0) {
        auto e = makeNetEdit(NetEditKind::AddPlace, "factory", "q" + std::to_string(pick(20)));
        why = doc->execute(std::make_unique<NetEditCommand>(e));
      } else {
        SceneEdit e;
        e.kind = static_cast<SceneEditKind>(pick(6));
        e.path = paths[pick(paths.size())];
        e.type = kTypes[pick(std::size(kTypes))];
        e.name = pick(3) == 0 ? std::string() : "n" + std::to_string(pick(5));
        if (e.kind == SceneEditKind::Reparent) e.name = paths[pick(paths.size())];  // under another node of the walk
        if (e.kind == SceneEditKind::Paste && paths.size() > 1) {
          // a copy of a node of the walk, as the clipboard would hold it
          auto fragment = std::make_shared<scene::Scene>(doc->scene()->types());
          fragment->copy(*doc->scene()->find(paths[1 + pick(paths.size() - 1)]), fragment->root());
          e.fragment = fragment;
        }
        e.with_marking = pick(2) == 0;
        why = run(*doc, e);
      }
      applied += why.empty() ? 1 : 0;
    }
    EXPECT_GT(applied, 20) << "seed " << seed;
    undoesToStartAndRedoesToEnd(*doc, start, "seed " + std::to_string(seed));
  }
}

}  // namespace
}  // namespace gdpn::ide
