#pragma once
// Input — the playtester's devices turned into Controls (DESIGN.md §2, §8, [T 4.1]):
//
//   * Gamepad: SDL's GameController API. Hot-plug: a controller added while the game runs is
//     opened, the one in use going away falls back to the next one attached, or to the
//     keyboard — never a crash. Mappings: SDL's built-in database plus
//     assets/gamecontrollerdb.txt when present. The left stick passes a radial dead zone
//     and sets move_x precisely: half a stick is the walk speed, a full stick the run
//     speed (player.h).
//   * MouseKeyboardInput: A/D or the arrows walk (move_x ±0.5); with Shift they run (±1 and
//     run). Key state is tracked from events (so events pushed with SDL_PushEvent count);
//     the mouse position, buttons and wheel are kept for the editors.
//
// SDL appears only in platform/ and app/ (STYLE.md); this header needs only SDL_Event's name.

#include <array>
#include <optional>
#include <cstdint>
#include <string>

#include <glm/vec2.hpp>

#include "ossa/game/controls.h"

union SDL_Event;
struct _SDL_GameController;

namespace ossa {

// Radial dead zone on a stick (components in [-1, 1]): magnitudes up to `dead_zone` give 0
// (a worn stick's drift, judged on the whole stick so diagonals are not cut off); outside
// it the stick passes unchanged, clamped to magnitude 1, so the throw sets the speed
// precisely (half a throw = walk speed). dead_zone in [0, 1).
glm::vec2 radial_dead_zone(glm::vec2 stick, float dead_zone);

// Buttons the game reacts to, whatever the device.
enum class Action : uint8_t {
  kNextCreature,    // keyboard N / gamepad Y: the next of the 44 examples
  kRandomCreature,  // keyboard M / gamepad X: a new random creature
  kToggleHud,       // keyboard H / gamepad Back
  kScreenshot,      // keyboard F12 or P
  kGif,             // keyboard G: GIF of the next seconds
  kRecord,          // keyboard R / gamepad Start: start/stop recording a replay
  kQuit,            // keyboard Escape
  kNextCharacter,   // keyboard C / gamepad left shoulder: the next shipped rigged character
  kNextLook,        // keyboard B: the creatures' look, body → x-ray → bones → body
  kCount
};

// Pressed-this-frame flags; cleared by begin_frame().
struct ActionPresses {
  std::array<bool, static_cast<size_t>(Action::kCount)> pressed{};
  bool operator[](Action a) const { return pressed[static_cast<size_t>(a)]; }
  void set(Action a) { pressed[static_cast<size_t>(a)] = true; }
};

// A key press as the editors' shortcuts read it: the key (an SDL keycode, so Ctrl+Z is where
// the layout puts Z) and the modifiers held. Taken from SDL_KEYDOWN events, so a press and
// its release within one frame still count (ImGui 1.86's key state drops those).
struct KeyChord {
  int32_t key = 0;  // SDL_Keycode (SDLK_F2, SDLK_z, ...)
  bool ctrl = false, shift = false, alt = false;
  friend bool operator==(const KeyChord&, const KeyChord&) = default;
};

// The chord of a key press (SDL_KEYDOWN, not an auto-repeat); nothing for any other event.
std::optional<KeyChord> key_chord(const SDL_Event& event);

class Gamepad {
 public:
  // Initialises SDL's game controller subsystem, loads `mapping_file` when it exists (a
  // missing file is fine; a malformed one logs and keeps SDL's built-in mappings) and opens
  // the first controller already attached.
  explicit Gamepad(const std::string& mapping_file = {});
  ~Gamepad();
  Gamepad(const Gamepad&) = delete;
  Gamepad& operator=(const Gamepad&) = delete;

  // Mappings read from the mapping file (0 when absent), or -1 when SDL rejected it.
  int mappings_loaded() const { return mappings_loaded_; }

  // Hot-plug and buttons: CONTROLLERDEVICEADDED / REMOVED, CONTROLLERBUTTONDOWN.
  void handle_event(const SDL_Event& event, ActionPresses& presses);

  bool connected() const { return controller_ != nullptr; }
  std::string name() const;
  // The left stick through the radial dead zone, x in [-1, 1].
  glm::vec2 stick() const;
  // Stick x as move_x; run while A, the right shoulder or the right trigger is held.
  Controls controls() const;
  // True when the stick is out of the dead zone or the run or jump button is held. A jumps;
  // the right shoulder or trigger runs.
  bool active() const;

  float dead_zone = 0.15f;  // fraction of the stick's full throw, [0, 1)

 private:
  void open_first();
  _SDL_GameController* controller_ = nullptr;
  int32_t instance_id_ = -1;
  int mappings_loaded_ = 0;
};

class MouseKeyboardInput {
 public:
  // Key and mouse state from events; quit requests from Escape and the window's close button.
  void handle_event(const SDL_Event& event, ActionPresses& presses);
  // Forgets held keys (focus lost).
  void release_all();

  // A/D or Left/Right: ±0.5 (walk); with Shift: ±1 and run. Both directions cancel. Space, W
  // or Up: jump.
  Controls controls() const;
  bool active() const { return left_ || right_ || jump_; }
  bool quit_requested() const { return quit_; }
  // Forgets a quit request (the game asked first and the user chose to stay).
  void clear_quit() { quit_ = false; }

  // Mouse for the editors: window pixels (x right, y down), buttons (SDL_BUTTON_* masks),
  // wheel steps accumulated since the last take_wheel().
  glm::vec2 mouse_px() const { return mouse_px_; }
  uint32_t mouse_buttons() const { return mouse_buttons_; }
  float take_wheel() {
    const float w = wheel_;
    wheel_ = 0.0f;
    return w;
  }

 private:
  bool left_ = false, right_ = false, shift_ = false, jump_ = false;
  bool key_a_ = false, key_d_ = false, key_left_ = false, key_right_ = false;
  bool lshift_ = false, rshift_ = false, key_space_ = false, key_w_ = false, key_up_ = false;
  bool quit_ = false;
  glm::vec2 mouse_px_{0.0f};
  uint32_t mouse_buttons_ = 0;
  float wheel_ = 0.0f;
};

// The controls of one frame: the keyboard while a direction key is held, else the gamepad
// when one is connected, else standing still.
Controls combine_controls(const MouseKeyboardInput& keyboard, const Gamepad& gamepad);

}  // namespace ossa
