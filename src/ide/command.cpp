// The undo stack: applied commands, merged while their keys agree, and the redo list.

#include "gdpn/ide/command.h"

#include "gdpn/ide/document.h"

namespace gdpn::ide {

std::string UndoStack::push(std::unique_ptr<Command> command, Document& doc) {
  auto before = doc.selections();
  if (auto why = command->apply(doc); !why.empty()) return why;
  doc.touched(command->changesScene());
  undone_.clear();
  // a drag: the new edit joins the step it continues
  const auto key = command->mergeKey();
  if (!sealed_ && key != 0 && !done_.empty() && done_.back().command->mergeKey() == key) {
    done_.back().command->absorb(*command);
    return {};
  }
  done_.push_back({std::move(command), std::move(before), {}});
  sealed_ = false;
  return {};
}

namespace {

/// Selects what of `selection` still names something in `doc`.
void selectIfThere(Document& doc, std::vector<Selection> selection) { doc.selectAll(stillNamed(doc, std::move(selection))); }

}  // namespace

bool UndoStack::undo(Document& doc) {
  if (done_.empty()) return false;
  auto& step = done_.back();
  step.after = doc.selections();
  step.command->revert(doc);
  doc.touched(step.command->changesScene());
  // what was selected before the step (a pasted node is gone again)
  selectIfThere(doc, step.before);
  undone_.push_back(std::move(step));
  done_.pop_back();
  sealed_ = true;
  return true;
}

bool UndoStack::redo(Document& doc) {
  if (undone_.empty()) return false;
  auto& step = undone_.back();
  // a command that applied once applies again on the state it was undone to
  (void)step.command->apply(doc);
  doc.touched(step.command->changesScene());
  selectIfThere(doc, step.after);
  done_.push_back(std::move(step));
  undone_.pop_back();
  sealed_ = true;
  return true;
}

void UndoStack::clear() {
  done_.clear();
  undone_.clear();
  sealed_ = true;
}

}  // namespace gdpn::ide
