// How every face analyses a hybrid model (session::analysedNet): its discrete part, with a
// note saying what was left out. A pump filling a tank until a level switch stops it: the
// discrete net alone is `running -> stop -> stopped`, two markings; the tank's threshold
// counts as met.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "gdpn/model/analysis.h"
#include "gdpn/model/model.h"
#include "gdpn/session/analysis_request.h"
#include "support/hybrid_models.h"

namespace gdpn::session {
namespace {

TEST(HybridAnalysis, TheDiscretePartIsAnalysedAndTheNoteSaysWhatWasLeftOut) {
  core::Diagnostics diags;
  auto m = model::parseModel(testing::fillModelText(), "tank.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  const auto analysed = analysedNet(m->net, diags);
  ASSERT_TRUE(analysed) << diags.str();
  const net::Net& net = *analysed->net;
  EXPECT_EQ(net.places().size(), 2u);       // running, stopped
  EXPECT_EQ(net.transitions().size(), 1u);  // stop
  EXPECT_EQ(net.fluid(), nullptr);
  ASSERT_EQ(analysed->notes.size(), 1u);
  EXPECT_NE(analysed->notes[0].find("the continuous part (1 continuous place, 1 continuous transition, 3 arcs) is left out"),
            std::string::npos)
      << analysed->notes[0];
  AnalysisRequest request;
  const auto answer = analyze(*analysed, "tank.gdpn.yaml", request);
  EXPECT_EQ(answer.analysis.space.states, 2u);
  std::ostringstream text;
  model::printAnalysis(text, net, answer.analysis);
  EXPECT_NE(text.str().find("note: the continuous part"), std::string::npos) << text.str();
  EXPECT_NE(model::analysisJson(net, answer.analysis).find("the continuous part"), std::string::npos);
}

TEST(HybridAnalysis, AMistakeInTheContinuousPartIsStillReported) {
  core::Diagnostics diags;
  std::string text = testing::fillModelText();
  text.replace(text.find("rate: 0.3"), 9, "rate: 0.3 * tnak");
  auto m = model::parseModel(text, "tank.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_FALSE(analysedNet(m->net, diags));
  EXPECT_NE(diags.str().find("no name 'tnak' (did you mean 'tank'?)"), std::string::npos) << diags.str();
}

}  // namespace
}  // namespace gdpn::session
