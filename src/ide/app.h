#pragma once
// The IDE's frame: the views over the document and the run, laid out by the splitters. One
// App serves the window and the headless IDE alike; the platform (window.cpp, headless.cpp)
// feeds ImGui its input, calls frame() between ImGui::NewFrame() and ImGui::Render(), and
// draws ImGui's output. Private to the ide module.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gdpn/ide/colour_edit.h"
#include "gdpn/ide/document.h"
#include "gdpn/ide/io_list.h"
#include "gdpn/ide/layout.h"
#include "gdpn/ide/manipulator.h"
#include "gdpn/ide/script_completion.h"
#include "gdpn/ide/token_types.h"
#include "gdpn/model/part_library.h"
#include "gdpn/ide/orbit.h"
#include "gdpn/ide/replay.h"
#include "gdpn/ide/run_control.h"
#include "gdpn/capture/movie.h"
#include "gdpn/render/renderer.h"
#include "gdpn/script/syntax.h"

struct ImFont;

namespace gdpn::ide {

class WorldTexture;
class PictureTexture;
struct NetViewState;
struct PaletteState;

/// What the world view's last picture showed: when nothing of it changes, the picture is
/// shown again without drawing.
struct WorldKey {
  std::int64_t steps = -1;                 ///< the run's steps
  RunMode mode = RunMode::Edit;            ///< edit, running, paused
  std::uint64_t revision = 0;              ///< the document's scene revision
  core::Vec3 eye, target;                  ///< the camera, m
  double fov = 0;                          ///< degrees
  std::vector<scene::NodeHandle> selection;  ///< the highlighted nodes
  int width = 0, height = 0;               ///< pixels
  unsigned shown = 0;                      ///< the overlays and looks on (App::Show bits)
  const void* session = nullptr;           ///< the run drawn
  std::uint64_t edit_scene = 0;            ///< the palette's edit scene's generation (machines, ghost)
  friend bool operator==(const WorldKey& a, const WorldKey& b) {
    return a.steps == b.steps && a.mode == b.mode && a.revision == b.revision && a.edit_scene == b.edit_scene && a.eye.x == b.eye.x &&
           a.eye.y == b.eye.y && a.eye.z == b.eye.z && a.target.x == b.target.x && a.target.y == b.target.y &&
           a.target.z == b.target.z && a.fov == b.fov && a.selection == b.selection && a.width == b.width &&
           a.height == b.height && a.shown == b.shown && a.session == b.session;
  }
};

/// The script editor's completion list (views/script_editor.cpp) across frames: what the text
/// field's callback found and what the keys asked of it.
struct CompletionPopup {
  bool open = false;         ///< the list shows under the cursor
  int selected = 0;          ///< the chosen name's index
  CompletionQuery query;     ///< what may follow the cursor
  int cursor = 0;            ///< the cursor last frame, bytes
  bool accept = false;       ///< Tab or Enter while open: the chosen name goes in
  bool ask = false;          ///< Tab after a name or a dot: complete it
  bool typed = false;        ///< a name's character or a dot was typed this frame
  bool enter = false;        ///< Enter with the list closed, in a field where Enter applies (completingField)
  float text_x = 0, text_y = 0;  ///< where the field's text begins on screen, pixels
};

/// The contents view's script editor: the script open for typing, its text, and the syntax
/// problems found when scripts were last compiled (each kept until its script changes).
struct ScriptEditing {
  std::string key;     ///< the script being typed ("" when none): construct, kind and slot
  std::string buffer;  ///< its text as typed
  bool focus = false;  ///< the field takes the keyboard in the next frame
  std::map<std::string, script::SyntaxProblem> problems;  ///< by key
  ScriptScope scope;           ///< what the script being typed sees (made when it opens)
  CompletionPopup completion;  ///< the completion list
  std::uint64_t placed_revision = ~std::uint64_t{0};  ///< the document revision `placed` is of
  net::NetSpec placed;         ///< the document's net with its scripts on their file lines
  /// the run's last error at a line of the model file (0: none), kept while the document
  /// stays at `error_revision`, and its message's last line
  int error_line = 0;
  std::uint64_t error_revision = 0;  ///< the document revision the erring run was made from
  std::string error_message;         ///< the exception ("NameError: name 'x' is not defined")
};

/// What a left drag over the selected node does in the world view (edit mode).
enum class Tool : std::uint8_t {
  Select,  ///< nothing: the drag turns the view
  Move,    ///< handles along three axes move a Transform
  Turn,    ///< rings about three axes turn a Transform
  Scale,   ///< tabs on a box's faces and edges (a Cube, a box Region) change its size
  Aim,     ///< a spot light's direction and the size of its cone
};

/// A manipulator drag under way.
struct ManipulatorDrag {
  Handle handle = Handle::None;  ///< what is dragged (None: no drag)
  std::string path;              ///< the node
  std::string field;             ///< the field it edits
  core::Vec3 origin, axis, reference;  ///< the handle's point and axis (world), angles' zero
  core::Vec3 parent_axis;        ///< the axis in the node's parent's frame (moves, turns)
  core::Vec3 point;              ///< scale tabs: where the drag began; aims: a point of the drag's plane (world, m)
  core::Quat frame;              ///< scale tabs: the box's rotation; aims: its parent's (world)
  core::Vec3 scale{1, 1, 1};     ///< scale tabs: the scale of the box's parents
  ScaleTab tab{};                ///< scale tabs: which one
  double start = 0;              ///< where the drag began: along the axis (m) or the angle (deg)
  scene::FieldValue value;       ///< the field's value when the drag began
  std::uint64_t id = 0;          ///< its merge key: the drag is one step
};

/// The world view's own state: its camera, what it shows, the tools of its manipulators, and
/// what it drew last (views/world_view.cpp, views/manipulators.cpp, the mini view).
struct WorldViewState {
  OrbitCamera orbit;                ///< the free camera
  std::string camera_node;          ///< the scene Camera node in use ("" : the free camera)
  OrbitCamera shown;                ///< the camera the last frame drew with (the free one or a Camera node's)
  bool show_sensors = false;        ///< draws sensor volumes
  bool show_joints = false;         ///< draws joint axes
  bool show_contacts = false;       ///< marks the contact points of the last step
  bool show_shadows = true;         ///< the main light casts shadows
  bool show_grid = true;            ///< draws the ground grid
  bool show_mini = false;           ///< the mini view (the net over the world view) is open
  Tool tool = Tool::Move;           ///< the manipulator a drag uses
  bool snap = true;                 ///< manipulators move, turn and scale in steps
  double move_step = 0.05;          ///< a step of a move (and of a scale), m
  double turn_step = 5.0;           ///< a step of a turn, degrees
  bool local_axes = false;          ///< the move and turn handles follow the node's own axes
  ManipulatorDrag manipulating;     ///< the manipulator drag under way
  int level = 0;                    ///< how far the resolution is lowered while running (kWorldScales)
  double level_age = 0;             ///< wall seconds since `level` last changed
  std::vector<std::string> pressed_keys;  ///< keys delivered to the sensors (report)
  std::vector<std::string> clicked;       ///< the mouse sensors the last click counts for (report)
  std::array<bool, 512> key_was_down{};   ///< the keys last frame, by GLFW code
  core::Vec3 last_eye{1e300, 0, 0};       ///< the viewpoint last sent to the sensors, m
  std::unique_ptr<render::Renderer> renderer;  ///< draws the scene
  std::unique_ptr<WorldTexture> texture;       ///< where the scene is drawn
  WorldKey key;                                ///< what the picture shows
  render::DrawStats stats;                     ///< what drawing it took
};

/// The fields of the inscription language (views/inscription_field.cpp): the one being typed,
/// its completion list, and the texts typed that do not check, kept in their fields (the
/// model's text stays in force until the typed one checks).
struct InscriptionEditing {
  std::string key;                           ///< the field being typed ("" when none)
  std::map<std::string, std::string> typed;  ///< by field: a text typed and not applied
  CompletionPopup completion;                ///< the completion list of the field being typed
};

/// The colour sets view's own state (views/colour_sets.cpp).
struct ColourSetsState {
  bool shown = false;                           ///< it has the inspector's panel (its tab, View > Colour Sets)
  std::map<std::string, std::string> typed;     ///< a text being typed and not applied, by field ("definition 2", "new name")
  std::map<std::string, TextProblem> problems;  ///< why a row's text was not applied, by row ("set 2", "new set")
  std::string new_variable_set;                 ///< the colour set chosen for a new variable
};

/// The inspector's and the contents view's own state (views/inspector.cpp, contents_view.cpp).
struct InspectorState {
  int break_tokens = 1;             ///< the token count for a place's breakpoint
  std::string break_condition;      ///< the breakpoints' field: a Python condition being typed
  std::uint64_t drag_id = 0;        ///< the current drag of a field (merge key)
  std::string error;                ///< why the last edit was refused
  std::string datum_key;            ///< the name for a datum to add
  std::string datum_value;          ///< and its value, as text (datumFromText)
  std::string new_arc_slot;         ///< the arc inspector's field: a slot to add to the arc
  ScriptEditing scripts;            ///< the contents view's script editor
  InscriptionEditing inscriptions;  ///< the fields of value slots, arcs' inscriptions and conditions
  net::SlotId contents_slot = net::kDefaultSlot;  ///< the slot the contents view edits
  std::string amount_error;         ///< why the run refused the amount last set in the contents view (hybrid nets)
  std::string amount_error_of;      ///< the place it was set on
  std::int64_t amount_error_step = -1;  ///< the run's step count then (the refusal shows until the run moves on)
  std::string rate_text;            ///< a continuous transition's rate as being typed
  std::string rate_of;              ///< the transition (page/name) whose rate rate_text holds
  bool rate_active = false;         ///< the rate field had the keyboard last frame
  std::unique_ptr<PictureTexture> picture_texture;  ///< a camera sensor's picture
};

/// The toolbar's own state (views/toolbar.cpp).
struct ToolbarState {
  std::string fire_target;              ///< the chosen transition
  int run_n = 100;                      ///< N for Run N steps
  RunSpeed speed = RunSpeed::RealTime;  ///< the speed for Run
};

/// The tree view's own state (views/tree_view.cpp).
struct TreeViewState {
  std::string rename;               ///< the node's name being typed in its menu
  std::string import_files;         ///< the mesh files to import, typed in its menu
  bool reveal = false;              ///< opens and scrolls to the selection once
};

/// What the file browser chooses a file for.
enum class BrowseFor : std::uint8_t {
  Open,    ///< a model to open
  SaveAs,  ///< the name to save the model as
};

/// The IDE's own file browser (views/file_browser.cpp): a folder's subfolders and model files.
struct FileBrowser {
  bool open = false;                ///< shown
  BrowseFor mode = BrowseFor::Open; ///< what for
  std::string folder;               ///< the folder listed (absolute)
  std::string name;                 ///< the file name typed or clicked
  std::string error;                ///< why the last choice was refused
  std::string replacing;            ///< the existing file Save As was told about once (the next Save replaces it)
};

/// What "save changes?" was asked for: it is done once the question is answered.
enum class AfterQuestion : std::uint8_t {
  None,   ///< no question
  New,    ///< a new model
  Open,   ///< open `SaveQuestion::path`
  Close,  ///< close the model
  Quit,   ///< close the IDE
};

/// The answers to "save changes?".
enum class SaveAnswer : std::uint8_t {
  Save,      ///< save, then go on (a new model is saved through Save As first)
  DontSave,  ///< go on; the edits are lost
  Cancel,    ///< stay
};

/// The question "save changes?" under way.
struct SaveQuestion {
  AfterQuestion then = AfterQuestion::None;  ///< what waits for the answer
  std::string path;                          ///< the file to open, for Open
};

/// The I/O list's own state (views/io_list.cpp).
struct IoListState {
  bool shown = false;                          ///< the I/O list has the inspector's panel (its tab, View > I/O List)
  std::uint64_t revision = ~std::uint64_t{0};  ///< the document's revision `rows` were found at
  std::vector<IoListRow> rows;                 ///< every part's I/O and what uses it
  std::map<std::string, std::string> typed;    ///< an analogue value being typed, by IoListRow::key
};

/// The library's newer versions of the model's parts, and the popup that takes them
/// (views/part_updates.cpp).
struct PartUpdatesState {
  std::vector<model::PartUpdate> updates;  ///< the model's parts the library holds in a newer version
  std::uint64_t revision = ~std::uint64_t{0};  ///< the document's revision they were found at
  std::uint64_t scans = ~std::uint64_t{0};     ///< and the palette's scan
  bool open = false;                       ///< the popup is shown
  std::vector<model::PartUpdate> offered;  ///< what the popup lists, as found when it opened
  std::vector<std::string> uses;           ///< the io section's uses of the I/O they remove, located
  std::string error;                       ///< why the update was refused
};

/// "Save as Part": a scene node and its subtree written to the user's parts folder as a new
/// part (views/save_as_part.cpp).
struct SaveAsPartState {
  bool open = false;      ///< the popup is shown
  bool focus = false;     ///< the name field takes the keyboard in the next frame
  std::string node;       ///< the node saved (its path in the model's scene)
  std::string name;       ///< the part's name, as typed
  std::string group;      ///< its group in the palette, as typed
  std::string error;      ///< why the last Save wrote nothing
  std::string replacing;  ///< the existing file the user was told of: the next Save replaces it
};

/// Fonts the views use (null: ImGui's default).
struct Fonts {
  ImFont* regular = nullptr;  ///< DejaVu Sans
  ImFont* bold = nullptr;     ///< DejaVu Sans Bold: node tokens and sensors in the tree
};

/// The IDE: the document, its run, the views' own state, and what they showed last frame.
class App {
 public:
  /// An IDE over `doc`; the run is made from it with `options` (the platform's imager of
  /// camera sensors); compile errors go to the Diagnostics view.
  explicit App(std::unique_ptr<Document> doc, session::SessionOptions options = {});
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  /// Needs a current OpenGL 3.3 context: makes the renderer. `fonts` from loadFonts().
  void initGraphics(Fonts fonts);
  /// Draws one frame of every view into ImGui (between NewFrame and Render) for a window of
  /// `width` x `height` pixels, `wall_seconds` after the last; Run takes its steps first.
  void frame(float width, float height, double wall_seconds);
  /// Performs a replay action that needs no synthetic input (not Key, Click, Drag, Frames,
  /// Screenshot). False with `error` when it cannot be done.
  bool perform(const Action& action, std::string& error);
  /// What the views showed in the last frame (JSON: one object per view).
  [[nodiscard]] const nlohmann::json& report() const { return report_; }
  /// The document.
  [[nodiscard]] Document& document() { return *doc_; }
  /// The document, to read.
  [[nodiscard]] const Document& document() const { return *doc_; }
  /// The run.
  [[nodiscard]] RunControl& run() { return run_; }
  /// The run, to read.
  [[nodiscard]] const RunControl& run() const { return run_; }
  /// The splitters (loaded from and saved to the settings file by the platform).
  [[nodiscard]] Splitters& splitters() { return splitters_; }
  /// The splitters, to read.
  [[nodiscard]] const Splitters& splittersView() const { return splitters_; }

