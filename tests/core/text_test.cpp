#include "gdpn/core/text.h"

#include <gtest/gtest.h>

#include "gdpn/core/diagnostics.h"

namespace gdpn::core {
namespace {

TEST(Text, EditDistance) {
  EXPECT_EQ(editDistance("capacity", "capacty"), 1u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("kye", "key"), 1u);  // a swap of neighbours is one slip
}

TEST(Text, DidYouMeanOnlyForCloseWords) {
  const std::vector<std::string> keys = {"tokens", "capacity", "description"};
  EXPECT_EQ(didYouMean("capasity", keys), " (did you mean 'capacity'?)");
  EXPECT_EQ(didYouMean("zzz", keys), "");
}

TEST(Text, FormatDoubleIsShortestExact) {
  EXPECT_EQ(formatDouble(0.1), "0.1");
  EXPECT_EQ(formatDouble(4.0), "4");
  EXPECT_EQ(formatDouble(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(formatDouble(-1.5), "-1.5");
}

TEST(Text, NegativeZeroIsWrittenZero) {
  EXPECT_EQ(formatDouble(-0.0), "0");
  EXPECT_EQ(formatDouble(-1.75 * 0.0), "0");
  EXPECT_EQ(formatDouble(-1e-300), "-1e-300");
}

TEST(Text, AFloatWidensToWhatItsShortestTextSays) {
  EXPECT_EQ(widenFloat(0.6F), 0.6);
  EXPECT_EQ(widenFloat(0.2F), 0.2);
  EXPECT_EQ(formatDouble(widenFloat(0.1F + 0.2F)), "0.3");  // 0.3F is the float nearest the sum
  EXPECT_EQ(formatDouble(widenFloat(1.0F / 3.0F)), "0.33333334");
  EXPECT_EQ(static_cast<float>(widenFloat(1.0F / 3.0F)), 1.0F / 3.0F);  // the same 32-bit value
  EXPECT_EQ(widenFloat(-0.0F), 0.0);
}

TEST(Text, ModelTimesPrintWithoutTheNoiseOfSummedSteps) {
  EXPECT_EQ(formatDouble(781 * 0.01), "7.8100000000000005");  // what a step count times dt gives
  EXPECT_EQ(formatTime(781 * 0.01), "7.81");
  EXPECT_EQ(formatTime(560 * 0.01), "5.6");
  EXPECT_EQ(formatTime(0.0), "0");
  EXPECT_EQ(formatTime(1.0 / 60.0), "0.016666667");  // to the nanosecond
  EXPECT_EQ(formatTime(1e-9), "1e-09");
  EXPECT_EQ(formatTime(-2.5), "-2.5");
}

TEST(Text, JsonQuoteEscapes) {
  EXPECT_EQ(jsonQuote("a\"b\\c\n\x01"), "\"a\\\"b\\\\c\\n\\u0001\"");
}

TEST(Text, Identifiers) {
  EXPECT_TRUE(isIdentifier("push_box"));
  EXPECT_TRUE(isIdentifier("_x1"));
  EXPECT_FALSE(isIdentifier("1st"));
  EXPECT_FALSE(isIdentifier("a-b"));
  EXPECT_FALSE(isIdentifier(""));
}

TEST(Diagnostics, GccForm) {
  Diagnostics d;
  d.error({"m.gdpn.yaml", 12, 7}, "field 'width' expects a number, got \"abc\"");
  d.warning({"m.gdpn.yaml", 3, 0}, "w");
  d.note({"", 0, 0}, "n");
  EXPECT_EQ(d.str(),
            "m.gdpn.yaml:12:7: error: field 'width' expects a number, got \"abc\"\n"
            "m.gdpn.yaml:3: warning: w\n"
            "<input>: note: n\n");
  EXPECT_EQ(d.errorCount(), 1u);
}

TEST(Diagnostics, OneSaidAgainAtTheSamePlaceIsSaidOnceWithItsNotes) {
  // a page type's mistake met again in its second instance: one error, one note; the same
  // words at another place, and a note of a new error, are kept
  Diagnostics d;
  for (int instance = 0; instance < 2; ++instance) {
    d.error({"m.gdpn.yaml", 7, 7}, "page type 'cell' contains itself (cell -> cell)");
    d.note({"m.gdpn.yaml", 3, 3}, "cell is here");
  }
  d.error({"m.gdpn.yaml", 9, 7}, "page type 'cell' contains itself (cell -> cell)");
  d.note({"m.gdpn.yaml", 3, 3}, "cell is here");
  Diagnostics more;
  more.error({"m.gdpn.yaml", 7, 7}, "page type 'cell' contains itself (cell -> cell)");
  d.append(more);
  EXPECT_EQ(d.str(),
            "m.gdpn.yaml:7:7: error: page type 'cell' contains itself (cell -> cell)\n"
            "m.gdpn.yaml:3:3: note: cell is here\n"
            "m.gdpn.yaml:9:7: error: page type 'cell' contains itself (cell -> cell)\n"
            "m.gdpn.yaml:3:3: note: cell is here\n");
  EXPECT_EQ(d.errorCount(), 2u);
}

}  // namespace
}  // namespace gdpn::core

namespace gdpn::core {
namespace {

TEST(Text, Utf8Validation) {
  EXPECT_EQ(firstInvalidUtf8("plain ascii"), std::string_view::npos);
  EXPECT_EQ(firstInvalidUtf8("gr\xc3\xbc\xc3\x9f \xe2\x82\xac \xf0\x9f\x98\x80"), std::string_view::npos);
  EXPECT_EQ(firstInvalidUtf8("ab\xff"), 2u);
  EXPECT_EQ(firstInvalidUtf8("\xc0\xaf"), 0u);          // overlong '/'
  EXPECT_EQ(firstInvalidUtf8("x\xed\xa0\x80"), 1u);     // a surrogate
  EXPECT_EQ(firstInvalidUtf8("\xe2\x82"), 0u);          // cut short
}

TEST(Text, LineColumn) {
  EXPECT_EQ(lineColumn("ab\ncd", 4), (std::pair<int, int>{2, 2}));
  EXPECT_EQ(lineColumn("", 0), (std::pair<int, int>{1, 1}));
}

}  // namespace
}  // namespace gdpn::core
