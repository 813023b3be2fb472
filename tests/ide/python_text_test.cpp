// The contents view's Python highlighting: every byte of a line in exactly one piece, each
// piece of the right kind, triple-quoted strings carried across lines.

#include "gdpn/ide/python_text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gdpn::ide {
namespace {

/// The pieces of `line` as "kind:text" words, kinds by their first letter (T K B S C N).
std::vector<std::string> pieces(std::string_view line, char& in_string) {
  std::vector<std::string> out;
  std::size_t next = 0;
  for (const auto& s : highlightPython(line, in_string)) {
    EXPECT_EQ(s.begin, next) << "pieces cover the line without gaps or overlaps";
    next = s.end;
    out.push_back(std::string(1, "TKBSCN"[static_cast<int>(s.kind)]) + ":" + std::string(line.substr(s.begin, s.end - s.begin)));
  }
  EXPECT_EQ(next, line.size());
  return out;
}

TEST(PythonText, KeywordsBuiltinsStringsNumbersAndComments) {
  char open = 0;
  EXPECT_EQ(pieces("if len(self.d0) > 2: x = 'a#b'  # two", open),
            (std::vector<std::string>{"K:if", "T: ", "B:len", "T:(", "B:self", "T:.", "T:d0", "T:) > ", "N:2",
                                      "T:: ", "T:x", "T: = ", "S:'a#b'", "T:  ", "C:# two"}));
  EXPECT_EQ(open, 0);
  EXPECT_EQ(pieces("y = \"say \\\"hi\\\"\" or 1.5e3", open),
            (std::vector<std::string>{"T:y", "T: = ", "S:\"say \\\"hi\\\"\"", "T: ", "K:or", "T: ", "N:1.5e3"}));
}

TEST(PythonText, ATripleQuotedStringRunsOnToItsEnd) {
  char open = 0;
  EXPECT_EQ(pieces("doc = \"\"\"first", open), (std::vector<std::string>{"T:doc", "T: = ", "S:\"\"\"first"}));
  EXPECT_EQ(open, '"');
  EXPECT_EQ(pieces("still # not a comment", open), (std::vector<std::string>{"S:still # not a comment"}));
  EXPECT_EQ(pieces("end\"\"\" + pass", open), (std::vector<std::string>{"S:end\"\"\"", "T: + ", "K:pass"}));
  EXPECT_EQ(open, 0);
  EXPECT_TRUE(pieces("", open).empty());
}

}  // namespace
}  // namespace gdpn::ide
