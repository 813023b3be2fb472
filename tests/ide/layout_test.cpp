// The fixed layout and the settings file that remembers the splitters.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "gdpn/ide/layout.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

TEST(Layout, TheViewsTileTheWindow) {
  Splitters s;
  const auto l = Layout::of(s, 1600, 900);
  EXPECT_EQ(l.toolbar.h, kToolbarHeight);
  EXPECT_EQ(l.tree.x, 0);
  EXPECT_EQ(l.tree.w, s.tree_width);
  EXPECT_FLOAT_EQ(l.world.x, s.tree_width + kHandle);
  EXPECT_FLOAT_EQ(l.net.x + l.net.w, 1600);
  EXPECT_FLOAT_EQ(l.diagnostics.x + l.diagnostics.w, 1600);
  EXPECT_FLOAT_EQ(l.inspector.y + l.inspector.h, 900 - kStatusHeight);
  EXPECT_FLOAT_EQ(l.world.y + l.world.h + kHandle, l.inspector.y);
  EXPECT_FLOAT_EQ(l.status.y, 900 - kStatusHeight);
}

TEST(Layout, SplittersAreClampedSoEveryViewKeepsASize) {
  Splitters s;
  s.tree_width = 5000;
  s.bottom_height = -3;
  const auto l = Layout::of(s, 800, 600);
  EXPECT_LT(s.tree_width, 800);
  EXPECT_GE(l.world.w, 0);
  EXPECT_GE(s.bottom_height, 60);
}

class SettingsFile : public gdpn::testing::TempDirTest {};

TEST_F(SettingsFile, SplittersSurviveASaveAndALoad) {
  const auto path = (dir_ / "deeper" / "ide.ini").string();
  Splitters s;
  s.tree_width = 333;
  s.net_width = 512;
  ASSERT_TRUE(saveSplitters(path, s));
  const auto back = loadSplitters(path);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, s);
  EXPECT_FALSE(loadSplitters((dir_ / "none.ini").string()));
}

TEST_F(SettingsFile, BadLinesArePassedOver) {
  const auto path = write("ide.ini", "tree_width=abc\nnet_width=-4\nnonsense\nbottom_height=300\n");
  const auto s = loadSplitters(path);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->tree_width, Splitters{}.tree_width);
  EXPECT_EQ(s->net_width, Splitters{}.net_width);
  EXPECT_EQ(s->bottom_height, 300);
}

TEST_F(SettingsFile, TheFileLivesUnderXdgConfigHome) {
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old != nullptr ? old : "";
  ::setenv("XDG_CONFIG_HOME", dir_.c_str(), 1);
  EXPECT_EQ(settingsPath(), (dir_ / "gdpn" / "ide.ini").string());
  if (old != nullptr) ::setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
  else ::unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace gdpn::ide
