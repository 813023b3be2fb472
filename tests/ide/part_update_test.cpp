// The parts library's two edits in the headless IDE, by user input: a part the library holds in
// a newer version is noted in the palette, listed (what it changes in the I/O and parameters,
// the uses it leaves unresolved) and taken as one step of undo, its removed I/O's use a located
// error in Diagnostics, and Undo gives the saved file back byte for byte; a selected scene node
// is saved as a new part into the user's parts folder, which the palette then lists.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gdpn/model/part_library.h"
#include "ide/headless_fixture.h"
#include "support/scoped_env.h"

namespace gdpn::ide {
namespace {

namespace fs = std::filesystem;

/// tests/data/part_update: a model keeping version 1 of the test part lamp, its input `seen`
/// mapped in the io section; data/gdpn/parts holds version 2, which no longer has `seen`.
const fs::path kUpdateDir = fs::path(GDPN_SOURCE_DIR) / "tests" / "data" / "part_update";

/// The text of the file at `path`.
std::string textOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The line of `path` that holds `text` (1 for the first), 0 when none does.
int lineOf(const fs::path& path, const std::string& text) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}

class PartUpdates : public HeadlessIde {
 protected:
  /// The model in the test's folder; the IDE's library is the test data's, version 2.
  std::string station() {
    fs::copy_file(kUpdateDir / "station.gdpn.yaml", dir_ / "station.gdpn.yaml");
    return (dir_ / "station.gdpn.yaml").string();
  }
  gdpn::testing::ScopedEnv data_{"XDG_DATA_HOME", (kUpdateDir / "data").string()};
};

TEST_F(PartUpdates, ANewerVersionIsNotedListedAndTakenAndItsRemovedIoIsALocatedError) {
  const auto model = station();
  // where the io section maps the input version 2 removes
  const std::string at = model + ":" + std::to_string(lineOf(model, "0: {part: lamp1, io: seen}")) + ":5";
  auto r = replayOn(model, "- frames: 1\n");
  const auto& notice = r["palette"]["updates"];
  EXPECT_EQ(notice["count"], 1) << r["palette"].dump();
  EXPECT_EQ(notice["text"], "1 part has a newer version:");
  EXPECT_EQ(notice["parts"], (nlohmann::json{"lamp"}));
  EXPECT_TRUE(notice.contains("update"));
  EXPECT_TRUE(r["diagnostics"].empty()) << r["diagnostics"].dump();

  // its button lists what changes
  r = replayOn(model, "- click: [palette, updates, update]\n");
  const auto& popup = r["parts_update"];
  ASSERT_TRUE(popup["open"].get<bool>()) << popup.dump();
  ASSERT_EQ(popup["parts"].size(), 1U);
  const auto& lamp = popup["parts"][0];
  EXPECT_EQ(lamp["name"], "lamp");
  EXPECT_EQ(lamp["from"], 1);
  EXPECT_EQ(lamp["to"], 2);
  EXPECT_EQ(lamp["added"], (nlohmann::json{"blink"}));
  EXPECT_EQ(lamp["removed"], (nlohmann::json{"seen"}));
  EXPECT_TRUE(lamp["changed"].empty());
  EXPECT_EQ(lamp["params_removed"], (nlohmann::json{"count"}));
  EXPECT_EQ(popup["uses"], (nlohmann::json{at + ": discrete input 0 uses lamp1.seen"}));
  EXPECT_EQ(r["undo"]["depth"], 0);

  // Update: one step, the notice gone, the use of 'seen' an error at its line
  r = replayOn(model, "- click: [palette, updates, update]\n- click: [parts_update, buttons, update]\n- key: ctrl+s\n");
  EXPECT_FALSE(r["parts_update"]["open"].get<bool>());
  EXPECT_EQ(r["undo"]["depth"], 1);
  EXPECT_EQ(r["undo"]["label"], "update lamp to version 2");
  EXPECT_EQ(r["palette"]["updates"]["count"], 0);
  ASSERT_EQ(r["diagnostics"].size(), 1U);
  EXPECT_EQ(r["diagnostics"][0].get<std::string>().rfind(at + ": error: discrete input 0: part 'main/lamp1' has no I/O 'seen'", 0), 0U)
      << r["diagnostics"].dump();
  core::Diagnostics diags;
  const auto saved = model::loadModel(model, diags);
  ASSERT_TRUE(saved) << diags.str();
  EXPECT_EQ(saved->parts.at("lamp").version, 2);
  EXPECT_NE(saved->parts.at("lamp").findIo("blink"), nullptr);
}

TEST_F(PartUpdates, UndoGivesTheSavedFileBackByteForByteAndCancelChangesNothing) {
  const auto model = station();
  // the file as the IDE saves it, before any update
  auto r = replayOn(model, "- key: ctrl+s\n");
  const auto before = textOf(model);
  // the action by its name (Edit > Update Parts...), then Update, Undo and Save
  r = replayOn(model, "- press: update-parts\n- click: [parts_update, buttons, update]\n- key: ctrl+z\n- key: ctrl+s\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_TRUE(r["undo"]["can_redo"].get<bool>());
  EXPECT_EQ(textOf(model), before);
  EXPECT_EQ(r["palette"]["updates"]["count"], 1);  // offered again
  EXPECT_TRUE(r["diagnostics"].empty()) << r["diagnostics"].dump();
  // Cancel: nothing happens
  r = replayOn(model, "- press: update-parts\n- click: [parts_update, buttons, cancel]\n");
  EXPECT_FALSE(r["parts_update"]["open"].get<bool>());
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_FALSE(r["document"]["modified"].get<bool>());
}

TEST_F(PartUpdates, NoNoticeAndNoUpdateWhereTheLibraryHasNoNewerVersion) {
  // a library without the lamp: no notice, and the action cannot be pressed
  const auto model = station();
  gdpn::testing::ScopedEnv data("XDG_DATA_HOME", (dir_ / "empty").string());
  auto r = replayOn(model, "- frames: 1\n");
  EXPECT_EQ(r["palette"]["updates"]["count"], 0);
  r = replayOn(model, "- press: update-parts\n", {}, 1);
  EXPECT_NE(last_.out.find("'update-parts' cannot be done now"), std::string::npos) << last_.out;
}

class SaveAsPart : public HeadlessIde {
 protected:
  /// The user's own parts folder, inside the test's folder.
  [[nodiscard]] fs::path folder() const { return dir_ / "data" / "gdpn" / "parts"; }
  /// The model of tests/data/part_update (its scene has a Transform `shelf` with a board).
  std::string model() {
    fs::copy_file(kUpdateDir / "station.gdpn.yaml", dir_ / "station.gdpn.yaml");
    return (dir_ / "station.gdpn.yaml").string();
  }
  void SetUp() override {
    HeadlessIde::SetUp();
    data_.emplace("XDG_DATA_HOME", (dir_ / "data").string());
  }
  void TearDown() override {
    data_.reset();
    HeadlessIde::TearDown();
  }
  std::optional<gdpn::testing::ScopedEnv> data_;
};

TEST_F(SaveAsPart, ASelectedNodeIsSavedAsAPartThatThePaletteLists) {
  const auto path = model();
  // user input only: a click on the node, the action, its name typed over the offered one,
  // a click on the group, its name, Save
  const std::string actions = R"Y(
- click: [tree, rows, shelf]
- press: save-as-part
- type: wall_shelf
- click: [save_as_part, fields, group]
- type: Fixtures
- click: [save_as_part, buttons, save]
)Y";
  const auto r = replayOn(path, actions);
  EXPECT_FALSE(r["save_as_part"]["open"].get<bool>()) << r["save_as_part"].dump();
  const auto file = folder() / "wall_shelf.gdpn.yaml";
  EXPECT_EQ(r["message"], "saved the part wall_shelf to " + file.string() + ": the palette lists it");
  // the palette scanned again lists it in its group
  bool listed = false;
  for (const auto& p : r["palette"]["list"]) listed = listed || (p["name"] == "wall_shelf" && p["group"] == "Fixtures");
  EXPECT_TRUE(listed) << r["palette"]["list"].dump();
  // the file loads as a part; the model is not changed
  core::Diagnostics diags;
  const auto parts = model::scanParts({folder().string()}, diags);
  const auto* part = model::findLibraryPart(parts, "wall_shelf");
  ASSERT_NE(part, nullptr) << diags.str();
  EXPECT_EQ(part->spec.group, "Fixtures");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_FALSE(r["document"]["modified"].get<bool>());
  // only the part file is there (it was written beside, then renamed)
  EXPECT_EQ(std::distance(fs::directory_iterator(folder()), fs::directory_iterator()), 1);
}

TEST_F(SaveAsPart, ABadNameIsRefusedInThePopupAndAnExistingPartIsReplacedOnlyWhenSavedAgain) {
  const auto path = model();
  auto r = replayOn(path, "- select: shelf\n- press: save-as-part\n- type: 2shelf\n- key: enter\n");
  const auto& popup = r["save_as_part"];
  ASSERT_TRUE(popup["open"].get<bool>()) << popup.dump();
  EXPECT_NE(popup["error"].get<std::string>().find("got '2shelf'"), std::string::npos) << popup.dump();
  EXPECT_FALSE(fs::exists(folder()));
  // there already: said once, replaced by a second Save
  fs::create_directories(folder());
  std::ofstream(folder() / "shelf.gdpn.yaml") << "gdpn: 1\n";
  r = replayOn(path, "- select: shelf\n- press: save-as-part\n- click: [save_as_part, buttons, save]\n");
  EXPECT_TRUE(r["save_as_part"]["open"].get<bool>());
  EXPECT_EQ(r["save_as_part"]["name"], "shelf");  // the node's name, offered
  EXPECT_NE(r["save_as_part"]["error"].get<std::string>().find("shelf.gdpn.yaml exists"), std::string::npos);
  EXPECT_EQ(textOf(folder() / "shelf.gdpn.yaml"), "gdpn: 1\n");
  r = replayOn(path, "- select: shelf\n- press: save-as-part\n- click: [save_as_part, buttons, save]\n"
                     "- click: [save_as_part, buttons, save]\n");
  EXPECT_FALSE(r["save_as_part"]["open"].get<bool>()) << r["save_as_part"].dump();
  core::Diagnostics diags;
  EXPECT_NE(model::findLibraryPart(model::scanParts({folder().string()}, diags), "shelf"), nullptr) << diags.str();
  // nothing selected: the action cannot be pressed
  r = replayOn(path, "- press: save-as-part\n", {}, 1);
  EXPECT_NE(last_.out.find("'save-as-part' cannot be done now"), std::string::npos) << last_.out;
}

}  // namespace
}  // namespace gdpn::ide
