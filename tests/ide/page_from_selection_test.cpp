// Making a page type from a selection (page_from_selection.h): on page `line` of the two-cell
// line (tests/data/page_from_selection/two_cells.gdpn.yaml), a group with a node-slot arc
// crossing in, one crossing out, a crossing inhibitor and test arcs becomes an instance of a new
// type; the net is the same up to the names that moved, scripts and signals follow them, saving
// reads back, and undo gives the starting file byte for byte. A name that cannot be followed,
// and a selection across two pages, are refused where they are written.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "gdpn/ide/document.h"
#include "gdpn/ide/page_from_selection.h"
#include "gdpn/model/analysis.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/analysis.h"
#include "gdpn/net/compile.h"

namespace gdpn::ide {
namespace {

const std::string kModel = std::string(GDPN_SOURCE_DIR) + "/tests/data/page_from_selection/two_cells.gdpn.yaml";

PageFromSelection prepStage() { return {"line", {"staged", "prep", "done", "jam"}, "prep_stage", "prep1"}; }

/// `text` with each old name of `result` put as its new one (longest first, whole names).
std::string renamed(std::string text, const PageFromSelectionResult& result) {
  auto names = result.renamed;
  std::sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  for (const auto& [from, to] : names) {
    for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
      const bool whole = at + from.size() == text.size() || !(std::isalnum(static_cast<unsigned char>(text[at + from.size()])) ||
                                                             text[at + from.size()] == '_');
      if (whole) text.replace(at, from.size(), to);
    }
  }
  return text;
}

/// The trace of a whole run of `model` (gdpn run's library call).
std::string traceOf(const model::Model& model) {
  core::Diagnostics diags;
  auto sim = model::Simulation::create(model, diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  return trace.str();
}

/// What `gdpn analyze` says of `model`'s net: states, edges, and the place invariants as text.
struct Answer {
  std::uint64_t states = 0, edges = 0;
  std::set<std::string> invariants;
};

Answer analyzed(const model::Model& model, const PageFromSelectionResult* names = nullptr) {
  core::Diagnostics diags;
  auto net = net::compile(model.net, diags);
  EXPECT_TRUE(net) << diags.str();
  EXPECT_FALSE(diags.hasErrors()) << diags.str();
  if (!net) return {};
  const model::Analysis a = model::analyze(*net, model.path);
  EXPECT_TRUE(a.space.complete);
  Answer out{a.space.states, a.space.edges, {}};
  for (const auto& y : a.invariants.p) {
    const std::string text = model::invariantText(*net, y);
    // its terms in name order: the places' order in the net is not the same
    std::vector<std::string> terms;
    std::istringstream in(names ? renamed(text, *names) : text);
    for (std::string term; std::getline(in, term, '+');) {
      while (!term.empty() && term.front() == ' ') term.erase(term.begin());
      while (!term.empty() && term.back() == ' ') term.pop_back();
      terms.push_back(term);
    }
    std::sort(terms.begin(), terms.end());
    std::string sorted;
    for (const auto& term : terms) sorted += (sorted.empty() ? "" : " + ") + term;
    out.invariants.insert(sorted);
  }
  return out;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PageFromSelection, TheNetIsTheSameUpToTheNamesThatMoved) {
  core::Diagnostics diags;
  auto doc = Document::open(kModel, diags);
  ASSERT_TRUE(doc) << diags.str();
  const model::Model before = doc->model();
  const Answer old_answer = analyzed(before);
  const std::string old_trace = traceOf(doc->snapshot());
  ASSERT_NE(old_trace.find("line/staged"), std::string::npos) << old_trace;

  auto command = std::make_unique<PageFromSelectionCommand>(prepStage());
  auto* made = command.get();
  ASSERT_EQ(doc->execute(std::move(command)), "");
  const PageFromSelectionResult& result = made->result();
  EXPECT_EQ(result.pulled_in, std::vector<std::string>{"line/power"});  // the test arcs' place
  EXPECT_EQ(result.references, (std::vector<std::string>{"staged", "power", "done"}));
  EXPECT_EQ(followName(result, "line/staged"), "line/prep1/staged");
  EXPECT_EQ(followName(result, "line/prep"), "line/prep1/prep");
  EXPECT_EQ(followName(result, "line/fetch"), "line/fetch");
  EXPECT_EQ(doc->selection().name, "line/prep1");
  const model::Model& after = doc->model();

  // the instance stands at the selection's centre; the crossing arcs reach its references
  const auto* line = &after.net.pages.front();
  ASSERT_EQ(line->instances.size(), 3u);
  EXPECT_EQ(line->instances.back().type, "prep_stage");
  ASSERT_TRUE(line->instances.back().position);
  EXPECT_EQ(*line->instances.back().position, (net::EditorPos{1.5, 2}));
  EXPECT_EQ(after.net.page_types.back().name, "prep_stage");
  const auto crossing = std::count_if(line->arcs.begin(), line->arcs.end(), [](const net::ArcSpec& a) {
    return a.from.starts_with("prep1/") || a.to.starts_with("prep1/");
  });
  EXPECT_EQ(crossing, 4);  // fetch -> staged, the test arc of fetch, done -> load_a, the inhibitor of load_a

  // scripts and signals follow the names
  EXPECT_EQ(after.signals.front().target, "line/prep1/staged");
  const auto& prep = after.net.page_types.back().transitions.front();
  EXPECT_NE(prep.post_fire.code.find("sim.place(\"line/prep1/staged\")"), std::string::npos) << prep.post_fire.code;
  EXPECT_NE(prep.post_fire.code.find("sim.place('line/prep1/done')"), std::string::npos) << prep.post_fire.code;

  // (a) it checks; (b) the same state space and invariants; (c) the same trace, up to names
  core::Diagnostics check;
  EXPECT_TRUE(net::compile(after.net, check)) << check.str();
  EXPECT_FALSE(check.hasErrors()) << check.str();
  const Answer new_answer = analyzed(after);
  EXPECT_EQ(new_answer.states, old_answer.states);
  EXPECT_EQ(new_answer.edges, old_answer.edges);
  EXPECT_GT(new_answer.states, 10u);
  EXPECT_EQ(new_answer.invariants, analyzed(before, &result).invariants);
  EXPECT_EQ(traceOf(doc->snapshot()), renamed(old_trace, result));

  // (d) saved, it reads back as the same model
  const std::string out = ::testing::TempDir() + "/page_from_selection.gdpn.yaml";
  core::Diagnostics saving;
  ASSERT_TRUE(doc->save(saving, out)) << saving.str();
  core::Diagnostics reading;
  auto again = model::loadModel(out, reading);
  ASSERT_TRUE(again) << reading.str();
  EXPECT_TRUE(*again == after) << readAll(out);

  // (e) undo gives the starting file byte for byte; redo the made one again
  const std::string made_text = doc->text();
  ASSERT_TRUE(doc->undo());
  EXPECT_TRUE(doc->model() == before);
  EXPECT_EQ(doc->text(), readAll(kModel));
  ASSERT_TRUE(doc->redo());
  EXPECT_EQ(doc->text(), made_text);
}

// a page with a script that builds a moved name at run time, and another page
const char* const kBuilt = R"(gdpn: 1
pages:
  line:
    places:
      a: {tokens: 1}
      b: {}
    transitions:
      t:
        pre_fire: |
          name = "b"
          sim.log(sim.place("line/" + name).a0.get())
    arcs:
      - a -> t
      - t -> b
  other:
    places:
      c: {}
)";

TEST(PageFromSelection, ANameBuiltAtRunTimeIsRefusedWhereItIsWritten) {
  core::Diagnostics diags;
  auto m = model::parseModel(kBuilt, "built.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  Document doc(*m);
  const std::string text = doc.text();
  // refused through the undo stack (which then drops the command): nothing changes
  const std::string why =
      doc.execute(std::make_unique<PageFromSelectionCommand>(PageFromSelection{"line", {"b"}, "sink", "s1"}));
  EXPECT_EQ(why, "built.gdpn.yaml:11:30: error: 'line/' begins the name 'line/b', which moves to 'line/s1/b', "
                 "but the rest of it is made at run time, so it cannot be followed");
  EXPECT_EQ(doc.text(), text);
  EXPECT_FALSE(doc.history().canUndo());
  // the command itself keeps every error, located
  PageFromSelectionCommand command(PageFromSelection{"line", {"b"}, "sink", "s1"});
  EXPECT_EQ(command.apply(doc), why);
  EXPECT_TRUE(command.diagnostics().hasErrors());
  EXPECT_EQ(doc.text(), text);
}

TEST(PageFromSelection, ASelectionAcrossTwoPagesIsRefused) {
  core::Diagnostics diags;
  auto m = model::parseModel(kBuilt, "built.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  Document doc(*m);
  const std::string text = doc.text();
  const std::string why = doc.execute(
      std::make_unique<PageFromSelectionCommand>(PageFromSelection{"line", {"line/a", "other/c"}, "pair", "p1"}));
  EXPECT_EQ(why, "built.gdpn.yaml:3:3: error: 'other/c' is on page 'other', not on 'line': a page type is made "
                 "from the constructs of one page");
  EXPECT_EQ(doc.text(), text);
}

TEST(PageFromSelection, ASelectedTransitionJoinedToAnotherInstanceIsRefused) {
  core::Diagnostics diags;
  auto doc = Document::open(kModel, diags);
  ASSERT_TRUE(doc) << diags.str();
  const std::string text = doc->text();
  const std::string why =
      doc->execute(std::make_unique<PageFromSelectionCommand>(PageFromSelection{"line", {"transfer"}, "t", "t1"}));
  EXPECT_NE(why.find("two_cells.gdpn.yaml:54:9: error: the arc between 'cellA/exit' and 'transfer'"), std::string::npos)
      << why;
  EXPECT_EQ(doc->text(), text);
}

TEST(PageFromSelection, APlaceHoldingNodeTokensByPathIsRefusedWhereTheyAreWritten) {
  core::Diagnostics diags;
  auto doc = Document::open(kModel, diags);
  ASSERT_TRUE(doc) << diags.str();
  const std::string text = doc->text();
  const std::string why =
      doc->execute(std::make_unique<PageFromSelectionCommand>(PageFromSelection{"line", {"trays"}, "t", "t1"}));
  EXPECT_NE(why.find("two_cells.gdpn.yaml:19:24:"), std::string::npos) << why;
  EXPECT_NE(why.find("place 'trays' holds node tokens by scene path"), std::string::npos) << why;
  EXPECT_EQ(doc->text(), text);
}

}  // namespace
}  // namespace gdpn::ide
