// The net editor's group edits and arcs as items (issue 57): several constructs moved or
// deleted as one step, an arc changed in place or reversed, an instance added, and the
// selection of several things kept across undo.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/net/compile.h"
#include "ide/edit_support.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

constexpr const char* kModel = R"Y(gdpn: 1
pages:
  main:
    places:
      a: {tokens: 2, at: [0, 0]}
      b: {at: [4, 0]}
    transitions:
      t: {at: [2, 0]}
    instances:
      c1: {type: cell, at: [2, 3]}
    arcs:
      - a -> t
      - t -> b
      - t -> c1/enter
page_types:
  cell:
    references: [enter]
    places:
      enter: {}
)Y";

class GroupEdit : public gdpn::testing::TempDirTest {
 protected:
  void SetUp() override {
    gdpn::testing::TempDirTest::SetUp();
    core::Diagnostics diags;
    doc_ = Document::open(write("m.gdpn.yaml", kModel), diags);
    ASSERT_TRUE(doc_) << diags.str();
  }
  std::string run(NetEdit e) { return doc_->execute(std::make_unique<NetEditCommand>(std::move(e))); }
  const net::PageSpec& main() { return *findPage(doc_->model().net, "main"); }
  std::unique_ptr<Document> doc_;
};

TEST_F(GroupEdit, ADragOfSeveralConstructsIsOneStepAndUndoPutsThemBack) {
  const auto start = doc_->text();
  for (int step = 1; step <= 3; ++step) {  // three frames of one drag
    auto e = makeNetEdit(NetEditKind::MoveMany, "main", {});
    e.moves = {{"a", {0, 0.25 * step}}, {"t", {2, 0.25 * step}}, {"c1", {2, 3 + 0.25 * step}}};
    e.drag = 7;
    ASSERT_EQ(run(e), "");
  }
  EXPECT_EQ(doc_->history().depth(), 1u);
  EXPECT_EQ(doc_->history().undoLabel(), "move 3 items of main");
  EXPECT_EQ(main().places[0].position, (net::EditorPos{0, 0.75}));
  EXPECT_EQ(main().instances[0].position, (net::EditorPos{2, 3.75}));
  ASSERT_TRUE(doc_->undo());
  EXPECT_EQ(doc_->text(), start);
  // a name not on the page: refused, nothing moved
  auto bad = makeNetEdit(NetEditKind::MoveMany, "main", {});
  bad.moves = {{"a", {9, 9}}, {"nothere", {1, 1}}};
  EXPECT_EQ(run(bad), "no place, transition or instance 'nothere' on page 'main'");
  EXPECT_EQ(doc_->text(), start);
}

TEST_F(GroupEdit, ADeleteOfSeveralItemsTakesTheirArcsAndIsOneStep) {
  const auto start = doc_->text();
  auto e = makeNetEdit(NetEditKind::DeleteMany, "main", {});
  e.names = {"b", "c1"};  // the instance takes the arc to its port with it
  net::ArcSpec arc;
  arc.from = "a";
  arc.to = "t";
  e.arcs = {arc};
  ASSERT_EQ(run(e), "");
  EXPECT_EQ(main().places.size(), 1u);
  EXPECT_TRUE(main().instances.empty());
  EXPECT_TRUE(main().arcs.empty());
  EXPECT_EQ(doc_->history().undoLabel(), "delete 3 items of main");
  testing::undoesToStartAndRedoesToEnd(*doc_, start, "delete many");
  // an arc that is not there: refused as a whole
  ASSERT_TRUE(doc_->undo());
  arc.kind = net::ArcKind::Test;
  e.arcs = {arc};
  e.names = {"b"};
  EXPECT_EQ(run(e), "no test arc from 'a' to 't' on page 'main'");
  EXPECT_EQ(doc_->text(), start);
}

