// EditorSuite: the creature panel's body section (issue 30) — the coat (base, belly and pattern
// colours, pattern, its scale), fatness, wing cover, the appendages (each on or off with its
// size) and the skull's proportions. Every control goes through CreaturePanelModel: a click is
// one undo step, a drag (a colour, a slider) one step from its start to its release.
#include <algorithm>
#include <string>

#include "ossa/editor/editor_suite.h"
#include "ossa/editor/editor_suite_internal.h"

namespace ossa {

namespace {

// Undo framing of the last item: a drag starts an edit and its release ends it.
void frame_edit(CreaturePanelModel& m, const std::string& label) {
  if (ImGui::IsItemActivated()) m.begin_edit(label);
  if (ImGui::IsItemDeactivated()) m.end_edit();
}

}  // namespace

void EditorSuite::draw_creature_body(CreaturePanelModel& m) {
  if (!ImGui::TreeNodeEx("Body", ImGuiTreeNodeFlags_DefaultOpen)) return;
  Look look = m.genome().look;
  // Colours: the value follows the picker; one undo step from the picker's opening to its
  // closing (ColorEdit3's popup is "picker" under the widget's label).
  const auto colour = [&](const char* label, glm::vec3& c) {
    float rgb[3] = {c.r, c.g, c.b};
    const bool moved = ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_NoInputs);
    ImGui::PushID(label);
    const bool open = ImGui::IsPopupOpen("picker");
    ImGui::PopID();
    if (open && colour_edit_.empty()) {
      colour_edit_ = label;
      m.begin_edit(std::string(label) + " colour");
    }
    if (moved) {
      c = {rgb[0], rgb[1], rgb[2]};
      m.set_look(look);
    }
    if (!open && colour_edit_ == label) {
      colour_edit_.clear();
      m.end_edit();
    }
  };
  colour("coat", look.base);
  ImGui::SameLine();
  colour("belly", look.belly);
  ImGui::SameLine();
  colour("pattern##colour", look.pattern_colour);
  ImGui::SetNextItemWidth(110);
  if (ImGui::BeginCombo("pattern", coat_pattern_name(look.pattern))) {
    for (int i = 0; i < kCoatPatternCount; ++i) {
      const auto p = static_cast<CoatPattern>(i);
      if (ImGui::Selectable(coat_pattern_name(p), p == look.pattern)) {
        look.pattern = p;
        m.set_look(look);
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  if (ImGui::SliderFloat("scale", &look.pattern_scale, kMinPatternScale, kMaxPatternScale, "%.2f",
                         ImGuiSliderFlags_Logarithmic)) {
    m.set_look(look);
  }
  frame_edit(m, "pattern scale");
  ImGui::SetNextItemWidth(110);
  if (ImGui::SliderFloat("fatness", &look.fatness, kMinFatness, kMaxFatness, "%.2f")) m.set_look(look);
  frame_edit(m, "fatness");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(100);
  if (ImGui::BeginCombo("wings##cover", wing_cover_name(look.wings))) {
    for (WingCover w : {WingCover::kFeathered, WingCover::kMembrane}) {
      if (ImGui::Selectable(wing_cover_name(w), w == look.wings)) {
        look.wings = w;
        m.set_look(look);
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::Button("Random look")) m.random_look();

  // Appendages: a checkbox each, its size beside it while on.
  if (ImGui::TreeNode("Appendages")) {
    for (int i = 0; i < kAppendageKindCount; ++i) {
      const auto kind = static_cast<AppendageKind>(i);
      const std::optional<float> size = m.appendage(kind);
      bool on = size.has_value();
      ImGui::PushID(i);
      if (ImGui::Checkbox(appendage_kind_name(kind), &on)) m.set_appendage(kind, on ? std::optional<float>(1.0f) : std::nullopt);
      if (on && size) {
        ImGui::SameLine(120);
        ImGui::SetNextItemWidth(120);
        float v = *size;
        if (ImGui::SliderFloat("size", &v, kMinAppendageSize, kMaxAppendageSize, "%.2f")) m.set_appendage(kind, v);
        frame_edit(m, std::string(appendage_kind_name(kind)) + " size");
      }
      ImGui::PopID();
    }
    ImGui::TreePop();
  }

  // The skull's proportions.
  if (ImGui::TreeNode("Skull")) {
    SkullShape shape = m.genome().skull_shape;
    const auto slider = [&](const char* label, float& v, float lo, float hi) {
      ImGui::SetNextItemWidth(160);
      if (ImGui::SliderFloat(label, &v, lo, hi, "%.2f")) m.set_skull_shape(shape);
      frame_edit(m, std::string("skull ") + label);
    };
    slider("length / back", shape.length, kMinSkullLength, kMaxSkullLength);
    slider("height / length", shape.height, kMinSkullHeight, kMaxSkullHeight);
    slider("snout / length", shape.snout, kMinSnout, kMaxSnout);
    ImGui::TreePop();
  }
  ImGui::TreePop();
}

}  // namespace ossa
