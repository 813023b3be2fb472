// NameTable: names -> ids over names held by the caller.

#include "gdpn/core/name_table.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gdpn::core {
namespace {

TEST(NameTable, FindsWhatWasInsertedAndKeepsTheFirstOfAName) {
  const std::vector<std::string> names{"main/p0", "main/t0", "main/p0", ""};
  auto nameOf = [&](std::uint32_t id) -> std::string_view { return names[id]; };
  NameTable table;
  EXPECT_FALSE(table.find("main/p0", nameOf));  // empty table
  EXPECT_EQ(table.insert(names[0], 0, nameOf), std::make_pair(0u, true));
  EXPECT_EQ(table.insert(names[1], 1, nameOf), std::make_pair(1u, true));
  EXPECT_EQ(table.insert(names[2], 2, nameOf), std::make_pair(0u, false));  // a second "main/p0"
  EXPECT_EQ(table.insert(names[3], 3, nameOf), std::make_pair(3u, true));   // the empty name is a name
  EXPECT_EQ(table.size(), 3u);
  EXPECT_EQ(table.find("main/t0", nameOf), 1u);
  EXPECT_EQ(table.find("", nameOf), 3u);
  EXPECT_FALSE(table.find("main/t1", nameOf));
  EXPECT_FALSE(table.find("main/p", nameOf));
  table.clear();
  EXPECT_EQ(table.size(), 0u);
  EXPECT_FALSE(table.find("main/t0", nameOf));
}

TEST(NameTable, GrowsAndStillFindsEveryName) {
  std::vector<std::string> names;
  for (int i = 0; i < 100000; ++i) names.push_back("n" + std::to_string(i));
  auto nameOf = [&](std::uint32_t id) -> std::string_view { return names[id]; };
  NameTable table;  // no reserve: it grows from 16 slots
  for (std::uint32_t i = 0; i < names.size(); ++i) ASSERT_TRUE(table.insert(names[i], i, nameOf).second) << i;
  for (std::uint32_t i = 0; i < names.size(); ++i) ASSERT_EQ(table.find(names[i], nameOf), i);
  EXPECT_FALSE(table.find("n100000", nameOf));
  EXPECT_GE(table.memoryBytes(), names.size() * 8);  // at most half full
}

}  // namespace
}  // namespace gdpn::core
