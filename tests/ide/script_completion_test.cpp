// The script editor's completion: what may follow `sim.`, `self.` of a transition, a node
// slot and a node token, the model's globals; nothing in a comment or a string.

#include "gdpn/ide/script_completion.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "gdpn/core/diagnostics.h"
#include "gdpn/ide/token_types.h"
#include "gdpn/model/model.h"
#include "gdpn/scene/node.h"
#include "gdpn/script/api.h"

namespace gdpn::ide {
namespace {

// a store of boxes (node tokens of a Body) that `pick` takes one of, a counter place, a
// photo-eye, parameters and globals
const char* const kModel = R"Y(gdpn: 1
params:
  belt_speed: {value: 0.5, unit: m/s, description: "speed of the belt"}
scripts:
  globals: |
    painted = 0
    def paint(box, colour="red"):
        """Paints a box."""
        global painted
        painted += 1
scene:
  - Body: {name: box, mass: 1, children: [{Cube: {name: shape, size: [0.2, 0.2, 0.2]}}]}
  - Region: {name: eye, size: [1, 1, 1]}
pages:
  main:
    places:
      store: {tokens: {d0: [box], a0: 2}}
      done: {}
      watch: {sensors: {c0: eye}}
    transitions:
      pick: {duration: 1}
    arcs:
      - {from: store, to: pick, weight: {a0: 1, d0: 1}}
      - {from: pick, to: done, weight: {d0: 1}}
      - {from: watch, to: pick, condition: {c0: 'value > 0'}}
)Y";

class Completing : public ::testing::Test {
 protected:
  void SetUp() override {
    core::Diagnostics diags;
    auto m = model::parseModel(kModel, "completion.gdpn.yaml", diags);
    ASSERT_TRUE(m) << diags.str();
    model_ = std::move(*m);
    const auto* plant = model_.scene.get();
    types_ = propagateTokenTypes(model_.net, [plant](const std::string&, const std::string& path) -> const scene::NodeType* {
      const auto* n = plant->find(path);
      return n != nullptr ? &n->type() : nullptr;
    });
  }
  /// The names offered at the end of `code` in a script of `kind` of `construct`.
  std::vector<std::string> names(const std::string& code, net::ScriptKind kind = net::ScriptKind::PreFire,
                                 const std::string& construct = "pick", net::SlotId slot = net::kDefaultSlot) {
    last_ = complete(scopeOf(model_, types_, "main", construct, kind, slot), code, code.size());
    std::vector<std::string> out;
    for (const auto& c : last_.names) out.push_back(c.name);
    return out;
  }
  [[nodiscard]] const Completion* offered(const std::string& name) const {
    const auto it = std::find_if(last_.names.begin(), last_.names.end(), [&](const auto& c) { return c.name == name; });
    return it == last_.names.end() ? nullptr : &*it;
  }
  static bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  }
  model::Model model_;
  TokenTypes types_;
  CompletionQuery last_;
};

TEST_F(Completing, SimOffersTheSimsBindingsEachWithItsLine) {
  const auto offered_names = names("x = sim.");
  EXPECT_TRUE(last_.member);
  EXPECT_EQ(last_.context, "sim");
  // exactly the binding's names (script/api.h reads them from the registered class)
  std::vector<std::string> bound;
  for (const auto& n : script::viewNames(script::ViewClass::Sim)) bound.push_back(n.name);
  std::sort(bound.begin(), bound.end());
  auto sorted = offered_names;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, bound);
  for (const char* n : {"time", "dt", "step", "log", "stop", "place", "node", "params", "random"}) EXPECT_TRUE(has(offered_names, n)) << n;
  ASSERT_NE(offered("stop"), nullptr);
  EXPECT_EQ(offered("stop")->kind, "method");
  EXPECT_EQ(offered("stop")->signature, "(reason='stopped by a script')");
  EXPECT_EQ(offered("stop")->detail, "ends the run after this step");
  ASSERT_NE(offered("time"), nullptr);
  EXPECT_EQ(offered("time")->kind, "attribute");
  EXPECT_EQ(offered("time")->detail, "seconds");
  // what was typed narrows the list, and says where the name begins
  EXPECT_EQ(names("sim.ti"), (std::vector<std::string>{"time"}));
  EXPECT_EQ(last_.start, 4u);
  EXPECT_EQ(last_.prefix, "ti");
}