  // files: each asks "save changes?" first where unsaved edits would be lost
  /// A new, empty model in place of this one (saved through Save As).
  void newModel();
  /// Opens the model file `path` in place of this one; its errors go to the message line.
  void openModel(const std::string& path);
  /// Closes the model: a new, empty one takes its place.
  void closeModel();
  /// Closes the IDE (the platform ends at the end of the frame).
  void quit();
  /// True once the IDE should close.
  [[nodiscard]] bool quitRequested() const { return quit_requested_; }
  /// Answers the "save changes?" question under way.
  void answer(SaveAnswer answer);
  /// Opens the file browser to choose a file for `mode`, in the model's folder.
  void browse(BrowseFor mode);
  /// The window's title: the model's file name, marked "*" while it has unsaved edits.
  [[nodiscard]] std::string title() const;
  /// True for a model made by New that has no file of its own yet.
  [[nodiscard]] bool untitled() const { return untitled_; }
  /// The world and net views trade places.
  void swapViews() { splitters_.swapped = !splitters_.swapped; }
  /// `view` fills the window, or the panels come back when it does already.
  void fill(FullView view) { splitters_.full = splitters_.full == view ? FullView::None : view; }
  /// Opens the IDE's guide (docs/ide.md, installed or beside the sources) in the browser.
  void openGuide();

