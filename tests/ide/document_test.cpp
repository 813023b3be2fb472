// The IDE's document: field edits through commands, undo and redo giving back byte-identical
// saves, a drag merged into one step, the selection, reloading from disk, and saves that keep the
// layout of a file written by hand.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/scene_edit.h"
#include "gdpn/ide/set_field.h"
#include "ide/ide_model.h"
#include "support/scratch.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

using gdpn::testing::TempDirTest;
using ide::testing::kBinModel;
using scene::FieldValue;

class DocumentTest : public TempDirTest {
 protected:
  std::unique_ptr<Document> openBin() {
    core::Diagnostics diags;
    auto doc = Document::open(write("bin.gdpn.yaml", kBinModel), diags);
    EXPECT_TRUE(doc) << diags.str();
    return doc;
  }
  static double bounce(const Document& doc) {
    const auto* node = doc.scene()->find("drop/paint");
    return std::get<double>(node->value(static_cast<std::size_t>(node->type().fieldIndex("bounce"))));
  }
};

TEST_F(DocumentTest, SetFieldChangesTheNodeAndUndoRedoGiveBackTheSameBytes) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.7})), "");
  EXPECT_DOUBLE_EQ(bounce(*doc), 0.7);
  const auto after = doc->text();
  EXPECT_NE(after, before);
  EXPECT_NE(after.find("bounce: 0.7"), std::string::npos) << after;
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
  ASSERT_TRUE(doc->redo());
  EXPECT_EQ(doc->text(), after);
  EXPECT_FALSE(doc->redo());
  ASSERT_TRUE(doc->undo());
  EXPECT_FALSE(doc->undo());
  EXPECT_EQ(doc->text(), before);
}

TEST_F(DocumentTest, AFieldSetByHandNoLongerNamesItsParameterUntilUndone) {
  core::Diagnostics diags;
  auto doc = Document::open(write("p.gdpn.yaml", "gdpn: 1\nparams: {speed: 0.4}\nscene:\n"
                                                  "  - Conveyor: {name: belt, speed: $speed}\n"),
                            diags);
  ASSERT_TRUE(doc) << diags.str();
  const auto before = doc->text();
  EXPECT_NE(before.find("speed: $speed"), std::string::npos) << before;
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("belt", "speed", FieldValue{0.7})), "");
  EXPECT_NE(doc->text().find("{name: belt, speed: 0.7}"), std::string::npos) << doc->text();
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
}

TEST_F(DocumentTest, TheTemplateMarkAndUserDataAreEditsUndoneByteForByte) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  ASSERT_EQ(doc->execute(std::make_unique<SetTemplateCommand>("drop", true)), "");
  ASSERT_EQ(doc->execute(std::make_unique<SetDatumCommand>("drop/paint", "kind", FieldValue{std::string("007")})), "");
  ASSERT_EQ(doc->execute(std::make_unique<SetDatumCommand>("drop/paint", "order", FieldValue{std::int64_t{17}})), "");
  ASSERT_EQ(doc->execute(std::make_unique<SetDatumCommand>("drop/paint", "kind", std::nullopt)), "");
  ASSERT_EQ(doc->execute(std::make_unique<SetDatumCommand>("drop/paint", "kind", FieldValue{std::string("red")})), "");
  const auto after = doc->text();
  EXPECT_NE(after.find("template: true"), std::string::npos) << after;
  EXPECT_NE(after.find("data: {order: 17, kind: red}"), std::string::npos) << after;
  // refused, and the document unchanged: a name that is no identifier, a datum that is not there
  EXPECT_NE(doc->execute(std::make_unique<SetDatumCommand>("drop/paint", "two words", FieldValue{true})), "");
  EXPECT_EQ(doc->execute(std::make_unique<SetDatumCommand>("drop/paint", "colour", std::nullopt)),
            "node 'drop/paint' has no datum 'colour'");
  EXPECT_NE(doc->execute(std::make_unique<SetTemplateCommand>("nowhere", true)), "");
  EXPECT_EQ(doc->text(), after);
  // undone step by step: the kind removed then set again comes back first, in its old place
  ASSERT_TRUE(doc->undo());
  ASSERT_TRUE(doc->undo());
  EXPECT_NE(doc->text().find("data: {kind: \"007\", order: 17}"), std::string::npos) << doc->text();
  while (doc->undo()) {
  }
  EXPECT_EQ(doc->text(), before);
  while (doc->redo()) {
  }
  EXPECT_EQ(doc->text(), after);
}

