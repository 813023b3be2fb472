// Editing the net through commands, on the factory example: each edit's effect on the saved
// text, its refusals (which change nothing), a drag merged into one step, and the property
// that any sequence of edits undone gives back the save it started from, byte for byte, and
// redone gives back the save it ended with.

#include <gtest/gtest.h>

#include <random>

#include "gdpn/ide/document.h"
#include "ide/edit_support.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/page_from_selection.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {
namespace {

using testing::openFactory;
using testing::readsBack;
using testing::undoesToStartAndRedoesToEnd;

std::string run(Document& doc, NetEdit e) { return doc.execute(std::make_unique<NetEditCommand>(std::move(e))); }

TEST(NetEdit, APlaceATransitionAndAnArcAreAddedWhereAsked) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  auto place = makeNetEdit(NetEditKind::AddPlace, "factory", "waiting");
  place.at = {3, -2};
  ASSERT_EQ(run(*doc, place), "");
  auto t = makeNetEdit(NetEditKind::AddTransition, "factory", "depart");
  t.at = {4, -2};
  ASSERT_EQ(run(*doc, t), "");
  auto arc = makeNetEdit(NetEditKind::AddArc, "factory", "waiting", "depart");
  arc.weight = 2;
  ASSERT_EQ(run(*doc, arc), "");
  const auto after = doc->text();
  EXPECT_NE(after.find("waiting: {at: [3, -2]}"), std::string::npos) << after;
  EXPECT_NE(after.find("depart: {at: [4, -2]}"), std::string::npos) << after;
  EXPECT_NE(after.find("{from: waiting, to: depart, weight: 2}"), std::string::npos) << after;
  readsBack(after);
  EXPECT_EQ(doc->history().undoLabel(), "add arc waiting -> depart");
  ASSERT_TRUE(doc->undo() && doc->undo() && doc->undo());
  EXPECT_EQ(doc->text(), before);
}

TEST(NetEdit, ARenameCarriesTheArcsAndADeleteTakesThemAway) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto* page = findPage(doc->editableNet(), "factory");
  ASSERT_NE(page, nullptr);
  const auto arcsOf = [&](const std::string& n) {
    return std::count_if(page->arcs.begin(), page->arcs.end(), [&](const auto& a) { return a.from == n || a.to == n; });
  };
  const auto touching = arcsOf("P1");
  ASSERT_GT(touching, 0);
  ASSERT_EQ(run(*doc, makeNetEdit(NetEditKind::Rename, "factory", "P1", "arm_idle")), "");
  EXPECT_EQ(arcsOf("P1"), 0);
  EXPECT_EQ(arcsOf("arm_idle"), touching);
  const auto arcs = page->arcs.size();
  ASSERT_EQ(run(*doc, makeNetEdit(NetEditKind::Delete, "factory", "arm_idle")), "");
  EXPECT_EQ(page->arcs.size(), arcs - static_cast<std::size_t>(touching));
  readsBack(doc->text());
}

TEST(NetEdit, RefusedEditsSayWhyAndChangeNothing) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  const std::pair<NetEdit, std::string> cases[] = {
      {makeNetEdit(NetEditKind::AddPlace, "nowhere", "p"), "no page or page type 'nowhere'"},
      {makeNetEdit(NetEditKind::AddPlace, "factory", "2nd"), "'2nd' is not a name (letters, digits and _, not starting with a digit)"},
      {makeNetEdit(NetEditKind::AddTransition, "factory", "P1"), "'P1' is taken on page 'factory'"},
      {makeNetEdit(NetEditKind::Rename, "factory", "P1", "P2"), "'P2' is taken on page 'factory'"},
      {makeNetEdit(NetEditKind::Delete, "factory", "ghost"), "no place or transition 'ghost' on page 'factory'"},
      {makeNetEdit(NetEditKind::AddArc, "factory", "P1", "P2"),
       "an arc joins a place (or a link) and a transition of page 'factory': 'P1' to 'P2' does not"},
      {makeNetEdit(NetEditKind::AddArc, "factory", "P1", "pickup"), "there is already an arc from 'P1' to 'pickup'"},
      {makeNetEdit(NetEditKind::DeleteArc, "factory", "pickup", "P1"), "no arc from 'pickup' to 'P1' on page 'factory'"},
  };
  for (const auto& [edit, why] : cases) {
    EXPECT_EQ(run(*doc, edit), why);
    EXPECT_EQ(doc->text(), before);
  }
  auto inhibitor = makeNetEdit(NetEditKind::AddArc, "factory", "pickup", "P1");
  inhibitor.arc_kind = net::ArcKind::Inhibitor;
  EXPECT_EQ(run(*doc, inhibitor), "an inhibitor arc runs from a place to a transition");
  auto heavy = makeNetEdit(NetEditKind::SetArcWeight, "factory", "P1", "pickup");
  heavy.weight = 0;
  EXPECT_EQ(run(*doc, heavy), "an arc's weight is a whole number from 1 to 10^9");
  EXPECT_EQ(doc->text(), before);
  EXPECT_FALSE(doc->history().canUndo());
}

