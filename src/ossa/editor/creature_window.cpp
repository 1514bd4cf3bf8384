// EditorSuite: the creature panel window — example picker, random with seed and conditions,
// the size (true size or a fixed frame), σ sliders of the first principal components, variations, part regeneration, genome files,
// the body's look, appendages and skull (creature_body_window.cpp), glTF / SVG / PNG export,
// apply / spawn — with a rest-pose preview of the skeleton.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "ossa/editor/editor_suite.h"
#include "ossa/editor/editor_suite_internal.h"
#include "ossa/skeleton/pose.h"

#include <glm/common.hpp>

namespace ossa {

namespace {
// The creature's bones in its rest pose, fitted into a box on the panel.
void draw_creature_preview(const Creature& creature, ImVec2 size) {
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(28, 30, 36, 255));
  const auto mats = model_matrices(creature.skeleton, creature.rest_pose.locals);
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  std::vector<std::pair<glm::vec2, glm::vec2>> segs;
  for (int b = 0; b < creature.skeleton.bone_count(); ++b) {
    const glm::vec2 a = bone_start(mats[b]), e = bone_end(mats[b], creature.skeleton.length(b));
    if (!std::isfinite(a.x + a.y + e.x + e.y)) continue;
    segs.push_back({a, e});
    lo = glm::min(lo, glm::min(a, e));
    hi = glm::max(hi, glm::max(a, e));
  }
  lo.y = std::min(lo.y, 0.0f);
  if (segs.empty()) return;
  const glm::vec2 ext = glm::max(hi - lo, glm::vec2(1e-3f));
  const float k = 0.9f * std::min(size.x / ext.x, size.y / ext.y);
  const glm::vec2 mid = 0.5f * (lo + hi);
  auto to_px = [&](glm::vec2 p) {
    return ImVec2(o.x + 0.5f * size.x + (p.x - mid.x) * k, o.y + 0.5f * size.y - (p.y - mid.y) * k);
  };
  dl->AddLine(to_px({lo.x - ext.x, 0.0f}), to_px({hi.x + ext.x, 0.0f}), IM_COL32(120, 100, 70, 255));
  for (const auto& [a, e] : segs) dl->AddLine(to_px(a), to_px(e), IM_COL32(235, 225, 200, 255), 2.0f);
}

bool optional_int(const char* label, std::optional<int>& v, int lo, int hi, int fallback) {
  bool on = v.has_value();
  bool changed = ImGui::Checkbox(label, &on);
  if (changed) v = on ? std::optional<int>(fallback) : std::nullopt;
  if (on) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    int x = *v;
    ImGui::PushID(label);
    if (ImGui::SliderInt("##v", &x, lo, hi)) {
      v = x;
      changed = true;
    }
    ImGui::PopID();
  }
  return changed;
}
}  // namespace

