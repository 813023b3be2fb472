// The names scripts reach, as the bindings register them (script/api.h): what the IDE's
// completion offers, each with its one line, and docs/format.md's tables of them, which must
// be viewNamesMarkdown(CLASS) line for line after `<!-- script-api: CLASS -->`, so that a name
// added, renamed or re-described in src/script/views.cpp fails here until the docs say so.
// GDPN_UPDATE_GOLDEN=1 rewrites the tables in the source tree instead.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "gdpn/script/api.h"

namespace gdpn::script {
namespace {

const std::string kFormatMd = std::string(GDPN_SOURCE_DIR) + "/docs/format.md";

const ViewName* named(ViewClass c, const std::string& name) {
  const auto& names = viewNames(c);
  const auto it = std::find_if(names.begin(), names.end(), [&](const ViewName& n) { return n.name == name; });
  return it == names.end() ? nullptr : &*it;
}

TEST(ScriptApi, SimOffersWhatItsBindingDefinesWithEachOnesLine) {
  for (const char* name : {"time", "dt", "step", "random", "params", "log", "stop", "place", "node", "part", "transition"}) {
    EXPECT_NE(named(ViewClass::Sim, name), nullptr) << name;
  }
  const auto* time = named(ViewClass::Sim, "time");
  ASSERT_NE(time, nullptr);
  EXPECT_FALSE(time->method);
  EXPECT_EQ(time->doc, "seconds");
  const auto* stop = named(ViewClass::Sim, "stop");
  ASSERT_NE(stop, nullptr);
  EXPECT_TRUE(stop->method);
  EXPECT_EQ(stop->arguments, "reason='stopped by a script'");
  EXPECT_EQ(stop->doc, "ends the run after this step");
  // no dunder, no private name
  for (const auto c : kViewClasses) {
    for (const auto& n : viewNames(c)) EXPECT_NE(n.name.front(), '_') << viewClassName(c) << "." << n.name;
  }
}

TEST(ScriptApi, ATransitionsAndANodesNamesAreTheirBindings) {
  for (const char* name : {"name", "elapsed", "progress", "occurrences", "servers", "start_time", "instance"}) {
    EXPECT_NE(named(ViewClass::Transition, name), nullptr) << name;
  }
  for (const char* name : {"name", "position", "set_velocity", "attach", "spawn", "delete", "data", "children"}) {
    EXPECT_NE(named(ViewClass::Node, name), nullptr) << name;
  }
  const auto* spawn = named(ViewClass::Node, "spawn");
  ASSERT_NE(spawn, nullptr);
  EXPECT_EQ(spawn->arguments, "template, at=None");
  for (const char* name : {"get", "set", "add", "capacity"}) EXPECT_NE(named(ViewClass::Slot, name), nullptr) << name;
}

// a name a script can reach but whose binding says nothing leaves the completion without a
// description: each binding gives its one line
TEST(ScriptApi, EveryNameHasItsOneLine) {
  for (const auto c : kViewClasses) {
    for (const auto& n : viewNames(c)) {
      EXPECT_FALSE(n.doc.empty()) << viewClassName(c) << "." << n.name
                                  << " has no docstring in src/script/views.cpp (the IDE shows it as the name's description)";
    }
  }
}

/// The lines of `text`, each with its '\n'.
std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line + "\n");
  return lines;
}

std::string marker(ViewClass c) { return "<!-- script-api: " + std::string(viewClassName(c)) + " -->"; }

TEST(ScriptApi, FormatMdTablesOfScriptNamesAreTheBindings) {
  std::ifstream in(kFormatMd, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty()) << kFormatMd;
  auto lines = linesOf(text.str());
  const bool update = std::getenv("GDPN_UPDATE_GOLDEN") != nullptr;
  for (const auto c : kViewClasses) {
    std::size_t begin = 0, end = 0;
    bool marked = false;
    for (std::size_t i = 0; i < lines.size() && !marked; ++i) {
      if (lines[i] != marker(c) + "\n") continue;
      marked = true;
      begin = end = i + 1;
      while (end < lines.size() && lines[end].starts_with("|")) ++end;
    }
    EXPECT_TRUE(marked) << kFormatMd << ": no marker " << marker(c) << " before the table of its names";
    if (!marked) continue;
    std::string written;
    for (std::size_t i = begin; i < end; ++i) written += lines[i];
    const std::string wanted = viewNamesMarkdown(c);
    if (update && written != wanted) {
      const auto fresh = linesOf(wanted);
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(begin), lines.begin() + static_cast<std::ptrdiff_t>(end));
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(begin), fresh.begin(), fresh.end());
      continue;
    }
    EXPECT_EQ(written, wanted) << kFormatMd << ": the table after " << marker(c)
                               << " lags the bindings (src/script/views.cpp); GDPN_UPDATE_GOLDEN=1 rewrites it";
  }
  if (update) {
    std::ofstream out(kFormatMd, std::ios::binary);
    for (const auto& l : lines) out << l;
  }
}

TEST(ScriptApi, GlobalNamesAreReadWithoutRunningTheScript) {
  const auto names = globalNames(
      "import math\n"
      "from collections import deque as Queue\n"
      "painted = 0\n"
      "a, b = 1, 2\n"
      "def paint(box, colour='red'):\n"
      "    \"\"\"Paints a box.\n\n    More.\"\"\"\n"
      "    global painted\n"
      "    painted += 1\n"
      "class Order:\n"
      "    pass\n"
      "if True:\n"
      "    late = sim.stop('never run')\n");
  std::vector<std::string> seen;
  for (const auto& n : names) seen.push_back(n.name);
  EXPECT_EQ(seen, (std::vector<std::string>{"math", "Queue", "painted", "a", "b", "paint", "Order", "late"}));
  EXPECT_EQ(names[5].kind, "function");
  EXPECT_EQ(names[5].detail, "(box, colour='red'): Paints a box.");
  EXPECT_EQ(names[5].line, 5);
  EXPECT_EQ(names[2].detail, "= 0");
  EXPECT_EQ(names[1].kind, "import");
  // text that does not parse (being typed) binds nothing yet
  EXPECT_TRUE(globalNames("def f(:\n").empty());
}

}  // namespace
}  // namespace gdpn::script
