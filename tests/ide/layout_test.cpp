// The layout (splitters, the world and net views swapped or filling the window) and the
// settings file that remembers it with the recent files.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

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

TEST(Layout, ThePartsPaletteStandsUnderTheTreeUntilHidden) {
  Splitters s;
  auto l = Layout::of(s, 1600, 900);
  EXPECT_FLOAT_EQ(l.palette.x, 0);
  EXPECT_FLOAT_EQ(l.palette.w, l.tree.w);
  EXPECT_FLOAT_EQ(l.palette.h, s.palette_height);
  EXPECT_FLOAT_EQ(l.tree.y + l.tree.h + kHandle, l.palette.y);
  EXPECT_FLOAT_EQ(l.palette.y + l.palette.h, 900 - kStatusHeight);
  EXPECT_FLOAT_EQ(l.handles[static_cast<int>(Splitter::Palette)].y, l.tree.y + l.tree.h);
  // as tall as the column allows, less a tree of its least size
  s.palette_height = 5000;
  l = Layout::of(s, 1600, 900);
  EXPECT_GE(l.tree.h, 120);
  s.show_palette = false;
  l = Layout::of(s, 1600, 900);
  EXPECT_EQ(l.palette.w, 0);
  EXPECT_EQ(l.handles[static_cast<int>(Splitter::Palette)].w, 0);
  EXPECT_FLOAT_EQ(l.tree.h, 900 - kToolbarHeight - kStatusHeight);
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

TEST(Layout, SwappedTheNetViewTakesTheBigPanel) {
  Splitters s;
  const auto before = Layout::of(s, 1600, 900);
  s.swapped = true;
  const auto l = Layout::of(s, 1600, 900);
  EXPECT_FLOAT_EQ(l.net.x, before.world.x);
  EXPECT_FLOAT_EQ(l.net.w, before.world.w);
  EXPECT_FLOAT_EQ(l.world.x, before.net.x);
  EXPECT_FLOAT_EQ(l.world.w, before.net.w);
  EXPECT_FLOAT_EQ(l.inspector.w, before.inspector.w);  // the bottom row stays
}

TEST(Layout, AViewFillingTheWindowTakesTheWholeBodyAndHidesTheOthers) {
  Splitters s;
  s.full = FullView::Net;
  const auto l = Layout::of(s, 1600, 900);
  EXPECT_FLOAT_EQ(l.net.x, 0);
  EXPECT_FLOAT_EQ(l.net.y, kToolbarHeight);
  EXPECT_FLOAT_EQ(l.net.w, 1600);
  EXPECT_FLOAT_EQ(l.net.h, 900 - kToolbarHeight - kStatusHeight);
  for (const Rect& hidden : {l.world, l.tree, l.inspector, l.diagnostics, l.palette}) EXPECT_EQ(hidden.w, 0);
  for (const Rect& h : l.handles) EXPECT_EQ(h.w, 0);
  EXPECT_EQ(l.toolbar.w, 1600);
  s.full = FullView::World;
  EXPECT_FLOAT_EQ(Layout::of(s, 1600, 900).world.w, 1600);
}

TEST(Layout, RecentFilesPutTheLatestFirstOnceAndKeepTen) {
  std::vector<std::string> r;
  for (int i = 0; i < 12; ++i) r = withRecent(r, "/m/" + std::to_string(i) + ".gdpn.yaml");
  ASSERT_EQ(r.size(), kRecentFiles);
  EXPECT_EQ(r.front(), "/m/11.gdpn.yaml");
  EXPECT_EQ(r.back(), "/m/2.gdpn.yaml");
  r = withRecent(r, "/m/5.gdpn.yaml");
  EXPECT_EQ(r.front(), "/m/5.gdpn.yaml");
  EXPECT_EQ(std::count(r.begin(), r.end(), "/m/5.gdpn.yaml"), 1);
  EXPECT_EQ(r.size(), kRecentFiles);
}

TEST_F(SettingsFile, TheLayoutAndRecentFilesSurviveASaveAndALoad) {
  const auto path = (dir_ / "deeper" / "ide.ini").string();
  Settings s;
  s.splitters.tree_width = 333;
  s.splitters.net_width = 512;
  s.splitters.swapped = true;
  s.splitters.full = FullView::Net;
  s.splitters.show_palette = false;
  s.splitters.palette_height = 222;
  s.recent = {"/a/b c.gdpn.yaml", "/d/e=f.gdpn.yaml"};  // spaces and '=' in names
  ASSERT_TRUE(saveSettingsFile(path, s));
  const auto back = loadSettingsFile(path);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, s);
  EXPECT_FALSE(loadSettingsFile((dir_ / "none.ini").string()));
}

TEST_F(SettingsFile, BadLinesArePassedOver) {
  const auto path = write("ide.ini", "tree_width=abc\nnet_width=-4\nnonsense\nbottom_height=300\nfull=sideways\nrecent=\n");
  const auto s = loadSettingsFile(path);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->splitters.tree_width, Splitters{}.tree_width);
  EXPECT_EQ(s->splitters.net_width, Splitters{}.net_width);
  EXPECT_EQ(s->splitters.bottom_height, 300);
  EXPECT_EQ(s->splitters.full, FullView::None);
  EXPECT_TRUE(s->recent.empty());
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
