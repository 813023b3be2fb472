// The IDE's shell: the table of actions (every entry pressable, its keys real), the menus, the
// files (New, Open through the file browser, Open Recent, Save As, "save changes?"), the title,
// and the panels (swapped, one filling the window, kept in the settings).

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "ide/detail/keys.h"
#include "gdpn/ide/actions.h"
#include "gdpn/ide/replay.h"
#include "ide/headless_fixture.h"
#include "ide/ide_model.h"

namespace gdpn::ide {
namespace {

TEST(ActionTable, EveryActionHasOneEntryANameAndARealKey) {
  std::set<std::string_view> names;
  std::set<std::string> keys;
  for (int i = 0; i <= static_cast<int>(ActionId::Guide); ++i) {
    const auto id = static_cast<ActionId>(i);
    EXPECT_EQ(info(id).id, id) << i;  // each id is described
  }
  EXPECT_EQ(actionInfos().size(), static_cast<std::size_t>(ActionId::Guide) + 1);
  for (const auto& a : actionInfos()) {
    EXPECT_TRUE(names.insert(a.name).second) << a.name;
    EXPECT_EQ(findAction(a.name), a.id);
    EXPECT_FALSE(a.label.empty() || a.help.empty()) << a.name;
    if (a.keys.empty()) continue;
    const auto shortcut = parseShortcut(a.keys);
    ASSERT_TRUE(shortcut) << a.keys;
    EXPECT_GE(keyCode(shortcut->key), 0) << a.keys << ": a key the platform knows";
    EXPECT_TRUE(keys.insert(std::string(a.keys)).second) << a.keys << " twice";
  }
  EXPECT_FALSE(findAction("fly"));
  const auto s = parseShortcut("Ctrl+Shift+S");
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->ctrl && s->shift && !s->alt);
  EXPECT_EQ(s->key, "s");
  EXPECT_FALSE(parseShortcut("Ctrl+"));
  EXPECT_FALSE(parseShortcut("S+Ctrl"));
}

TEST(ActionTable, AReplayMayPressEveryActionByItsName) {
  for (const auto& a : actionInfos()) {
    core::Diagnostics diags;
    const auto actions = parseReplay("- press: " + std::string(a.name) + "\n", "a.yaml", diags);
    ASSERT_TRUE(actions) << diags.str();
    EXPECT_EQ((*actions)[0].kind, ActionKind::Press);
  }
}

class Shell : public HeadlessIde {
 protected:
  /// A model file of the test's own (the bin model) at `name` under the test's folder.
  std::string model(const std::string& name) { return write(name, testing::kBinModel); }
  /// The text of the file at `path`.
  static std::string text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

TEST_F(Shell, EveryActionOfTheTableIsDoneByPressInAStateThatAllowsIt) {
  const auto path = model("bin.gdpn.yaml");
  // each action pressed where it can be done (a press that cannot is an error: the replay
  // would fail); the autosave's Restore and Discard are tested where an autosave is offered,
  // Update Parts where the library holds a newer version (part_update_test.cpp)
  const std::string actions = R"Y(
- select: drop
- press: save-as-part
- click: [save_as_part, buttons, cancel]
- press: copy
- press: paste
- press: undo
- press: redo
- press: cut
- press: undo
- select: drop
- press: delete
- press: undo
- select: drop
- press: turn-quarter
- press: undo
- press: net-place
- press: net-transition
- press: net-arc
- press: net-select
- press: select-all
- press: align-left
- press: undo
- press: align-top
- press: undo
- press: distribute-across
- press: undo
- press: distribute-down
- press: undo
- select: 'main: idle -> work'
- press: reverse-arc
- press: undo
- select: main/work
- press: page-type-from-selection
- press: open-instance
- press: undo
- press: swap-views
- press: swap-views
- press: world-full
- press: world-full
- press: net-full
- press: net-full
- press: mini-view
- press: palette
- press: palette
- press: io-list
- press: io-list
- press: colour-sets
- press: colour-sets
- press: sensors
- press: joints
- press: contacts
- press: shadows
- press: grid
- press: select-tool
- press: turn-tool
- press: scale-tool
- press: aim-tool
- press: move-tool
- press: snap
- press: local-axes
- press: frame
- press: screenshot
- press: movie
- frames: 2
- press: movie
- break: {starts: main/work}
- press: clear-breakpoints
- press: run
- frames: 3
- press: pause
- press: faster
- press: pause
- press: fastest
- press: pause
- press: step
- press: release-forces
- press: run-n
- press: fire
- press: plant-only
- press: plant-only
- press: serve-opcua
- frames: 2
- press: serve-opcua
- press: reset
- press: keys
- press: guide
- press: save
- press: open
- click: [file_browser, buttons, cancel]
- press: save-as
- click: [file_browser, buttons, cancel]
- press: new
- press: close
- press: quit
)Y";
  std::set<std::string> pressed;
  std::istringstream lines(actions);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("- press: ")) pressed.insert(line.substr(9));
  }
  for (const auto& a : actionInfos()) {
    if (a.id == ActionId::Restore || a.id == ActionId::Discard || a.id == ActionId::UpdateParts) continue;
    EXPECT_TRUE(pressed.contains(std::string(a.name))) << a.name;
  }
  // in the test's folder: the screenshot and the movie land there
  const auto file = write("all.yaml", actions);
  const auto report = (dir_ / "all.json").string();
  last_ = gdpn::testing::runShell("cd '" + dir_.string() + "' && " + env() + " \"$GDPN\" ide '" + path +
                                  "' --headless --size 1280x720 --replay '" + file + "' --report '" + report + "'");
  ASSERT_EQ(last_.code, 0) << last_.out;
  std::ifstream in(report);
  const auto r = nlohmann::json::parse(in, nullptr, false);
  EXPECT_EQ(r["document"]["untitled"], true);  // Close left a new model
  EXPECT_TRUE(std::filesystem::exists(dir_ / "gdpn-ide-1.png"));
  EXPECT_TRUE(r["run"]["breakpoints"].empty());
}

