// The creature panel's size (issue 29) without any UI: the genome's size choice (true size or
// a fixed frame) is one undo step that sets the scale, new creatures keep it, and every edit
// that moves the weight or the body applies it again, so a true-size creature follows its
// weight and a framed one keeps its frame.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "ossa/editor/creature_panel_model.h"
#include "ossa/editor/undo_stack.h"
#include "ossa/gen/true_size.h"
#include "ossa/io/json.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {
std::string genome_text(const Genome& g) { return genome_to_json(g).dump(); }
// The panel's size line starts with the leg height the size rule uses.
std::string hip_text(const Creature& c) {
  char text[32];
  std::snprintf(text, sizeof text, "hip %.3g m, ", static_cast<double>(leg_height(c)));
  return text;
}
}  // namespace

TEST_CASE("creature panel: the size choice sets the scale, one undo step, kept for new creatures", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const Genome true_horse = m.genome();
  REQUIRE(true_horse.options.true_size);  // the default
  REQUIRE(true_horse.scale > 0.0022f);    // the horse at true size: 1 m at the hip
  REQUIRE(m.creature());
  const float true_hip = leg_height(*m.creature());
  CHECK(true_hip > 0.95f);
  CHECK(m.size_text().find(hip_text(*m.creature())) == 0);

  // A 2 m frame: every creature as big as a pony.
  m.set_size({false, 2.0f});
  CHECK(undo.size() == 1);
  CHECK(undo.undo_label() == "size frame");
  CHECK(m.dirty());
  CHECK_FALSE(m.genome().options.true_size);
  CHECK(m.genome().scale == Approx(0.002f));
  CHECK(m.creature()->scale == Approx(0.002f));
  CHECK(genome_to_json(m.genome())["size"].get<double>() == Approx(2.0));
  CHECK(leg_height(*m.creature()) == Approx(true_hip * 0.002f / true_horse.scale).epsilon(1e-3));
  CHECK(m.size_text().find(hip_text(*m.creature())) == 0);
  CHECK(m.size_text().find("600 kg") != std::string::npos);
  m.set_size({false, 2.0f});  // no change, no step
  CHECK(undo.size() == 1);
  m.set_size({false, 1000.0f});  // clamped into the frame's range
  CHECK(m.genome().options.frame_m == kMaxFrameMetres);
  CHECK(m.genome().scale == Approx(kMaxFrameMetres / 1000.0f));
  CHECK(undo.size() == 2);

  // A drag of the frame slider is one step.
  m.begin_edit("size frame");
  for (int i = 1; i <= 5; ++i) m.set_size({false, static_cast<float>(i)});
  m.end_edit();
  CHECK(undo.size() == 3);
  CHECK(m.genome().scale == Approx(0.005f));

  // New creatures keep the choice.
  m.random();
  CHECK_FALSE(m.genome().options.true_size);
  CHECK(m.genome().scale == Approx(0.005f));
  REQUIRE(m.pick_example("pig").ok());
  CHECK(m.genome().scale == Approx(0.005f));

  // Undo goes back through every step to the true-size horse; redo forward again.
  for (int i = 0; i < 5; ++i) REQUIRE(undo.undo());
  CHECK(genome_text(m.genome()) == genome_text(true_horse));
  CHECK(m.creature()->scale == true_horse.scale);
  CHECK_FALSE(m.dirty());
  REQUIRE(undo.redo());
  CHECK(m.genome().scale == Approx(0.002f));
  CHECK(m.creature()->scale == Approx(0.002f));

  // Back to true size: the horse's own scale again.
  m.set_size({true, 2.0f});
  CHECK(m.genome().options.true_size);
  CHECK(m.genome().scale == Approx(true_horse.scale));
  CHECK(undo.undo_label() == "true size");
  CHECK(genome_to_json(m.genome())["size"] == "true");
}

TEST_CASE("creature panel: a true-size creature follows its weight, a framed one keeps its frame", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const Generator& generator = scenes::generator();
  // The σ slider that moves the weight most.
  int heavy = 0;
  double most = 0.0;
  for (int i = 0; i < CreaturePanelModel::kSliderCount; ++i) {
    const double before = m.genome().pca[kWeightKg];
    m.set_sigma(i, m.sigma(i) + 1.0);
    const double ratio = std::abs(std::log(m.genome().pca[kWeightKg] / before));
    if (ratio > most) most = ratio, heavy = i;
    REQUIRE(undo.undo());
  }
  REQUIRE(most > 0.1);
  const Genome before = m.genome();
  m.set_sigma(heavy, m.sigma(heavy) + 1.5);
  const Genome& after = m.genome();
  REQUIRE(std::abs(std::log(after.pca[kWeightKg] / before.pca[kWeightKg])) > 0.1);
  CHECK(after.scale != Approx(before.scale));
  Genome resized = after;
  generator.apply_size(resized);
  CHECK(after.scale == resized.scale);  // the size rule's scale for the new weight and body
  // Heavier: bigger; lighter: smaller.
  CHECK((after.pca[kWeightKg] > before.pca[kWeightKg]) == (after.scale > before.scale));
  REQUIRE(undo.undo());
  CHECK(m.genome().scale == before.scale);

  // A random creature conditioned on its weight: heavier is bigger at true size.
  GenerateOptions light;
  light.weight_kg = 20.0;
  m.set_conditions(light);
  const float light_scale = m.genome().scale;
  GenerateOptions heavy_options = light;
  heavy_options.weight_kg = 2000.0;
  m.set_conditions(heavy_options);
  CHECK(m.genome().scale > 2.0f * light_scale);

  // In a fixed frame the slider, a variation and a regenerated part keep the frame.
  m.set_size({false, 2.0f});
  m.set_sigma(heavy, m.sigma(heavy) + 1.5);
  CHECK(m.genome().scale == Approx(0.002f));
  m.variation(0.5);
  CHECK(m.genome().scale == Approx(0.002f));
  m.regenerate(CreaturePart::kLimbs);
  CHECK(m.genome().scale == Approx(0.002f));
  // Back at true size, a regenerated part or appendage measures the new body.
  m.set_size({true, 2.0f});
  m.regenerate(CreaturePart::kTail);
  Genome check = m.genome();
  generator.apply_size(check);
  CHECK(m.genome().scale == check.scale);
  m.set_appendage(AppendageKind::kHump, 1.5f);
  check = m.genome();
  generator.apply_size(check);
  CHECK(m.genome().scale == check.scale);
}
