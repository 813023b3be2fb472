// Part instances edited in a document: a library part placed (its types copied in) and
// undone byte for byte, its control pattern added once, its parameters and placement set and
// checked; the result runs. The library's newer version of a part taken as one step, undone
// byte for byte, its removed I/O's uses located; a scene node saved as a new part.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "gdpn/ide/document.h"
#include "gdpn/ide/part_edit.h"
#include "gdpn/ide/run_control.h"
#include "gdpn/model/part_library.h"
#include "gdpn/model/simulation.h"
#include "support/scoped_env.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

class PartEdit : public gdpn::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    core::Diagnostics diags;
    parts_ = model::scanParts({std::string(GDPN_SOURCE_DIR) + "/tests/data/palette",
                               std::string(GDPN_SOURCE_DIR) + "/tests/data/parts"},
                              diags);
    ASSERT_TRUE(diags.all().empty()) << diags.str();
    doc_ = Document::create((dir_ / "station.gdpn.yaml").string());
  }
  const model::LibraryPart& part(const std::string& name) {
    const auto* p = model::findLibraryPart(parts_, name);
    EXPECT_NE(p, nullptr) << name;
    return *p;
  }
  /// Places `name` at `x` on page main; the instance's name.
  std::string place(const std::string& name, double x, double angle = 0, bool control = false) {
    auto command = std::make_unique<PlacePartCommand>(part(name), "main", std::array<double, 3>{x, 0, 0}, angle, control);
    const auto* placing = command.get();
    EXPECT_EQ(doc_->execute(std::move(command)), "");
    return placing->made().empty() ? std::string() : placing->made().front();
  }
  std::vector<model::LibraryPart> parts_;
  std::unique_ptr<Document> doc_;
};

TEST_F(PartEdit, APlacedPartBringsItsTypesAndUndoGivesTheModelBackExactly) {
  const auto before = doc_->text();
  EXPECT_EQ(place("belt_conveyor", 2, 90), "belt_conveyor1");
  const auto after = doc_->text();
  const auto at = findPartInstance(doc_->model(), "belt_conveyor1");
  ASSERT_TRUE(at);
  EXPECT_EQ(*at, (PartInstanceAt{"main", "belt_conveyor1"}));
  EXPECT_EQ(findPartInstance(doc_->model(), "main/belt_conveyor1"), at);
  const auto* inst = instanceAt(doc_->model(), *at);
  ASSERT_NE(inst, nullptr);
  EXPECT_EQ(inst->translation, (std::array<double, 3>{2, 0, 0}));
  EXPECT_EQ(inst->rotation, (std::array<double, 4>{0, 0, 1, 90}));
  EXPECT_TRUE(doc_->model().parts.contains("belt_conveyor"));
  EXPECT_TRUE(doc_->model().type_scenes.contains("belt_conveyor"));
  EXPECT_EQ(doc_->history().undoLabel(), "place belt_conveyor1 (belt_conveyor)");
  ASSERT_TRUE(doc_->undo());
  EXPECT_EQ(doc_->text(), before);
  EXPECT_FALSE(doc_->model().parts.contains("belt_conveyor"));
  ASSERT_TRUE(doc_->redo());
  EXPECT_EQ(doc_->text(), after);
  // a second one takes the next name; the type is not copied again
  EXPECT_EQ(place("belt_conveyor", 4), "belt_conveyor2");
}

TEST_F(PartEdit, APartWhoseNameTheModelUsesForAnotherTypeIsRefused) {
  net::PageSpec own;
  own.name = "belt_conveyor";
  doc_->editableNet().page_types.push_back(own);
  const auto before = doc_->text();
  const auto why = doc_->execute(std::make_unique<PlacePartCommand>(part("belt_conveyor"), "main", std::array<double, 3>{0, 0, 0}, 0.0));
  EXPECT_NE(why.find("page type 'belt_conveyor' of its own"), std::string::npos) << why;
  EXPECT_EQ(doc_->text(), before);
  EXPECT_FALSE(doc_->history().canUndo());
}

