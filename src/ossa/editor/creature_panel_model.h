#pragma once
// CreaturePanelModel — the creature panel without any UI (DESIGN.md §10, [Z 8.3]): pick an
// example or draw a random creature with a seed under conditions (wings, leg pairs, weight,
// neck girdle, several limbs per girdle), choose the size (true size or a fixed frame), move
// the first 8 principal components in σ units,
// draw variations with a σ, regenerate one part (limbs, ribs, tail, skull) keeping the rest,
// save / load the genome, export glTF, SVG and PNG, and hand the creature to the game (apply to
// the player, spawn as an NPC) through callbacks.
//
// Step-wise generation [Z 8.3]: every change of the genome is one UndoStack step (document
// kGenome); a slider drag (begin_edit … set_sigma … end_edit) is one step. The body's look
// (coat colours, pattern, its scale, fatness, wing cover), its appendages and the skull's
// proportions are edited the same way.
//
// Exports (files written atomically; on failure the error names the file, an existing file is
// left untouched and the genome is kept):
//   glTF — skeleton nodes and a skinned sprite mesh through Assimp (ossa/render/gltf_export.h);
//   SVG  — the bones as shapes (ossa/gen/export_svg.h);
//   PNG  — the creature in its rest pose drawn by the game's renderer into an offscreen
//          framebuffer, framed on it (ossa/render/creature_image.h). Needs a current GL context:
//          the editor runs inside the game, which has one; without it export_png says so.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ossa/editor/undo_stack.h"
#include "ossa/gen/creature.h"
#include "ossa/gen/generator.h"
#include "ossa/io/result.h"
#include "ossa/render/creature_image.h"

namespace ossa {

enum class CreaturePart : int { kLimbs, kRibs, kTail, kSkull };
const char* creature_part_name(CreaturePart part);

// The name of a genome the panel changed (a variation, a regenerated part, a moved slider): the
// creature is no longer the example or random creature it started as; the HUD and saved
// genomes show it.
inline constexpr const char* kCustomName = "custom";

class CreaturePanelModel {
 public:
  static constexpr int kSliderCount = 8;      // principal components shown as sliders
  static constexpr float kSigmaRange = 3.0f;  // slider range ±3 σ

  using CreatureFn = std::function<void(std::shared_ptr<const Creature>)>;
  // `generator` and `undo` must outlive the model. Starts with example `start_example`
  // (or the first example when that name is unknown).
  CreaturePanelModel(const Generator& generator, UndoStack& undo,
                     const std::string& start_example = "horse");

  CreatureFn on_apply_to_player;   // called by apply_to_player()
  CreatureFn on_spawn_npc;         // called by spawn_npc()

  const Genome& genome() const { return genome_; }
  // The creature built from genome() (nullptr with error() set if the build failed).
  std::shared_ptr<const Creature> creature() const { return creature_; }
  const std::vector<std::string>& example_names() const { return example_names_; }

  // Conditions for random creatures (and the options of examples).
  GenerateOptions conditions;
  uint64_t seed = 1;

  // ---- Generation (each one undo step) -------------------------------------------------
  Status pick_example(const std::string& name);
  void random();                   // Generator::random(seed, conditions)
  // Changes the conditions and regenerates: the σ sliders follow the new genome.
  void set_conditions(const GenerateOptions& options);
  // A variation of the current genome with `sigma` (σ units) from `seed`.
  void variation(double sigma);
  // Redraws one part from `seed` keeping everything else.
  void regenerate(CreaturePart part);
  // Smooth skinning of the current genome (options.smooth_skinning; one undo step when it
  // changes) and of the creatures generated next (conditions.genome).
  void set_smooth_skinning(bool on);

  // ---- Size (issue 29) ---------------------------------------------------------------------
  // The genome's size choice: its animal's true size (from its weight and body plan) or a fixed
  // frame of `size.frame_m` metres (clamped into [kMinFrameMetres, kMaxFrameMetres]); the scale
  // follows (Generator::apply_size) and the creature is rebuilt. One undo step when it changes
  // (one per drag inside begin_edit/end_edit); creatures generated next keep the choice
  // (conditions.genome). Every other edit that moves the weight or the body (σ sliders,
  // variations, regenerated parts, appendages, the skull) applies the choice again, so a
  // true-size creature follows its weight.
  void set_size(SizeChoice size);
  // What the size gave, for the panel: "hip 1.07 m, length 2.64 m, 600 kg" (the leg height the
  // size rule uses, gen/true_size.h, "shoulder" for forelegs only and left out without legs;
  // the snout-to-tail length on the rest pose; the weight); "" without a creature.
  std::string size_text() const;

  // ---- The body: look, appendages, skull (issue 30; each one undo step, or one per drag
  // inside begin_edit/end_edit). Values are clamped into the genome's ranges (gen/look.h,
  // gen/skull_shape.h); a change that leaves the genome as it is adds no step.
  void set_look(Look look);
  // A new look drawn from `seed` (random_look) for this body's kind.
  void random_look();
  // The appendage of `kind`: added or resized to `size`, or removed when `size` is empty.
  void set_appendage(AppendageKind kind, std::optional<float> size);
  // The appendage of `kind` on the current genome, if any.
  std::optional<float> appendage(AppendageKind kind) const;
  void set_skull_shape(SkullShape shape);

  // ---- σ sliders -------------------------------------------------------------------------
  // Coordinate of the current genome along principal component i (0 <= i < kSliderCount),
  // in standard deviations.
  double sigma(int i) const;
  // Moves component i to `value` σ (clamped to ±kSigmaRange); the other components stay.
  // Wings and leg pairs keep their values (the limbs are discrete choices already made);
  // rest angles are recomputed. One undo step unless inside begin_edit/end_edit.
  void set_sigma(int i, double value);
  void begin_edit(const std::string& label);
  void end_edit();

  // ---- Files -----------------------------------------------------------------------------
  bool dirty() const { return undo_->is_dirty(EditorDocument::kGenome); }
  const std::string& path() const { return path_; }
  Status save_genome(const std::string& path);
  Status load_genome(const std::string& path);   // one undo step; keeps the genome on error
  // Exports set last_note() to "exported F" and clear last_error() on success; on failure
  // last_error() holds the message (naming F) and last_note() is cleared.
  Status export_gltf(const std::string& path) const;
  Status export_svg(const std::string& path) const;
  Status export_png(const std::string& path, const CreatureImageOptions& options = {}) const;

  void apply_to_player() const { if (creature_ && on_apply_to_player) on_apply_to_player(creature_); }
  void spawn_npc() const { if (creature_ && on_spawn_npc) on_spawn_npc(creature_); }

  const std::string& last_error() const { return error_; }
  const std::string& last_note() const { return note_; }

  // Replaces the genome as one undo step labelled `label`.
  void set_genome(Genome genome, const std::string& label);

 private:
  void assign(const Genome& g);   // set + rebuild the creature
  Genome sized(Genome g) const;   // g with its size choice applied (the weight or body moved)
  Status fail(const Status& s) const { if (!s.ok()) error_ = s.message(); return s; }
  // An export's outcome: the error, or a note naming the file.
  Status exported(const Status& s, const std::string& path) const;

  const Generator* generator_;
  UndoStack* undo_;
  Genome genome_;
  std::shared_ptr<const Creature> creature_;
  std::vector<std::string> example_names_;
  std::string path_;
  mutable std::string error_;
  mutable std::string note_;  // exports are const but report what they wrote
  bool editing_ = false;
  Genome edit_before_;
  std::string edit_label_;
};

}  // namespace ossa