TEST_F(Shell, PressingAnActionThatCannotBeDoneNowIsAnErrorThatSaysSo) {
  const auto path = model("bin.gdpn.yaml");
  replayOn(path, "- press: undo\n", "", 1);
  EXPECT_NE(last_.out.find("'undo' cannot be done now"), std::string::npos) << last_.out;
}

TEST_F(Shell, RTurnsTheSelectedTransformAQuarterRoundEachAStepOfUndo) {
  // R twice: half round (180 degrees about z); Ctrl+Z: a quarter (90); saved as such
  const auto path = model("bin.gdpn.yaml");
  const auto r = replayOn(path, "- select: drop\n- key: r\n- key: r\n- key: ctrl+z\n- key: ctrl+s\n");
  EXPECT_EQ(r["undo"]["depth"], 1);
  const std::string saved = text(path);
  EXPECT_NE(saved.find("rotation: [0, 0, 1, 90]"), std::string::npos) << saved;
  // nothing selected: R does nothing (it cannot be pressed)
  replayOn(path, "- press: turn-quarter\n", "", 1);
  EXPECT_NE(last_.out.find("'turn-quarter' cannot be done now"), std::string::npos) << last_.out;
}

TEST_F(Shell, ANewEmptyModelShowsAnEmptyNetNotAnError) {
  // `gdpn: 1` alone: the net view says how a net starts, and the diagnostics hold nothing
  const auto path = write("empty.gdpn.yaml", "gdpn: 1\n");
  const auto r = replayOn(path, "- frames: 1\n");
  EXPECT_FALSE(r["net_view"].contains("error")) << r["net_view"].dump();
  EXPECT_EQ(r["net_view"]["empty"], true);
}