  // the views' shared state, read and written by the view files (views/*.cpp)
  /// The scene the world and tree views show: the run's plant once it has run, else the
  /// document's scene (with the part instances' machines placed in it, views/palette.cpp).
  [[nodiscard]] scene::Scene* shownScene() const;
  /// Selects `path` of the shown scene, and says so in the message line.
  void selectNode(const std::string& path);
  /// Selects what `name` names: a node path, else a place, transition or instance. False
  /// when nothing has that name.
  bool selectByName(const std::string& name);
  /// Points the world view's free camera at the selected node so that it fills the view (the
  /// whole scene when no node is selected).
  void frameSelection();
  /// Undo or redo through the document, then the world shows the result.
  void undo();
  void redo();
  /// Saves the model to its file (the message says how it went).
  void save();
  /// Deletes the selected node (refused, with where, when the net holds it: the tree's menu
  /// offers to take it out of the marking too), or what is selected on the net view's page (with
  /// the arcs of what goes), as one step; edit mode.
  void deleteSelection();
  /// Puts the selected node's subtree, or the net view's selected places and transitions with
  /// the arcs among them, on the clipboard as a model file holding them (Ctrl+C); false (with
  /// the reason in the status bar) when nothing it takes is selected, or an instance is.
  bool copySelection();
  /// Pastes the clipboard's scene nodes (a model file's) under the selected node, or beside it
  /// when it takes no children, or at the top; names taken there get a number (Ctrl+V).
  void paste();
  /// Imports the mesh files named in `files` (separated by ';' or new lines; a relative name is
  /// looked for beside the model, then in the current folder) through the mesh importers, each
  /// a Group of Materials and Meshes, under the selected node (beside it, or at the top): one
  /// step for all of them.
  void importMeshes(const std::string& files);
  /// Saves the model as `path`, which it is from then on (the message says how it went).
  void saveAs(const std::string& path);
  /// Puts the newer autosave offered at the start in place of the model (one undoable step).
  void restoreAutosave();
  /// Declines the autosave offered at the start and removes it.
  void discardAutosave();
  /// Reset of the run (errors to the Diagnostics view).
  void reset();
  /// The node types propagated through the edited net and what they flag (token_types.h), found
  /// again when the document changed.
  [[nodiscard]] const TokenTypes& tokenTypes();
  /// The net view's page, layout and viewport (views/net_view.cpp).
  [[nodiscard]] NetViewState& netView() { return *net_view_; }
  /// The net view's state, to read.
  [[nodiscard]] const NetViewState& netView() const { return *net_view_; }
  /// The parts palette's state and the edit scene with the parts' machines (views/palette.cpp).
  [[nodiscard]] PaletteState& palette() { return *palette_; }
  /// The same, to read.
  [[nodiscard]] const PaletteState& palette() const { return *palette_; }
  /// The compile errors of the run, if it failed to build.
  [[nodiscard]] const core::Diagnostics& runDiagnostics() const { return run_.buildDiagnostics(); }