TEST_F(DocumentTest, SavedEditsReadBackAsTheSameModel) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/box/shape", "size", FieldValue{std::array{0.3, 0.2, 0.1}})), "");
  core::Diagnostics diags;
  const auto out = (dir_ / "saved.gdpn.yaml").string();
  ASSERT_TRUE(doc->save(diags, out)) << diags.str();
  auto again = Document::open(out, diags);
  ASSERT_TRUE(again) << diags.str();
  EXPECT_EQ(again->text(), doc->text());
}

TEST_F(DocumentTest, EachSaveKeepsTheFileItReplacesAsANumberedBackupTheNewestFive) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  const auto path = doc->model().path;
  std::string previous;
  {
    std::ifstream in(path);
    previous.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (int i = 1; i <= 7; ++i) {
    ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.1 * i})), "");
    core::Diagnostics diags;
    ASSERT_TRUE(doc->save(diags)) << diags.str();
    // the file just replaced is the newest backup, byte for byte
    std::ifstream kept(path + ".~" + std::to_string(i) + "~");
    ASSERT_TRUE(kept.good()) << i;
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), previous);
    std::ifstream now(path);
    previous.assign(std::istreambuf_iterator<char>(now), {});
  }
  for (int i = 1; i <= 7; ++i) {
    EXPECT_EQ(std::filesystem::exists(path + ".~" + std::to_string(i) + "~"), i > 2) << i;
  }
  EXPECT_EQ(previous, doc->text());
}

TEST_F(DocumentTest, AnInvalidValueIsRefusedWithTheLoadersMessage) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  const auto why = doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{1.5}));
  EXPECT_EQ(why, "'bounce' must lie in [0, 1], got 1.5");
  EXPECT_EQ(doc->text(), before);
  EXPECT_FALSE(doc->history().canUndo());
  // the wrong kind of value, an unknown field, a missing node
  EXPECT_NE(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{std::string("x")})), "");
  EXPECT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "colour", FieldValue{1.0})),
            "a Material has no field 'colour'");
  EXPECT_EQ(doc->execute(std::make_unique<SetFieldCommand>("nowhere", "bounce", FieldValue{0.1})), "no node 'nowhere'");
  EXPECT_EQ(doc->text(), before);
}

TEST_F(DocumentTest, ADragOfASliderIsOneStep) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  for (double v : {0.3, 0.4, 0.5, 0.6}) {
    ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{v}, 7)), "");
  }
  EXPECT_EQ(doc->history().depth(), 1U);
  EXPECT_DOUBLE_EQ(bounce(*doc), 0.6);
  // the drag ends; a new drag of the same field is a step of its own
  doc->history().seal();
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.9}, 7)), "");
  EXPECT_EQ(doc->history().depth(), 2U);
  ASSERT_TRUE(doc->undo());
  EXPECT_DOUBLE_EQ(bounce(*doc), 0.6);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
}

TEST_F(DocumentTest, EditsOfDifferentFieldsAreSeparateSteps) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.3}, 1)), "");
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "friction", FieldValue{0.3}, 1)), "");
  EXPECT_EQ(doc->history().depth(), 2U);
  EXPECT_EQ(doc->history().undoLabel(), "set drop/paint.friction");
}

TEST_F(DocumentTest, ANewEditClearsTheRedoList) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.3})), "");
  ASSERT_TRUE(doc->undo());
  ASSERT_TRUE(doc->history().canRedo());
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.4})), "");
  EXPECT_FALSE(doc->history().canRedo());
}

TEST_F(DocumentTest, TheSnapshotForARunIsACopy) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  auto snap = doc->snapshot();
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.3})), "");
  EXPECT_NE(snap.scene.get(), doc->model().scene.get());
  EXPECT_FALSE(model::Model::sameScene(snap.scene, doc->model().scene));
}