TEST_F(Shell, TheMenusListTheTableAndAChoiceDoesTheAction) {
  const auto path = model("bin.gdpn.yaml");
  auto r = replayOn(path, "- click: [menu, File]\n");
  EXPECT_EQ(r["menu"]["open"], "File");
  for (const char* item : {"New", "Open...", "Open Recent", "Save", "Save As...", "Close", "Quit"}) {
    EXPECT_TRUE(r["menu"]["items"].contains(item)) << item << " in " << r["menu"]["items"].dump();
  }
  EXPECT_FALSE(r["menu"]["items"].contains("Undo"));
  // View > Net Fills the Window: the net view alone; again: the panels
  r = replayOn(path, "- click: [menu, View]\n- click: [menu, items, Net Fills the Window]\n");
  EXPECT_EQ(r["splitters"]["full"], "net");
  EXPECT_FALSE(r.contains("world"));
  EXPECT_FLOAT_EQ(r["layout"]["net"][2].get<float>(), 1280);
  std::filesystem::remove_all(dir_ / "config");  // the layout the last session kept
  r = replayOn(path, "- press: net-full\n- press: net-full\n- press: swap-views\n");
  EXPECT_EQ(r["splitters"]["full"], "none");
  EXPECT_EQ(r["splitters"]["swapped"], true);
  EXPECT_GT(r["layout"]["net"][2].get<float>(), r["layout"]["world"][2].get<float>());  // the big panel
  // Help > Keys lists every action
  r = replayOn(path, "- press: keys\n");
  EXPECT_EQ(r["keys"]["actions"].size(), actionInfos().size());
}

TEST_F(Shell, TheFactorysNetFillingTheWindowIsReadable) {
  size_ = "1600x900";
  auto r = replay("[]");
  EXPECT_EQ(r["net_view"]["label_px"], 0) << "in its panel, the factory's net is too small for names";
  r = replay("- press: net-full\n");
  EXPECT_GE(r["net_view"]["label_px"].get<double>(), 10.0) << r["net_view"].dump();
  EXPECT_EQ(r["net_view"]["places"], 13);
}

TEST_F(Shell, TheLayoutIsKeptBetweenSessions) {
  const auto path = model("bin.gdpn.yaml");
  replayOn(path, "- press: swap-views\n- press: world-full\n");
  const auto r = replayOn(path, "[]");
  EXPECT_EQ(r["splitters"]["swapped"], true);
  EXPECT_EQ(r["splitters"]["full"], "world");
}

TEST_F(Shell, NewGivesAnUntitledModelThatSaveNamesThroughTheFileBrowser) {
  const auto path = model("bin.gdpn.yaml");
  auto r = replayOn(path, "- press: new\n");
  EXPECT_EQ(r["document"]["untitled"], true);
  EXPECT_EQ(std::filesystem::path(r["document"]["path"].get<std::string>()).filename(), "untitled.gdpn.yaml");
  EXPECT_EQ(r["document"]["title"], "untitled.gdpn.yaml - gdpn ide");
  EXPECT_EQ(r["net_view"]["places"], 0);
  EXPECT_FALSE(r["tree"].empty());
  // Save on an untitled model asks for its name; the name typed is where it goes
  r = replayOn(path, "- press: new\n- press: save\n");
  EXPECT_EQ(r["file_browser"]["open"], true);
  EXPECT_EQ(r["file_browser"]["mode"], "save-as");
  r = replayOn(path, "- press: new\n- press: save\n- click: [file_browser, buttons, name]\n- type: \"-mine\"\n"
                     "- click: [file_browser, buttons, save]\n");
  const auto saved = dir_ / "untitled.gdpn.yaml-mine.gdpn.yaml";
  EXPECT_TRUE(std::filesystem::exists(saved)) << r["file_browser"].dump() << r["message"];
  EXPECT_EQ(r["document"]["untitled"], false);
  EXPECT_EQ(r["document"]["recent"][0], saved.string());
}