TEST_F(Completing, SelfOfATransitionOffersItsSlotsAndItsBindings) {
  const auto offered_names = names("self.");
  for (const char* n : {"a0", "d0", "c0", "name", "elapsed", "progress", "servers", "start_time"}) EXPECT_TRUE(has(offered_names, n)) << n;
  EXPECT_FALSE(has(offered_names, "b0"));  // no arc carries it
  ASSERT_NE(offered("d0"), nullptr);
  EXPECT_EQ(offered("d0")->kind, "slot");
  EXPECT_EQ(offered("d0")->detail, "node slot: holds a Body");
  EXPECT_EQ(offered("a0")->detail, "control slot: a count of tokens");
  EXPECT_EQ(offered("c0")->detail, "sensor slot: reads eye (a Region)");
  // a place's script: the place's view and slots
  const auto place_names = names("self.", net::ScriptKind::OnDeposit, "store", *net::parseSlot("d0"));
  EXPECT_TRUE(has(place_names, "d0"));
  EXPECT_TRUE(has(place_names, "capacity"));
  EXPECT_FALSE(has(place_names, "elapsed"));
}

TEST_F(Completing, ANodeSlotAndANodeTokenOfferTheNodesFieldsAndActions) {
  // a slot: its own methods, and what its first token has
  auto slot_names = names("self.d0.");
  for (const char* n : {"get", "set", "add", "capacity", "mass", "set_velocity", "attach", "position"}) {
    EXPECT_TRUE(has(slot_names, n)) << n;
  }
  ASSERT_NE(offered("mass"), nullptr);
  EXPECT_EQ(offered("mass")->kind, "field");
  EXPECT_NE(offered("mass")->detail.find("kg"), std::string::npos) << offered("mass")->detail;
  // a token: the node's methods and its type's fields, and none of a slot's
  const auto token_names = names("self.d0[0].");
  EXPECT_TRUE(has(token_names, "mass"));
  EXPECT_TRUE(has(token_names, "spawn"));
  EXPECT_FALSE(has(token_names, "get"));
  // `token` in a place's script of that slot, and a node reached by path
  EXPECT_TRUE(has(names("token.", net::ScriptKind::OnDeposit, "store", *net::parseSlot("d0")), "mass"));
  EXPECT_TRUE(has(names("sim.node('box')."), "mass"));
  EXPECT_TRUE(has(names("sim.node(\"eye\")."), "size"));
  // a sensor slot: the Region's channels, not another kind's
  const auto eye = names("self.c0.");
  EXPECT_TRUE(has(eye, "items"));
  EXPECT_TRUE(has(eye, "value"));
  EXPECT_FALSE(has(eye, "distance"));  // a RangeFinder's
}

TEST_F(Completing, TheGlobalsAndTheParametersAreOffered) {
  const auto top = names("pa");
  EXPECT_EQ(top, (std::vector<std::string>{"paint", "painted"}));
  ASSERT_NE(offered("paint"), nullptr);
  EXPECT_EQ(offered("paint")->kind, "function");
  EXPECT_EQ(offered("paint")->detail, "(box, colour='red'): Paints a box.");
  EXPECT_TRUE(has(names("s"), "sim"));
  EXPECT_TRUE(has(names("s"), "self"));
  EXPECT_FALSE(has(names("s", net::ScriptKind::Globals, ""), "self"));  // the globals have no self
  EXPECT_TRUE(has(names("sim.params."), "belt_speed"));
  EXPECT_EQ(offered("belt_speed")->detail, "= 0.5 m/s: speed of the belt");
}

TEST_F(Completing, NothingInACommentOrAStringOrAfterAnUnknownThing) {
  EXPECT_TRUE(names("# sim.").empty());
  EXPECT_TRUE(names("x = 'sim.").empty());
  EXPECT_TRUE(names("x = \"\"\"a\nsim.").empty());
  EXPECT_TRUE(names("painted.").empty());
  EXPECT_TRUE(names("(1 + 2).").empty());
  EXPECT_TRUE(names("x = 3.").empty());
  // after a closed string, completion is back
  EXPECT_FALSE(names("sim.log('a'); sim.").empty());
  EXPECT_FALSE(names("x = '#'\nsim.").empty());
}

}  // namespace
}  // namespace gdpn::ide