TEST_F(DocumentTest, ReloadTakesTheNewFileOrKeepsTheOldModelAndShowsTheErrors) {
  auto doc = openBin();
  ASSERT_TRUE(doc);
  doc->select(Selection::node("drop/paint"));
  const auto before = doc->text();
  EXPECT_FALSE(doc->changedOnDisk());

  // a broken file: the old model stays, the diagnostics are located
  write("bin.gdpn.yaml", "gdpn: 1\nscene:\n  - Cube: {size: oops}\n");
  std::filesystem::last_write_time(dir_ / "bin.gdpn.yaml",
                                   std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
  EXPECT_TRUE(doc->changedOnDisk());
  EXPECT_FALSE(doc->reload());
  EXPECT_EQ(doc->text(), before);
  ASSERT_TRUE(doc->diagnostics().hasErrors());
  EXPECT_NE(doc->diagnostics().all().front().str().find("bin.gdpn.yaml:3:"), std::string::npos)
      << doc->diagnostics().str();
  EXPECT_FALSE(doc->changedOnDisk());

  // a good file: taken, the selection kept since the node is still there
  auto edited = kBinModel;
  edited.replace(edited.find("bounce: 0.2"), 11, "bounce: 0.4");
  write("bin.gdpn.yaml", edited);
  std::filesystem::last_write_time(dir_ / "bin.gdpn.yaml",
                                   std::filesystem::file_time_type::clock::now() + std::chrono::seconds(1));
  EXPECT_TRUE(doc->reload()) << doc->diagnostics().str();
  EXPECT_DOUBLE_EQ(bounce(*doc), 0.4);
  EXPECT_EQ(doc->selection(), Selection::node("drop/paint"));
  EXPECT_FALSE(doc->diagnostics().hasErrors());
}

TEST_F(DocumentTest, AChangedScriptBesideTheModelIsNoticedOnce) {
  const auto py = write("helpers.py", "x = 1\n");
  auto doc = openBin();
  ASSERT_TRUE(doc);
  EXPECT_FALSE(doc->scriptsChanged());
  std::filesystem::last_write_time(py, std::filesystem::file_time_type::clock::now() + std::chrono::seconds(2));
  EXPECT_TRUE(doc->scriptsChanged());
  EXPECT_FALSE(doc->scriptsChanged());
  write("more.py", "y = 2\n");
  EXPECT_TRUE(doc->scriptsChanged());
  EXPECT_FALSE(doc->changedOnDisk());
}

TEST_F(DocumentTest, ANewModelHasAnEmptyPageAndSceneAndSavesAsAModelFile) {
  const auto path = (dir_ / "new.gdpn.yaml").string();
  auto doc = Document::create(path);
  ASSERT_NE(doc->scene(), nullptr);
  ASSERT_EQ(doc->model().net.pages.size(), 1U);
  EXPECT_EQ(doc->model().net.pages.front().name, "main");
  EXPECT_FALSE(doc->modified());
  core::Diagnostics diags;
  ASSERT_TRUE(doc->save(diags)) << diags.str();
  auto again = Document::open(path, diags);
  ASSERT_TRUE(again) << diags.str();
  EXPECT_EQ(again->text(), doc->text());
}

TEST_F(DocumentTest, ModifiedUntilSaved) {
  auto doc = openBin();
  EXPECT_FALSE(doc->modified());
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.7})), "");
  EXPECT_TRUE(doc->modified());
  core::Diagnostics diags;
  ASSERT_TRUE(doc->save(diags));
  EXPECT_FALSE(doc->modified());
}

TEST_F(DocumentTest, SaveAsMakesTheNewFileTheDocumentsAndRefusesOtherSuffixes) {
  auto doc = openBin();
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.7})), "");
  const auto other = (dir_ / "other.gdpn.yaml").string();
  core::Diagnostics diags;
  EXPECT_FALSE(doc->saveAs((dir_ / "other.yaml").string(), diags));
  EXPECT_NE(diags.str().find("ends in .gdpn.yaml"), std::string::npos) << diags.str();
  ASSERT_TRUE(doc->saveAs(other, diags)) << diags.str();
  EXPECT_EQ(doc->model().path, other);
  EXPECT_FALSE(doc->modified());
  EXPECT_EQ(gdpn::testing::fileBytes(other), doc->text());
  // the original file is as it was read
  EXPECT_EQ(gdpn::testing::fileBytes((dir_ / "bin.gdpn.yaml").string()), kBinModel);
}