TEST_F(Shell, OpenGoesThroughTheFileBrowserAndRecentFilesComeBack) {
  const auto a = model("a.gdpn.yaml");
  std::filesystem::create_directories(dir_ / "sub");
  const auto b = model("sub/b.gdpn.yaml");
  // the browser lists the model's folder: its subfolders and model files
  auto r = replayOn(a, "- press: open\n");
  ASSERT_EQ(r["file_browser"]["open"], true);
  EXPECT_EQ(r["file_browser"]["folder"], dir_.string());
  EXPECT_TRUE(r["file_browser"]["entries"].contains("sub"));
  EXPECT_TRUE(r["file_browser"]["entries"].contains("a.gdpn.yaml"));
  EXPECT_FALSE(r["file_browser"]["entries"].contains("actions.yaml"));  // not a model file
  // into sub, b chosen, Open
  r = replayOn(a, "- press: open\n- click: [file_browser, entries, sub]\n- click: [file_browser, entries, b.gdpn.yaml]\n"
                  "- click: [file_browser, buttons, open]\n");
  EXPECT_EQ(r["document"]["path"], b) << r["message"];
  EXPECT_EQ(r["file_browser"]["open"], false);
  EXPECT_EQ(r["document"]["recent"][0], b);
  EXPECT_EQ(r["document"]["recent"][1], a);
  // the next session offers both; File > Open Recent > a opens a again
  r = replayOn(b, "- click: [menu, File]\n- click: [menu, items, Open Recent]\n");
  ASSERT_TRUE(r["menu"]["recent"].contains("a.gdpn.yaml")) << r["menu"].dump();
  r = replayOn(b, "- click: [menu, File]\n- click: [menu, items, Open Recent]\n- click: [menu, recent, a.gdpn.yaml]\n");
  EXPECT_EQ(r["document"]["path"], a);
  // a name that is no file is refused in the browser, which stays open
  r = replayOn(a, "- press: open\n- type: nothing.gdpn.yaml\n- click: [file_browser, buttons, open]\n");
  EXPECT_EQ(r["file_browser"]["open"], true);
  EXPECT_NE(r["file_browser"]["error"].get<std::string>().find("no file"), std::string::npos);
}

TEST_F(Shell, SaveAsGoesThroughTheFileBrowserAndAsksBeforeReplacingAFile) {
  const auto a = model("a.gdpn.yaml");
  std::filesystem::create_directories(dir_ / "sub");
  auto r = replayOn(a, "- press: save-as\n- click: [file_browser, entries, sub]\n- click: [file_browser, buttons, save]\n");
  const auto copy = (dir_ / "sub" / "a.gdpn.yaml").string();
  EXPECT_EQ(r["document"]["path"], copy);
  const auto written = text(copy);  // the model as the writer writes it
  EXPECT_NE(written.find("name: drop"), std::string::npos) << written;
  // over another file: once told, the second Save replaces it
  const auto other = model("other.gdpn.yaml");
  std::ofstream(other) << "gdpn: 1\n";
  const std::string over = "- press: save-as\n- click: [file_browser, entries, other.gdpn.yaml]\n- click: [file_browser, buttons, save]\n";
  r = replayOn(a, over);
  EXPECT_NE(r["file_browser"]["error"].get<std::string>().find("exists"), std::string::npos);
  EXPECT_EQ(text(other), "gdpn: 1\n");
  r = replayOn(a, over + "- click: [file_browser, buttons, save]\n");
  EXPECT_EQ(text(other), written);
  EXPECT_EQ(r["document"]["path"], other);
}

TEST_F(Shell, UnsavedEditsAreMarkedInTheTitleAndAskedAboutBeforeTheyAreLost) {
  const auto a = model("a.gdpn.yaml");
  const auto before = text(a);
  const std::string edit = "- set: {node: drop, field: translation, value: [0, 0, 2]}\n";
  auto r = replayOn(a, edit);
  EXPECT_EQ(r["document"]["title"], "*a.gdpn.yaml - gdpn ide");
  // New with unsaved edits asks; Cancel keeps everything
  r = replayOn(a, edit + "- press: new\n");
  ASSERT_EQ(r["save_changes"]["open"], true);
  EXPECT_EQ(r["save_changes"]["file"], "a.gdpn.yaml");
  r = replayOn(a, edit + "- press: new\n- click: [save_changes, buttons, cancel]\n");
  EXPECT_EQ(r["save_changes"]["open"], false);
  EXPECT_EQ(r["document"]["path"], a);
  EXPECT_EQ(r["document"]["modified"], true);
  // Don't Save: the new model; the file as it was
  r = replayOn(a, edit + "- press: new\n- click: [save_changes, buttons, dont-save]\n");
  EXPECT_EQ(r["document"]["untitled"], true);
  EXPECT_EQ(text(a), before);
  // Save: the file saved, then the new model
  r = replayOn(a, edit + "- press: close\n- click: [save_changes, buttons, save]\n");
  EXPECT_EQ(r["document"]["untitled"], true);
  EXPECT_NE(text(a), before);
  EXPECT_NE(text(a).find("translation: [0, 0, 2]"), std::string::npos) << text(a);
}

