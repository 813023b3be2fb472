// Value tokens in the headless IDE (issue 59), on tests/data/colour/orders.gdpn.yaml: a colour
// set declared in the colour sets view, an arc inscription typed with a type error (shown with
// its column, not applied) and corrected, and a binding chosen and fired by hand, with the
// values it leaves. Asserted on the report and the file saved, not on pixels.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "ide/headless_fixture.h"
#include "support/cli.h"
#include "support/scratch.h"

namespace gdpn::ide {
namespace {

class ColourReplay : public HeadlessIde {
 protected:
  void SetUp() override {
    HeadlessIde::SetUp();
    hidePalette();
    size_ = "1600x900";
    model_ = write("orders.gdpn.yaml", gdpn::testing::fileBytes(GDPN_SOURCE_DIR "/tests/data/colour/orders.gdpn.yaml"));
  }
  nlohmann::json run(const std::string& actions) { return replayOn(model_, actions); }
  std::string model_;
};

TEST_F(ColourReplay, AColourSetIsDeclaredInItsViewAMistakeShownInPlaceAndNotApplied) {
  const std::string open = "- press: colour-sets\n- frames: 2\n";
  const std::string typed = open + "- click: [colour_sets, fields, new name]\n- type: Size\n"
                                   "- click: [colour_sets, fields, new definition]\n- type: '{enum: [small, large'\n"
                                   "- key: enter\n- frames: 2\n";
  // the bracket left open: said at the end of the text, and nothing declared
  auto r = run(typed);
  const auto& view = r["colour_sets"];
  ASSERT_TRUE(view["problems"].contains("new set")) << view.dump();
  EXPECT_EQ(view["problems"]["new set"]["column"], 21);
  EXPECT_NE(view["problems"]["new set"]["message"].get<std::string>().find("YAML syntax"), std::string::npos);
  EXPECT_EQ(view["sets"].size(), 3u);
  EXPECT_EQ(r["undo"]["depth"], 0);
  // closed and declared: one step of undo, listed with its values, saved as the file writes it
  r = run(typed + "- click: [colour_sets, fields, new definition]\n- key: end\n- type: ']}'\n"
                  "- click: [colour_sets, buttons, Declare set]\n- frames: 2\n- press: save\n");
  ASSERT_EQ(r["colour_sets"]["sets"].size(), 4u) << r["colour_sets"].dump();
  EXPECT_EQ(r["colour_sets"]["sets"][3]["name"], "Size");
  EXPECT_EQ(r["colour_sets"]["sets"][3]["definition"], "{enum: [small, large]}");
  EXPECT_EQ(r["colour_sets"]["sets"][3]["values"], "2 values");
  EXPECT_TRUE(r["colour_sets"]["problems"].empty()) << r["colour_sets"].dump();
  EXPECT_EQ(r["undo"]["label"], "declare colour set Size");
  const auto saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("Size: {enum: [small, large]}"), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model_ + "'").code, 0) << saved;
  // a set in use is not deleted
  r = run(open + "- click: [colour_sets, buttons, delete Id]\n- frames: 2\n");
  EXPECT_EQ(r["colour_sets"]["sets"].size(), 4u);
  ASSERT_TRUE(r["colour_sets"]["problems"].contains("set 0")) << r["colour_sets"].dump();
  EXPECT_NE(r["colour_sets"]["problems"]["set 0"]["message"].get<std::string>().find("is used by colour set Order"),
            std::string::npos);
}

TEST_F(ColourReplay, AnInscriptionWithATypeErrorIsMarkedAtItsColumnAndAppliedOnlyOnceCorrected) {
  const std::string pick = "- select: 'main: waiting -> serve'\n- frames: 2\n";
  const std::string wrong = pick + "- click: [inspector, fields, inscription a0]\n- key: ctrl+a\n- type: '(s, n)'\n"
                                   "- key: enter\n- frames: 2\n";
  auto r = run(wrong);
  const auto& field = r["inspector"]["inscriptions"]["inscription a0"];
  ASSERT_TRUE(field.contains("problem")) << r["inspector"].dump();
  EXPECT_EQ(field["problem"]["column"], 2);
  EXPECT_EQ(field["problem"]["message"], "expected Id, found Name");
  EXPECT_EQ(field["typed"], "(s, n)");
  EXPECT_EQ(field["text"], "(n, s)");  // the old text in force
  EXPECT_EQ(r["undo"]["depth"], 0);
  // completion while typing: `n` and `s` offered at the start of a word
  ASSERT_TRUE(field.contains("completion"));
  // corrected: applied as one step, saved, and the model checks
  r = run(wrong + "- key: ctrl+a\n- type: \"1'(n, s)\"\n- key: enter\n- frames: 2\n- press: save\n");
  const auto& fixed = r["inspector"]["inscriptions"]["inscription a0"];
  EXPECT_FALSE(fixed.contains("problem")) << fixed.dump();
  EXPECT_EQ(fixed["text"], "1'(n, s)");
  EXPECT_EQ(r["undo"]["depth"], 1);
  const auto saved = gdpn::testing::fileBytes(model_);
  EXPECT_NE(saved.find("inscription: \"1'(n, s)\""), std::string::npos) << saved;
  EXPECT_EQ(gdpn::testing::runGdpn("check '" + model_ + "'").code, 0) << saved;
}

TEST_F(ColourReplay, ABindingChosenIsFiredByHandAndThePlacesShowTheValuesItLeaves) {
  auto r = run("- select: main/serve\n- frames: 2\n");
  // before the run: both orders under 3 are bindings, in canonical order
  EXPECT_EQ(r["inspector"]["bindings"], (nlohmann::json{"n = 1, s = \"a\"", "n = 2, s = \"b\""})) << r["inspector"].dump();
  r = run("- select: main/waiting\n- frames: 2\n");
  EXPECT_EQ(r["inspector"]["values"]["a0"], "2'(1, \"a\") ++ 1'(2, \"b\")");
  // the second one fired: it occurs in it, and the one control token is gone
  const std::string fire = "- select: main/serve\n- frames: 2\n- click: [inspector, binding_at, 'n = 2, s = \"b\"']\n- frames: 2\n";
  r = run(fire);
  EXPECT_EQ(r["inspector"]["binding"], "n = 2, s = \"b\"") << r["inspector"].dump();
  EXPECT_EQ(r["inspector"]["bindings"], nlohmann::json::array());
  // one step completes it: the values moved
  r = run(fire + "- steps: 1\n- select: main/done\n- frames: 2\n");
  EXPECT_EQ(r["inspector"]["values"]["a0"], "1'(2, \"b\")") << r["inspector"].dump();
  r = run(fire + "- steps: 1\n- select: main/waiting\n- frames: 2\n");
  EXPECT_EQ(r["inspector"]["values"]["a0"], "2'(1, \"a\")") << r["inspector"].dump();
}

}  // namespace
}  // namespace gdpn::ide