  Fonts fonts;                      ///< the fonts
  WorldViewState world;             ///< the world view's (and its manipulators' and mini view's) own state
  InspectorState inspector;         ///< the inspector's and the contents view's own state
  ToolbarState toolbar;             ///< the toolbar's own state
  TreeViewState tree;               ///< the tree view's own state
  IoListState io_list;              ///< the I/O list's own state
  ColourSetsState colour_sets;      ///< the colour sets view's own state
  PartUpdatesState part_updates;    ///< the library's newer versions of the model's parts
  SaveAsPartState save_part;        ///< "Save as Part"
  double edit_quiet = 0;            ///< seconds since the document last changed (edit mode)
  std::uint64_t quiet_revision = 0; ///< the revision edit_quiet counts from
  std::uint64_t followed_revision = 0;  ///< the revision the run last tried to follow
  double autosave_seconds = 60;     ///< how long unsaved edits wait before they are autosaved, s (0: never)
  double autosave_clock = 0;        ///< seconds the edits not yet autosaved have waited
  std::uint64_t autosaved_revision = 0;  ///< the document's revision last autosaved
  bool restore_offered = false;     ///< the start found a newer autosave: the IDE asks what to do
  FileBrowser browser;              ///< the file browser (Open, Save As)
  SaveQuestion question;            ///< "save changes?" under way
  std::vector<std::string> recent;  ///< model files opened, the latest first (the settings file keeps them)
  bool keys_open = false;           ///< Help's list of the actions and their keys is shown
  std::string message;              ///< the status bar's message line
  std::string copied;               ///< what the last copy put on the clipboard (a model file)
  double fps = 0;                   ///< frames per second, smoothed
  /// The share of its pixels (per side) the world view is drawn at: 1 unless busy (running),
  /// where a frame rate under 30 fps lowers it in steps to 0.5 and one over 45 raises it again.
  /// Edits never lower it.
  [[nodiscard]] double worldScale() const;
  /// True while the model runs (not while the user edits with nothing running): the world view
  /// may be drawn at a lower resolution to keep the frame rate.
  [[nodiscard]] bool busy() const;
  bool screenshot_requested = false;  ///< the toolbar asked for a picture of the next frame
  int screenshots = 0;              ///< pictures taken so far (their names count up)
  std::unique_ptr<capture::MovieWriter> movie;  ///< the movie being filmed (null when none)
  std::string movie_path;           ///< its file
  int movies = 0;                   ///< movies started so far (their names count up)
  /// Starts filming the window (its size taken at the next frame) or finishes the movie.
  void toggleMovie();
  /// Adds the frame just drawn (`width` x `height` pixels, RGB, top row first) to the movie;
  /// an odd last row or column is left out (H.264 wants even sizes).
  void filmFrame(int width, int height, const std::vector<std::uint8_t>& rgb);