TEST_F(PartEdit, ItsControlPatternIsAddedOnceBoundToIt) {
  ASSERT_EQ(place("pusher", 0), "pusher1");
  const PartInstanceAt at{"main", "pusher1"};
  EXPECT_EQ(model::controlPatterns(doc_->model(), "pusher").front(), "pusher_control");
  EXPECT_TRUE(model::controlPatterns(doc_->model(), "missing").empty());
  EXPECT_EQ(controllerOf(doc_->model(), at), "");
  const auto before = doc_->text();
  auto command = std::make_unique<AddPartControlCommand>(at);
  const auto* adding = command.get();
  ASSERT_EQ(doc_->execute(std::move(command)), "");
  EXPECT_EQ(adding->made(), "pusher1_control");
  EXPECT_EQ(controllerOf(doc_->model(), at), "pusher1_control");
  const auto* control = instanceAt(doc_->model(), {"main", "pusher1_control"});
  ASSERT_NE(control, nullptr);
  EXPECT_EQ(control->type, "pusher_control");
  EXPECT_EQ(control->part, "pusher1");
  // once
  EXPECT_NE(doc_->execute(std::make_unique<AddPartControlCommand>(at)).find("controls 'pusher1' already"), std::string::npos);
  // a part with no control pattern
  ASSERT_EQ(place("belt_conveyor", 3), "belt_conveyor1");
  EXPECT_NE(doc_->execute(std::make_unique<AddPartControlCommand>(PartInstanceAt{"main", "belt_conveyor1"})).find("no control pattern"),
            std::string::npos);
  ASSERT_TRUE(doc_->undo());  // the belt
  ASSERT_TRUE(doc_->undo());  // the control
  EXPECT_EQ(doc_->text(), before);
  // placed with its control at once, as placePart does
  EXPECT_EQ(place("lamp", 5, 0, true), "lamp1");
  EXPECT_EQ(controllerOf(doc_->model(), {"main", "lamp1"}), "lamp1_control");
}

TEST_F(PartEdit, AnInstancesParametersAndPlacementAreSetAndChecked) {
  ASSERT_EQ(place("lamp", 0), "lamp1");
  const PartInstanceAt at{"main", "lamp1"};
  const auto before = doc_->text();
  ASSERT_EQ(doc_->execute(SetInstanceCommand::param(at, "length", 3)), "");
  ASSERT_EQ(doc_->execute(SetInstanceCommand::param(at, "brightness", 0.8)), "");
  const auto* inst = instanceAt(doc_->model(), at);
  ASSERT_EQ(inst->params.size(), 2U);
  EXPECT_EQ(inst->params[0].name, "length");  // in the type's order
  EXPECT_EQ(inst->params[0].value, 3);
  EXPECT_EQ(doc_->history().undoLabel(), "set lamp1.brightness = 0.8");
  ASSERT_EQ(doc_->execute(SetInstanceCommand::param(at, "length", 4)), "");  // set again: changed in place
  EXPECT_EQ(instanceAt(doc_->model(), at)->params[0].value, 4);
  EXPECT_EQ(instanceAt(doc_->model(), at)->params.size(), 2U);
  // refused: no such parameter, a fraction for a whole number, no such instance
  EXPECT_NE(doc_->execute(SetInstanceCommand::param(at, "colour", 1)).find("no parameter 'colour'"), std::string::npos);
  EXPECT_NE(doc_->execute(SetInstanceCommand::param(at, "length", 2.5)).find("whole number"), std::string::npos);
  EXPECT_NE(doc_->execute(SetInstanceCommand::param({"main", "lamp9"}, "length", 1)).find("no instance"), std::string::npos);
  // a drag's moves are one step
  const auto placed = doc_->history().depth();
  ASSERT_EQ(doc_->execute(SetInstanceCommand::placement(at, {1, 0, 0}, {0, 0, 1, 0}, 7)), "");
  ASSERT_EQ(doc_->execute(SetInstanceCommand::placement(at, {2, 0, 0}, {0, 0, 1, 0}, 7)), "");
  EXPECT_EQ(doc_->history().depth(), placed + 1);
  EXPECT_EQ(instanceAt(doc_->model(), at)->translation, (std::array<double, 3>{2, 0, 0}));
  while (doc_->history().depth() > 1) ASSERT_TRUE(doc_->undo());
  EXPECT_EQ(doc_->text(), before);
}

TEST_F(PartEdit, AStationOfPlacedPartsRuns) {
  ASSERT_EQ(place("belt_conveyor", 0), "belt_conveyor1");
  ASSERT_EQ(place("belt_conveyor", 2), "belt_conveyor2");
  ASSERT_EQ(place("pusher", 0.5, 0, true), "pusher1");
  ASSERT_EQ(doc_->execute(SetInstanceCommand::param({"main", "belt_conveyor2"}, "length", 3)), "");
  core::Diagnostics diags;
  const auto sim = model::Simulation::create(doc_->snapshot(), diags);
  ASSERT_NE(sim, nullptr) << diags.str();
  // the second belt's machine is made with its own length
  const auto* surface = sim->plant()->find("belt_conveyor2/belt/surface");
  ASSERT_NE(surface, nullptr);
  EXPECT_EQ(surface->value(0), scene::FieldValue(std::array<double, 3>{3, 0.5, 0.1}));
}

