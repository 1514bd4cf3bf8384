// EditorSuite: the spline prototype editor window — walk and run canvases side by side with
// draggable keys and tangent handles, the blended preview, numeric fields and files.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "ossa/editor/editor_suite.h"
#include "ossa/editor/editor_suite_internal.h"
#include "ossa/game/world.h"

namespace ossa {

namespace {
constexpr float kHandlePickPx = 8.0f;
const ImU32 kWalkColour = IM_COL32(90, 180, 255, 255);
const ImU32 kRunColour = IM_COL32(255, 140, 70, 255);
const ImU32 kBlendColour = IM_COL32(140, 235, 120, 255);

// Curve sampled at 64 points through the canvas mapping.
template <class C>
void draw_spline(ImDrawList* dl, const C& c, const HermiteSpline& s, ImU32 col, float thickness) {
  if (!s.is_valid()) return;
  ImVec2 pts[65];
  const float t0 = s.keys.front().t, t1 = s.keys.back().t;
  for (int i = 0; i <= 64; ++i) {
    const float t = t0 + (t1 - t0) * static_cast<float>(i) / 64.0f;
    pts[i] = c.to_screen({t, s.position(t)});
  }
  dl->AddPolyline(pts, 65, col, 0, thickness);
}

template <class C>
void draw_frame(ImDrawList* dl, const C& c) {
  const ImVec2 a = c.origin, b{c.origin.x + c.size.x, c.origin.y + c.size.y};
  dl->AddRectFilled(a, b, IM_COL32(28, 30, 36, 255));
  dl->AddRect(a, b, IM_COL32(90, 90, 100, 255));
  // t = 0 and 1 verticals, p = 0 horizontal.
  for (float t : {0.0f, 0.5f, 1.0f}) {
    dl->AddLine(c.to_screen({t, c.p_min}), c.to_screen({t, c.p_max}), IM_COL32(70, 70, 80, 255));
  }
  if (c.p_min < 0.0f && c.p_max > 0.0f)
    dl->AddLine(c.to_screen({c.t_min, 0.0f}), c.to_screen({c.t_max, 0.0f}), IM_COL32(110, 110, 120, 255));
}
}  // namespace

void EditorSuite::draw_spline_canvas(int slot, SplineVersion version, float width, float height) {
  SplineEditorModel& m = *spline_;
  Canvas& c = canvases_[slot];
  ImGui::BeginGroup();
  ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(version == SplineVersion::kWalk ? kWalkColour : kRunColour),
                     version == SplineVersion::kWalk ? "walk" : "run");
  c.origin = ImGui::GetCursorScreenPos();
  c.size = ImVec2(width, height);
  c.drawn = true;
  // The value range covers both versions (so walk and run read alike) and is frozen while a
  // drag is under way.
  if (!m.dragging()) {
    float lo = 0.0f, hi = 0.0f;
    for (SplineVersion v : {SplineVersion::kWalk, SplineVersion::kRun}) {
      for (int i = 0; i < static_cast<int>(m.spline(v).keys.size()); ++i) {
        const float p = m.key_position(v, i).y, h = m.tangent_position(v, i).y;
        lo = std::min({lo, p, h});
        hi = std::max({hi, p, h});
      }
    }
    const float pad = std::max(0.15f * (hi - lo), 0.05f);
    c.p_min = lo - pad;
    c.p_max = hi + pad;
  }
  ImGui::PushID(slot);
  ImGui::InvisibleButton("canvas", c.size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  draw_frame(dl, c);
  dl->PushClipRect(c.origin, ImVec2(c.origin.x + c.size.x, c.origin.y + c.size.y), true);

  const HermiteSpline& s = m.spline(version);
  const int n = static_cast<int>(s.keys.size());
  // Nearest handle under the mouse: tangent handles first (they sit on top).
  std::optional<SplineHandle> under;
  float best = kHandlePickPx * kHandlePickPx;
  for (int i = 0; i < n; ++i) {
    for (auto part : {SplineHandle::Part::kTangent, SplineHandle::Part::kKey}) {
      const glm::vec2 tp = part == SplineHandle::Part::kKey ? m.key_position(version, i)
                                                            : m.tangent_position(version, i);
      const ImVec2 q = c.to_screen(tp);
      const float d2 = (q.x - mouse.x) * (q.x - mouse.x) + (q.y - mouse.y) * (q.y - mouse.y);
      if (d2 < best) {
        best = d2;
        under = SplineHandle{part, version, i};
      }
    }
  }
  if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    if (under) m.begin_drag(*under); else m.select(std::nullopt);
  }
  if (m.dragging() && ImGui::IsItemActive() && m.selected() && m.selected()->version == version) {
    m.drag_to(c.to_curve(mouse));
  }
  if (m.dragging() && ImGui::IsItemDeactivated()) m.end_drag();
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !under) {
    m.add_key(c.to_curve(mouse).x);
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right) && under &&
      under->part == SplineHandle::Part::kKey) {
    m.remove_key(under->key);
  }

  // The other version faintly behind, then this one.
  const SplineVersion other = version == SplineVersion::kWalk ? SplineVersion::kRun : SplineVersion::kWalk;
  draw_spline(dl, c, m.spline(other), IM_COL32(120, 120, 120, 90), 1.0f);
  const ImU32 col = version == SplineVersion::kWalk ? kWalkColour : kRunColour;
  draw_spline(dl, c, s, col, 2.0f);
  for (int i = 0; i < n; ++i) {
    const ImVec2 k = c.to_screen(m.key_position(version, i));
    const ImVec2 h = c.to_screen(m.tangent_position(version, i));
    const bool sel = m.selected() && m.selected()->version == version && m.selected()->key == i;
    dl->AddLine(k, h, IM_COL32(200, 200, 200, 160));
    dl->AddCircleFilled(h, 3.5f, IM_COL32(230, 230, 230, 255));
    dl->AddRectFilled(ImVec2(k.x - 4.5f, k.y - 4.5f), ImVec2(k.x + 4.5f, k.y + 4.5f),
                      sel ? IM_COL32(255, 230, 80, 255) : col);
    dl->AddRect(ImVec2(k.x - 4.5f, k.y - 4.5f), ImVec2(k.x + 4.5f, k.y + 4.5f), IM_COL32(0, 0, 0, 255));
  }
  dl->PopClipRect();
  ImGui::PopID();
  ImGui::EndGroup();
}