 private:
  void checkReload();
  void checkAutosave(double wall_seconds);
  // pastes `fragment`'s top nodes under the selection (beside it, or at the top) as one step and
  // selects the first; "" or why not, the first node's path into `made`
  std::string pasteScene(std::shared_ptr<const scene::Scene> fragment, std::string& made);
  void followEdits(double wall_seconds);
  void drawRestoreOffer(nlohmann::json& report);
  // does what the question waited for (no question asked)
  void proceed(AfterQuestion then, const std::string& path);
  // true when `then` must wait for "save changes?" (asked now)
  bool askFirst(AfterQuestion then, const std::string& path);
  // puts `doc` in place of the document: a new run, the views' state of the old model dropped
  void replaceDocument(std::unique_ptr<Document> doc, bool untitled);
  std::unique_ptr<Document> doc_;
  session::SessionOptions options_;  // how each run is made
  bool untitled_ = false;
  bool quit_requested_ = false;
  std::unique_ptr<NetViewState> net_view_;
  std::unique_ptr<PaletteState> palette_;
  TokenTypes token_types_;
  std::uint64_t token_types_revision_ = ~std::uint64_t{0};
  RunControl run_;
  Splitters splitters_;
  nlohmann::json report_;
  std::uint64_t frames_ = 0;  // frames drawn
};

/// Loads DejaVu Sans (regular and bold) into ImGui's font atlas; the defaults when missing.
Fonts loadFonts();

}  // namespace gdpn::ide