/// tests/data/part_update: a model keeping version 1 of the test part lamp, its input `seen`
/// mapped in the io section; its library (data/gdpn/parts) holds version 2, without `seen`.
const std::string kUpdateDir = std::string(GDPN_SOURCE_DIR) + "/tests/data/part_update";

/// The line of `path` that holds `text` (1 for the first), 0 when none does.
int lineOf(const std::string& path, const std::string& text) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}

TEST(PartUpdate, TheLibrarysNewerVersionIsTakenAsOneStepUndoneExactlyAndItsRemovedIoLocated) {
  const std::string path = kUpdateDir + "/station.gdpn.yaml";
  core::Diagnostics diags;
  auto doc = Document::open(path, diags);
  ASSERT_NE(doc, nullptr) << diags.str();
  RunControl run;
  ASSERT_TRUE(run.open(*doc, diags)) << diags.str();
  EXPECT_TRUE(run.buildDiagnostics().all().empty()) << run.buildDiagnostics().str();
  const auto library = model::scanParts({kUpdateDir + "/data/gdpn/parts"}, diags);
  ASSERT_TRUE(diags.all().empty()) << diags.str();
  const auto updates = model::partUpdates(doc->model(), library);
  ASSERT_EQ(updates.size(), 1U);
  EXPECT_EQ(updates[0].removed, (std::vector<std::string>{"seen"}));
  // what it will leave unresolved, located where the io section writes it
  const std::string at = path + ":" + std::to_string(lineOf(path, "0: {part: lamp1, io: seen}")) + ":5";
  std::string why;
  const auto uses = removedIoUses(doc->model(), updates, why);
  EXPECT_EQ(why, "");
  EXPECT_EQ(uses, (std::vector<std::string>{at + ": discrete input 0 uses lamp1.seen"}));
  EXPECT_EQ(doc->model().parts.at("lamp").version, 1);  // the preview left the model as it was

  const auto before = doc->text();
  auto command = std::make_unique<UpdatePartsCommand>(updates);
  const auto* updating = command.get();
  ASSERT_EQ(doc->execute(std::move(command)), "");
  EXPECT_EQ(updating->uses(), uses);
  EXPECT_EQ(doc->history().depth(), 1U);
  EXPECT_EQ(doc->history().undoLabel(), "update lamp to version 2");
  EXPECT_EQ(doc->model().parts.at("lamp").version, 2);
  EXPECT_EQ(doc->model().parts.at("lamp_control").version, 2);
  EXPECT_TRUE(doc->model().net.pages.at(0).instances.at(0).params.empty());  // 'count' is gone
  const auto after = doc->text();
  // the run made again: the io section's use of 'seen' is a located error
  ASSERT_TRUE(run.reset(diags));
  EXPECT_NE(run.buildDiagnostics().str().find(at + ": error: discrete input 0: part 'main/lamp1' has no I/O 'seen'"),
            std::string::npos)
      << run.buildDiagnostics().str();
  // undone byte for byte, redone the same
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
  EXPECT_EQ(model::partUpdates(doc->model(), library).size(), 1U);
  core::Diagnostics again;
  ASSERT_TRUE(run.reset(again));
  EXPECT_TRUE(run.buildDiagnostics().all().empty()) << run.buildDiagnostics().str();
  ASSERT_TRUE(doc->redo());
  EXPECT_EQ(doc->text(), after);
  EXPECT_TRUE(model::partUpdates(doc->model(), library).empty());
}

TEST(PartUpdate, AnUpdateWhoseLibraryFileIsGoneIsRefusedAndChangesNothing) {
  core::Diagnostics diags;
  auto doc = Document::open(kUpdateDir + "/station.gdpn.yaml", diags);
  ASSERT_NE(doc, nullptr) << diags.str();
  auto updates = model::partUpdates(doc->model(), model::scanParts({kUpdateDir + "/data/gdpn/parts"}, diags));
  ASSERT_EQ(updates.size(), 1U);
  updates[0].file = kUpdateDir + "/no_such_file.gdpn.yaml";
  const auto before = doc->text();
  std::string why;
  EXPECT_TRUE(removedIoUses(doc->model(), updates, why).empty());
  EXPECT_NE(why.find("no_such_file.gdpn.yaml"), std::string::npos) << why;
  why = doc->execute(std::make_unique<UpdatePartsCommand>(updates));
  EXPECT_NE(why.find("'lamp' cannot be updated"), std::string::npos) << why;
  EXPECT_EQ(doc->text(), before);
  EXPECT_FALSE(doc->history().canUndo());
  EXPECT_EQ(doc->execute(std::make_unique<UpdatePartsCommand>(std::vector<model::PartUpdate>{})),
            "no part has a newer version in the library");
}

