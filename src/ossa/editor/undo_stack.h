#pragma once
// UndoStack — the one undo history shared by every editor (DESIGN.md §10): Ctrl+Z undoes,
// Ctrl+Y redoes, one mouse drag is one step, and each document (level, prototypes, genome,
// tuning) knows exactly whether it differs from its last save.
//
// A Command is a pair of closures (redo = do, undo) plus the document it changes. Models
// apply an edit live while the mouse drags and push one command with `already_applied` when
// the drag ends, so the whole drag is a single step. begin_group / end_group merge any
// commands pushed in between into one step as well (e.g. "add key" to walk and run).
//
// Unsaved-change markers: every executed command gives its document a fresh state id and
// remembers the id it replaced; undo restores that id. mark_saved(doc) records the current
// id, so is_dirty(doc) is exact — undoing back to the saved state is clean again, and
// undoing past it, or editing after an undo, is dirty.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ossa {

enum class EditorDocument : int { kLevel, kPrototypes, kGenome, kTuning, kRig, kCount };
constexpr int kEditorDocumentCount = static_cast<int>(EditorDocument::kCount);

struct Command {
  std::string label;                    // shown as "Undo <label>"
  EditorDocument document = EditorDocument::kLevel;
  std::function<void()> redo;           // applies the change (also the first "do")
  std::function<void()> undo;           // reverts it
};

class UndoStack {
 public:
  UndoStack();

  // Executes `command.redo` (unless `already_applied`) and records it; drops the redo tail.
  // Inside a group the command joins the group's step.
  void push(Command command, bool already_applied = false);

  // Merges every push until end_group() into one step labelled `label` (nesting counts).
  void begin_group(const std::string& label, EditorDocument document);
  void end_group();
  bool in_group() const { return group_depth_ > 0; }

  bool can_undo() const { return cursor_ > 0; }
  bool can_redo() const { return cursor_ < static_cast<int>(steps_.size()); }
  // Reverts / re-applies one step; false when there is nothing to do.
  bool undo();
  bool redo();
  // Label of the step undo() / redo() would act on ("" when none).
  std::string undo_label() const;
  std::string redo_label() const;
  int size() const { return static_cast<int>(steps_.size()); }
  int cursor() const { return cursor_; }

  // Unsaved-change markers per document.
  void mark_saved(EditorDocument document);
  bool is_dirty(EditorDocument document) const;
  bool any_dirty() const;

  // Forgets every step of `document` (a new file was loaded: its old steps would act on the
  // wrong data) and marks it saved. Steps of other documents stay.
  void clear(EditorDocument document);
  // Forgets everything and marks every document saved.
  void clear();

 private:
  struct Step {
    std::string label;
    EditorDocument document;
    std::vector<Command> commands;   // applied in order, undone in reverse
    uint64_t state_before = 0;       // the document's state id before / after the step
    uint64_t state_after = 0;
  };
  uint64_t new_state_id() { return ++next_id_; }
  void commit_step(Step step);

  std::vector<Step> steps_;
  int cursor_ = 0;                   // steps_[0, cursor_) are applied
  Step group_;
  int group_depth_ = 0;
  uint64_t next_id_ = 0;
  uint64_t state_[kEditorDocumentCount] = {};
  uint64_t saved_[kEditorDocumentCount] = {};
};

}  // namespace ossa
