#pragma once
/// \file
/// Commands and the undo stack: every change to the document is a Command with apply and
/// revert, and a merge key so that a slider's drag becomes one step.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/ide/selection.h"

namespace gdpn::ide {

class Document;

/// One undoable change to a document.
class Command {
 public:
  virtual ~Command() = default;
  /// Makes the change. "" when done, else why not (the document is then unchanged).
  virtual std::string apply(Document& doc) = 0;
  /// Undoes a change apply() made.
  virtual void revert(Document& doc) = 0;
  /// What it does, for menus and messages ("set arm/turn.vel1").
  [[nodiscard]] virtual std::string label() const = 0;
  /// Commands with the same non-zero key that follow one another become one step (0: never).
  [[nodiscard]] virtual std::uint64_t mergeKey() const { return 0; }
  /// Takes in `next` (already applied, same merge key) so that reverting this one undoes both.
  virtual void absorb(const Command& next) = 0;
  /// False for a command that leaves the scene as it is (the world view need not be drawn again).
  [[nodiscard]] virtual bool changesScene() const { return true; }
};

/// Done and undone commands, each with the selection before it: undo selects again what was
/// selected before the step, redo what was selected when it was undone, each only what still
/// names something, so that no view shows a thing the step took away.
class UndoStack {
 public:
  /// Applies `command` to `doc`; on success it goes on the stack (merged into the top when
  /// their merge keys agree) and the redo list is cleared. "" or why it was refused.
  std::string push(std::unique_ptr<Command> command, Document& doc);
  /// Reverts the last command and selects what was selected before it; false when there is none.
  bool undo(Document& doc);
  /// Applies the last undone command again and selects what was selected when it was undone;
  /// false when there is none.
  bool redo(Document& doc);
  /// Ends merging: the next command starts a new step even with the same key (a drag ended).
  void seal() { sealed_ = true; }
  /// True when there is something to undo.
  [[nodiscard]] bool canUndo() const { return !done_.empty(); }
  /// True when there is something to redo.
  [[nodiscard]] bool canRedo() const { return !undone_.empty(); }
  /// Steps that can be undone.
  [[nodiscard]] std::size_t depth() const { return done_.size(); }
  /// The label of the step undo() would revert ("" when none).
  [[nodiscard]] std::string undoLabel() const { return done_.empty() ? std::string() : done_.back().command->label(); }
  /// Forgets everything (a reload).
  void clear();

 private:
  /// A command and the selections around it.
  struct Step {
    std::unique_ptr<Command> command;
    std::vector<Selection> before;  ///< selected when it was first applied
    std::vector<Selection> after;   ///< selected when it was last undone
  };
  std::vector<Step> done_;
  std::vector<Step> undone_;
  bool sealed_ = true;
};

}  // namespace gdpn::ide
