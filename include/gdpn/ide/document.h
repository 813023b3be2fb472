#pragma once
/// \file
/// The document the IDE edits: the model (its scene and net spec), the selection shared by
/// every view, and the undo stack. No ImGui, no OpenGL: testable without a window. Running
/// never changes it; a run is made from a snapshot (run_control.h).

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "gdpn/core/diagnostics.h"
#include "gdpn/ide/command.h"
#include "gdpn/ide/selection.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {

/// A model being edited.
class Document {
 public:
  /// The model file at `path`; null with the located diagnostics when it cannot be read.
  static std::unique_ptr<Document> open(const std::string& path, core::Diagnostics& diags);
  /// A new model to be saved at `path`: one empty page `main` and an empty scene.
  static std::unique_ptr<Document> create(const std::string& path);
  /// A document over `model` (already loaded).
  explicit Document(model::Model model);

  /// The model as edited.
  [[nodiscard]] const model::Model& model() const { return model_; }
  /// The net, for the commands that edit it (net_edit.h); everything else reads model().net.
  [[nodiscard]] net::NetSpec& editableNet() { return model_.net; }
  /// The whole model, for the commands that edit more than the net and the scene (a part
  /// placed from the palette brings page types, their scenes and part sections: part_edit.h).
  [[nodiscard]] model::Model& editableModel() { return model_; }
  /// The `io` section, for the command that maps a part's I/O (io_list.h).
  [[nodiscard]] model::IoSpec& editableIo() { return model_.io; }
  /// Puts `scene` in place of the model's scene (for the commands that edit the tree,
  /// scene_edit.h); returns the one it replaces.
  std::shared_ptr<scene::Scene> swapScene(std::shared_ptr<scene::Scene> scene);
  /// The editable scene (null when the model has none).
  [[nodiscard]] scene::Scene* scene() const { return scene_.get(); }
  /// The model with a scene of its own, for a run: nothing the run does reaches the document.
  /// Its scripts stand on the lines that text() gives them (script_places.h), so that a
  /// script's error is reported at the line it has in the file as saved.
  [[nodiscard]] model::Model snapshot() const;
  /// What saving writes: the model over the text of its file as last read or saved, which keeps
  /// the comments, key order and layout of all that the edits did not change
  /// (model::writeModelOver); the canonical text for a new model.
  [[nodiscard]] std::string text() const { return model::writeModelOver(model_, source_); }
  /// The text of the model's file as last read or saved ("" for a new model).
  [[nodiscard]] const std::string& source() const { return source_; }
  /// How many numbered backups of a model file saving keeps.
  static constexpr std::size_t kBackups = 5;
  /// Writes the model to its file (or `path`), atomically; a file there is first kept as
  /// `NAME.~N~` (N counting up; the newest kBackups kept). False with a diagnostic when it could
  /// not.
  bool save(core::Diagnostics& diags, const std::string& path = {});
  /// Save As: writes the model to `path` as save() does, and from then on the document is
  /// that file (relative script and mesh files are read from its folder). False with a
  /// diagnostic when it could not.
  bool saveAs(const std::string& path, core::Diagnostics& diags);
  /// True when there are edits since the model was read or last saved.
  [[nodiscard]] bool modified() const { return revision_ != saved_revision_; }

  /// The file autosave() writes: in the user's state folder ($XDG_STATE_HOME, else
  /// ~/.local/state) under gdpn/autosave/, named for the model file and a hash of its
  /// absolute path, never beside the model.
  [[nodiscard]] std::string autosavePath() const;
  /// Writes the model as saving would, but to autosavePath() (atomically). False with a
  /// diagnostic when it could not.
  bool autosave(core::Diagnostics& diags);
  /// True when an autosave of this model is newer than its file and holds something else:
  /// the edits of a session that ended without saving them.
  [[nodiscard]] bool autosavePending() const;
  /// Puts the autosave's model in place of the document's, as one step that can be undone;
  /// "" or why not (the autosave has errors: they go to diagnostics()).
  std::string restoreAutosave();
  /// Removes the autosave (saving does this too).
  void discardAutosave() const;

