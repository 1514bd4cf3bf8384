// EditorSuite: the tuning panel window — every AnimatorParams field with its unit, the gait
// override, and the live footfall diagram (stance bars per leg over the last seconds).
#include <algorithm>
#include <cstdio>
#include <string>

#include "ossa/editor/editor_suite.h"
#include "ossa/editor/editor_suite_internal.h"
#include "ossa/game/world.h"

namespace ossa {

namespace {
// Footfall diagram: one row per leg, time runs left (oldest) to right (now); a filled bar
// wherever the foot is on the ground (stance), as in gait diagrams of locomotion papers.
void draw_footfalls(const TuningModel& t, float width) {
  const int legs = t.leg_count();
  const float row = 16.0f;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const ImVec2 size(width, row * std::max(legs, 1) + 4.0f);
  ImGui::Dummy(size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(28, 30, 36, 255));
  const float label_w = 34.0f;
  const float plot_w = width - label_w;
  const int cap = std::max(t.sample_capacity(), 1);
  for (int leg = 0; leg < legs; ++leg) {
    const auto& h = t.leg_history(leg);
    const float y0 = o.y + 2.0f + row * leg + 2.0f, y1 = y0 + row - 4.0f;
    char label[16];
    std::snprintf(label, sizeof label, "L%d", leg);
    dl->AddText(ImVec2(o.x + 4.0f, y0 - 1.0f), IM_COL32(200, 200, 200, 255), label);
    const ImU32 col = leg % 2 ? IM_COL32(255, 160, 80, 255) : IM_COL32(100, 190, 255, 255);
    // Right-aligned: the newest sample is at the right edge.
    const int n = static_cast<int>(h.size());
    const float x_of = plot_w / static_cast<float>(cap);
    int i = 0;
    while (i < n) {
      if (!h[i]) { ++i; continue; }
      int j = i;
      while (j < n && h[j]) ++j;
      const float xa = o.x + label_w + (cap - n + i) * x_of, xb = o.x + label_w + (cap - n + j) * x_of;
      dl->AddRectFilled(ImVec2(xa, y0), ImVec2(xb, y1), col);
      i = j;
    }
  }
  // One-second ticks.
  for (float s = 0.0f; s <= t.history_seconds; s += 1.0f) {
    const float x = o.x + size.x - s / t.history_seconds * plot_w;
    dl->AddLine(ImVec2(x, o.y), ImVec2(x, o.y + size.y), IM_COL32(255, 255, 255, 40));
  }
}
}  // namespace

void EditorSuite::draw_tuning_window() {
  TuningModel& m = *tuning_;
  place_next_window(EditorWindow::kTuning);
  const std::string title = std::string("Tuning") + (m.dirty() ? " *" : "") + "###tuning";
  if (!ImGui::Begin(title.c_str(), &show_tuning)) {
    ImGui::End();
    return;
  }
  // Footfall diagram first: it is what the sliders change.
  const Player* player = world_->player();
  if (player) {
    const Animator& a = player->animator();
    ImGui::Text("%s (%s)  v %.2f m/s  Fr %.2f  duty %.2f  run %.2f", gait_name(a.gait()), gait_family_name(a.gait_family()),
                a.velocity(), a.froude(), a.duty_factor(), a.run_factor());
  }
  ImGui::TextDisabled("footfalls, last %.0f s (bars = stance)", m.history_seconds);
  draw_footfalls(m, ImGui::GetContentRegionAvail().x);

  // The family (auto: the creature's own) and which of its gaits: walk, the middle gait, the
  // fast gait, named by the family the player moves by.
  int family = static_cast<int>(m.params().gait_family);
  ImGui::SetNextItemWidth(120);
  if (ImGui::Combo("gait family", &family, [](void*, int i, const char** out) {
        *out = gait_family_name(static_cast<GaitFamily>(i));
        return true;
      }, nullptr, kGaitFamilyCount)) {
    m.set_gait_family(static_cast<GaitFamily>(family));
  }
  std::array<std::string, 4> gait_labels{"auto", "walk", "middle gait", "fast gait"};
  if (player) {
    const anim::GaitBands bands = player->animator().gait_bands();
    for (int k = 0; k < 3; ++k) gait_labels[k + 1] = gait_name(bands.gaits[k]);
  }
  const char* gaits[] = {gait_labels[0].c_str(), gait_labels[1].c_str(), gait_labels[2].c_str(), gait_labels[3].c_str()};
  int gait = static_cast<int>(m.params().gait_override) + 1;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  if (ImGui::Combo("gait override", &gait, gaits, 4)) m.set_gait_override(static_cast<GaitOverride>(gait - 1));
  ImGui::SameLine();
  if (ImGui::Button("Defaults")) m.reset();

  const auto fields = tuning_fields();
  for (int i = 0; i < static_cast<int>(fields.size()); ++i) {
    const TuningField& f = fields[i];
    float v = m.value(i);
    const std::string fmt = std::string("%.3f ") + f.unit;
    ImGui::SetNextItemWidth(170);
    const bool moved = ImGui::SliderFloat(f.name, &v, f.min, f.max, fmt.c_str());
    if (ImGui::IsItemActivated()) m.begin_edit(f.name);
    if (moved) m.set_value(i, v);
    if (ImGui::IsItemDeactivated()) m.end_edit();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.help);
  }
  ImGui::Separator();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##tuningpath", tuning_path_buf_, sizeof tuning_path_buf_);
  if (ImGui::Button("Save")) (void)m.save_as(tuning_path_buf_);
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    const std::string path = tuning_path_buf_;
    confirm_discard(EditorDocument::kTuning, [this, path] { (void)tuning_->load(path); });
  }
  show_messages(m.last_error(), "");
  ImGui::End();
}

}  // namespace ossa
