// P-invariants of coloured nets found without unfolding (coloured_invariants.h): the known
// ones by hand (the philosophers' per-philosopher and per-fork families, a product's
// component), the refusal where an inscription is not a function of the family's variables,
// and, on the contest's coloured models, every invariant found checked against the unfolded
// net: for every x, its weights on the unfolded places are a P-invariant there (no unfolded
// transition changes the weighted sum) and the sum in the initial marking is the one given.

#include <gtest/gtest.h>

#include <algorithm>

#include "gdpn/net/compile.h"
#include "gdpn/net/coloured_invariants.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/unfold.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

using testing::kColourConformanceDir;

/// A page `net` with colour sets, variables, places (name, set or "", initial values) and
/// arcs (from, to, inscription or "" for a plain arc of weight 1); transitions are every arc
/// end that is no place, with the condition `when` given per name.
struct Sketch {
  NetSpec spec;
  PageSpec page;
  Sketch() { page.name = "net"; }
  void colours(const std::string& name, std::vector<std::string> constants, bool cyclic) {
    ColourSetSpec s;
    s.name = name;
    s.kind = ColourKind::Enum;
    s.constants = std::move(constants);
    s.cyclic = cyclic;
    spec.colours.push_back(s);
  }
  void product(const std::string& name, std::vector<std::string> components) {
    ColourSetSpec s;
    s.name = name;
    s.kind = ColourKind::Product;
    s.components = std::move(components);
    spec.colours.push_back(s);
  }
  void variable(const std::string& name, const std::string& set) { spec.variables.push_back({name, set, {}}); }
  void place(const std::string& name, const std::string& set, const std::string& values, std::int64_t tokens = 0) {
    PlaceSpec s;
    s.name = name;
    if (!set.empty()) s.colours.push_back({kDefaultSlot, set, {}});
    if (!values.empty()) s.values.push_back({kDefaultSlot, values, {}});
    if (tokens > 0) s.tokens.push_back({kDefaultSlot, tokens, {}, {}});
    page.places.push_back(s);
  }
  void transition(const std::string& name, const std::string& when = "") {
    TransitionSpec s;
    s.name = name;
    s.when.text = when;
    page.transitions.push_back(s);
  }
  void arc(const std::string& from, const std::string& to, const std::string& text) {
    ArcSpec a;
    a.from = from;
    a.to = to;
    if (!text.empty()) a.inscriptions.push_back({kDefaultSlot, text, {}});
    page.arcs.push_back(a);
  }
  NetSpec done() const {
    NetSpec s = spec;
    s.pages.push_back(page);
    return s;
  }
};

/// The dining philosophers of tests/data/colour/philosophers.gdpn.yaml (five, cyclic; a
/// condition p <> succ(p)), with a plain place counting the meals.
NetSpec philosophers() {
  Sketch s;
  s.colours("Phil", {"ph1", "ph2", "ph3", "ph4", "ph5"}, true);
  s.variable("p", "Phil");
  s.place("thinking", "Phil", "all");
  s.place("forks", "Phil", "all");
  s.place("eating", "Phil", "");
  s.place("meals", "", "");
  s.transition("take", "p <> succ(p)");
  s.transition("release");
  s.arc("thinking", "take", "p");
  s.arc("forks", "take", "p ++ succ(p)");
  s.arc("take", "eating", "p");
  s.arc("take", "meals", "");
  s.arc("eating", "release", "p");
  s.arc("release", "forks", "p ++ succ(p)");
  s.arc("release", "thinking", "p");
  return s.done();
}

/// The texts of `found`'s invariants.
std::vector<std::string> texts(const Net& net, const ColouredInvariants& found) {
  std::vector<std::string> out;
  for (const auto& inv : found.invariants) out.push_back(colouredInvariantText(net, inv));
  return out;
}

/// How many members (an invariant, a value of x) were checked, and those that do not hold.
struct Checked {
  std::size_t members = 0;
  std::vector<std::string> wrong;
};