  /// The current selection: the one thing the inspector shows (of several, the last one added).
  [[nodiscard]] const Selection& selection() const { return selection_; }
  /// Selects `selection` alone (every view follows).
  void select(Selection selection) {
    selection_ = std::move(selection);
    also_.clear();
  }
  /// What is selected beside the current selection (read every frame: no copy).
  [[nodiscard]] const std::vector<Selection>& alsoSelected() const { return also_; }
  /// Everything selected, the current selection last; empty when nothing is.
  [[nodiscard]] std::vector<Selection> selections() const;
  /// How many things are selected.
  [[nodiscard]] std::size_t selectedCount() const { return selection_.any() ? also_.size() + 1 : 0; }
  /// Selects every one of `all` (the last becomes the current one; None entries and repeats
  /// are left out).
  void selectAll(const std::vector<Selection>& all);
  /// Adds `one` to the selection, as the current one, or takes it out when it is selected
  /// (Shift- or Ctrl-click).
  void toggleSelected(const Selection& one);
  /// True when `one` is selected (the current selection or beside it).
  [[nodiscard]] bool isSelected(const Selection& one) const;

  /// Applies `command` and keeps it for undo; "" or why it was refused.
  std::string execute(std::unique_ptr<Command> command);
  /// Undoes the last step; false when there is none.
  bool undo() { return undo_.undo(*this); }
  /// Redoes the last undone step; false when there is none.
  bool redo() { return undo_.redo(*this); }
  /// The undo stack.
  [[nodiscard]] UndoStack& history() { return undo_; }
  /// The undo stack, to read.
  [[nodiscard]] const UndoStack& history() const { return undo_; }

  /// Counts changes: it grows with every applied, undone or redone command and reload.
  [[nodiscard]] std::uint64_t revision() const { return revision_; }
  /// Counts the changes to the scene alone (the world view draws again when it grows).
  [[nodiscard]] std::uint64_t sceneRevision() const { return scene_revision_; }
  /// Commands call this after each change they make; `scene`: the scene may have changed.
  void touched(bool scene = true) {
    ++revision_;
    if (scene) ++scene_revision_;
  }

  /// The problems found when the model was last read or checked (every one located).
  [[nodiscard]] const core::Diagnostics& diagnostics() const { return diagnostics_; }
  /// Replaces the diagnostics shown (a compile of the model adds its own).
  void setDiagnostics(core::Diagnostics diags) { diagnostics_ = std::move(diags); }
  /// True when the model file changed on disk since it was read.
  [[nodiscard]] bool changedOnDisk() const;
  /// True when a Python file in the model's folder changed, appeared or went since the last
  /// call (or since the model was read): its scripts should be read again (a run's reset
  /// does). The first call after opening answers false.
  bool scriptsChanged();
  /// Reads the model file again. On success the model is replaced, the history cleared and the
  /// selection kept when it still names something; on error the old model stays and the
  /// diagnostics say why. False on error.
  bool reload();

 private:
  void adopt(model::Model model);
  /// Writes `text` to `to` atomically, the file there first kept as a backup.
  bool writeFile(const std::string& to, const std::string& text, core::Diagnostics& diags);
  friend class ReplaceModelCommand;
  /// Puts `model`'s content (not its path) in place of the document's; returns the old content.
  model::Model exchange(model::Model model);
  model::Model model_;
  std::string source_;  // the file's text as last read or saved: saving keeps its layout
  std::shared_ptr<scene::Scene> scene_;  // the same object as model_.scene, editable
  Selection selection_;
  std::vector<Selection> also_;  // selected beside selection_ (only while it is something)
  UndoStack undo_;
  std::uint64_t revision_ = 0;
  std::uint64_t saved_revision_ = 0;  // the revision last read or saved
  std::uint64_t scene_revision_ = 0;  // changes to the scene
  core::Diagnostics diagnostics_;
  std::optional<std::filesystem::file_time_type> stamp_;  // the file's time when read
  std::map<std::string, std::filesystem::file_time_type> script_stamps_;  // *.py beside the model
  [[nodiscard]] std::map<std::string, std::filesystem::file_time_type> scriptStamps() const;
};

}  // namespace gdpn::ide
