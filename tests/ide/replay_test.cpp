// Replay files: every action read, every mistake located.

#include <gtest/gtest.h>

#include "gdpn/ide/replay.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/scene/types.h"

namespace gdpn::ide {
namespace {

std::optional<std::vector<Action>> parse(const std::string& text, core::Diagnostics& diags) {
  return parseReplay(text, "a.yaml", diags);
}

TEST(Replay, ReadsEveryAction) {
  core::Diagnostics diags;
  const auto a = parse(R"Y(- select: arm/turn
- press: step
- fire: factory/pickup
- run: 2.5
- steps: 10
- frames: 3
- key: g
- click: [10, 20]
- drag: {from: [1, 2], to: [3, 4], button: right}
- set: {node: arm/turn, field: axis1, value: [0, 0, 1]}
- view: top
- screenshot: out.png
- break: {place: main/buffer, at_least: 3}
)Y", diags);
  ASSERT_TRUE(a) << diags.str();
  ASSERT_EQ(a->size(), 13U);
  EXPECT_EQ((*a)[12].kind, ActionKind::Break);
  EXPECT_EQ((*a)[12].field, "place");
  EXPECT_EQ((*a)[12].number, 3);
  EXPECT_EQ((*a)[0].kind, ActionKind::Select);
  EXPECT_EQ((*a)[0].text, "arm/turn");
  EXPECT_EQ((*a)[3].number, 2.5);
  EXPECT_EQ((*a)[7].x, 10);
  EXPECT_EQ((*a)[8].button, 1);
  EXPECT_EQ((*a)[8].y2, 4);
  EXPECT_TRUE((*a)[9].list);
  EXPECT_EQ((*a)[9].value.size(), 3U);
  EXPECT_EQ((*a)[11].loc.line, 12);
  EXPECT_EQ((*a)[11].loc.column, 3);
}

TEST(Replay, ABreakpointMayBeWrittenAsGdpnRunWritesIt) {
  core::Diagnostics diags;
  const auto a = parse("- break: start:factory/pickup\n- break: 'main/buffer>=3'\n- break: 'when:sim.time > 2'\n", diags);
  ASSERT_TRUE(a) << diags.str();
  ASSERT_EQ(a->size(), 3U);
  for (const auto& action : *a) {
    EXPECT_EQ(action.kind, ActionKind::Break);
    EXPECT_EQ(action.field, "written");
  }
  EXPECT_EQ((*a)[0].text, "start:factory/pickup");
  EXPECT_EQ((*a)[2].text, "when:sim.time > 2");
}

TEST(Replay, MistakesAreLocated) {
  const std::pair<const char*, const char*> cases[] = {
      {"- hop: 1\n", "a.yaml:1:3: error: unknown action 'hop'"},
      {"- press: fly\n", "a.yaml:1:10: error: unknown action 'fly'"},
      {"- run: -1\n", "a.yaml:1:8: error: expects seconds from 0 to 10^7"},
      {"- steps: 1.5\n", "a.yaml:1:10: error: expects a whole number"},
      {"- click: [1]\n", "a.yaml:1:10: error: expects a point [X, Y] in window pixels"},
      {"- drag: {from: [1, 2], to: [3, 4], button: thumb}\n", "a.yaml:1:44: error: expects a button"},
      {"- set: {node: a}\n", "a.yaml:1:8: error: expects {node: PATH, field: NAME, value: VALUE}"},
      {"- wheel: {at: [1, 2]}\n", "a.yaml:1:10: error: expects {at: [X, Y], clicks: N}"},
      {"- wheel: {at: [1, 2], clicks: 1e9}\n", "a.yaml:1:31: error: expects clicks from -100 to 100"},
      {"select: a\n", "a.yaml:1:1: error: a replay file is a list of actions"},
      {"- break: {place: p}\n", "a.yaml:1:10: error: a place's breakpoint expects at_least: N tokens"},
      // as gdpn run --break writes it: located at the character that goes wrong
      {"- break: main/buffer=>3\n", "a.yaml:1:21: error: expected start:TRANSITION, complete:TRANSITION"},
      {"- break: 'main/buffer>=x'\n", "a.yaml:1:24: error: expected start:TRANSITION"},
      {"- [a, b]\n", "a.yaml:1:3: error: an action is a map with one key"},
  };
  for (const auto& [text, expected] : cases) {
    core::Diagnostics diags;
    EXPECT_FALSE(parse(text, diags)) << text;
    EXPECT_NE(diags.str().find(expected), std::string::npos) << text << "\n" << diags.str();
  }
}

TEST(Replay, ADragMayHoldItsButtonDownAndStartAtANamedItem) {
  core::Diagnostics diags;
  const auto a = parse("- drag: {from: [palette, items, belt_conveyor], to: [world, parts, belt1, +x], hold: true}\n- drag: {from: [1, 2], to: [3, 4]}\n", diags);
  ASSERT_TRUE(a) << diags.str();
  EXPECT_TRUE((*a)[0].hold);
  EXPECT_EQ((*a)[0].on, (std::vector<std::string>{"palette", "items", "belt_conveyor"}));
  EXPECT_EQ((*a)[0].on2, (std::vector<std::string>{"world", "parts", "belt1", "+x"}));
  EXPECT_FALSE((*a)[1].hold);
  EXPECT_FALSE(parse("- drag: {from: [1, 2], to: [3, 4], hold: sometimes}\n", diags));
  EXPECT_NE(diags.str().find("a.yaml:1:42: error: expects hold: true or false"), std::string::npos) << diags.str();
}

TEST(Replay, FramesMayStandForASlowMachine) {
  core::Diagnostics diags;
  const auto a = parse("- frames: {count: 20, seconds: 0.2}\n- frames: 3\n", diags);
  ASSERT_TRUE(a) << diags.str();
  EXPECT_EQ((*a)[0].kind, ActionKind::Frames);
  EXPECT_EQ((*a)[0].number, 20);
  EXPECT_EQ((*a)[0].seconds, 0.2);
  EXPECT_EQ((*a)[1].seconds, 0);  // 1/60 s
  EXPECT_FALSE(parse("- frames: {count: 2, seconds: 11}\n", diags));
  EXPECT_NE(diags.str().find("a.yaml:1:31: error: expects {count: N, seconds: S}"), std::string::npos) << diags.str();
  EXPECT_FALSE(parse("- frames: {count: 2}\n", diags));
  EXPECT_NE(diags.str().find("a.yaml:1:11: error: expects {count: N, seconds: S}"), std::string::npos) << diags.str();
}

TEST(Replay, AnEmptyFileHasNoActions) {
  core::Diagnostics diags;
  const auto a = parse("", diags);
  ASSERT_TRUE(a);
  EXPECT_TRUE(a->empty());
}

TEST(FieldValueFromWords, ReadsEachKind) {
  const auto& types = scene::builtinTypes();
  const auto& joint = *types.find("Joint");
  const auto field = [&](const char* name) { return *joint.fields[static_cast<std::size_t>(joint.fieldIndex(name))]; };
  std::string why;
  EXPECT_EQ(fieldValueFromWords(field("vel1"), {"2.5"}, false, why), scene::FieldValue{2.5});
  EXPECT_EQ(fieldValueFromWords(field("axis1"), {"0", "0", "1"}, true, why),
            (scene::FieldValue{std::array{0.0, 0.0, 1.0}}));
  EXPECT_EQ(fieldValueFromWords(field("kind"), {"slider"}, false, why), scene::FieldValue{std::string("slider")});
  EXPECT_FALSE(fieldValueFromWords(field("axis1"), {"0", "1"}, true, why));
  EXPECT_EQ(why, "'axis1' expects 3 numbers");
  EXPECT_FALSE(fieldValueFromWords(field("vel1"), {"fast"}, false, why));
}

}  // namespace
}  // namespace gdpn::ide