TEST_F(DocumentTest, AnAutosaveIsOfferedOnlyWhenNewerThanTheFileAndDifferent) {
  setenv("XDG_STATE_HOME", (dir_ / "state").c_str(), 1);
  auto doc = openBin();
  EXPECT_TRUE(doc->autosavePath().starts_with((dir_ / "state" / "gdpn" / "autosave").string()));
  EXPECT_FALSE(doc->autosavePending());
  core::Diagnostics diags;
  ASSERT_TRUE(doc->autosave(diags)) << diags.str();
  EXPECT_FALSE(doc->autosavePending()) << "the same model is nothing to restore";
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.7})), "");
  ASSERT_TRUE(doc->autosave(diags)) << diags.str();
  const auto edited = doc->text();

  // a new session on the same file: offered, restored as one step, undone back to the file
  auto next = Document::open(doc->model().path, diags);
  ASSERT_TRUE(next) << diags.str();
  ASSERT_TRUE(next->autosavePending());
  const auto file = next->text();
  ASSERT_EQ(next->restoreAutosave(), "");
  EXPECT_EQ(next->text(), edited);
  EXPECT_TRUE(next->modified());
  ASSERT_TRUE(next->undo());
  EXPECT_EQ(next->text(), file);

  // a file written after the autosave wins: nothing offered
  std::filesystem::last_write_time(next->autosavePath(),
                                   std::filesystem::last_write_time(next->model().path) - std::chrono::seconds(10));
  EXPECT_FALSE(next->autosavePending());
  next->discardAutosave();
  EXPECT_FALSE(std::filesystem::exists(next->autosavePath()));
  unsetenv("XDG_STATE_HOME");
}

TEST_F(DocumentTest, UndoSelectsWhatWasSelectedBeforeTheStepNeverAThingItTookAway) {
  auto doc = openBin();
  doc->select(Selection::node("drop/paint"));
  // a copy of the box pasted under drop and selected, as the IDE's Paste does
  auto fragment = std::make_shared<scene::Scene>(doc->scene()->types());
  fragment->copy(*doc->scene()->find("drop/box"), fragment->root());
  auto paste = std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Paste, "drop", {}, {}, false, fragment});
  const auto* pasted = paste.get();
  ASSERT_EQ(doc->execute(std::move(paste)), "");
  const auto copy = Selection::node(pasted->made());
  ASSERT_TRUE(namesSomething(*doc, copy));
  doc->select(copy);
  // undone: the copy is gone, and the inspector is back on what was selected before
  ASSERT_TRUE(doc->undo());
  EXPECT_FALSE(namesSomething(*doc, copy));
  EXPECT_EQ(doc->selection(), Selection::node("drop/paint"));
  // redone: the copy again, selected as it was when undone
  ASSERT_TRUE(doc->redo());
  EXPECT_EQ(doc->selection(), copy);

  // a place added with nothing selected before: undone, nothing is selected
  doc->select({});
  ASSERT_EQ(doc->execute(std::make_unique<NetEditCommand>(makeNetEdit(NetEditKind::AddPlace, "main", "fresh"))), "");
  const Selection fresh{SelectionKind::Place, "main/fresh"};
  ASSERT_TRUE(namesSomething(*doc, fresh));
  doc->select(fresh);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->selection(), Selection{});
  EXPECT_FALSE(namesSomething(*doc, fresh));

  // a deleted node selected while deleted would name nothing: undoing the delete selects it
  // again, redoing it leaves nothing selected
  doc->select(Selection::node("drop/paint"));
  ASSERT_EQ(doc->execute(std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Delete, "drop/paint", {}, {}, false, {}})), "");
  doc->select({});
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->selection(), Selection::node("drop/paint"));
  ASSERT_TRUE(doc->redo());
  EXPECT_EQ(doc->selection(), Selection{});
  EXPECT_TRUE(namesSomething(*doc, {SelectionKind::Transition, "main/work"}));
  EXPECT_FALSE(namesSomething(*doc, {SelectionKind::Transition, "main/idle"}));  // a place
}

