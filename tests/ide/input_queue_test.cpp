// The input queue: each press and release reaches the UI in a frame of its own, characters in
// order with their keys, modifiers with the keys they go with, clicks where they happened.

#include <gtest/gtest.h>

#include <string>

#include "ide/detail/input_queue.h"
#include "ide/detail/key_chord.h"

namespace gdpn::ide {
namespace {

int code(const char* name) {
  const int c = keyByName(name);
  EXPECT_GE(c, 0) << name;
  return c;
}

/// Queues the chords `text` ("ctrl+a x").
void press(InputQueue& q, const char* text) {
  std::string error;
  const auto chords = parseChords(text, error);
  ASSERT_TRUE(chords) << error;
  for (const auto& c : *chords) queueChord(q, c);
}

/// The characters of `frame` as text (ASCII).
std::string typed(const InputFrame& frame) {
  std::string s;
  for (const unsigned int c : frame.characters) s += static_cast<char>(c);
  return s;
}

TEST(InputQueue, AKeyPressedAndReleasedBeforeOneFrameIsDownOneFrameAndUpTheNext) {
  InputQueue q;
  q.key(code("s"), true);
  q.key(code("s"), false);
  q.next();
  EXPECT_TRUE(q.keyDown(code("s")));
  EXPECT_FALSE(q.empty());
  q.next();
  EXPECT_FALSE(q.keyDown(code("s")));
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, CtrlSBetweenTwoFramesIsSeenWithCtrlDown) {
  // xdotool key ctrl+s: Ctrl down, S down, S up, Ctrl up, 12 ms in all
  InputQueue q;
  press(q, "ctrl+s");
  q.next();
  EXPECT_TRUE(q.ctrl());
  EXPECT_TRUE(q.keyDown(code("s")));
  q.next();
  EXPECT_FALSE(q.ctrl());
  EXPECT_FALSE(q.keyDown(code("s")));
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, AModifierChangesOnlyBeforeTheKeysItGoesWith) {
  // S, then a quick Ctrl+Z: S is never seen with Ctrl, nor Z without it
  InputQueue q;
  press(q, "s ctrl+z");
  q.next();
  EXPECT_TRUE(q.keyDown(code("s")));
  EXPECT_FALSE(q.ctrl());
  q.next();
  EXPECT_TRUE(q.ctrl());
  EXPECT_TRUE(q.keyDown(code("z")));
  EXPECT_FALSE(q.keyDown(code("s")));
  q.next();
  EXPECT_FALSE(q.ctrl());
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, CtrlAThenTypingTypesAfterTheSelectAllAndWithoutCtrl) {
  InputQueue q;
  press(q, "ctrl+a x y");
  auto f = q.next();
  EXPECT_TRUE(q.ctrl() && q.keyDown(code("a")));
  EXPECT_TRUE(f.characters.empty());
  std::string text;
  while (!q.empty()) {
    f = q.next();
    if (!f.characters.empty()) {
      EXPECT_FALSE(q.ctrl()) << "characters typed while Ctrl is down are dropped by ImGui";
    }
    text += typed(f);
  }
  EXPECT_EQ(text, "xy");
}

TEST(InputQueue, TypingFlowsSeveralCharactersAFrameAndTheirReleasesFollow) {
  InputQueue q;
  press(q, "h e l o");
  auto f = q.next();
  EXPECT_EQ(typed(f), "helo");
  EXPECT_TRUE(q.keyDown(code("h")) && q.keyDown(code("o")));
  f = q.next();
  EXPECT_TRUE(f.characters.empty());
  EXPECT_FALSE(q.keyDown(code("h")) || q.keyDown(code("o")));
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, ARepeatedLetterWaitsForItsRelease) {
  InputQueue q;
  press(q, "s s");
  EXPECT_EQ(typed(q.next()), "s");
  q.next();  // S up
  EXPECT_FALSE(q.keyDown(code("s")));
  EXPECT_EQ(typed(q.next()), "s");
  EXPECT_TRUE(q.keyDown(code("s")));
}

TEST(InputQueue, NoCharacterFollowsEnterInItsFrame) {
  // ImGui reads a frame's characters before its keys: "a" typed after Enter would go into the
  // field before Enter ends it
  InputQueue q;
  press(q, "x enter a");
  auto f = q.next();
  EXPECT_EQ(typed(f), "x");
  EXPECT_TRUE(q.keyDown(code("enter")));
  f = q.next();
  EXPECT_EQ(typed(f), "a");
}

TEST(InputQueue, CapitalsComeWithShiftAndShiftWithThem) {
  InputQueue q;
  press(q, "shift+a b");
  auto f = q.next();
  EXPECT_EQ(typed(f), "A");
  EXPECT_TRUE(q.shift());
  f = q.next();
  EXPECT_FALSE(q.shift());
  EXPECT_EQ(typed(f), "b");
}

TEST(InputQueue, AQuickClickIsAPressThenAReleaseWhereItHappened) {
  InputQueue q;
  q.move(10, 20);
  q.button(0, true);
  q.button(0, false);
  q.move(300, 40);  // the mouse moves on at once
  auto f = q.next();
  EXPECT_TRUE(f.mouse);
  EXPECT_TRUE(q.buttonDown(0));
  EXPECT_EQ(q.mouseX(), 10.0F);
  f = q.next();
  EXPECT_FALSE(q.buttonDown(0));
  EXPECT_EQ(q.mouseX(), 10.0F);
  f = q.next();
  EXPECT_EQ(q.mouseX(), 300.0F);
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, ADoubleClickBetweenTwoFramesIsTwoClicks) {
  InputQueue q;
  for (int i = 0; i < 2; ++i) {
    q.button(0, true);
    q.button(0, false);
  }
  int presses = 0;
  bool was = false;
  while (!q.empty()) {
    q.next();
    if (q.buttonDown(0) && !was) ++presses;
    was = q.buttonDown(0);
  }
  EXPECT_EQ(presses, 2);
  EXPECT_FALSE(was);
}

TEST(InputQueue, ADragIsSeenWithTheButtonDownBeforeItsRelease) {
  InputQueue q;
  q.move(10, 10);
  q.button(0, true);
  q.move(50, 10);
  q.button(0, false);
  q.next();
  EXPECT_TRUE(q.buttonDown(0));
  EXPECT_EQ(q.mouseX(), 10.0F);
  q.next();
  EXPECT_TRUE(q.buttonDown(0));
  EXPECT_EQ(q.mouseX(), 50.0F);
  q.next();
  EXPECT_FALSE(q.buttonDown(0));
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, TypingThenAClickElsewhereComeInTwoFrames) {
  // the click ends the field: the text reaches it first
  InputQueue q;
  q.text("ok");
  q.button(0, true);
  auto f = q.next();
  EXPECT_EQ(typed(f), "ok");
  EXPECT_FALSE(q.buttonDown(0));
  q.next();
  EXPECT_TRUE(q.buttonDown(0));
}

TEST(InputQueue, TheWheelAddsUpAndAReleaseOfAKeyNeverPressedChangesNothing) {
  InputQueue q;
  q.key(code("g"), false);
  q.scroll(0, 1);
  q.scroll(0, 2);
  const auto f = q.next();
  EXPECT_EQ(f.wheel_y, 3.0F);
  EXPECT_EQ(f.events, 3U);
  EXPECT_FALSE(q.keyDown(code("g")));
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, TextIsDecodedFromUtf8InOrder) {
  InputQueue q;
  q.text("a\xC3\xA9\xE2\x82\xAC\n");  // a, e acute, euro, new line
  const auto f = q.next();
  ASSERT_EQ(f.characters.size(), 4U);
  EXPECT_EQ(f.characters[1], 0xE9U);
  EXPECT_EQ(f.characters[2], 0x20ACU);
  EXPECT_EQ(f.characters[3], static_cast<unsigned int>('\n'));
}

TEST(InputQueue, EveryFrameTakesAnEventSoTheQueueEmpties) {
  InputQueue q;
  press(q, "ctrl+a shift+x enter ctrl+shift+s x x x");
  q.button(1, true);
  q.button(1, false);
  q.text("abc");
  int frames = 0;
  while (!q.empty() && frames < 100) {
    EXPECT_GT(q.next().events, 0U);
    ++frames;
  }
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.ctrl() || q.shift() || q.buttonDown(1));
}

TEST(KeyChord, ChordsAreModifiersAndAKeyAndUnknownNamesAreRefused) {
  std::string error;
  const auto chords = parseChords("ctrl+shift+s  enter x shift+x", error);
  ASSERT_TRUE(chords) << error;
  ASSERT_EQ(chords->size(), 4U);
  EXPECT_EQ((*chords)[0].modifiers.size(), 2U);
  EXPECT_EQ((*chords)[0].key, code("s"));
  EXPECT_EQ((*chords)[0].character, 0U);  // Ctrl types nothing
  EXPECT_EQ((*chords)[1].character, 0U);
  EXPECT_EQ((*chords)[2].character, static_cast<unsigned int>('x'));
  EXPECT_EQ((*chords)[3].character, static_cast<unsigned int>('X'));
  EXPECT_FALSE(parseChords("ctrl+f13", error));
  EXPECT_EQ(error.rfind("unknown key 'f13'", 0), 0U) << error;
  EXPECT_FALSE(parseChords("a+b", error));
  EXPECT_EQ(error.rfind("'a' in 'a+b' is no modifier", 0), 0U) << error;
  EXPECT_FALSE(parseChords("ctrl+", error));
  EXPECT_EQ(error.rfind("unknown key 'ctrl+'", 0), 0U) << error;
}

}  // namespace
}  // namespace gdpn::ide
