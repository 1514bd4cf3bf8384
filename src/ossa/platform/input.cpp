#include "ossa/platform/input.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ossa {

glm::vec2 radial_dead_zone(glm::vec2 stick, float dead_zone) {
  const float dz = std::clamp(dead_zone, 0.0f, 0.99f);
  const float m = std::sqrt(stick.x * stick.x + stick.y * stick.y);
  if (!(m > dz)) return glm::vec2(0.0f);  // also catches NaN
  // Outside the zone the stick passes unchanged (only clamped to the unit circle): the
  // throw is the speed, so half a throw is exactly the walk speed [T 4.1]. Rescaling the
  // zone away would make every speed below full throw slightly slower than the stick says.
  return m > 1.0f ? stick / m : stick;
}

// ---- Gamepad ------------------------------------------------------------------------------

Gamepad::Gamepad(const std::string& mapping_file) {
  // SDL ignores joystick input while none of the app's windows has focus; an offscreen or
  // freshly mapped window may never get it, and a playtester glancing at another window
  // should not lose the stick either.
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (!SDL_WasInit(SDL_INIT_GAMECONTROLLER) && SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
    std::fprintf(stderr, "ossa: gamepad support unavailable: %s\n", SDL_GetError());
    return;
  }
  std::error_code ec;
  if (!mapping_file.empty() && std::filesystem::is_regular_file(mapping_file, ec)) {
    mappings_loaded_ = SDL_GameControllerAddMappingsFromFile(mapping_file.c_str());
    if (mappings_loaded_ < 0) {
      std::fprintf(stderr, "ossa: %s: controller mappings not loaded: %s (using SDL's built-in ones)\n",
                   mapping_file.c_str(), SDL_GetError());
    }
  }
  open_first();
}

Gamepad::~Gamepad() {
  if (controller_) SDL_GameControllerClose(controller_);
}

void Gamepad::open_first() {
  for (int i = 0; i < SDL_NumJoysticks(); ++i) {
    if (!SDL_IsGameController(i)) continue;
    if (SDL_GameController* c = SDL_GameControllerOpen(i)) {
      controller_ = c;
      instance_id_ = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(c));
      return;
    }
  }
}

void Gamepad::handle_event(const SDL_Event& e, ActionPresses& presses) {
  switch (e.type) {
    case SDL_CONTROLLERDEVICEADDED:
      if (!controller_) open_first();
      break;
    case SDL_CONTROLLERDEVICEREMOVED:
      if (controller_ && e.cdevice.which == instance_id_) {
        // The device is gone: close our handle and take the next one, if any — the keyboard
        // keeps working either way.
        SDL_GameControllerClose(controller_);
        controller_ = nullptr;
        instance_id_ = -1;
        open_first();
      }
      break;
    case SDL_CONTROLLERBUTTONDOWN:
      if (!controller_ || e.cbutton.which != instance_id_) break;
      switch (e.cbutton.button) {
        case SDL_CONTROLLER_BUTTON_Y: presses.set(Action::kNextCreature); break;
        case SDL_CONTROLLER_BUTTON_X: presses.set(Action::kRandomCreature); break;
        case SDL_CONTROLLER_BUTTON_LEFTSHOULDER: presses.set(Action::kNextCharacter); break;
        case SDL_CONTROLLER_BUTTON_BACK: presses.set(Action::kToggleHud); break;
        case SDL_CONTROLLER_BUTTON_START: presses.set(Action::kRecord); break;
        default: break;
      }
      break;
    default: break;
  }
}

std::string Gamepad::name() const {
  const char* n = controller_ ? SDL_GameControllerName(controller_) : nullptr;
  return n ? n : "";
}

glm::vec2 Gamepad::stick() const {
  if (!controller_) return glm::vec2(0.0f);
  // SDL axes are in [-32768, 32767]: divide by 32768 so the half throw 16384 is exactly 0.5
  // (the walk speed), and read the positive end as a full 1.
  auto axis = [&](SDL_GameControllerAxis a) {
    const Sint16 v = SDL_GameControllerGetAxis(controller_, a);
    return v >= 32767 ? 1.0f : static_cast<float>(v) / 32768.0f;
  };
  return radial_dead_zone({axis(SDL_CONTROLLER_AXIS_LEFTX), axis(SDL_CONTROLLER_AXIS_LEFTY)}, dead_zone);
}

Controls Gamepad::controls() const {
  Controls c;
  if (!controller_) return c;
  c.move_x = stick().x;
  c.run = SDL_GameControllerGetButton(controller_, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER) != 0 ||
          SDL_GameControllerGetAxis(controller_, SDL_CONTROLLER_AXIS_TRIGGERRIGHT) > 16384;
  c.jump = SDL_GameControllerGetButton(controller_, SDL_CONTROLLER_BUTTON_A) != 0;
  return c;
}