TEST_F(Shell, QuitAsksFirstAndEndsTheIde) {
  const auto a = model("a.gdpn.yaml");
  // nothing to lose: the IDE ends at once, the actions after Quit are not done
  auto r = replayOn(a, "- press: quit\n- press: grid\n");
  EXPECT_EQ(r["document"]["path"], a);
  const std::string edit = "- set: {node: drop, field: translation, value: [0, 0, 2]}\n";
  r = replayOn(a, edit + "- press: quit\n");
  EXPECT_EQ(r["save_changes"]["open"], true);
}

TEST_F(Shell, PasteThenUndoPutsTheInspectorBackOnWhatWasSelectedBefore) {
  const auto path = model("bin.gdpn.yaml");
  // a Material copied and pasted beside itself: the copy is selected
  const std::string paste = "- select: drop/paint\n- press: copy\n- press: paste\n";
  auto r = replayOn(path, paste);
  ASSERT_EQ(r["selection"]["kind"], "node");
  const auto copy = r["selection"]["name"].get<std::string>();
  EXPECT_NE(copy, "drop/paint");
  EXPECT_EQ(r["inspector"]["node"], copy);
  // undone: the copy is gone, and so is it from the inspector
  r = replayOn(path, paste + "- press: undo\n");
  EXPECT_EQ(r["selection"]["name"], "drop/paint");
  EXPECT_EQ(r["inspector"]["node"], "drop/paint");
  EXPECT_EQ(r["inspector"]["type"], "Material");
  // a place pasted into the net view, undone
  r = replayOn(path, "- select: main/idle\n- press: copy\n- press: paste\n- press: undo\n");
  EXPECT_EQ(r["selection"]["name"], "main/idle");
  EXPECT_EQ(r["inspector"]["name"], "main/idle");
}

TEST_F(Shell, PasteWithNothingToPasteDoesNothingSilently) {
  const auto path = model("bin.gdpn.yaml");
  const auto r = replayOn(path, "- select: drop/paint\n- press: paste\n");
  EXPECT_EQ(r["message"], "");
  EXPECT_EQ(r["undo"]["depth"], 0);
  EXPECT_EQ(r["selection"]["name"], "drop/paint");
  EXPECT_EQ(last_.out.find("error"), std::string::npos) << last_.out;
}

TEST_F(Shell, TheWorldViewLowersItsResolutionOnlyWhileASlowRunGoesOn) {
  const auto path = model("bin.gdpn.yaml");
  // a slow machine: 5 frames a second. A move handle held down (editing, the view still) for
  // 4 s keeps the whole resolution
  const std::string hold =
      "- select: high\n- drag: {from: [world, handles, move x], to: [world, handles, move x], hold: true}\n"
      "- frames: {count: 20, seconds: 0.2}\n";
  auto r = replayOn(path, hold);
  EXPECT_EQ(r["world"]["manipulating"], "move x") << r["world"].dump();
  EXPECT_EQ(r["world"]["scale"], 1.0);
  // so does a frame of nothing at all
  r = replayOn(path, "- frames: {count: 20, seconds: 0.2}\n");
  EXPECT_EQ(r["world"]["scale"], 1.0);
  // the model running that slowly: lowered in steps to half each side; paused, whole again
  const std::string run = "- press: run\n- frames: {count: 20, seconds: 0.2}\n";
  r = replayOn(path, run);
  EXPECT_EQ(r["run"]["mode"], "running");
  EXPECT_EQ(r["world"]["scale"], 0.5);
  r = replayOn(path, run + "- press: pause\n");
  EXPECT_EQ(r["world"]["scale"], 1.0);
  // at 60 frames a second nothing is lowered
  r = replayOn(path, "- press: run\n- frames: 120\n");
  EXPECT_EQ(r["world"]["scale"], 1.0);
  // a slow frame is read as a replay's mistake when it asks for too much
  replayOn(path, "- frames: {count: 2, seconds: 0}\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:31: error: expects {count: N, seconds: S}"), std::string::npos) << last_.out;
}

