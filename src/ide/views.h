#pragma once
// The views, each a function of the App (the document and the run) that draws into the
// rectangle it is given, pushes commands, and writes what it showed into `report`.

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "gdpn/ide/actions.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app.h"
#include "gdpn/ide/part_edit.h"
#include "gdpn/ide/layout.h"

namespace gdpn::ide {

/// The drag-and-drop payload of a scene node dragged from the tree view: its path.
inline constexpr const char* kNodePayload = "GDPN_NODE";

/// The menus (File, Edit, View, Run, Help), then Run, Pause, Step, Run N, Fire, Plant only,
/// Reset, Save, Undo, Redo: every button an action of the table (gdpn/ide/actions.h).
void drawToolbar(App& app, const Rect& at, nlohmann::json& report, nlohmann::json& menu_report);
/// The menus at the toolbar's start, each listing its actions of the table with their keys,
/// check marks and whether they can be done now; File's Open Recent lists App::recent.
void drawMenus(App& app, nlohmann::json& report);
/// Help's list of every action with its key and what it does, while App::keys_open.
void drawKeys(App& app, nlohmann::json& report);
/// The file browser, while App::browser.open: the folder's subfolders and model files, a name
/// field, and Open or Save.
void drawFileBrowser(App& app, nlohmann::json& report);
/// "Save changes?" while App::question waits: Save, Don't Save, Cancel.
void drawSaveQuestion(App& app, nlohmann::json& report);
/// The scene tree (node tokens and sensors in bold, colours by category) and the net's
/// places and transitions.
void drawTreeView(App& app, const Rect& at, nlohmann::json& report);
/// The plant in 3D: orbit, pan, zoom, pick, standard views, the scene's cameras, live input.
void drawWorldView(App& app, const Rect& at, nlohmann::json& report);
/// The net of the page or instance chosen, with the run's marking: zoom, pan, fit, pick, go
/// into an instance.
void drawNetView(App& app, const Rect& at, nlohmann::json& report);
/// The selected place's 8 x 4 slot grid (kinds, tokens, names) or transition's duration, and
/// the construct's scripts, highlighted; read-only. Drawn inside the inspector.
void drawContents(App& app, const Selection& sel, nlohmann::json& report);
/// What the inspector shows when nothing is selected: the model's globals script, editable in
/// edit mode.
void drawModelContents(App& app, nlohmann::json& report);
/// The manipulators of the selected node over the world view's picture (at `at`, `w` x `h`
/// pixels, seen by `view`), in edit mode; a press on a handle (the world view's button was just
/// pressed) starts a drag that edits the node's field. True while a drag takes the mouse.
bool drawManipulators(App& app, scene::Scene& scene, const OrbitCamera& view, ImVec2 at, float w, float h,
                      nlohmann::json& report);
/// The mini view: the net view's page, fitted, in a small movable window over the world view
/// (`world`), when App::show_mini; a click selects as in the net view.
void drawMiniView(App& app, const Rect& world, nlohmann::json& report);
/// The selected node's fields, edited through commands; a place's or transition's state.
void drawInspector(App& app, const Rect& at, nlohmann::json& report);
/// The inspector's part for a selected arc: kind, weights by slot, predicates and conditions,
/// reverse and delete.
void arcInspector(App& app, const Selection& sel, nlohmann::json& report);
/// The tabs over the inspector's panel, Inspector and I/O (App::io_list.shown), where its
/// heading would be; returns the rectangle below them, for the chosen view.
Rect drawInspectorTabs(App& app, const Rect& at, nlohmann::json& report);
/// Every part's inputs and outputs: direction, signal, unit, the value in the run (a lamp for
/// a bit), forces and releases, the `io` section's addresses, what uses each; Map for PLC.
void drawIoList(App& app, const Rect& at, nlohmann::json& report);
/// The model's colour sets and variables, while App::colour_sets.shown: each set's name and
/// definition (the model file's text) and how many values it has, each editable (Enter or
/// leaving the field applies it; a mistake is shown under it, with its column, and not
/// applied); a row that declares a new one; delete, refused while something uses it.
void drawColourSets(App& app, const Rect& at, nlohmann::json& report);
/// A text of the inscription language edited in place (a value slot's values, an arc's
/// inscription, a transition's condition): typed with completion of variables, colour sets,
/// constants and the language's words; checked as it is typed against the model's sets and
/// variables (`set`: the slot's colour set by name; ignored for a condition), its first mistake
/// shown under it with the column; applied through `store` on Enter or when left, and only when
/// it checks (else the typed text stays in the field, marked, and the model's text stays in
/// force). An empty text is applied as none. Its state goes into `report["inscriptions"][label]`,
/// its centre into `report["fields"][label]`.
void inscriptionField(App& app, const std::string& key, const std::string& label, const std::string& current,
                      const std::string& set, InscriptionRole role, const std::function<void(const std::string&)>& store,
                      nlohmann::json& report);
/// The most distinct values a place's marking shows in the inspector before "... and K more
/// values" (the net view's tooltip shows kTooltipValues).
inline constexpr std::size_t kShownValues = 40;
/// The most a tooltip shows.
inline constexpr std::size_t kTooltipValues = 8;
/// The most enabled bindings the inspector lists.
inline constexpr std::size_t kShownBindings = 30;
/// In the inspector, for place `p` of the run: the values on each of its value slots, as the
/// language writes a multiset (`2'(1,"a") ++ 1'(2,"b")`), wrapped, the first kShownValues.
void placeValues(const session::Session& session, net::PlaceId p, nlohmann::json& report);
/// In the inspector, for coloured transition `t` (named `name`) of the run: the binding of its
/// current occurrence, and the bindings enabled now, each a button that fires the transition
/// in it.
void transitionBindings(App& app, const session::Session& session, net::TransitionId t, const std::string& name,
                        nlohmann::json& report);
/// The values of place `p`'s value slots for a tooltip, one line a slot ("" when it has none).
std::string valuesTooltip(const session::Session& session, net::PlaceId p);
/// Every error and warning at file:line:col; a click selects the construct.
void drawDiagnostics(App& app, const Rect& at, nlohmann::json& report, nlohmann::json& breakpoints);
/// The run's breakpoints (each with a button that removes it) and a field that adds one on a
/// Python condition; drawn under the diagnostics.
void drawBreakpoints(App& app, nlohmann::json& report);
/// The drag-and-drop payload of a part dragged from the palette: its name.
inline constexpr const char* kPartPayload = "GDPN_PART";

/// The Parts palette: the library's parts (scanned along model::partSearchPath of the model's
/// folder when a model is opened), grouped, each with its picture and name, a search field;
/// a part dragged from it is dropped in the world view.
void drawPalette(App& app, const Rect& at, nlohmann::json& report);
/// Scans the library (model::scanParts along model::partSearchPath of the model's folder) for
/// the palette once per model file opened, and again after Rescan (PaletteState::scanned_for
/// reset).
void scanLibrary(App& app);
/// Once a frame before the views draw: the parts of the model the library holds in a newer
/// version (model::partUpdates), found again when the document changed or the library was
/// scanned again (scanned first when the model uses parts).
void refreshPartUpdates(App& app);
/// Opens the popup that lists the newer versions found (App::part_updates) and takes them.
void openPartUpdates(App& app);
/// In the palette, under its search: "1 part has a newer version" and Update..., when the
/// library holds one; its button goes into `report["update"]`.
void drawPartUpdateNotice(App& app, nlohmann::json& report);
/// The popup "Update Parts": per part its versions, the I/O and parameters it adds, removes and
/// changes, the io section's uses of removed I/O; Update (one step of undo) or Cancel.
void drawPartUpdates(App& app, nlohmann::json& report);
/// Opens "Save as Part" for the selected scene node (App::save_part).
void openSaveAsPart(App& app);
/// The popup "Save as Part": the part's name and group, Save (the part file written to the
/// user's parts folder, the palette scanned again) or Cancel; why nothing was written in red.
void drawSaveAsPart(App& app, nlohmann::json& report);
/// After a drop of a part with a control pattern: "Add its control pattern?" at the drop point
/// (Yes, the default on Enter; No, or Escape); its buttons go into `report["offer"]`.
void drawDropOffer(App& app, nlohmann::json& report);
/// Once a frame before the views draw (edit mode): the run follows an edit of the part instances
/// at once, and the edit scene (the document's scene with the parts' machines) is made again
/// when the document or the run changed; none is needed when the model places no machine.
void refreshEditScene(App& app);
/// What a ghost scene the world view draws while a part is dragged over it.
struct PaletteGhost {
  scene::Scene* scene = nullptr;             ///< the edit scene with the ghost (null: no drag)
  std::vector<scene::NodeHandle> selection;  ///< the ghost, outlined
};
/// Before the world view draws: where a part dragged over the picture (at `at`, `w` x `h`
/// pixels, seen by `view`) would land, and the scene with its ghost there.
PaletteGhost paletteGhost(App& app, const OrbitCamera& view, ImVec2 at, float w, float h);
/// After the world view's button: a part dropped on it is placed (one step of undo), selected,
/// and offered its control; the footprint where it would land is drawn; the part instances'
/// points go into `report`, for replays to drop at: `parts/NAME/center` (its top's middle),
/// `top -x` and `top +x` (its top a quarter from each end), `+x`, `-x`, `+y`, `-y` (0.1 m
/// beyond the middle of each side, on its floor).
void paletteDrop(App& app, const OrbitCamera& view, ImVec2 at, float w, float h, nlohmann::json& report);
/// The Transform holding a part instance's machine that `path` lies in (the part is one node to
/// the views), else `path`.
[[nodiscard]] std::string partPathOf(const App& app, const std::string& path);
/// The part instance whose machine the shown scene (the edit scene, or the run's plant) holds
/// at `path` (its Transform: a top-level node named after the instance), if any.
[[nodiscard]] std::optional<PartInstanceAt> partAtPath(const App& app, const std::string& path);
/// The command a manipulator's drag of `field` of node `path` makes: a part instance's
/// placement (translation, rotation) for a part's Transform, else a SetFieldCommand.
[[nodiscard]] std::unique_ptr<Command> manipulatorCommand(const App& app, const std::string& path,
                                                          const std::string& field, const scene::FieldValue& value,
                                                          std::uint64_t merge);
/// The inspector of part instance `at`: its version, its parameters (each edit one step), its
/// I/O and its control ("Add its control" when it has a pattern and nothing controls it yet).
void drawPartInspector(App& app, const PartInstanceAt& at, nlohmann::json& report);

/// Model time, steps, real-time factor, frames per second, the message.
void drawStatusBar(App& app, const Rect& at, nlohmann::json& report);

/// Begins a borderless child window filling `at` (in window pixels) with a heading; the view
/// draws inside and then calls endPanel().
void beginPanel(const char* id, const Rect& at, const char* heading);
/// Ends a panel begun by beginPanel().
void endPanel();

/// Notes the centre of the last item drawn, in window pixels, in `positions` under `label` (so
/// that replay files and tests can click it).
void noteItem(const std::string& label, nlohmann::json& positions);

/// ImGui::BeginMenu(`label`), its centre noted in `positions` as noteItem() does (taken
/// before the submenu opens: after, the last item is the submenu's).
bool beginMenu(const char* label, nlohmann::json& positions);

/// A menu item `label`; its centre, in window pixels, goes into `positions` under its label (so
/// that replay files and tests can click it). True when chosen.
bool menuItem(const char* label, nlohmann::json& positions);

/// Menu items for the actions `ids` that can be done now, from the table of actions (label,
/// key, help), each noted in `positions`; a chosen one is performed.
void actionItems(App& app, std::initializer_list<ActionId> ids, nlohmann::json& positions);

}  // namespace gdpn::ide
