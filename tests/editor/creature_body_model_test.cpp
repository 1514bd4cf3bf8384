// The creature panel's body section (issue 30) without any UI: the look, appendages and skull
// shape are edited on the genome with undo, clamped into the genome's ranges, and the creature
// is rebuilt with them.

#include <catch2/catch.hpp>

#include "ossa/editor/creature_panel_model.h"
#include "ossa/editor/undo_stack.h"
#include "shared/scenes.h"

using namespace ossa;

TEST_CASE("creature panel: the look is one undo step, clamped, and reaches the creature", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const Look before = m.genome().look;
  Look look = before;
  look.base = {0.2f, 0.3f, 0.4f};
  look.pattern = CoatPattern::kStripes;
  look.fatness = 5.0f;  // beyond the range: clamped
  m.set_look(look);
  CHECK(undo.size() == 1);
  CHECK(undo.undo_label() == "look");
  CHECK(m.genome().look.base == look.base);
  CHECK(m.genome().look.pattern == CoatPattern::kStripes);
  CHECK(m.genome().look.fatness == kMaxFatness);
  REQUIRE(m.creature());
  CHECK(m.creature()->look == m.genome().look);
  CHECK(m.dirty());
  // The same look again adds no step.
  m.set_look(m.genome().look);
  CHECK(undo.size() == 1);
  REQUIRE(undo.undo());
  CHECK(m.genome().look == before);
  CHECK(m.creature()->look == before);
  CHECK(!m.dirty());
  REQUIRE(undo.redo());
  CHECK(m.genome().look.pattern == CoatPattern::kStripes);
}

TEST_CASE("creature panel: a colour or slider drag is one step, and a random look follows the seed", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "pig");
  const Look before = m.genome().look;
  m.begin_edit("coat colour");
  Look look = before;
  for (int i = 1; i <= 10; ++i) {
    look.base = glm::vec3(0.05f * static_cast<float>(i));
    m.set_look(look);
  }
  m.end_edit();
  CHECK(undo.size() == 1);
  CHECK(m.genome().look.base == glm::vec3(0.5f));
  REQUIRE(undo.undo());
  CHECK(m.genome().look == before);
  // Random looks: drawn from the seed, a plausible (in-range) look, one step each.
  m.seed = 7;
  m.random_look();
  const Look seven = m.genome().look;
  m.seed = 8;
  m.random_look();
  CHECK(!(m.genome().look == seven));
  m.seed = 7;
  m.random_look();
  CHECK(m.genome().look == seven);
  CHECK(m.genome().look.fatness >= kMinFatness);
  CHECK(m.genome().look.fatness <= kMaxFatness);
}

TEST_CASE("creature panel: appendages are added, resized and removed, each one step", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  REQUIRE(!m.appendage(AppendageKind::kHorns));
  const size_t count = m.genome().appendages.size();
  m.set_appendage(AppendageKind::kHorns, 1.0f);
  CHECK(m.appendage(AppendageKind::kHorns) == Approx(1.0f));
  CHECK(m.genome().appendages.size() == count + 1);
  m.set_appendage(AppendageKind::kHorns, 9.0f);  // clamped
  CHECK(m.appendage(AppendageKind::kHorns) == Approx(kMaxAppendageSize));
  m.set_appendage(AppendageKind::kHorns, std::nullopt);
  CHECK(!m.appendage(AppendageKind::kHorns));
  CHECK(undo.size() == 3);
  CHECK(undo.undo_label() == "remove horns");
  // Removing one that is not there adds nothing.
  m.set_appendage(AppendageKind::kHorns, std::nullopt);
  CHECK(undo.size() == 3);
  REQUIRE(undo.undo());
  CHECK(m.appendage(AppendageKind::kHorns) == Approx(kMaxAppendageSize));
  REQUIRE(m.creature());
  bool horns = false;
  for (const Appendage& a : m.creature()->appendages) horns |= a.kind == AppendageKind::kHorns;
  CHECK(horns);
  REQUIRE(undo.undo());
  REQUIRE(undo.undo());
  CHECK(m.genome().appendages.size() == count);
}

TEST_CASE("creature panel: the skull's proportions are clamped genes with undo", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const SkullShape before = m.genome().skull_shape;
  const float snout_before = m.creature()->skull_snout;
  SkullShape shape = before;
  shape.snout = 0.8f;
  shape.length = 10.0f;  // clamped
  m.set_skull_shape(shape);
  CHECK(m.genome().skull_shape.snout == Approx(0.8f));
  CHECK(m.genome().skull_shape.length == Approx(kMaxSkullLength));
  CHECK(m.creature()->skull_snout != Approx(snout_before));
  m.set_skull_shape(m.genome().skull_shape);  // unchanged: no step
  CHECK(undo.size() == 1);
  REQUIRE(undo.undo());
  CHECK(m.genome().skull_shape == before);
}
