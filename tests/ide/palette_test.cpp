// The parts palette in the headless IDE: the library's parts listed by group with their
// pictures, searched; a station dragged together from an empty file by user input alone (a belt,
// a second belt snapped to its end, a pusher beside it with its control, a parameter typed in the
// inspector), saved, and the saved file loads and runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "gdpn/model/simulation.h"
#include "ide/headless_fixture.h"

namespace gdpn::ide {
namespace {

namespace fs = std::filesystem;

class Palette : public HeadlessIde {
 protected:
  /// An empty model file in the test's folder, with the test library's part files beside it
  /// (the model's own folder is the first place parts are looked for).
  std::string station() {
    for (const auto& e : fs::directory_iterator(fs::path(GDPN_SOURCE_DIR) / "tests" / "data" / "palette")) {
      fs::copy_file(e.path(), dir_ / e.path().filename(), fs::copy_options::overwrite_existing);
    }
    return write("station.gdpn.yaml", "gdpn: 1\n");
  }
  /// The instance `name` of page main of `m`.
  static const net::InstanceSpec& instance(const model::Model& m, const std::string& name) {
    for (const auto& i : m.net.pages.at(0).instances) {
      if (i.name == name) return i;
    }
    ADD_FAILURE() << "no instance " << name;
    static const net::InstanceSpec none;
    return none;
  }
};

TEST_F(Palette, ListsTheLibrarysPartsByGroupWithPicturesAndFindsThemByName) {
  const auto model = station();
  auto r = replayOn(model, "- frames: 1\n");
  const auto& p = r["palette"];
  ASSERT_TRUE(p["shown"].get<bool>()) << p.dump();
  EXPECT_EQ(p["folders"][0], dir_.string());
  // the test's parts (a library installed or in the source tree may add more)
  const auto groups = p["groups"].get<std::vector<std::string>>();
  for (const auto* g : {"Actuators", "Conveyors", "Sensors"}) EXPECT_NE(std::find(groups.begin(), groups.end(), g), groups.end()) << g;
  EXPECT_TRUE(std::is_sorted(groups.begin(), groups.end()));
  for (const auto& item : p["list"]) EXPECT_TRUE(item["picture"].get<bool>()) << item.dump();
  EXPECT_TRUE(p["items"].contains("belt_conveyor"));
  EXPECT_TRUE(p["items"].contains("pusher"));
  // a search by the words of a name, a group or a description
  r = replayOn(model, "- click: [palette, controls, search]\n- type: photo_eye\n");
  EXPECT_EQ(r["palette"]["listed"], 1);
  EXPECT_EQ(r["palette"]["list"][0]["name"], "photo_eye");
  EXPECT_TRUE(r["palette"]["items"].contains("photo_eye"));
  r = replayOn(model, "- click: [palette, controls, search]\n- type: barrel plate\n");
  EXPECT_EQ(r["palette"]["listed"], 0);  // no part's words hold both
  r = replayOn(model, "- click: [palette, controls, search]\n- type: cylinder beside\n");
  EXPECT_EQ(r["palette"]["list"][0]["name"], "pusher");
  // View > Parts Palette hides it, and the tree takes the column
  r = replayOn(model, "- press: palette\n");
  EXPECT_FALSE(r["palette"]["shown"].get<bool>());
  EXPECT_EQ(r["layout"]["tree"][3], r["layout"]["world"][3].get<double>() + r["layout"]["inspector"][3].get<double>() + 6);
}

TEST_F(Palette, AStationIsDraggedTogetherFromAnEmptyFileSavedAndRuns) {
  const auto model = station();
  // user input only: three drags, a click on the offer, a click, a chord, typed text, Enter, Ctrl+S
  const std::string actions = R"Y(
- drag: {from: [palette, items, belt_conveyor], to: [world, center]}
- drag: {from: [palette, items, belt_conveyor], to: [world, parts, belt_conveyor1, +x]}
- drag: {from: [palette, items, pusher], to: [world, parts, belt_conveyor1, -y]}
- click: [palette, offer, buttons, yes]
- click: [inspector, part, fields, stroke]
- key: ctrl+a
- type: "0.8"
- key: enter
- key: ctrl+s
)Y";
  const auto r = replayOn(model, actions);
  EXPECT_EQ(r["undo"]["depth"], 5) << r["message"];  // three parts, a control, a parameter
  EXPECT_EQ(r["selection"]["name"], "pusher1");
  EXPECT_EQ(r["inspector"]["part"]["params"]["stroke"]["value"], 0.8) << r["inspector"].dump();
  EXPECT_EQ(r["inspector"]["part"]["control"]["controller"], "pusher1_control");
  EXPECT_EQ(r["tree"]["rows"].size(), 3U) << r["tree"].dump();  // each part one row
  EXPECT_FALSE(r["document"]["modified"].get<bool>());

  // the saved file: the second belt at the first one's end, the pusher on its centre line
  core::Diagnostics diags;
  const auto m = model::loadModel(model, diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(instance(*m, "belt_conveyor1").translation, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(instance(*m, "belt_conveyor2").translation, (std::array<double, 3>{2, 0, 0}));
  const auto& pusher = instance(*m, "pusher1");
  EXPECT_EQ(pusher.translation[1], 0);
  ASSERT_EQ(pusher.params.size(), 1U);
  EXPECT_EQ(pusher.params[0].name, "stroke");
  EXPECT_EQ(pusher.params[0].value, 0.8);
  EXPECT_EQ(instance(*m, "pusher1_control").part, "pusher1");
  EXPECT_EQ(m->parts.at("pusher").version, 1);
  // and it runs
  const auto sim = model::Simulation::create(*m, diags);
  ASSERT_NE(sim, nullptr) << diags.str();
  EXPECT_NE(sim->plant()->find("belt_conveyor2/belt/surface"), nullptr);
}

TEST_F(Palette, ADropIsOneStepOfUndoAndTheGhostShowsWhereItLands) {
  const auto model = station();
  // held over the first belt's end: the ghost snaps there, and nothing is placed yet
  const std::string first = "- drag: {from: [palette, items, belt_conveyor], to: [world, center]}\n";
  auto r = replayOn(model, first + "- drag: {from: [palette, items, belt_conveyor], to: [world, parts, belt_conveyor1, -x], hold: true}\n");
  ASSERT_TRUE(r["world"].contains("drop")) << r["world"].dump();
  EXPECT_EQ(r["world"]["drop"]["snap"], "end -x");
  EXPECT_EQ(r["world"]["drop"]["neighbour"], "belt_conveyor1");
  EXPECT_EQ(r["world"]["drop"]["translation"], (nlohmann::json{-2.0, 0.0, 0.0}));
  EXPECT_EQ(r["palette"]["dragging"], "belt_conveyor");
  EXPECT_EQ(r["undo"]["depth"], 1);
  // dropped, then undone: gone from the model and the views
  r = replayOn(model, first + "- key: ctrl+z\n");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_TRUE(r["world"]["parts"].empty()) << r["world"].dump();
  EXPECT_FALSE(r["tree"]["rows"].contains("belt_conveyor1"));
}

}  // namespace
}  // namespace gdpn::ide