void EditorSuite::draw_creature_window() {
  const std::string dirty = creature_ && creature_->dirty() ? " *" : "";
  const std::string title = "Creature: " + (creature_ ? creature_->genome().name : std::string("-")) +
                            dirty + "###creature";
  place_next_window(EditorWindow::kCreature);
  if (!ImGui::Begin(title.c_str(), &show_creature)) {
    ImGui::End();
    return;
  }
  if (!creature_) {
    ImGui::TextWrapped("No creature dataset loaded (assets/creatures/examples.json): the creature panel is unavailable.");
    ImGui::End();
    return;
  }
  CreaturePanelModel& m = *creature_;
  if (auto c = m.creature()) draw_creature_preview(*c, ImVec2(ImGui::GetContentRegionAvail().x, 130));

  // Example picker and random.
  const auto& names = m.example_names();
  // The combo shows the genome's example when it is one (after undo, load, ...).
  for (int i = 0; i < static_cast<int>(names.size()); ++i)
    if (names[i] == m.genome().name) creature_example_ = i;
  creature_example_ = std::clamp(creature_example_, 0, std::max(0, static_cast<int>(names.size()) - 1));
  ImGui::SetNextItemWidth(150);
  if (!names.empty() && ImGui::BeginCombo("example", names[creature_example_].c_str())) {
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
      if (ImGui::Selectable(names[i].c_str(), i == creature_example_)) {
        creature_example_ = i;
        (void)m.pick_example(names[i]);
      }
    }
    ImGui::EndCombo();
  }
  int seed = static_cast<int>(m.seed);
  ImGui::SetNextItemWidth(110);
  if (ImGui::InputInt("seed", &seed)) m.seed = static_cast<uint64_t>(std::max(seed, 0));
  ImGui::SameLine();
  if (ImGui::Button("Random")) m.random();

  // Conditions: any change regenerates, and the σ sliders follow the new genome.
  if (ImGui::TreeNodeEx("Conditions", ImGuiTreeNodeFlags_DefaultOpen)) {
    GenerateOptions o = m.conditions;
    bool changed = optional_int("wings", o.wings, 0, 1, 1);
    changed |= optional_int("leg pairs", o.leg_pairs, 0, 2, 2);
    bool w_on = o.weight_kg.has_value();
    if (ImGui::Checkbox("weight", &w_on)) {
      o.weight_kg = w_on ? std::optional<double>(50.0) : std::nullopt;
      changed = true;
    }
    if (w_on) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(120);
      float kg = static_cast<float>(*o.weight_kg);
      // The value follows the slider; the creature regenerates when the slider is released.
      if (ImGui::SliderFloat("kg", &kg, 0.01f, 10000.0f, "%.2f", ImGuiSliderFlags_Logarithmic)) o.weight_kg = kg;
      if (ImGui::IsItemDeactivatedAfterEdit()) changed = true;
    }
    changed |= ImGui::Checkbox("neck girdle", &o.genome.neck_girdle);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("several limbs per girdle", &o.genome.multi_limb);
    if (changed) m.set_conditions(o); else m.conditions = o;
    // A drawing option saved with the genome: sprites blend across joints (off: rigid bones).
    bool smooth = m.genome().options.smooth_skinning;
    if (ImGui::Checkbox("smooth skinning", &smooth)) m.set_smooth_skinning(smooth);
    ImGui::TreePop();
  }

  // Size: the animal's true size, or a fixed frame (metres; a drag is one undo step). What it
  // gave shows below.
  if (ImGui::TreeNodeEx("Size", ImGuiTreeNodeFlags_DefaultOpen)) {
    SizeChoice size{m.genome().options.true_size, m.genome().options.frame_m};
    if (ImGui::Checkbox("true size", &size.true_size)) m.set_size(size);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("from its weight and body plan; off: a fixed frame for every creature");
    if (!size.true_size) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(140);
      // Logarithmic: a 5 cm frame and a 50 m one on one slider (Ctrl+click types a value).
      const bool moved = ImGui::SliderFloat("m frame", &size.frame_m, kMinFrameMetres, kMaxFrameMetres, "%.2f",
                                            ImGuiSliderFlags_Logarithmic);
      if (ImGui::IsItemActivated()) m.begin_edit("size frame");
      if (moved) m.set_size(size);
      if (ImGui::IsItemDeactivated()) m.end_edit();
    }
    ImGui::TextDisabled("%s", m.size_text().c_str());
    ImGui::TreePop();
  }

  // σ sliders: one drag = one undo step.
  if (ImGui::TreeNodeEx("Principal components (sd)", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (int i = 0; i < CreaturePanelModel::kSliderCount; ++i) {
      float v = static_cast<float>(m.sigma(i));
      const std::string label = "PC" + std::to_string(i + 1);
      ImGui::SetNextItemWidth(200);
      const bool moved = ImGui::SliderFloat(label.c_str(), &v, -CreaturePanelModel::kSigmaRange,
                                            CreaturePanelModel::kSigmaRange, "%+.2f sd");
      if (ImGui::IsItemActivated()) m.begin_edit(label);
      if (moved) m.set_sigma(i, v);
      if (ImGui::IsItemDeactivated()) m.end_edit();
    }
    ImGui::TreePop();
  }

  draw_creature_body(m);

  ImGui::SetNextItemWidth(120);
  ImGui::SliderFloat("sd##var", &variation_sigma_, 0.05f, 2.0f, "%.2f");
  ImGui::SameLine();
  if (ImGui::Button("Variation")) m.variation(variation_sigma_);
  ImGui::TextUnformatted("Regenerate:");
  for (CreaturePart p : {CreaturePart::kLimbs, CreaturePart::kRibs, CreaturePart::kTail, CreaturePart::kSkull}) {
    ImGui::SameLine();
    if (ImGui::Button(creature_part_name(p))) m.regenerate(p);
  }
  ImGui::Separator();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##genome", genome_path_buf_, sizeof genome_path_buf_);
  if (ImGui::Button("Save genome")) (void)m.save_genome(genome_path_buf_);
  ImGui::SameLine();
  if (ImGui::Button("Load genome")) {
    const std::string path = genome_path_buf_;
    confirm_discard(EditorDocument::kGenome, [this, path] { (void)creature_->load_genome(path); });
  }
  // Exports: a path field and its button per format; the outcome shows below (last_note /
  // last_error).
  const float button_w = ImGui::CalcTextSize("Export glTF").x + 2.0f * ImGui::GetStyle().FramePadding.x;
  auto export_row = [&](const char* id, char* buf, size_t size, const char* button) {
    ImGui::SetNextItemWidth(-(button_w + ImGui::GetStyle().ItemSpacing.x));
    ImGui::InputText(id, buf, size);
    ImGui::SameLine();
    return ImGui::Button(button, ImVec2(button_w, 0.0f));
  };
  if (export_row("##gltf", gltf_path_buf_, sizeof gltf_path_buf_, "Export glTF"))
    (void)m.export_gltf(gltf_path_buf_);
  if (export_row("##svg", svg_path_buf_, sizeof svg_path_buf_, "Export SVG"))
    (void)m.export_svg(svg_path_buf_);
  if (export_row("##png", png_path_buf_, sizeof png_path_buf_, "Export PNG")) {
    CreatureImageOptions o;
    o.width = png_size_[0];
    o.height = png_size_[1];
    o.background = png_transparent_
                       ? glm::vec4(0.0f)
                       : glm::vec4(png_background_[0], png_background_[1], png_background_[2], 1.0f);
    (void)m.export_png(png_path_buf_, o);
  }
  ImGui::SetNextItemWidth(120);
  if (ImGui::InputInt2("px##pngsize", png_size_)) {
    for (int& v : png_size_) v = std::clamp(v, 16, 4096);
  }
  ImGui::SameLine();
  ImGui::Checkbox("transparent", &png_transparent_);
  if (!png_transparent_) {
    ImGui::SameLine();
    ImGui::ColorEdit3("##pngbg", png_background_, ImGuiColorEditFlags_NoInputs);
  }
  if (ImGui::Button("Apply to player")) m.apply_to_player();
  ImGui::SameLine();
  if (ImGui::Button("Spawn NPC")) m.spawn_npc();
  show_messages(m.last_error(), m.last_note());
  // Rigged characters (their rig mappings): the player may be one of them instead.
  if (!paths_.characters.empty()) {
    ImGui::Separator();
    ImGui::TextUnformatted("Rigged characters");
    creature_character_ = std::clamp(creature_character_, 0, static_cast<int>(paths_.characters.size()) - 1);
    const std::string current = character_name(paths_.characters[static_cast<size_t>(creature_character_)]);
    ImGui::SetNextItemWidth(160);
    if (ImGui::BeginCombo("##character", current.c_str())) {
      for (size_t i = 0; i < paths_.characters.size(); ++i) {
        if (ImGui::Selectable(character_name(paths_.characters[i]).c_str(), static_cast<int>(i) == creature_character_)) {
          creature_character_ = static_cast<int>(i);
        }
      }
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Apply character to player")) {
      const Status st = apply_character_to_player(paths_.characters[static_cast<size_t>(creature_character_)]);
      character_message_ = st.ok() ? "the player is " + current : st.message();
    }
    if (!character_message_.empty()) ImGui::TextDisabled("%s", character_message_.c_str());
  }
  ImGui::End();
}

}  // namespace ossa
