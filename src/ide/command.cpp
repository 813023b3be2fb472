// The undo stack: applied commands, merged while their keys agree, and the redo list.

#include "gdpn/ide/command.h"

#include "gdpn/ide/document.h"

namespace gdpn::ide {

std::string UndoStack::push(std::unique_ptr<Command> command, Document& doc) {
  if (auto why = command->apply(doc); !why.empty()) return why;
  doc.touched(command->changesScene());
  undone_.clear();
  // a drag: the new edit joins the step it continues
  const auto key = command->mergeKey();
  if (!sealed_ && key != 0 && !done_.empty() && done_.back()->mergeKey() == key) {
    done_.back()->absorb(*command);
    return {};
  }
  done_.push_back(std::move(command));
  sealed_ = false;
  return {};
}

bool UndoStack::undo(Document& doc) {
  if (done_.empty()) return false;
  done_.back()->revert(doc);
  doc.touched(done_.back()->changesScene());
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  sealed_ = true;
  return true;
}

bool UndoStack::redo(Document& doc) {
  if (undone_.empty()) return false;
  // a command that applied once applies again on the state it was undone to
  (void)undone_.back()->apply(doc);
  doc.touched(undone_.back()->changesScene());
  done_.push_back(std::move(undone_.back()));
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