void EditorSuite::draw_preview_canvas(float width, float height) {
  SplineEditorModel& m = *spline_;
  Canvas& c = canvases_[2];
  c.origin = ImGui::GetCursorScreenPos();
  c.size = ImVec2(width, height);
  c.p_min = canvases_[0].p_min;
  c.p_max = canvases_[0].p_max;
  c.drawn = true;
  ImGui::Dummy(c.size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  draw_frame(dl, c);
  draw_spline(dl, c, m.pair().walk, IM_COL32(90, 180, 255, 110), 1.0f);
  draw_spline(dl, c, m.pair().run, IM_COL32(255, 140, 70, 110), 1.0f);
  draw_spline(dl, c, m.preview(preview_w_), kBlendColour, 2.5f);
}

void EditorSuite::draw_spline_window() {
  SplineEditorModel& m = *spline_;
  const std::string name = m.path().empty() ? std::string("(unsaved)")
                                            : std::filesystem::path(m.path()).filename().string();
  const std::string title = "Spline prototypes: " + name + (m.dirty() ? " *" : "") + "###splines";
  // Top right, leaving the middle of the viewport free (editor_layout.h).
  place_next_window(EditorWindow::kSplines);
  // A permanent scrollbar: the canvases must not change width (and keys jump under the
  // mouse) when the numeric fields of a selected key make the content taller.
  if (!ImGui::Begin(title.c_str(), &show_splines, ImGuiWindowFlags_AlwaysVerticalScrollbar)) {
    ImGui::End();
    for (int i = 0; i < 3; ++i) canvases_[i].drawn = false;
    return;
  }
  // Prototype picker.
  int current = static_cast<int>(m.current());
  ImGui::SetNextItemWidth(180);
  if (ImGui::BeginCombo("prototype", prototype_name(m.current()))) {
    for (int i = 0; i < kPrototypeCount; ++i) {
      if (ImGui::Selectable(prototype_name(static_cast<PrototypeId>(i)), i == current))
        m.pick(static_cast<PrototypeId>(i));
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("double-click: add key, right-click: remove");
  ImGui::PopTextWrapPos();

  const float avail = ImGui::GetContentRegionAvail().x;
  const float w = std::max(120.0f, (avail - ImGui::GetStyle().ItemSpacing.x) * 0.5f);
  const float h = 170.0f;
  draw_spline_canvas(0, SplineVersion::kWalk, w, h);
  ImGui::SameLine();
  draw_spline_canvas(1, SplineVersion::kRun, w, h);

  // Blended preview at the walk→run factor (the player's, or a slider).
  const Player* player = world_->player();
  ImGui::Checkbox("follow player", &preview_follow_player_);
  ImGui::SameLine();
  if (preview_follow_player_ && player) preview_w_ = player->animator().run_factor();
  ImGui::SetNextItemWidth(200);
  ImGui::BeginDisabled(preview_follow_player_ && player);
  ImGui::SliderFloat("walk-run", &preview_w_, 0.0f, 1.0f, "%.2f");
  ImGui::EndDisabled();
  draw_preview_canvas(avail, 110.0f);

  // Numeric fields of the selected key, walk and run.
  if (auto sel = m.selected(); sel && sel->key < static_cast<int>(m.pair().walk.keys.size())) {
    for (SplineVersion v : {SplineVersion::kWalk, SplineVersion::kRun}) {
      HermiteKey k = m.spline(v).keys[sel->key];
      float tpm[3] = {k.t, k.p, k.m};
      ImGui::PushID(static_cast<int>(v));
      const std::string label = std::string(v == SplineVersion::kWalk ? "walk" : "run") +
                                " key " + std::to_string(sel->key) + " t p m";
      if (ImGui::InputFloat3(label.c_str(), tpm, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue))
        m.set_key(v, sel->key, HermiteKey{tpm[0], tpm[1], tpm[2]});
      ImGui::PopID();
    }
    if (ImGui::Button("Remove key")) m.remove_key(sel->key);
  } else {
    ImGui::TextDisabled("select a key to edit its numbers");
  }
  ImGui::Separator();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##protopath", proto_path_buf_, sizeof proto_path_buf_);
  if (ImGui::Button("Save")) {
    if (m.path().empty()) (void)m.save_as(proto_path_buf_); else (void)m.save();
  }
  ImGui::SameLine();
  if (ImGui::Button("Save as")) (void)m.save_as(proto_path_buf_);
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    const std::string path = proto_path_buf_;
    confirm_discard(EditorDocument::kPrototypes, [this, path] { (void)spline_->load(path); });
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(m.path().empty());
  if (ImGui::Button("Revert")) confirm_discard(EditorDocument::kPrototypes, [this] { (void)spline_->revert(); });
  ImGui::EndDisabled();
  show_messages(m.last_error(), m.last_note());
  ImGui::End();
}

}  // namespace ossa