/// Checks every invariant of `found` (of `coloured`, compiled from `spec`) on `spec` unfolded:
/// for every x, its weights on the unfolded places are a P-invariant of the unfolded net whose
/// sum in the initial marking is the one found.
Checked checkUnfolded(const NetSpec& spec, const Net& coloured, const ColouredInvariants& found) {
  core::Diagnostics diags;
  auto unfolded = unfold(spec, diags);
  EXPECT_TRUE(unfolded) << diags.str();
  if (!unfolded) return {};
  const auto net = compile(unfolded->net, diags);
  EXPECT_TRUE(net) << diags.str();
  if (!net) return {};
  const Colouring* colouring = coloured.colouring();
  // each coloured place slot's unfolded place slots with their values (null: a slot without values)
  std::vector<std::vector<std::pair<PlaceSlotId, const Value*>>> image(coloured.placeSlots().size());
  std::vector<std::vector<Value>> values(coloured.placeSlots().size());
  for (PlaceSlotId ps : coloured.placeSlotIds()) {
    const PlaceId p = coloured.placeSlots()[ps].place;
    const std::string name = coloured.placeName(p);
    const auto set = colouring != nullptr ? colouring->setOf(ps) : std::nullopt;
    if (!set) {
      const auto q = net->findPlace(name);
      EXPECT_TRUE(q) << name;
      if (!q) return {};
      const auto qs = net->findPlaceSlot(*q, coloured.placeSlots()[ps].slot);
      EXPECT_TRUE(qs) << name;
      if (qs) image[ps].emplace_back(*qs, nullptr);
      continue;
    }
    // one value slot per place in these nets: its places follow the place itself where it stays
    values[ps] = colouring->colours.values(*set);
    const auto& names = unfolded->names.places.at(name);
    EXPECT_EQ(coloured.placeSlotsOf(p).size(), 1u) << name;
    const std::size_t skip = names.size() - values[ps].size();
    EXPECT_LE(skip, 1u) << name;
    for (std::size_t i = 0; i < values[ps].size(); ++i) {
      const auto q = net->findPlace(names[skip + i]);
      EXPECT_TRUE(q) << names[skip + i];
      if (!q) return {};
      // a place no arc reaches and without tokens has no slot
      for (PlaceSlotId qs : net->placeSlotsOf(*q)) image[ps].emplace_back(qs, &values[ps][i]);
    }
  }
  Checked checked;
  for (const auto& inv : found.invariants) {
    const std::size_t members = inv.over ? colouring->colours.values(*inv.over).size() : 1;
    EXPECT_EQ(inv.tokens.size(), members) << colouredInvariantText(coloured, inv);
    for (std::size_t x = 0; x < members && x < inv.tokens.size(); ++x) {
      Invariant y;
      std::int64_t initial = 0;
      for (PlaceSlotId ps : coloured.placeSlotIds()) {
        for (const auto& [qs, v] : image[ps]) {
          const auto w = colouredWeight(coloured, inv, x, ps, v);
          if (w == 0) continue;
          y.weights.emplace_back(qs, w);
          initial += w * net->placeSlots()[qs].initial;
        }
      }
      std::sort(y.weights.begin(), y.weights.end());
      const std::string member = colouredInvariantText(coloured, inv) + " at x number " + std::to_string(x);
      if (!isPInvariant(*net, y)) checked.wrong.push_back(member + ": not a P-invariant of the unfolded net");
      if (initial != inv.tokens[x]) checked.wrong.push_back(member + ": initially " + std::to_string(initial));
      ++checked.members;
    }
  }
  return checked;
}