TEST_F(GroupEdit, AnArcIsChangedInPlaceAndReversedUnlessItWouldBeATestArcOutOfATransition) {
  auto e = makeNetEdit(NetEditKind::SetArc, "main", "a", "t");
  net::ArcSpec arc = main().arcs[0];
  arc.kind = net::ArcKind::Test;
  arc.weights = {net::SlotCount{net::kDefaultSlot, 3}};
  e.arc = arc;
  ASSERT_EQ(run(e), "");
  EXPECT_EQ(main().arcs[0].kind, net::ArcKind::Test);  // where it was in the list
  EXPECT_NE(doc_->text().find("{from: a, to: t, kind: test, weight: 3}"), std::string::npos) << doc_->text();
  // a test arc reversed would run out of a transition: refused
  auto turn = makeNetEdit(NetEditKind::SetArc, "main", "a", "t");
  turn.arc_kind = net::ArcKind::Test;
  net::ArcSpec turned = main().arcs[0];
  std::swap(turned.from, turned.to);
  turn.arc = turned;
  EXPECT_EQ(run(turn), "a test arc runs from a place to a transition");
  // a normal arc reversed: t -> b becomes b -> t
  auto flip = makeNetEdit(NetEditKind::SetArc, "main", "t", "b");
  net::ArcSpec flipped = main().arcs[1];
  std::swap(flipped.from, flipped.to);
  flip.arc = flipped;
  ASSERT_EQ(run(flip), "");
  EXPECT_EQ(main().arcs[1].from, "b");
  EXPECT_EQ(main().arcs[1].to, "t");
  // a weight of 0 is refused
  auto zero = makeNetEdit(NetEditKind::SetArc, "main", "b", "t");
  net::ArcSpec none = main().arcs[1];
  none.weights = {net::SlotCount{net::kDefaultSlot, 0}};
  zero.arc = none;
  EXPECT_EQ(run(zero), "an arc's weight is a whole number from 1 to 10^9");
}

TEST_F(GroupEdit, AnInstanceIsAddedOfAPageTypeThatDoesNotHoldThePage) {
  ASSERT_EQ(run(makeNetEdit(NetEditKind::AddInstance, "main", "c2", "cell", {5, 3})), "");
  EXPECT_EQ(main().instances.size(), 2u);
  // written nowhere yet, it is placed in the model's file (a message about it names the file, not "<input>")
  EXPECT_EQ(main().instances.back().loc.str(), doc_->model().path);
  EXPECT_EQ(doc_->history().undoLabel(), "add instance main/c2 of cell");
  ASSERT_EQ(run(makeNetEdit(NetEditKind::AddTransition, "main", "T1", {}, {6, 0})), "");
  core::Diagnostics diags;
  (void)net::compile(doc_->model().net, diags);
  EXPECT_NE(diags.str().find(doc_->model().path + ": warning: transition 'T1' has no input arcs"), std::string::npos)
      << diags.str();
  EXPECT_EQ(run(makeNetEdit(NetEditKind::AddInstance, "cell", "self", "cell")),
            "page type 'cell' holds 'cell': an instance of it there would hold itself");
  EXPECT_EQ(run(makeNetEdit(NetEditKind::AddInstance, "main", "c3", "nothing")), "no page type 'nothing'");
  EXPECT_EQ(run(makeNetEdit(NetEditKind::AddInstance, "main", "a", "cell")), "'a' is taken on page 'main'");
}

TEST_F(GroupEdit, SeveralThingsAreSelectedAndAnUndoSelectsThemAgain) {
  const Selection a{SelectionKind::Place, "main/a"}, t{SelectionKind::Transition, "main/t"};
  const Selection arc{SelectionKind::Arc, arcName("main", "t", "c1/enter", net::ArcKind::Normal)};
  EXPECT_EQ(arc.name, "main: t -> c1/enter");
  EXPECT_TRUE(namesSomething(*doc_, arc));
  doc_->selectAll({a, t, arc});
  EXPECT_EQ(doc_->selectedCount(), 3u);
  EXPECT_EQ(doc_->selection(), arc);  // the last one is the current one
  doc_->toggleSelected(t);
  EXPECT_EQ(doc_->selectedCount(), 2u);
  EXPECT_FALSE(doc_->isSelected(t));
  doc_->toggleSelected(t);
  EXPECT_EQ(doc_->selection(), t);
  // a delete of all three, undone: all three are selected again
  auto e = makeNetEdit(NetEditKind::DeleteMany, "main", {});
  e.names = {"a", "t"};
  ASSERT_EQ(run(e), "");
  doc_->select({});
  ASSERT_TRUE(doc_->undo());
  EXPECT_EQ(doc_->selectedCount(), 3u);
  EXPECT_TRUE(doc_->isSelected(a) && doc_->isSelected(t) && doc_->isSelected(arc));
  // redo: none of them is there any more
  ASSERT_TRUE(doc_->redo());
  EXPECT_EQ(doc_->selectedCount(), 0u);
}

