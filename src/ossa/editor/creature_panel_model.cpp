#include "ossa/editor/creature_panel_model.h"

#include <algorithm>
#include <cstdio>

#include "ossa/gen/export_svg.h"
#include "ossa/gen/pca_model.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/gen/true_size.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/math/rng.h"
#include "ossa/render/gltf_export.h"

namespace ossa {

const char* creature_part_name(CreaturePart part) {
  switch (part) {
    case CreaturePart::kLimbs: return "limbs";
    case CreaturePart::kRibs: return "ribs";
    case CreaturePart::kTail: return "tail";
    case CreaturePart::kSkull: return "skull";
  }
  return "?";
}

namespace {
PcaVector to_pca_vector(const std::array<double, kPcaDims>& a) {
  PcaVector v;
  for (int i = 0; i < kPcaDims; ++i) v[i] = a[i];
  return v;
}
}  // namespace

CreaturePanelModel::CreaturePanelModel(const Generator& generator, UndoStack& undo,
                                       const std::string& start_example)
    : generator_(&generator), undo_(&undo) {
  for (const Animal& a : generator.dataset().animals) example_names_.push_back(a.name);
  std::string name = start_example;
  if (!generator.dataset().find(name) && !example_names_.empty()) name = example_names_.front();
  auto g = generator.example(name, seed, conditions);
  assign(g.ok() ? g.value() : generator.random(seed, conditions));
  undo.clear(EditorDocument::kGenome);
}

void CreaturePanelModel::assign(const Genome& g) {
  genome_ = g;
  auto built = build_creature(genome_);
  if (built.ok()) {
    creature_ = std::make_shared<const Creature>(std::move(built.value()));
  } else {
    creature_.reset();
    error_ = built.message();
  }
}

Genome CreaturePanelModel::sized(Genome g) const {
  generator_->apply_size(g);
  return g;
}

void CreaturePanelModel::set_genome(Genome g, const std::string& label) {
  if (editing_) {
    assign(g);
    return;
  }
  const Genome before = genome_;
  undo_->push({label, EditorDocument::kGenome, [this, g] { assign(g); },
               [this, before] { assign(before); }});
}

Status CreaturePanelModel::pick_example(const std::string& name) {
  auto g = generator_->example(name, seed, conditions);
  if (!g.ok()) return fail(Error{g.message()});
  set_genome(g.value(), "example " + name);
  return {};
}

void CreaturePanelModel::random() { set_genome(generator_->random(seed, conditions), "random creature"); }

void CreaturePanelModel::set_conditions(const GenerateOptions& options) {
  conditions = options;
  random();
}

void CreaturePanelModel::set_smooth_skinning(bool on) {
  conditions.genome.smooth_skinning = on;
  if (genome_.options.smooth_skinning == on) return;
  Genome g = genome_;
  g.options.smooth_skinning = on;
  set_genome(std::move(g), on ? "smooth skinning" : "rigid sprites");
}

void CreaturePanelModel::set_size(SizeChoice size) {
  size.frame_m = std::clamp(size.frame_m, kMinFrameMetres, kMaxFrameMetres);
  size.apply_to(conditions.genome);
  Genome g = genome_;
  size.apply_to(g.options);
  g = sized(std::move(g));
  if (genome_to_json(g) == genome_to_json(genome_)) return;
  set_genome(std::move(g), size.true_size ? "true size" : "size frame");
}

std::string CreaturePanelModel::size_text() const {
  if (!creature_) return "";
  const Creature& c = *creature_;
  char legs[48] = "";
  if (const float h = leg_height(c); h > 0.0f) {
    std::snprintf(legs, sizeof legs, "%s %.3g m, ", size_measure(c, SizeMeasure::kHip) > 0.0f ? "hip" : "shoulder",
                  static_cast<double>(h));
  }
  const double kg = genome_.pca[kWeightKg];
  char text[128];
  std::snprintf(text, sizeof text, "%slength %.3g m, %.*f kg", legs, static_cast<double>(size_measure(c, SizeMeasure::kLength)),
                kg >= 10.0 ? 0 : kg >= 0.1 ? 2 : 3, kg);
  return text;
}

void CreaturePanelModel::variation(double sigma) {
  Genome g = generator_->variation(genome_, seed, sigma);
  g.name = kCustomName;
  set_genome(std::move(g), "variation");
}

void CreaturePanelModel::regenerate(CreaturePart part) {
  // Complete the same PCA point again from a new seed, then take only the chosen part:
  // the rest of the genome (and so the rest of the skeleton) is untouched [Z 8.3].
  Rng rng(seed);
  GenerateOptions o = conditions;
  o.genome = genome_.options;
  const Genome fresh = generator_->complete(genome_.pca, rng, o, genome_.name, seed);
  Genome g = genome_;
  switch (part) {
    case CreaturePart::kLimbs:
      g.limbs = fresh.limbs;
      g.contact = fresh.contact;
      break;
    case CreaturePart::kRibs: g.rib_interval = fresh.rib_interval; break;
    case CreaturePart::kTail: g.tail_vertebrae = fresh.tail_vertebrae; break;
    case CreaturePart::kSkull: g.skull_variant = fresh.skull_variant; break;
  }
  g.name = kCustomName;
  set_genome(sized(std::move(g)), std::string("regenerate ") + creature_part_name(part));
}

void CreaturePanelModel::set_look(Look look) {
  clamp_look(look);
  if (look == genome_.look) return;
  Genome g = genome_;
  g.look = look;
  set_genome(std::move(g), "look");
}

void CreaturePanelModel::random_look() {
  const bool winged = std::any_of(genome_.limbs.begin(), genome_.limbs.end(), [](const LimbGene& l) { return l.kind == LimbKind::kWing; });
  set_look(ossa::random_look(seed, genome_.skull_variant, winged));
}

std::optional<float> CreaturePanelModel::appendage(AppendageKind kind) const {
  for (const Appendage& a : genome_.appendages) {
    if (a.kind == kind) return a.size;
  }
  return std::nullopt;
}

void CreaturePanelModel::set_appendage(AppendageKind kind, std::optional<float> size) {
  Genome g = genome_;
  auto it = std::find_if(g.appendages.begin(), g.appendages.end(), [&](const Appendage& a) { return a.kind == kind; });
  if (!size) {
    if (it == g.appendages.end()) return;
    g.appendages.erase(it);
  } else if (it == g.appendages.end()) {
    g.appendages.push_back({kind, *size});
  } else {
    it->size = *size;
  }
  clamp_appendages(g.appendages);
  g = sized(std::move(g));  // appendages are part of the body the size rule measures
  if (genome_to_json(g) == genome_to_json(genome_)) return;
  set_genome(std::move(g), std::string(size ? "" : "remove ") + appendage_kind_name(kind));
}

void CreaturePanelModel::set_skull_shape(SkullShape shape) {
  Genome g = genome_;
  g.skull_shape = shape;
  clamp_to_genome_limits(g);
  if (g.skull_shape == genome_.skull_shape) return;
  set_genome(sized(std::move(g)), "skull shape");
}

double CreaturePanelModel::sigma(int i) const {
  if (i < 0 || i >= kPcaDims) return 0.0;
  return generator_->model().to_sigma(to_pca_vector(genome_.pca))[i];
}

void CreaturePanelModel::set_sigma(int i, double value) {
  if (i < 0 || i >= kSliderCount) return;
  const PcaModel& model = generator_->model();
  PcaVector s = model.to_sigma(to_pca_vector(genome_.pca));
  s[i] = std::clamp(value, -double(kSigmaRange), double(kSigmaRange));
  const PcaVector raw = model.from_sigma(s);
  Genome g = genome_;
  for (int d = 0; d < kPcaDims; ++d) {
    if (d == kWings || d == kLegPairs) continue;  // discrete choices stay as generated
    g.pca[d] = raw[d];
  }
  recompute_rest_angles(g);
  g.name = kCustomName;
  set_genome(sized(std::move(g)), "PC" + std::to_string(i + 1));
}

void CreaturePanelModel::begin_edit(const std::string& label) {
  if (editing_) return;
  editing_ = true;
  edit_before_ = genome_;
  edit_label_ = label;
}

void CreaturePanelModel::end_edit() {
  if (!editing_) return;
  editing_ = false;
  const Genome before = edit_before_;
  const Genome after = genome_;
  if (genome_to_json(before) == genome_to_json(after)) return;
  undo_->push({edit_label_, EditorDocument::kGenome, [this, after] { assign(after); },
               [this, before] { assign(before); }},
              true);
}

Status CreaturePanelModel::save_genome(const std::string& path) {
  Status s = ossa::save_genome(path, genome_);
  if (!s.ok()) return fail(s);
  path_ = path;
  undo_->mark_saved(EditorDocument::kGenome);
  error_.clear();
  note_ = "saved " + path;
  return s;
}

Status CreaturePanelModel::load_genome(const std::string& path) {
  auto g = ossa::load_genome(path);
  if (!g.ok()) return fail(Error{g.message()});
  set_genome(g.value(), "load genome");
  path_ = path;
  undo_->mark_saved(EditorDocument::kGenome);
  error_.clear();
  note_ = "loaded " + path;
  return {};
}

Status CreaturePanelModel::exported(const Status& s, const std::string& path) const {
  note_ = s.ok() ? "exported " + path : std::string();  // no stale "exported" under an error
  if (!s.ok()) return fail(s);
  error_.clear();
  return s;
}

Status CreaturePanelModel::export_gltf(const std::string& path) const {
  if (!creature_) return exported(Error::at(path, "", "no creature to export"), path);
  return exported(ossa::export_gltf(*creature_, path), path);
}

Status CreaturePanelModel::export_svg(const std::string& path) const {
  if (!creature_) return exported(Error::at(path, "", "no creature to export"), path);
  SvgOptions o;
  o.skull_variant = genome_.skull_variant;
  return exported(write_file_atomic(path, creature_svg(*creature_, o)), path);
}

Status CreaturePanelModel::export_png(const std::string& path, const CreatureImageOptions& options) const {
  if (!creature_) return exported(Error::at(path, "", "no creature to export"), path);
  return exported(write_creature_png(path, *creature_, options), path);
}

}  // namespace ossa