TEST(NetEdit, ADragIsOneStep) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto before = doc->text();
  for (int i = 1; i <= 10; ++i) {
    auto move = makeNetEdit(NetEditKind::Move, "factory", "pickup");
    move.at = {0.5 * i, 1};
    move.drag = 7;
    ASSERT_EQ(run(*doc, move), "");
  }
  EXPECT_EQ(doc->history().depth(), 1u);
  EXPECT_NE(doc->text().find("pickup:"), std::string::npos);
  const auto after = doc->text();
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
  ASSERT_TRUE(doc->redo());
  EXPECT_EQ(doc->text(), after);
}

TEST(NetEdit, ASlotsKindTokensCapacityNodesAndScriptsAreSetAndTheEmptyOnesLeaveNoTrace) {
  net::PlaceSpec p;
  p.name = "p";
  const net::PlaceSpec bare = p;
  const auto b0 = *net::parseSlot("b0");
  const auto c0 = *net::parseSlot("c0");
  EXPECT_EQ(slotKindOf(p, b0), net::SlotKind::Control);
  addNodeToken(p, b0, "arm/turn");
  addNodeToken(p, b0, "arm/lift");
  EXPECT_EQ(slotKindOf(p, b0), net::SlotKind::Node);
  ASSERT_EQ(p.nodes.size(), 1u);
  EXPECT_EQ(p.nodes[0].nodes, (std::vector<std::string>{"arm/turn", "arm/lift"}));
  EXPECT_TRUE(removeNodeToken(p, b0, "arm/turn"));
  EXPECT_FALSE(removeNodeToken(p, b0, "arm/turn"));
  // a sensor slot drops what the node slot held, and its scripts
  setSlotScript(p, b0, net::ScriptKind::OnDeposit, "print(token)\n");
  setSlotKind(p, b0, net::SlotKind::Sensor, "eye");
  EXPECT_EQ(slotKindOf(p, b0), net::SlotKind::Sensor);
  EXPECT_TRUE(p.nodes.empty());
  EXPECT_TRUE(p.scripts.empty());
  ASSERT_EQ(p.sensors.size(), 1u);
  EXPECT_EQ(p.sensors[0].path, "eye");
  // back to control: nothing is left over
  setSlotKind(p, b0, net::SlotKind::Control);
  EXPECT_EQ(p, bare);
  setSlotCount(p.tokens, c0, 3);
  setSlotCount(p.capacity, c0, 5);
  EXPECT_EQ(slotCount(p.tokens, c0), 3);
  EXPECT_EQ(slotCount(p.capacity, c0), 5);
  setSlotCount(p.tokens, c0, std::nullopt);
  setSlotCount(p.capacity, c0, std::nullopt);
  setSlotScript(p, c0, net::ScriptKind::OnRemove, "x = 1\n");
  setSlotScript(p, c0, net::ScriptKind::OnRemove, "");
  EXPECT_EQ(p, bare);
}

