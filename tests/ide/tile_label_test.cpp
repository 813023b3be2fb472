// The palette tile's name in lines: at spaces, inside a word that alone is too wide, cut with
// ".." when the lines run out; measured here as 7 units a character (a monospace font).

#include "gdpn/ide/tile_label.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gdpn::ide {
namespace {

using Lines = std::vector<std::string>;

float mono(std::string_view text) { return 7.0F * static_cast<float>(text.size()); }

TEST(TileLabel, ANameThatFitsIsOneLine) {
  EXPECT_EQ(tileLabel("pusher", 66, mono), Lines{"pusher"});
  EXPECT_EQ(tileLabel("", 66, mono), Lines{});
}

TEST(TileLabel, WordsGoOnTheNextLineAtASpace) {
  // 9 characters fit in 66 units
  EXPECT_EQ(tileLabel("belt conveyor", 66, mono), (Lines{"belt", "conveyor"}));
  EXPECT_EQ(tileLabel("diffuse sensor", 66, mono), (Lines{"diffuse", "sensor"}));
}

TEST(TileLabel, AWordTooWideIsBrokenWithAHyphen) {
  // "potentiometer" (13) was clipped to "potentiome" in the palette
  EXPECT_EQ(tileLabel("potentiometer", 66, mono), (Lines{"potentio-", "meter"}));
  EXPECT_EQ(tileLabel("pick and place", 66, mono), (Lines{"pick and", "place"}));
}

TEST(TileLabel, TheLastLineEndsInDotsWhenTheNameGoesOn) {
  const auto lines = tileLabel("pivot arm sorter with a very long name", 66, mono);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "pivot arm");
  EXPECT_EQ(lines[1], "sorter..");
  for (const auto& l : lines) EXPECT_LE(mono(l), 66.0F) << l;
  EXPECT_EQ(tileLabel("potentiometer", 66, mono, 1), Lines{"potenti.."});
}

TEST(TileLabel, EveryLineFitsAndNothingIsLostWhileLinesLast) {
  const std::string name = "a_name_with_no_spaces_at_all";
  const auto lines = tileLabel(name, 40, mono, 10);
  std::string joined;
  for (const auto& l : lines) {
    EXPECT_LE(mono(l), 40.0F) << l;
    joined += l.back() == '-' ? l.substr(0, l.size() - 1) : l;
  }
  EXPECT_EQ(joined, name);
  // narrower than one character: one a line, still every character
  EXPECT_EQ(tileLabel("abc", 3, mono, 5), (Lines{"a-", "b-", "c"}));
  // spaces at a break go, none is a line of its own
  EXPECT_EQ(tileLabel("  belt   conveyor", 66, mono), (Lines{"belt", "conveyor"}));
}

TEST(TileLabel, AUtf8CharacterIsNeverSplit) {
  // "Förderband" is 11 bytes: measured by bytes, 9 fit before the hyphen
  const auto lines = tileLabel("F\xC3\xB6rderbandanlage", 66, mono);
  ASSERT_EQ(lines.size(), 2u);
  for (const auto& l : lines) {
    for (std::size_t i = 0; i < l.size(); ++i) {
      const auto c = static_cast<unsigned char>(l[i]);
      if (c == 0xC3) {
        ASSERT_LT(i + 1, l.size()) << l;  // its second byte on the same line
        EXPECT_EQ(static_cast<unsigned char>(l[i + 1]), 0xB6) << l;
      }
    }
  }
  EXPECT_EQ(tileLabel("\xC3\xB6\xC3\xB6", 3, mono, 5), (Lines{"\xC3\xB6-", "\xC3\xB6"}));
}

}  // namespace
}  // namespace gdpn::ide
