// docs/format.md's key tables are the schema's: each table follows a marker
// `<!-- schema: SECTION -->` and must be schemaMarkdown(SECTION) line for line, so a key added,
// renamed or re-described in the schema fails here until the docs say so.
// GDPN_UPDATE_GOLDEN=1 rewrites the tables in the source tree instead.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "gdpn/model/schema.h"

namespace gdpn::model::schema {
namespace {

const std::string kFormatMd = std::string(GDPN_SOURCE_DIR) + "/docs/format.md";

std::string marker(Section section) { return "<!-- schema: " + std::string(sectionName(section)) + " -->"; }

/// The lines of `text`, each with its '\n'.
std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line + "\n");
  return lines;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

/// The table after the marker of `section` (the '|' lines that follow it), and where it
/// stands in `lines`: [begin, end). Nothing when the marker is missing.
struct Found {
  std::size_t begin = 0, end = 0;
  bool marked = false;
};
Found tableOf(const std::vector<std::string>& lines, Section section) {
  Found f;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i] != marker(section) + "\n") continue;
    f.marked = true;
    f.begin = f.end = i + 1;
    while (f.end < lines.size() && lines[f.end].starts_with("|")) ++f.end;
    break;
  }
  return f;
}

TEST(SchemaDocs, FormatMdKeyTablesAreTheSchemas) {
  const std::string text = readFile(kFormatMd);
  ASSERT_FALSE(text.empty()) << kFormatMd;
  auto lines = linesOf(text);
  const bool update = std::getenv("GDPN_UPDATE_GOLDEN") != nullptr;
  for (const Section s : kSections) {
    const Found f = tableOf(lines, s);
    EXPECT_TRUE(f.marked) << kFormatMd << ": no marker " << marker(s) << " before the table of its keys";
    if (!f.marked) continue;
    std::string written;
    for (std::size_t i = f.begin; i < f.end; ++i) written += lines[i];
    const std::string wanted = schemaMarkdown(s);
    if (update && written != wanted) {
      const auto fresh = linesOf(wanted);
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(f.begin), lines.begin() + static_cast<std::ptrdiff_t>(f.end));
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(f.begin), fresh.begin(), fresh.end());
      continue;
    }
    EXPECT_EQ(written, wanted) << kFormatMd << ": the table after " << marker(s)
                               << " lags the schema (src/model/schema.cpp); GDPN_UPDATE_GOLDEN=1 rewrites it";
  }
  if (update) {
    std::ofstream out(kFormatMd, std::ios::binary);
    for (const auto& l : lines) out << l;
  }
}

TEST(SchemaDocs, EachMarkerStandsOnce) {
  const std::string text = readFile(kFormatMd);
  for (const Section s : kSections) {
    const std::string m = marker(s);
    const auto first = text.find(m);
    ASSERT_NE(first, std::string::npos) << m;
    EXPECT_EQ(text.find(m, first + 1), std::string::npos) << m << " stands twice";
  }
}

}  // namespace
}  // namespace gdpn::model::schema
