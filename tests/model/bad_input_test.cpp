// Bad model files: every file in tests/data/bad names, on its first line, the diagnostic it
// must produce ("# expect: LINE:COL: error: text"). Loading and checking must report exactly
// there, and never crash.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <fstream>

#include "gdpn/core/file.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "support/temp_files.h"

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

/// Loads and checks `path` as `gdpn check` does, returning all diagnostics.
core::Diagnostics diagnose(const std::string& path) {
  core::Diagnostics diags;
  if (auto m = loadModel(path, diags)) {
    checkModel(*m, diags);
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

TEST(BadInput, APageTypesMistakeIsReportedOnceHoweverManyInstancesItHas) {
  // a page type that contains itself, instanced twice: one error, at the instance inside it
  core::Diagnostics diags;
  auto m = parseModel(R"(gdpn: 1
page_types:
  cell:
    places:
      p: {}
    instances:
      inner: {type: cell}
pages:
  main:
    instances:
      a: {type: cell}
      b: {type: cell}
)", "self.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_FALSE(net::compile(m->net, diags));
  const std::string all = diags.str();
  EXPECT_EQ(diags.errorCount(), 1u) << all;
  EXPECT_EQ(all, "self.gdpn.yaml:7:7: error: page type 'cell' contains itself (cell -> cell)\n");
}

TEST(BadInput, MissingFileIsAnErrorNotACrash) {
  core::Diagnostics diags;
  EXPECT_FALSE(loadModel("/nonexistent/x.gdpn.yaml", diags));
  EXPECT_EQ(diags.str(), "/nonexistent/x.gdpn.yaml: error: cannot read the file\n");
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

// --- every reader is bounded by the file's real size ---------------------------------------

/// The three readers of whole files: a model, input events, a PNML net; each gives a result or
/// diagnostics.
const std::vector<std::pair<std::string, std::function<bool(const std::string&, core::Diagnostics&)>>>& readers() {
  static const std::vector<std::pair<std::string, std::function<bool(const std::string&, core::Diagnostics&)>>> kReaders = {
      {"model", [](const std::string& p, core::Diagnostics& d) { return loadModel(p, d).has_value(); }},
      {"input", [](const std::string& p, core::Diagnostics& d) { return loadInput(p, d).has_value(); }},
      {"pnml", [](const std::string& p, core::Diagnostics& d) { return net::loadPnml(p, d).has_value(); }}};
  return kReaders;
}

/// Each reader refuses `path` within a few seconds with exactly `expected` as its diagnostics.
void expectRefused(const std::string& path, const std::string& expected) {
  for (const auto& reader : readers()) {
    const auto& name = reader.first;  // not a structured binding: clang 14 captures none
    const auto& read = reader.second;
    core::Diagnostics diags;
    EXPECT_LT(testing::secondsFor([&] { EXPECT_FALSE(read(path, diags)) << name << " " << path; }), 5.0) << name;
    EXPECT_EQ(diags.str(), expected) << name;
  }
}

TEST(ReadingLimits, EndlessAndNonRegularFilesAreRefusedAtOnce) {
  expectRefused("/dev/zero", "/dev/zero: error: is a character device, not a regular file\n");
  expectRefused("/dev/urandom", "/dev/urandom: error: is a character device, not a regular file\n");
  const auto dir = fs::temp_directory_path() / ("gdpn_limits_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto fifo = (dir / "pipe.gdpn.yaml").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectRefused(fifo, fifo + ": error: is a FIFO, not a regular file\n");
  fs::remove_all(dir);
}

TEST(ReadingLimits, AGigabyteIsRefusedNamingTheLimit) {
  const auto dir = fs::temp_directory_path() / ("gdpn_limits_big_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // sparse: a gigabyte that takes no disk
  const auto big = (dir / "big.gdpn.yaml").string();
  std::ofstream{big};
  fs::resize_file(big, std::uintmax_t{1} << 30);
  expectRefused(big, big + ": error: the file is 1024 MiB; gdpn reads input files of at most 256 MiB\n");
  // garbage over a lowered limit; under it, garbage is a located error
  std::string garbage;
  for (int i = 0; i < 5000; ++i) garbage += static_cast<char>((i * 7919) % 251);
  const auto junk = (dir / "junk.yaml").string();
  std::ofstream(junk, std::ios::binary) << garbage;
  {
    core::InputLimit limit(4096);
    expectRefused(junk, junk + ": error: the file is 5000 bytes; gdpn reads input files of at most 4 KiB\n");
  }
  for (const auto& reader : readers()) {
    const auto& name = reader.first;  // not a structured binding: clang 14 captures none
    const auto& read = reader.second;
    core::Diagnostics diags;
    EXPECT_FALSE(read(junk, diags)) << name;
    ASSERT_TRUE(diags.hasErrors()) << name;
    EXPECT_EQ(diags.all()[0].loc.file, junk) << name;
    EXPECT_GT(diags.all()[0].loc.line, 0) << name << ": " << diags.str();
  }
  fs::remove_all(dir);
}

TEST(ReadingLimits, InputEventsReportTheirPlace) {
  const auto path = (fs::temp_directory_path() / ("gdpn_input_" + std::to_string(::getpid()) + ".yaml")).string();
  std::ofstream(path) << "- {t: 1, key: a}\n- {t: -2, key: b}\n- " + std::string(100000, '[') + "\n";
  core::Diagnostics diags;
  EXPECT_FALSE(loadInput(path, diags));
  ASSERT_TRUE(diags.hasErrors());
  EXPECT_EQ(diags.all()[0].loc.file, path);
  EXPECT_GT(diags.all()[0].loc.line, 0) << diags.str();
  fs::remove(path);
}

}  // namespace
}  // namespace gdpn::model