bool Gamepad::active() const {
  const Controls c = controls();
  return c.move_x != 0.0f || c.run || c.jump;
}

// ---- Mouse and keyboard -------------------------------------------------------------------

std::optional<KeyChord> key_chord(const SDL_Event& e) {
  if (e.type != SDL_KEYDOWN || e.key.repeat != 0) return std::nullopt;
  const Uint16 mod = e.key.keysym.mod;
  return KeyChord{static_cast<int32_t>(e.key.keysym.sym), (mod & KMOD_CTRL) != 0, (mod & KMOD_SHIFT) != 0,
                  (mod & KMOD_ALT) != 0};
}

void MouseKeyboardInput::handle_event(const SDL_Event& e, ActionPresses& presses) {
  switch (e.type) {
    case SDL_QUIT: quit_ = true; break;
    case SDL_WINDOWEVENT:
      if (e.window.event == SDL_WINDOWEVENT_CLOSE) quit_ = true;
      if (e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) release_all();
      break;
    case SDL_KEYDOWN:
    case SDL_KEYUP: {
      const bool down = e.type == SDL_KEYDOWN;
      switch (e.key.keysym.scancode) {
        case SDL_SCANCODE_A: key_a_ = down; break;
        case SDL_SCANCODE_D: key_d_ = down; break;
        case SDL_SCANCODE_LEFT: key_left_ = down; break;
        case SDL_SCANCODE_RIGHT: key_right_ = down; break;
        case SDL_SCANCODE_LSHIFT: lshift_ = down; break;
        case SDL_SCANCODE_RSHIFT: rshift_ = down; break;
        case SDL_SCANCODE_SPACE: key_space_ = down; break;
        case SDL_SCANCODE_W: key_w_ = down; break;
        case SDL_SCANCODE_UP: key_up_ = down; break;
        default: break;
      }
      if (down && e.key.repeat == 0) {
        switch (e.key.keysym.scancode) {
          case SDL_SCANCODE_ESCAPE: presses.set(Action::kQuit); quit_ = true; break;
          case SDL_SCANCODE_N: presses.set(Action::kNextCreature); break;
          case SDL_SCANCODE_C: presses.set(Action::kNextCharacter); break;
          case SDL_SCANCODE_B: presses.set(Action::kNextLook); break;
          case SDL_SCANCODE_M: presses.set(Action::kRandomCreature); break;
          case SDL_SCANCODE_H: presses.set(Action::kToggleHud); break;
          case SDL_SCANCODE_F12:
          case SDL_SCANCODE_P: presses.set(Action::kScreenshot); break;
          case SDL_SCANCODE_G: presses.set(Action::kGif); break;
          case SDL_SCANCODE_R: presses.set(Action::kRecord); break;
          default: break;
        }
      }
      left_ = key_a_ || key_left_;
      right_ = key_d_ || key_right_;
      shift_ = lshift_ || rshift_;
      jump_ = key_space_ || key_w_ || key_up_;
      break;
    }
    case SDL_MOUSEMOTION:
      mouse_px_ = {static_cast<float>(e.motion.x), static_cast<float>(e.motion.y)};
      mouse_buttons_ = e.motion.state;
      break;
    case SDL_MOUSEBUTTONDOWN: mouse_buttons_ |= SDL_BUTTON(e.button.button); break;
    case SDL_MOUSEBUTTONUP: mouse_buttons_ &= ~SDL_BUTTON(e.button.button); break;
    case SDL_MOUSEWHEEL:
      wheel_ += static_cast<float>(e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y);
      break;
    default: break;
  }
}

void MouseKeyboardInput::release_all() {
  key_a_ = key_d_ = key_left_ = key_right_ = lshift_ = rshift_ = key_space_ = key_w_ = key_up_ = false;
  left_ = right_ = shift_ = jump_ = false;
  mouse_buttons_ = 0;
}

Controls MouseKeyboardInput::controls() const {
  Controls c;
  c.jump = jump_;
  const float dir = (right_ ? 1.0f : 0.0f) - (left_ ? 1.0f : 0.0f);
  if (dir == 0.0f) return c;
  c.move_x = dir * (shift_ ? 1.0f : 0.5f);
  c.run = shift_;
  return c;
}

Controls combine_controls(const MouseKeyboardInput& keyboard, const Gamepad& gamepad) {
  if (keyboard.active()) return keyboard.controls();
  if (gamepad.connected()) return gamepad.controls();
  return {};
}

}  // namespace ossa