TEST_F(Shell, TheInspectorRefusesAShapeOfNoSize) {
  const auto path = model("bin.gdpn.yaml");
  replayOn(path, "- set: {node: drop/box/shape, field: size, value: [0.2, 0, 0.2]}\n", {}, 1);
  EXPECT_NE(last_.out.find("actions.yaml:1:3: error: 'size' must be above 0, got 0"), std::string::npos) << last_.out;
  const auto r = replayOn(path, "- set: {node: drop/box/shape, field: size, value: [0.2, 0.05, 0.2]}\n");
  EXPECT_EQ(r["undo"]["depth"], 1);
}

/// The IDE as a real process, ended by a signal.
class Signalled : public Shell {
 protected:
  /// Starts the headless IDE on `model` with the replay `actions`, SIGTERM ignored as a launcher
  /// may leave it when `ignored`; its process id. It writes `started.png` when it got going.
  pid_t start(const std::string& model, const std::string& actions, bool ignored) {
    const auto file = write("actions.yaml", actions);
    const std::string command = "exec env " + env() + " '" + GDPN_CLI + "' ide '" + model +
                                "' --headless --size 640x480 --replay '" + file + "' --report '" +
                                (dir_ / "report.json").string() + "' >'" + (dir_ / "ide.log").string() + "' 2>&1";
    const pid_t pid = ::fork();
    if (pid == 0) {
      if (ignored) ::signal(SIGTERM, SIG_IGN);
      ::chdir(dir_.c_str());
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    return pid;
  }
  /// Waits until the IDE shows that it got going (at most a minute); false when it did not.
  bool started(pid_t pid) {
    for (int i = 0; i < 600; ++i) {
      if (std::filesystem::exists(dir_ / "started.png")) return true;
      if (::waitpid(pid, &status_, WNOHANG) == pid) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }
  /// Sends SIGTERM and waits for the end, at most 5 s (then SIGKILL); the seconds it took, or
  /// a negative number when it did not end.
  double terminate(pid_t pid) {
    const auto sent = std::chrono::steady_clock::now();
    ::kill(pid, SIGTERM);
    for (;;) {
      const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
      if (::waitpid(pid, &status_, WNOHANG) == pid) return took;
      if (took > 5) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status_, 0);
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  int status_ = 0;
};

TEST_F(Signalled, SigtermEndsTheIdeAtOnceSavingNothingEvenWhereALauncherIgnoredIt) {
  const auto path = model("bin.gdpn.yaml");
  const auto before = text(path);
  // an unsaved edit, then frames that would last half an hour; once with the model running
  const std::string edit = "- set: {node: drop, field: translation, value: [0, 0, 2]}\n- screenshot: started.png\n";
  for (const bool ignored : {false, true}) {
    for (const std::string& then : {std::string(), std::string("- press: run\n")}) {
      SCOPED_TRACE(std::string(ignored ? "SIGTERM ignored by the launcher" : "SIGTERM as it comes") +
                   (then.empty() ? ", editing" : ", running"));
      std::filesystem::remove(dir_ / "started.png");
      const pid_t pid = start(path, edit + then + "- frames: 100000\n", ignored);
      ASSERT_TRUE(started(pid)) << text((dir_ / "ide.log").string());
      const double took = terminate(pid);
      ASSERT_GE(took, 0) << "still running 5 s after SIGTERM";
      std::cout << "  the IDE ended " << std::lround(took * 1000) << " ms after SIGTERM\n";
      // ended by the signal, as the default action would (a shell says 143)
      ASSERT_TRUE(WIFSIGNALED(status_)) << "exit status " << WEXITSTATUS(status_) << ": " << text((dir_ / "ide.log").string());
      EXPECT_EQ(WTERMSIG(status_), SIGTERM);
      // nothing saved: the model as it was, no autosave, no report
      EXPECT_EQ(text(path), before);
      EXPECT_TRUE(autosaves().empty());
      EXPECT_FALSE(std::filesystem::exists(dir_ / "report.json"));
      EXPECT_EQ(text((dir_ / "ide.log").string()).find("error"), std::string::npos) << text((dir_ / "ide.log").string());
    }
  }
}

}  // namespace
}  // namespace gdpn::ide
