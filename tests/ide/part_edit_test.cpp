// Part instances edited in a document: a library part placed (its types copied in) and
// undone byte for byte, its control pattern added once, its parameters and placement set and
// checked; the result runs.

#include <gtest/gtest.h>

#include <filesystem>

#include "gdpn/ide/document.h"
#include "gdpn/ide/part_edit.h"
#include "gdpn/model/part_library.h"
#include "gdpn/model/simulation.h"
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

}  // namespace
}  // namespace gdpn::ide