TEST_F(DocumentTest, AShapeOfNoSizeIsRefusedAndTheModelKeptAsItWas) {
  auto doc = openBin();
  const auto before = doc->text();
  // a Cube flat on one axis: the size's rule says each edge is above 0
  const auto why = doc->execute(std::make_unique<SetFieldCommand>(
      "drop/box/shape", "size", FieldValue{std::array<double, 3>{0.2, 0.0, 0.2}}, 0));
  EXPECT_EQ(why, "'size' must be above 0, got 0");
  EXPECT_EQ(doc->text(), before);
  EXPECT_FALSE(doc->history().canUndo());
  // a small one is a size
  EXPECT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/box/shape", "size",
                                                           FieldValue{std::array<double, 3>{0.2, 1e-4, 0.2}}, 0)),
            "");
}

/// A model written by hand: comments, keys in an order of its own, flow and block styles.
constexpr const char* kCommented = R"(# Two stations (written by hand)
gdpn: 1
scene:
  # the box that drops
  - Transform:
      name: drop
      translation: [0, 0, 3]   # three metres up
      children:
        - Material: {name: paint, diffuse: [0.8, 0.2, 0.1], bounce: 0.2}
        - Cube: {name: old, size: [0.2, 0.2, 0.2]}   # to go
pages:
  main:
    places:
      # what waits
      idle: {tokens: 2, at: [0, 0]}   # two to begin
      busy: {at: [2, 0]}
    transitions:
      work:
        # logs each start
        pre_fire: |
          sim.log("start")   # a Python comment
        at: [1, 0]
        duration: 0.3
    arcs:
      - idle -> work
      - work -> busy
settings: {seed: 3}   # settings last, as this author likes
)";

TEST_F(DocumentTest, SavingKeepsTheFilesCommentsOrderAndLayoutWhereTheEditsDidNotReach) {
  core::Diagnostics diags;
  auto doc = Document::open(write("line.gdpn.yaml", kCommented), diags);
  ASSERT_TRUE(doc) << diags.str();
  EXPECT_EQ(doc->text(), kCommented) << "unedited, the file is saved as it is";
  // a field changed, a node deleted, a place moved, a transition added
  ASSERT_EQ(doc->execute(std::make_unique<SetFieldCommand>("drop/paint", "bounce", FieldValue{0.5})), "");
  SceneEdit remove;
  remove.kind = SceneEditKind::Delete;
  remove.path = "drop/old";
  ASSERT_EQ(doc->execute(std::make_unique<SceneEditCommand>(remove)), "");
  ASSERT_EQ(doc->execute(std::make_unique<NetEditCommand>(makeNetEdit(NetEditKind::Move, "main", "busy", {}, {2.5, -0.0}))), "");
  ASSERT_EQ(doc->execute(std::make_unique<NetEditCommand>(makeNetEdit(NetEditKind::AddTransition, "main", "rest", {}, {3, 0}))), "");
  ASSERT_TRUE(doc->save(diags)) << diags.str();
  const std::string expected = R"(# Two stations (written by hand)
gdpn: 1
scene:
  # the box that drops
  - Transform:
      name: drop
      translation: [0, 0, 3]   # three metres up
      children:
        - Material: {name: paint, diffuse: [0.8, 0.2, 0.1], bounce: 0.5}
pages:
  main:
    places:
      # what waits
      idle: {tokens: 2, at: [0, 0]}   # two to begin
      busy: {at: [2.5, 0]}
    transitions:
      work:
        # logs each start
        pre_fire: |
          sim.log("start")   # a Python comment
        at: [1, 0]
        duration: 0.3
      rest: {at: [3, 0]}
    arcs:
      - idle -> work
      - work -> busy
settings: {seed: 3}   # settings last, as this author likes
)";
  EXPECT_EQ(gdpn::testing::fileBytes(doc->model().path), expected);
  // the saved file is the document's from now on: it reads back as the same model
  auto again = Document::open(doc->model().path, diags);
  ASSERT_TRUE(again) << diags.str();
  EXPECT_EQ(model::writeModel(again->model()), model::writeModel(doc->model()));
  // undone back to the first model, the save gives the first file again
  while (doc->undo()) {
  }
  EXPECT_EQ(model::writeModelOver(doc->model(), kCommented), kCommented);
}

TEST(Selection, KindsHaveNames) {
  EXPECT_STREQ(selectionKindName(SelectionKind::Transition), "transition");
  EXPECT_FALSE(Selection{}.any());
  EXPECT_TRUE(Selection::node("a").any());
}

}  // namespace
}  // namespace gdpn::ide