TEST(ColouredInvariants, PhilosophersPerPhilosopherAndPerFork) {
  const NetSpec spec = philosophers();
  core::Diagnostics diags;
  const auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  const auto found = colouredInvariants(*net);
  EXPECT_TRUE(found.complete);
  EXPECT_EQ(texts(*net, found), (std::vector<std::string>{
                                    "|net/thinking| + |net/eating| = 5",
                                    "|net/forks| + 2*|net/eating| = 5",
                                    "net/thinking(x) + net/eating(x) = 1 for every x in Phil",
                                    "net/forks(x) + net/eating(x) + net/eating(pred(x)) = 1 for every x in Phil",
                                }));
  EXPECT_TRUE(found.notes.empty()) << found.notes.front();
  const auto checked = checkUnfolded(spec, *net, found);
  EXPECT_EQ(checked.members, 2u + 2u * 5u);
  EXPECT_EQ(checked.wrong, std::vector<std::string>{});
  // the check finds a wrong one: eating(succ(x)) for eating(pred(x)), and a wrong sum
  ColouredInvariants wrong = found;
  ASSERT_EQ(wrong.invariants.size(), 4u);
  wrong.invariants[3].terms.back().offset = 1;
  wrong.invariants[2].tokens[0] = 2;
  EXPECT_EQ(checkUnfolded(spec, *net, wrong).wrong.size(), 5u + 1u);
}

TEST(ColouredInvariants, AProductsComponentAndAnInitialMarkingThatDiffersByValue) {
  // jobs J on machines M: a job waits, is worked on as (job, machine), then is done; the
  // the three jobs start waiting, one done
  Sketch s;
  s.colours("J", {"j1", "j2", "j3"}, false);
  s.colours("M", {"m1", "m2"}, false);
  s.product("JM", {"J", "M"});
  s.variable("j", "J");
  s.variable("m", "M");
  s.place("waiting", "J", "2'j1 ++ j2");
  s.place("done", "J", "");
  s.place("busy", "JM", "");
  s.place("idle", "M", "all");
  s.transition("start");
  s.transition("finish");
  s.transition("again");
  s.arc("waiting", "start", "j");
  s.arc("idle", "start", "m");
  s.arc("start", "busy", "(j, m)");
  s.arc("busy", "finish", "(j, m)");
  s.arc("finish", "idle", "m");
  s.arc("finish", "done", "j");
  s.arc("done", "again", "j");
  s.arc("again", "waiting", "j");
  const NetSpec spec = s.done();
  core::Diagnostics diags;
  const auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  const auto found = colouredInvariants(*net);
  const auto all = texts(*net, found);
  for (const char* want : {"|net/waiting| + |net/done| + |net/busy| = 3", "|net/busy| + |net/idle| = 2",
                           "net/waiting(x) + net/done(x) + net/busy(x, _) = 1 for x = j2; 2 for x = j1; 0 for every other x in J",
                           "net/busy(_, x) + net/idle(x) = 1 for every x in M"}) {
    EXPECT_NE(std::find(all.begin(), all.end(), want), all.end()) << want << " not among:\n" << ::testing::PrintToString(all);
  }
  EXPECT_EQ(all.size(), 4u) << ::testing::PrintToString(all);
  const auto checked = checkUnfolded(spec, *net, found);
  EXPECT_EQ(checked.members, 2u + 3u + 2u);
  EXPECT_EQ(checked.wrong, std::vector<std::string>{});
}

TEST(ColouredInvariants, AnInscriptionOfAnotherSetsVariableLeavesThePlaceOut) {
  // `move` puts its token back on x or on x's successor as y says: no family over P holds
  // Here, but the count of Here does
  Sketch s;
  s.colours("P", {"a", "b", "c"}, true);
  s.colours("Y", {"stay", "go"}, false);
  s.variable("x", "P");
  s.variable("y", "Y");
  s.place("Here", "P", "a");
  s.place("There", "P", "");
  s.place("Choice", "Y", "all");
  s.transition("move");
  s.transition("back");
  s.arc("Here", "move", "x");
  s.arc("Choice", "move", "y");
  s.arc("move", "Choice", "y");
  s.arc("move", "There", "if y = stay then x else succ(x)");
  s.arc("There", "back", "x");
  s.arc("back", "Here", "x");
  const NetSpec spec = s.done();
  core::Diagnostics diags;
  const auto net = compile(spec, diags);
  ASSERT_TRUE(net) << diags.str();
  const auto found = colouredInvariants(*net);
  const auto all = texts(*net, found);
  EXPECT_EQ(all, (std::vector<std::string>{"|net/Here| + |net/There| = 1", "|net/Choice| = 2",
                                           "net/Choice(x) = 1 for every x in Y"}));
  ASSERT_FALSE(found.notes.empty());
  EXPECT_NE(found.notes.front().find("over P: 'net/There' is left out"), std::string::npos) << found.notes.front();
  const auto checked = checkUnfolded(spec, *net, found);
  EXPECT_EQ(checked.members, 1u + 1u + 2u);
  EXPECT_EQ(checked.wrong, std::vector<std::string>{});
}