TEST(NetEdit, APlaceOrTransitionIsSetWholeAndBadValuesAreRefused) {
  auto doc = openFactory();
  ASSERT_TRUE(doc);
  const auto at = locateConstruct(doc->model().net, "factory/stationA/skip");
  ASSERT_TRUE(at);
  EXPECT_EQ(at->page, "station");
  EXPECT_EQ(at->name, "skip");
  EXPECT_FALSE(locateConstruct(doc->model().net, "factory/nobody/skip"));
  auto t = *std::find_if(findPage(doc->editableNet(), "station")->transitions.begin(),
                         findPage(doc->editableNet(), "station")->transitions.end(), [](const auto& x) { return x.name == "skip"; });
  auto e = makeNetEdit(NetEditKind::SetTransition, "station", "skip");
  t.probability = 0;
  e.transition = t;
  EXPECT_EQ(run(*doc, e), "a probability lies in (0, 1]");
  t.probability = 1;
  t.duration = {net::Duration::Law::Uniform, 2, 1, {}};
  e.transition = t;
  EXPECT_EQ(run(*doc, e), "a uniform duration's bounds are 0 <= low <= high");
  t.duration = {net::Duration::Law::Normal, 2, 0.5, {}};
  t.priority = 4;
  e.transition = t;
  EXPECT_EQ(run(*doc, e), "");
  EXPECT_NE(doc->text().find("skip:\n        duration: {normal: [2, 0.5]}\n        priority: 4\n"), std::string::npos) << doc->text();
  EXPECT_EQ(doc->history().undoLabel(), "edit transition station/skip");
  // a slot's initial tokens are nodes or a count: P2's box slot takes no count beside its box
  const auto& places = findPage(doc->editableNet(), "factory")->places;
  auto p2 = *std::find_if(places.begin(), places.end(), [](const auto& x) { return x.name == "P2"; });
  setSlotCount(p2.tokens, *net::parseSlot("d0"), 2);
  auto set = makeNetEdit(NetEditKind::SetPlace, "factory", "P2");
  set.place = p2;
  const auto before = doc->text();
  EXPECT_EQ(run(*doc, set), "slot d0 holds node tokens: it has no count of its own");
  EXPECT_EQ(doc->text(), before);
}

