#include "ossa/editor/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ossa {

void Hud::add_frame_time(float seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0f) return;
  frame_millis_[next_] = seconds * 1000.0f;
  next_ = (next_ + 1) % kHistory;
  count_ = std::min(count_ + 1, kHistory);
}

float Hud::fps() const {
  if (count_ == 0) return 0.0f;
  float sum = 0.0f;
  for (int i = 0; i < count_; ++i) sum += frame_millis_[i];
  return sum > 0.0f ? 1000.0f * static_cast<float>(count_) / sum : 0.0f;
}

void Hud::draw(const HudInfo& info) {
  if (!visible) return;
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("ossa hud", nullptr, flags)) {
    ImGui::Text("%s", info.creature.c_str());
    ImGui::Separator();
    ImGui::Text("speed   %6.2f m/s  (walk %.2f, run %.2f)", info.speed, info.walk_speed, info.run_speed);
    ImGui::Text("gait    %s  (%s)", info.gait.c_str(), info.locomotion.c_str());
    if (info.gallop_speed > 0.0f) {
      ImGui::Text("bands   walk < %.2f < trot < %.2f < gallop", info.trot_speed, info.gallop_speed);
    } else if (info.biped_run_speed > 0.0f) {
      ImGui::Text("bands   walk < %.2f < run", info.biped_run_speed);
    }
    ImGui::Text("Froude  %6.2f", info.froude);
    const float f = fps();
    ImGui::Text("FPS     %6.1f  (%.2f ms)  sim %d Hz", f, f > 0.0f ? 1000.0f / f : 0.0f, info.tick_hz);
    // The ring buffer in time order: oldest first.
    std::array<float, kHistory> ordered{};
    float peak = 1.0f;
    for (int i = 0; i < count_; ++i) {
      ordered[i] = frame_millis_[(next_ - count_ + i + kHistory) % kHistory];
      peak = std::max(peak, ordered[i]);
    }
    ImGui::PlotLines("##frametime", ordered.data(), count_, 0, "frame time (ms)", 0.0f,
                     std::max(20.0f, peak * 1.1f), ImVec2(300.0f, 50.0f));
    ImGui::Text("input   %s", info.input.c_str());
    if (info.recording) ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.3f, 1.0f), "REC replay");
    if (info.gif) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f), "GIF capture");
    if (!info.status.empty()) ImGui::TextWrapped("%s", info.status.c_str());
    ImGui::Separator();
    ImGui::TextDisabled("A/D walk, Shift run, Space/W/Up jump, N next, M random, C character, H hud");
    ImGui::TextDisabled("pad: RB/RT run, A jump, Y next, X random, LB character, Back hud");
    ImGui::TextDisabled("F12/P shot, G gif, R replay, wheel zoom, F2 editors, Esc quit");
  }
  ImGui::End();
}

}  // namespace ossa
