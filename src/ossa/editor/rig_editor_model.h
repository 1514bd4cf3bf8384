#pragma once
// RigEditorModel — the Rig window without any UI (DESIGN.md §10; issue 15): a skinned mesh's
// bone tree, the rig mapping being edited, the character it builds (or the error that says
// why it does not: file, field, bone) and a preview of it standing or walking on flat ground.
//
// A designer picks a part (a slot: the root, a spine bone, a leg's upper bone ...) and clicks
// a bone; the bone takes the part (leaving any part it had) and the selection moves on to the
// next part of the chain (upper → lower → foot), so a leg is three clicks. Every edit is one
// UndoStack step (document kRig); every edit rebuilds the character and restarts the preview.
// Saves are atomic (save_rig_mapping); a mapping that does not build can still be saved (the
// loaders then name the problem).
//
//   RigEditorModel m(undo);
//   m.open_mapping("assets/characters/humanoid.rig.json");   // or open_mesh("robot.gltf")
//   m.select({RigSlot::kLegFoot, 0});
//   m.assign(m.slot(), m.skeleton().find("foot_l"));
//   m.step_preview(1.0f / 60.0f);                             // walks at preview_stick

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/rig/character.h"
#include "ossa/rig/rig_mapping.h"
#include "ossa/editor/undo_stack.h"
#include "ossa/io/result.h"
#include "ossa/level/level.h"
#include "ossa/render/rigged_mesh.h"

namespace ossa {

// A part of the mapping a bone can play.
enum class RigSlotKind : uint8_t {
  kRoot, kSpine, kNeck, kHead, kTail, kLegUpper, kLegLower, kLegFoot, kArmUpper, kArmLower, kArmHand
};
struct RigSlot {
  RigSlotKind kind = RigSlotKind::kRoot;
  int index = 0;  // the spine / neck / tail bone, or the leg or arm
  bool operator==(const RigSlot&) const = default;
};
// The mapping's field of a slot: "root", "spine[1]", "legs[0].foot" ...
std::string rig_slot_field(const RigSlot& slot);

class RigEditorModel {
 public:
  explicit RigEditorModel(UndoStack& undo);

  // ---- Opening (both replace the document and forget its undo steps) ---------------------
  // A mapping file and the mesh it names.
  Status open_mapping(const std::string& rig_path);
  // A mesh without a mapping: the mapping starts as the guess from its bone names, to be
  // saved as `rig_path` (default: the mesh's name with ".rig.json").
  Status open_mesh(const std::string& mesh_path, const std::string& rig_path = {});
  // The same from a mesh already loaded (tests).
  void open(RiggedMesh mesh, RigMapping mapping, const std::string& rig_path);
  bool is_open() const { return mesh_ != nullptr; }
  // The open mesh (null when none).
  const RiggedMesh* mesh() const { return mesh_.get(); }

  // ---- The bone tree ------------------------------------------------------------------------
  const ImportedSkeleton& skeleton() const { return skeleton_; }
  const std::vector<int>& children(int bone) const { return children_[static_cast<size_t>(bone)]; }
  std::vector<int> roots() const;
  // The field bone b plays in the mapping ("legs[0].upper"), or "" when none.
  std::string part_of(int bone) const;
  // The bone a slot names, or -1.
  int bone_of(const RigSlot& slot) const;

  // ---- Editing (each one undo step) ------------------------------------------------------------
  const RigSlot& slot() const { return slot_; }
  void select(const RigSlot& slot) { slot_ = slot; }
  // `bone` plays the slot's part (and leaves the one it had); selection moves to the next slot
  // of the chain. A spine, neck or tail slot one past the end appends.
  void assign(const RigSlot& slot, int bone);
  // The slot's part is empty again (a spine, neck or tail entry is removed).
  void clear(const RigSlot& slot);
  void add_leg();
  void add_arm();
  void remove_leg(int leg);
  void remove_arm(int arm);
  void set_side(bool leg, int index, Side side);
  void set_contact(int leg, std::optional<glm::vec2> contact_mesh_units);
  // Replaces the mapping with the guess from the bone names.
  void guess();
  // Sets the whole mapping as one step (its mesh fields are kept).
  void set_mapping(const RigMapping& mapping, const std::string& label);

  // ---- The result ----------------------------------------------------------------------------
  const RigMapping& mapping() const { return mapping_; }
  // The character the mapping builds, or null; error() says why not (file, field, bone).
  std::shared_ptr<const Character> character() const { return character_; }
  const std::string& error() const { return error_; }
  const std::vector<std::string>& notes() const { return notes_; }   // the last guess's

  // ---- Preview: the character on flat ground ---------------------------------------------------
  float preview_stick = 0.0f;       // [-1, 1]: 0 stands, 0.5 walks, 1 runs (Player's mapping)
  // One preview step of dt seconds (ticks of 1/120 s). Does nothing without a character.
  void step_preview(float dt);
  const Animator* preview() const { return preview_.get(); }
  const Level& preview_level() const { return preview_level_; }

  // ---- Files (document kRig) --------------------------------------------------------------------
  const std::string& path() const { return path_; }
  bool dirty() const { return undo_->is_dirty(EditorDocument::kRig); }
  Status save() { return save_as(path_); }
  Status save_as(const std::string& rig_path);
  const std::string& last_error() const { return file_error_; }

 private:
  void apply(const RigMapping& m);  // sets the mapping, rebuilds, restarts the preview
  void rebuild();
  void push(const std::string& label, const RigMapping& after);

  UndoStack* undo_;
  std::unique_ptr<RiggedMesh> mesh_;
  ImportedSkeleton skeleton_;
  std::vector<std::vector<int>> children_;
  RigMapping mapping_;
  std::string path_;
  RigSlot slot_;
  std::shared_ptr<const Character> character_;
  std::string error_, file_error_;
  std::vector<std::string> notes_;
  Level preview_level_;
  std::unique_ptr<Animator> preview_;
  float preview_clock_ = 0.0f;
};

}  // namespace ossa
