#include "ossa/editor/undo_stack.h"

#include <utility>

#include "ossa/assert.h"

namespace ossa {

namespace {
int index_of(EditorDocument d) { return static_cast<int>(d); }
}  // namespace

UndoStack::UndoStack() {
  for (int i = 0; i < kEditorDocumentCount; ++i) state_[i] = saved_[i] = new_state_id();
}

void UndoStack::push(Command command, bool already_applied) {
  OSSA_ASSERT(command.redo && command.undo, "a command needs redo and undo");
  if (!already_applied) command.redo();
  if (group_depth_ > 0) {
    group_.commands.push_back(std::move(command));
    return;
  }
  Step step;
  step.label = command.label;
  step.document = command.document;
  step.commands.push_back(std::move(command));
  commit_step(std::move(step));
}

void UndoStack::commit_step(Step step) {
  // A new edit drops the redo tail (the usual linear history).
  steps_.resize(cursor_);
  const int d = index_of(step.document);
  step.state_before = state_[d];
  step.state_after = new_state_id();
  state_[d] = step.state_after;
  steps_.push_back(std::move(step));
  cursor_ = static_cast<int>(steps_.size());
}

void UndoStack::begin_group(const std::string& label, EditorDocument document) {
  if (group_depth_++ == 0) {
    group_ = Step{};
    group_.label = label;
    group_.document = document;
  }
}

void UndoStack::end_group() {
  OSSA_ASSERT(group_depth_ > 0, "end_group without begin_group");
  if (--group_depth_ > 0) return;
  if (group_.commands.empty()) return;  // nothing changed: no step
  commit_step(std::move(group_));
  group_ = Step{};
}

bool UndoStack::undo() {
  if (!can_undo() || group_depth_ > 0) return false;
  Step& step = steps_[--cursor_];
  for (auto it = step.commands.rbegin(); it != step.commands.rend(); ++it) it->undo();
  state_[index_of(step.document)] = step.state_before;
  return true;
}

bool UndoStack::redo() {
  if (!can_redo() || group_depth_ > 0) return false;
  Step& step = steps_[cursor_++];
  for (auto& c : step.commands) c.redo();
  state_[index_of(step.document)] = step.state_after;
  return true;
}

std::string UndoStack::undo_label() const { return can_undo() ? steps_[cursor_ - 1].label : ""; }
std::string UndoStack::redo_label() const { return can_redo() ? steps_[cursor_].label : ""; }

void UndoStack::mark_saved(EditorDocument document) {
  saved_[index_of(document)] = state_[index_of(document)];
}

bool UndoStack::is_dirty(EditorDocument document) const {
  return state_[index_of(document)] != saved_[index_of(document)];
}

bool UndoStack::any_dirty() const {
  for (int i = 0; i < kEditorDocumentCount; ++i)
    if (state_[i] != saved_[i]) return true;
  return false;
}

void UndoStack::clear(EditorDocument document) {
  std::vector<Step> kept;
  int cursor = 0;
  for (int i = 0; i < static_cast<int>(steps_.size()); ++i) {
    if (steps_[i].document == document) continue;
    if (i < cursor_) ++cursor;
    kept.push_back(std::move(steps_[i]));
  }
  steps_ = std::move(kept);
  cursor_ = cursor;
  const int d = index_of(document);
  state_[d] = saved_[d] = new_state_id();
}

void UndoStack::clear() {
  steps_.clear();
  cursor_ = 0;
  for (int i = 0; i < kEditorDocumentCount; ++i) state_[i] = saved_[i] = new_state_id();
}

}  // namespace ossa