using gdpn::testing::ScopedEnv;

class SavePart : public gdpn::testing::TempDirTest {};

TEST_F(SavePart, TheUsersPartsFolderIsXdgDataHomesElseHomes) {
  {
    ScopedEnv data("XDG_DATA_HOME", "/data/me");
    EXPECT_EQ(userPartsFolder(), "/data/me/gdpn/parts");
  }
  ScopedEnv data("XDG_DATA_HOME", "");  // empty: as if unset
  {
    ScopedEnv home("HOME", "/home/me");
    EXPECT_EQ(userPartsFolder(), "/home/me/.local/share/gdpn/parts");
  }
  ScopedEnv home("HOME", std::nullopt);
  EXPECT_EQ(userPartsFolder(), "");
}

TEST_F(SavePart, ANodeIsWrittenAsAPartThatTheLibraryLoadsAndAnExistingOneIsReplacedOnlyWhenAsked) {
  core::Diagnostics diags;
  const auto m = model::parseModel("gdpn: 1\nparams: {w: 0.5, speed: 2, unused: 1}\nscene:\n"
                                   "  - Transform:\n"
                                   "      name: shelf\n"
                                   "      translation: [3, 1, 0]\n"
                                   "      children:\n"
                                   "        - Cube: {name: board, size: [1, $w, 0.05]}\n"
                                   "        - Conveyor: {speed: =2*speed}\n",
                                   "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  const auto folder = (dir_ / "data" / "gdpn" / "parts").string();
  // a bad name, a node that is not there: nothing written
  auto saved = savePartOfNode(*m, "shelf", "2shelf", "Fixtures", folder, false);
  EXPECT_NE(saved.error.find("got '2shelf'"), std::string::npos) << saved.error;
  saved = savePartOfNode(*m, "table", "table", "Fixtures", folder, false);
  EXPECT_NE(saved.error.find("no node 'table'"), std::string::npos) << saved.error;
  saved = savePartOfNode(*m, "shelf", "shelf", "Fixtures", "", false);
  EXPECT_NE(saved.error.find("no parts folder"), std::string::npos) << saved.error;
  EXPECT_FALSE(std::filesystem::exists(folder));
  // written, the folder made; no file of another name beside it
  saved = savePartOfNode(*m, "shelf", "wall_shelf", "Fixtures", folder, false);
  ASSERT_EQ(saved.error, "");
  EXPECT_EQ(saved.file, folder + "/wall_shelf.gdpn.yaml");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()), 1);
  // the library loads it: its group, the parameters its fields name (not 'unused'), its origin
  const auto parts = model::scanParts({folder}, diags);
  ASSERT_TRUE(diags.all().empty()) << diags.str();
  const auto* part = model::findLibraryPart(parts, "wall_shelf");
  ASSERT_NE(part, nullptr);
  EXPECT_EQ(part->spec.group, "Fixtures");
  EXPECT_EQ(part->spec.version, 1);
  std::vector<std::string> params;
  for (const auto& p : part->spec.params) params.push_back(p.name);
  EXPECT_EQ(params, (std::vector<std::string>{"w", "speed"}));
  const auto file = model::loadModel(saved.file, diags);
  ASSERT_TRUE(file) << diags.str();
  EXPECT_EQ(file->type_scenes.at("wall_shelf")->find("shelf")->vec3(scene::field::Transform::Translation), (core::Vec3{0, 0, 0}));
  // there already: refused unless replacing, and left as it was
  std::ifstream in(saved.file);
  std::stringstream text;
  text << in.rdbuf();
  saved = savePartOfNode(*m, "shelf/board", "wall_shelf", "Boards", folder, false);
  EXPECT_TRUE(saved.exists);
  EXPECT_NE(saved.error.find("wall_shelf.gdpn.yaml exists in " + folder), std::string::npos) << saved.error;
  std::ifstream kept(saved.file);
  std::stringstream kept_text;
  kept_text << kept.rdbuf();
  EXPECT_EQ(kept_text.str(), text.str());
  saved = savePartOfNode(*m, "shelf/board", "wall_shelf", "Boards", folder, true);
  ASSERT_EQ(saved.error, "");
  EXPECT_EQ(model::findLibraryPart(model::scanParts({folder}, diags), "wall_shelf")->spec.group, "Boards");
}

}  // namespace
}  // namespace gdpn::ide