class ColouredModelInvariants : public ::testing::TestWithParam<const char*> {};

TEST_P(ColouredModelInvariants, EveryOneFoundHoldsOnTheUnfoldedNet) {
  const std::string model = GetParam();
  core::Diagnostics diags;
  const auto spec = loadPnml((kColourConformanceDir / model / "model.pnml").string(), diags);
  ASSERT_TRUE(spec) << diags.str();
  const auto net = compile(*spec, diags);
  ASSERT_TRUE(net) << diags.str();
  const auto found = colouredInvariants(*net);
  EXPECT_TRUE(found.complete);
  EXPECT_FALSE(found.invariants.empty());
  std::size_t families = 0;
  for (const auto& inv : found.invariants) families += inv.over ? 1u : 0u;
  // Sudoku-COL-AN01's one set has a single value: no family
  EXPECT_EQ(families > 0, model != "Sudoku-COL-AN01");
  const auto all = texts(*net, found);
  const auto checked = checkUnfolded(*spec, *net, found);
  EXPECT_GE(checked.members, all.size());
  EXPECT_EQ(checked.wrong, std::vector<std::string>{});
  auto has = [&](const std::string& text) { return std::find(all.begin(), all.end(), text) != all.end(); };
  if (model == "Philosophers-COL-000005") {
    // a philosopher thinks, has caught one fork or the other, or eats; a fork lies, or is held
    // by one of its two philosophers
    EXPECT_EQ(all, (std::vector<std::string>{
                       "|net/Think| + |net/Catch1| + |net/Catch2| + |net/Eat| = 5",
                       "|net/Fork| + |net/Catch1| + |net/Catch2| + 2*|net/Eat| = 5",
                       "net/Think(x) + net/Catch1(x) + net/Catch2(x) + net/Eat(x) = 1 for every x in Philo",
                       "net/Fork(x) + net/Catch1(succ(x)) + net/Catch2(x) + net/Eat(x) + net/Eat(succ(x)) = 1 for every x in Philo",
                   }));
  }
  if (model == "TokenRing-COL-005") {
    // each process is in one state
    EXPECT_TRUE(has("net/State(x, _) = 1 for every x in Process")) << ::testing::PrintToString(all);
  }
  if (model == "SharedMemory-COL-000005") {
    // a processor works on its own memory, waits, is active or accesses another's; a memory is
    // free or accessed by one processor
    EXPECT_TRUE(has("net/OwnMemAcc(x) + net/Queue(x) + net/Active(x) + net/Ext_Mem_Acc(x, _) = 1 for every x in P"));
    EXPECT_TRUE(has("net/Memory(x) + net/Ext_Mem_Acc(_, x) = 1 for every x in P"));
  }
}

INSTANTIATE_TEST_SUITE_P(Nets, ColouredModelInvariants,
                         ::testing::Values("DrinkVendingMachine-COL-02", "LamportFastMutEx-COL-2", "NeoElection-COL-2",
                                           "Philosophers-COL-000005", "SharedMemory-COL-000005",
                                           "SharedMemory-COL-000010", "Sudoku-COL-AN01", "Sudoku-COL-AN02",
                                           "TokenRing-COL-005"));

}  // namespace
}  // namespace gdpn::net
