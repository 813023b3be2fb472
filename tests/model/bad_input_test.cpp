// Bad model files: every file in tests/data/bad names, on its first line, the diagnostic it
// must produce ("# expect: LINE:COL: error: text"). Loading and checking must report exactly
// there, and never crash.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/compile.h"

namespace gdpn::model {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> badFiles() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(GDPN_SOURCE_DIR) / "tests/data/bad")) {
    if (e.path().string().ends_with(kModelSuffix)) files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Loads and compiles `path` with its scripts, returning all diagnostics.
core::Diagnostics diagnose(const std::string& path) {
  core::Diagnostics diags;
  if (auto m = loadModel(path, diags)) {
    if (auto net = net::compile(m->net, diags); net && (net->scripted() || m->scene)) Simulation::create(*m, diags);
  }
  return diags;
}

class BadModel : public ::testing::TestWithParam<std::string> {};

TEST_P(BadModel, ReportsTheMistakeAtItsLocation) {
  const std::string path = GetParam();
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  const std::string marker = "# expect: ";
  ASSERT_EQ(first.rfind(marker, 0), 0u) << path << " must start with '" << marker << "'";
  const std::string expected = path + ":" + first.substr(marker.size());

  const auto diags = diagnose(path);
  EXPECT_TRUE(diags.hasErrors());
  bool found = false;
  for (const auto& d : diags.all()) found = found || d.str().rfind(expected, 0) == 0;
  EXPECT_TRUE(found) << "expected a diagnostic starting with\n  " << expected << "\ngot\n" << diags.str();
}

INSTANTIATE_TEST_SUITE_P(Files, BadModel, ::testing::ValuesIn(badFiles()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = fs::path(param.param).filename().string();
                           name = name.substr(0, name.find('.'));
                           return name;
                         });

TEST(BadInput, CheckingGoesOnToFindEveryMistake) {
  core::Diagnostics diags;
  auto m = parseModel(R"(gdpn: 1
pages:
  main:
    places:
      P: {tokens: 1, capasity: 3}
      Q: {tokens: many}
    transitions:
      T: {duration: soon, prio: 2}
)", "many.gdpn.yaml", diags);
  EXPECT_FALSE(m);
  EXPECT_EQ(diags.errorCount(), 4u) << diags.str();
  const std::string all = diags.str();
  EXPECT_NE(all.find("many.gdpn.yaml:5:22: error: unknown key 'capasity'"), std::string::npos) << all;
  EXPECT_NE(all.find("many.gdpn.yaml:6:19: error: 'tokens' expects a whole number, got \"many\""), std::string::npos) << all;
  EXPECT_NE(all.find("many.gdpn.yaml:8:21: error: 'duration' expects a number, got \"soon\""), std::string::npos) << all;
  EXPECT_NE(all.find("many.gdpn.yaml:8:27: error: unknown key 'prio' in transition (did you mean 'priority'?)"),
            std::string::npos) << all;
}

TEST(BadInput, SemanticErrorsAreAllReportedToo) {
  core::Diagnostics diags;
  auto m = parseModel(R"(pages:
  main:
    places:
      P: {tokens: 3, capacity: 1}
    transitions:
      T: {duration: -1}
    arcs:
      - P -> X
      - {from: P, to: T, weight: 0}
)", "sem.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_FALSE(net::compile(m->net, diags));
  const std::string all = diags.str();
  EXPECT_EQ(diags.errorCount(), 4u) << all;
  EXPECT_NE(all.find("sem.gdpn.yaml:4:32: error: capacity 1"), std::string::npos) << all;
  EXPECT_NE(all.find("sem.gdpn.yaml:6:21: error: duration of transition 'T' is negative"), std::string::npos) << all;
  EXPECT_NE(all.find("sem.gdpn.yaml:8:9: error: 'X' names no place"), std::string::npos) << all;
  EXPECT_NE(all.find("sem.gdpn.yaml:9:34: error: arc weight must be at least 1, got 0"), std::string::npos) << all;
}

TEST(BadInput, MissingFileIsAnErrorNotACrash) {
  core::Diagnostics diags;
  EXPECT_FALSE(loadModel("/nonexistent/x.gdpn.yaml", diags));
  EXPECT_EQ(diags.str(), "/nonexistent/x.gdpn.yaml: error: no such file\n");
}

TEST(BadInput, AnEmptyFileIsRefusedAtItsFirstLine) {
  // nothing, blanks, or only comments: more likely a mistake than a model
  for (const std::string text : {"", "  \n\n\t\n", "# a comment\n\n# another\n"}) {
    core::Diagnostics diags;
    EXPECT_FALSE(parseModel(text, "empty.gdpn.yaml", diags)) << '"' << text << '"';
    EXPECT_EQ(diags.str(), "empty.gdpn.yaml:1:1: error: the model file is empty\n") << '"' << text << '"';
  }
}

TEST(BadInput, AFolderIsNotAModelFile) {
  core::Diagnostics diags;
  EXPECT_FALSE(loadModel(GDPN_SOURCE_DIR, diags));
  EXPECT_EQ(diags.str(), std::string(GDPN_SOURCE_DIR) + ": error: is a folder, not a file\n");
}

TEST(BadInput, GarbageBytesAreAnErrorNotACrash) {
  core::Diagnostics diags;
  const std::string junk("\x00\xff\xfe{[:\n\t- ]]}\x01", 14);
  EXPECT_FALSE(parseModel(junk, "junk.gdpn.yaml", diags));
  EXPECT_TRUE(diags.hasErrors());
  EXPECT_EQ(diags.all()[0].loc.file, "junk.gdpn.yaml");
}

TEST(BadInput, DeepNestingIsAnErrorNotAStackOverflow) {
  core::Diagnostics diags;
  const std::string deep = "pages: " + std::string(100000, '[');
  EXPECT_FALSE(parseModel(deep, "deep.gdpn.yaml", diags));
  EXPECT_TRUE(diags.hasErrors());
}

TEST(ModelPath, AFolderMustHoldExactlyOneModel) {
  core::Diagnostics diags;
  const auto dir = fs::path(GDPN_SOURCE_DIR) / "examples/basics/figure31";
  auto one = resolveModelPath(dir.string(), diags);
  ASSERT_TRUE(one);
  EXPECT_EQ(fs::path(*one).filename(), "figure31.gdpn.yaml");
  core::Diagnostics many;
  EXPECT_FALSE(resolveModelPath((fs::path(GDPN_SOURCE_DIR) / "tests/data/bad").string(), many));
  EXPECT_NE(many.str().find("model files"), std::string::npos);
  core::Diagnostics none;
  EXPECT_FALSE(resolveModelPath((fs::path(GDPN_SOURCE_DIR) / "docs").string(), none));
  EXPECT_NE(none.str().find("holds no model file"), std::string::npos);
}

}  // namespace
}  // namespace gdpn::model