/// Random edits, good and bad, on every page and page type of the factory: every kind of
/// NetEdit, and now and then a page type made from a few constructs.
class RandomEdits {
 public:
  RandomEdits(Document& doc, std::uint32_t seed) : doc_(doc), rng_(seed) {
    for (const auto* list : {&doc.model().net.pages, &doc.model().net.page_types}) {
      for (const auto& p : *list) pages_.push_back(p.name);
    }
  }
  NetEdit next() {
    const net::PageSpec& page = *findPage(doc_.editableNet(), pick(pages_));
    std::vector<std::string> names{"x" + std::to_string(pick(10)), "y" + std::to_string(pick(10)), "bad name"};
    for (const auto& p : page.places) names.push_back(p.name);
    for (const auto& t : page.transitions) names.push_back(t.name);
    NetEdit e;
    e.kind = static_cast<NetEditKind>(pick(15));
    e.page = page.name;
    e.name = pick(names);
    e.new_name = pick(names);
    e.at = {static_cast<double>(pick(20)) - 10, static_cast<double>(pick(20)) - 10};
    e.arc_kind = static_cast<net::ArcKind>(pick(3));
    e.weight = static_cast<std::int64_t>(pick(4));  // 0 is refused
    e.drag = pick(2) == 0 ? 0 : 1 + pick(2);
    const auto slot = static_cast<net::SlotId>(pick(net::kSlotCount));
    if (e.kind == NetEditKind::SetPlace && !page.places.empty()) {
      // what the contents view does to a place: a slot's kind, tokens, capacity, nodes, a script
      net::PlaceSpec p = page.places[pick(page.places.size())];
      e.name = p.name;
      switch (pick(6)) {
        case 0: setSlotKind(p, slot, static_cast<net::SlotKind>(pick(3)), "line/landing_at/landing"); break;
        case 1: setSlotCount(p.tokens, slot, static_cast<std::int64_t>(pick(4)) - 1); break;
        case 2: setSlotCount(p.capacity, slot, pick(2) == 0 ? std::nullopt : std::optional<std::int64_t>(pick(5))); break;
        case 3: addNodeToken(p, slot, "boxes/b0" + std::to_string(pick(10)) + "/box"); break;
        case 4: setSlotScript(p, slot, net::kSlotScripts[pick(6)], pick(2) == 0 ? "" : "print('x')\n"); break;
        default: p.name = "renamed"; break;  // refused: a rename is its own edit
      }
      e.place = p;
    } else if (e.kind == NetEditKind::Paste) {
      // what a copy puts on the clipboard: a construct of this page, or of another
      const net::PageSpec& from = *findPage(doc_.editableNet(), pick(pages_));
      net::PageSpec fragment;
      if (!from.places.empty() && pick(2) == 0) fragment.places.push_back(from.places[pick(from.places.size())]);
      if (!from.transitions.empty() && pick(2) == 0) fragment.transitions.push_back(from.transitions[pick(from.transitions.size())]);
      e.fragment = fragment;  // empty now and then: refused
    } else if (e.kind == NetEditKind::MoveMany) {
      // a group dragged, aligned or distributed (a name not on the page now and then: refused)
      for (std::size_t k = 0, n = 1 + pick(4); k < n; ++k) {
        e.moves.emplace_back(pick(names), net::EditorPos{static_cast<double>(pick(40)) / 4.0, static_cast<double>(pick(40)) / 4.0});
      }
    } else if (e.kind == NetEditKind::DeleteMany) {
      // a rubber band's worth: constructs and arcs
      for (std::size_t k = 0, n = pick(3); k < n; ++k) e.names.push_back(pick(names));
      if (!page.arcs.empty() && pick(2) == 0) e.arcs.push_back(page.arcs[pick(page.arcs.size())]);
      if (!page.instances.empty() && pick(4) == 0) e.names.push_back(page.instances[pick(page.instances.size())].name);
    } else if (e.kind == NetEditKind::SetArc && !page.arcs.empty()) {
      // what the arc inspector does: its kind, a weight, reversed, a slot added
      net::ArcSpec a = page.arcs[pick(page.arcs.size())];
      e.name = a.from;
      e.new_name = a.to;
      e.arc_kind = a.kind;
      switch (pick(4)) {
        case 0: a.kind = static_cast<net::ArcKind>(pick(3)); break;
        case 1: a.weights = {net::SlotCount{net::kDefaultSlot, static_cast<std::int64_t>(pick(4))}}; break;  // 0: refused
        case 2: std::swap(a.from, a.to); break;
        default: a.weights.push_back(net::SlotCount{slot, 2}); break;
      }
      e.arc = a;
    } else if (e.kind == NetEditKind::AddInstance) {
      // an instance of a page type (of the page itself now and then: refused)
      e.new_name = pick(pages_);
    } else if (e.kind == NetEditKind::SetTransition && !page.transitions.empty()) {
      net::TransitionSpec t = page.transitions[pick(page.transitions.size())];
      e.name = t.name;
      switch (pick(5)) {
        case 0: t.duration = {static_cast<net::Duration::Law>(pick(4)), static_cast<double>(pick(5)) - 1, 2.0, {}}; break;
        case 1: t.priority = static_cast<std::int64_t>(pick(5)); break;
        case 2: t.probability = static_cast<double>(pick(4)) / 2.0; break;  // 0 and 1.5 are refused
        case 3: net::scriptOf(t, net::kTransitionScripts[pick(4)]).code = pick(2) == 0 ? "" : "x = 1\n"; break;
        default: break;
      }
      e.transition = t;
    }
    return e;
  }
  /// The next command: mostly a NetEdit, one in twenty a page type made from two or three of
  /// a page's places and transitions (refused where they cannot move).
  std::unique_ptr<Command> nextCommand() {
    if (pick(20) != 0) return std::make_unique<NetEditCommand>(next());
    const net::PageSpec& page = *findPage(doc_.editableNet(), pick(pages_));
    PageFromSelection request;
    request.page = page.name;
    for (std::size_t k = 0, n = 2 + pick(2); k < n; ++k) {
      if (!page.places.empty() && pick(2) == 0) request.names.push_back(page.places[pick(page.places.size())].name);
      else if (!page.transitions.empty()) request.names.push_back(page.transitions[pick(page.transitions.size())].name);
    }
    request.type = "made" + std::to_string(++made_);
    request.instance = "inst" + std::to_string(made_);
    return std::make_unique<PageFromSelectionCommand>(request);
  }

 private:
  int made_ = 0;
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  const std::string& pick(const std::vector<std::string>& v) { return v[pick(v.size())]; }
  Document& doc_;
  std::mt19937 rng_;
  std::vector<std::string> pages_;
};

TEST(NetEdit, AnySequenceUndoneGivesBackTheStartAndRedoneTheEndByteForByte) {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    auto doc = openFactory();
    ASSERT_TRUE(doc);
    const auto start = doc->text();
    RandomEdits edits(*doc, seed);
    int applied = 0;
    for (int i = 0; i < 150; ++i) {
      const net::NetSpec before = doc->model().net;
      if (doc->execute(edits.nextCommand()).empty()) {
        ++applied;
      } else {
        ASSERT_TRUE(doc->model().net == before) << "a refused edit changed the net (seed " << seed << ", edit " << i << ")";
      }
    }
    EXPECT_GT(applied, 30) << "seed " << seed;
    undoesToStartAndRedoesToEnd(*doc, start, "seed " + std::to_string(seed));
  }
}

}  // namespace
}  // namespace gdpn::ide