TEST_F(GroupEdit, APastedArcBringsItsBendsAlongWithItsEnds) {
  net::PageSpec fragment;
  fragment.places.push_back(main().places[0]);
  fragment.transitions.push_back(main().transitions[0]);
  net::ArcSpec arc = main().arcs[0];
  arc.via = {{1, 1}};
  fragment.arcs.push_back(arc);
  auto e = makeNetEdit(NetEditKind::Paste, "main", {});
  e.fragment = fragment;
  ASSERT_EQ(run(e), "");
  const auto& pasted = main().arcs.back();
  EXPECT_EQ(pasted.from, "a_1");
  EXPECT_EQ(pasted.via, (std::vector<net::EditorPos>{{1.5, 1.5}}));  // half a unit down and right, as its ends
}

TEST_F(GroupEdit, ABendDraggedKeepsOnlyTheArcForUndoAndAGroupMoveTakesItsBends) {
  const auto start = doc_->text();
  for (int step = 1; step <= 3; ++step) {  // a bend dragged over three frames: one step
    auto e = makeNetEdit(NetEditKind::SetArc, "main", "a", "t");
    net::ArcSpec arc = main().arcs[0];
    arc.via = {{1, 0.5 * step}};
    e.arc = arc;
    e.drag = 3;
    ASSERT_EQ(run(e), "");
  }
  EXPECT_EQ(doc_->history().depth(), 1u);
  EXPECT_EQ(main().arcs[0].via, (std::vector<net::EditorPos>{{1, 1.5}}));
  const auto bent = doc_->text();
  // the two ends moved together: the bend goes along; one end alone: it stays
  auto both = makeNetEdit(NetEditKind::MoveMany, "main", {});
  both.moves = {{"a", {0, 1}}, {"t", {2, 1}}};
  ASSERT_EQ(run(both), "");
  EXPECT_EQ(main().arcs[0].via, (std::vector<net::EditorPos>{{1, 2.5}}));
  auto one = makeNetEdit(NetEditKind::MoveMany, "main", {});
  one.moves = {{"a", {0, 3}}};
  ASSERT_EQ(run(one), "");
  EXPECT_EQ(main().arcs[0].via, (std::vector<net::EditorPos>{{1, 2.5}}));
  testing::undoesToStartAndRedoesToEnd(*doc_, start, "a bend dragged, then moves");
  ASSERT_TRUE(doc_->undo() && doc_->undo());
  EXPECT_EQ(doc_->text(), bent);
}

TEST(ArcName, ReadsBackWhatItWritesLinksAndKindsIncluded) {
  for (const auto kind : {net::ArcKind::Normal, net::ArcKind::Test, net::ArcKind::Inhibitor}) {
    const auto name = arcName("line/cellA", "exit", "cellB/enter", kind);
    const auto back = parseArcName(name);
    ASSERT_TRUE(back) << name;
    EXPECT_EQ(back->prefix, "line/cellA");
    EXPECT_EQ(back->from, "exit");
    EXPECT_EQ(back->to, "cellB/enter");
    EXPECT_EQ(back->kind, kind);
  }
  EXPECT_EQ(arcName("main", "busy", "start", net::ArcKind::Inhibitor), "main: busy -> start (inhibitor)");
  EXPECT_FALSE(parseArcName("main/a"));
  EXPECT_FALSE(parseArcName("main: a ->"));
  EXPECT_FALSE(parseArcName(": a -> b"));
}

}  // namespace
}  // namespace gdpn::ide
