#include "ossa/editor/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

HudMode next_hud_mode(HudMode mode) {
  switch (mode) {
    case HudMode::kPlayer: return HudMode::kDeveloper;
    case HudMode::kDeveloper: return HudMode::kOff;
    case HudMode::kOff: break;
  }
  return HudMode::kPlayer;
}

const char* hud_mode_name(HudMode mode) {
  switch (mode) {
    case HudMode::kOff: return "off";
    case HudMode::kPlayer: return "player";
    case HudMode::kDeveloper: return "developer";
  }
  return "?";
}

namespace {

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// "horse (quadruped), hip 1.07 m": the name, the gait family and the size (a 3 cm frog and a
// 3 m dinosaur look alike on a screen that frames each by its size).
std::string name_line(const HudInfo& info) {
  std::string line = info.family.empty() ? info.creature : info.creature + " (" + info.family + ")";
  if (info.hip_height > 0.0f) {
    line += info.hip_height < 0.1f ? format(", hip %.1f cm", info.hip_height * 100.0f) : format(", hip %.2f m", info.hip_height);
  }
  return line;
}

}  // namespace

std::vector<std::string> hud_lines(const HudInfo& info, HudMode mode, float fps) {
  std::vector<std::string> lines;
  if (mode == HudMode::kOff) return lines;
  if (mode == HudMode::kPlayer) {
    const bool grounded = info.locomotion.empty() || info.locomotion == "grounded";
    lines.push_back(name_line(info));
    lines.push_back(format("%.1f km/h  %s%s", std::abs(info.speed) * 3.6f, info.gait.c_str(),
                           grounded ? "" : (" (" + info.locomotion + ")").c_str()));
    if (!info.blocked.empty()) lines.push_back(info.blocked);
    if (info.recording) lines.push_back("REC replay");
    if (info.gif) lines.push_back("GIF capture");
    if (!info.status.empty()) lines.push_back(info.status);
    lines.push_back("H: more, F2: editors");
    return lines;
  }
  lines.push_back(name_line(info));
  lines.push_back(format("speed   %6.2f m/s  %.1f km/h  (walk %.2f, run %.2f)", info.speed, std::abs(info.speed) * 3.6f,
                         info.walk_speed, info.run_speed));
  lines.push_back(format("gait    %s  (%s)", info.gait.c_str(), info.locomotion.c_str()));
  if (info.mid_speed > 0.0f || info.fast_speed > 0.0f) {
    std::string bands = "bands   " + info.gaits[0];
    if (info.mid_speed > 0.0f) bands += format(" < %.2f < ", info.mid_speed) + info.gaits[1];
    if (info.fast_speed > 0.0f) bands += format(" < %.2f < ", info.fast_speed) + info.gaits[2];
    lines.push_back(bands);
  }
  if (!info.blocked.empty()) lines.push_back(info.blocked);
  lines.push_back(format("Froude  %6.2f", info.froude));
  lines.push_back(format("FPS     %6.1f  (%.2f ms)  sim %d Hz", fps, fps > 0.0f ? 1000.0f / fps : 0.0f, info.tick_hz));
  lines.push_back("input   " + info.input);
  if (info.recording) lines.push_back("REC replay");
  if (info.gif) lines.push_back("GIF capture");
  if (!info.status.empty()) lines.push_back(info.status);
  return lines;
}

void Hud::draw(const HudInfo& info) {
  if (mode == HudMode::kOff) return;
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  const float f = fps();
  const std::vector<std::string> lines = hud_lines(info, mode, f);
  if (ImGui::Begin("ossa hud", nullptr, flags)) {
    for (size_t i = 0; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      if (line == "REC replay") ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.3f, 1.0f), "%s", line.c_str());
      else if (line == "GIF capture") ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f), "%s", line.c_str());
      else if (mode == HudMode::kPlayer && i + 1 == lines.size()) ImGui::TextDisabled("%s", line.c_str());
      else if (i > 0 && line == info.status) ImGui::TextWrapped("%s", line.c_str());
      else ImGui::TextUnformatted(line.c_str());
      if (i == 0 && mode == HudMode::kDeveloper) ImGui::Separator();
      if (mode == HudMode::kDeveloper && line.rfind("FPS", 0) == 0) {
        // The ring buffer in time order: oldest first.
        std::array<float, kHistory> ordered{};
        float peak = 1.0f;
        for (int k = 0; k < count_; ++k) {
          ordered[k] = frame_millis_[(next_ - count_ + k + kHistory) % kHistory];
          peak = std::max(peak, ordered[k]);
        }
        ImGui::PlotLines("##frametime", ordered.data(), count_, 0, "frame time (ms)", 0.0f,
                         std::max(20.0f, peak * 1.1f), ImVec2(300.0f, 50.0f));
      }
    }
    if (mode == HudMode::kDeveloper) {
      ImGui::Separator();
      ImGui::TextDisabled("A/D walk, Shift run, Space/W/Up jump, N next, M random, C character, H hud");
      ImGui::TextDisabled("B look: body, x-ray, bones");
      ImGui::TextDisabled("pad: RB/RT run, A jump, Y next, X random, LB character, Back hud");
      ImGui::TextDisabled("F12/P shot, G gif, R replay, wheel zoom, F2 editors, Esc quit");
    }
  }
  ImGui::End();
}

}  // namespace ossa
