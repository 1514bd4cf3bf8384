#include "app/options.h"

#include <cstdlib>

#include "ossa/io/parse_arg.h"

namespace ossa {

const char* const kGameUsage = R"(usage: ossa [--level F] [--creature F | --example NAME | --seed N | --character F]
            [--size true|FRAME_M] [--npcs N]
            [--replay F] [--record F] [--headless --frames N] [--png F] [--gif F]
            [--state F] [--hz N] [--threads N] [options]

Walk a generated creature over a box level with a gamepad or the keyboard.

  --level F         level file (default levels/default.json): an ossa level, a Tiled map
                    (.tmj, .tmx) or an LDtk project (.ldtk, pick a level with F#LevelName)
  --pixels-per-metre P  scale of a Tiled/LDtk map with neither a pixels_per_metre property
                    nor a tile size (default 32; else the property, or one tile = 0.5 m)
  --creature F      the player's creature: a saved genome (.creature.json)
  --example NAME    ... or one of the 44 example animals (default horse)
  --seed N          ... or a random creature drawn with seed N
  --character F     ... or a rigged character: its rig mapping (.rig.json, e.g.
                    assets/characters/humanoid.rig.json) and the skinned mesh it names
  --size true|FRAME_M  the size of every creature the game makes (the player, the NPCs, N
                    and M): true (default: the animal's true size from its weight and body
                    plan) or a fixed frame of FRAME_M metres (0.05 to 50, e.g. 2: every
                    creature as big as a pony); a --creature genome is resized (default: as
                    saved). --size WxH is the window's size (below)
  --npcs N          NPC walkers roaming the level, 0-64 (default 3)
  --npc-characters  every other NPC is one of the shipped rigged characters
  --replay F        play a replay file back (its creature, spawn and tick rate)
  --record F        record the player's controls to a replay file (written on exit)
  --headless        no window: SDL's offscreen driver, fixed 1/60 s frames, and a
                    demo script driving the player (unless --replay)
  --frames N        stop after N frames (headless default: 600, or the replay's end)
  --png F           write the last frame as PNG on exit
  --gif F           record a GIF (headless: the whole run; else the first --gif-seconds),
                    half size, without the HUD
  --gif-seconds S   length of a GIF, 0.5-60 seconds (default 5)
  --state F         write JSON on exit: frames, player {x, y, speed, creature}, spawn {x, y}
  --hz N            simulation ticks per second, 30-480 (default 120)
  --threads N       threads stepping the creatures, 0-1024 (0 = every core, the default;
                    the poses are the same on any number)
  --no-vsync        do not wait for the display's refresh
  --fps-cap N       frames per second limit without vsync, 0-1000 (0 = none)
  --size WxH        window size in pixels (default 1280x720)
  --no-hud          start with the HUD off (default: the player HUD: name, km/h, gait)
  --look L          how creatures are drawn: body (default: flesh, skin and coat), xray
                    (the body translucent over the bones) or bones (bone sprites); key B
                    cycles them
  --out DIR         folder for key-triggered screenshots, GIFs and replays (default out)
  --help            this text

keys: A/D or Left/Right walk, Shift runs, Space/W/Up jumps, N next example, M random
      creature, C next character (humanoid, dog), B next look (body, x-ray, bones),
      H HUD (player, developer, off), F12/P screenshot, G GIF of the next seconds,
      R start/stop a replay, wheel zoom, F2 editors, Esc quits
editors: Ctrl+Z undo, Ctrl+Y (or Ctrl+Shift+Z) redo, Ctrl+S save the level, Delete removes
      the selected box
gamepad: left stick walks (half throw = walk speed, full = run), RB/RT run, A jumps,
      Y next example, X random creature, LB next character, Back HUD, Start replay
)";

Result<ParsedArgs> parse_game_args(const std::vector<std::string>& args) {
  ParsedArgs p;
  GameOptions& o = p.options;
  o.level.clear();  // empty = default (or the replay's level)
  bool frames_set = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    std::string v;
    auto value = [&]() -> bool {
      if (i + 1 >= args.size() || args[i + 1].empty()) return false;
      v = args[++i];
      return true;
    };
    auto number = [&](long lo, long hi, auto& out) -> Status {
      if (!value()) return Error{flag + ": missing value"};
      auto n = parse_int_arg(flag, v, lo, hi);
      if (!n.ok()) return n.error();
      out = static_cast<std::remove_reference_t<decltype(out)>>(n.value());
      return {};
    };
    auto text = [&](std::string& out) -> Status {
      if (!value()) return Error{flag + ": missing value"};
      out = v;
      return {};
    };
    Status s;
    if (flag == "--help" || flag == "-h") {
      p.help = true;
      return p;
    } else if (flag == "--level") {
      s = text(o.level);
    } else if (flag == "--creature") {
      s = text(o.creature_file);
    } else if (flag == "--example") {
      s = text(o.example);
    } else if (flag == "--character") {
      s = text(o.character);
    } else if (flag == "--npc-characters") {
      o.npc_characters = true;
    } else if (flag == "--seed") {
      long seed = 0;
      s = number(0, 2147483647L, seed);
      if (s.ok()) o.seed = static_cast<uint64_t>(seed);
    } else if (flag == "--npcs") {
      s = number(0, 64, o.npcs);
    } else if (flag == "--replay") {
      s = text(o.replay);
    } else if (flag == "--record") {
      s = text(o.record);
    } else if (flag == "--headless") {
      o.headless = true;
    } else if (flag == "--frames") {
      s = number(1, 10000000, o.frames);
      frames_set = true;
    } else if (flag == "--png") {
      s = text(o.png);
    } else if (flag == "--gif") {
      s = text(o.gif);
    } else if (flag == "--pixels-per-metre") {
      if (!value()) {
        s = Error{flag + ": missing value"};
      } else {
        char* end = nullptr;
        const double d = std::strtod(v.c_str(), &end);
        if (*end != '\0' || !(d > 0.0 && d <= 1e6)) s = Error{flag + ": expected a number in (0, 1000000], got \"" + v + "\""};
        else o.pixels_per_metre = static_cast<float>(d);
      }
    } else if (flag == "--gif-seconds") {
      long secs = 0;
      if (!value()) {
        s = Error{flag + ": missing value"};
      } else {
        char* end = nullptr;
        const double d = std::strtod(v.c_str(), &end);
        if (*end != '\0' || !(d >= 0.5 && d <= 60.0)) s = Error{flag + ": expected seconds in [0.5, 60], got \"" + v + "\""};
        else o.gif_seconds = static_cast<float>(d);
      }
      (void)secs;
    } else if (flag == "--state") {
      s = text(o.state);
    } else if (flag == "--hz") {
      s = number(30, 480, o.tick_hz);
    } else if (flag == "--threads") {
      s = number(0, 1024, o.threads);
    } else if (flag == "--no-vsync") {
      o.vsync = false;
    } else if (flag == "--fps-cap") {
      s = number(0, 1000, o.fps_cap);
    } else if (flag == "--size") {
      // Two sizes, told apart by their form: the window's (WIDTHxHEIGHT) and the creatures'
      // (true, or a frame in metres: a number).
      if (!value()) {
        s = Error{flag + ": missing value"};
      } else if (v.find('x') == std::string::npos) {
        auto size = parse_size_arg(flag, v);
        if (!size.ok()) {
          s = Error{flag + ": expected true or a frame in metres (a number in [0.05, 50]) for the creatures, or "
                           "WIDTHxHEIGHT for the window, got \"" + v + "\""};
        } else {
          o.size = size.value();
        }
      } else {
        const size_t x = v.find('x');
        auto w = parse_int_arg(flag + " width", v.substr(0, x), 16, 8192);
        auto h = parse_int_arg(flag + " height", v.substr(x + 1), 16, 8192);
        if (!w.ok() || !h.ok()) s = Error{flag + ": expected WIDTHxHEIGHT with sides in [16, 8192], got \"" + v + "\""};
        else o.width = static_cast<int>(w.value()), o.height = static_cast<int>(h.value());
      }
    } else if (flag == "--no-hud") {
      o.hud = false;
    } else if (flag == "--look") {
      if (!value()) {
        s = Error{flag + ": missing value"};
      } else if (const auto look = creature_look_from_name(v)) {
        o.look = *look;
      } else {
        s = Error{flag + ": expected body, xray or bones, got \"" + v + "\""};
      }
    } else if (flag == "--out") {
      s = text(o.out_dir);
    } else {
      s = Error{"unknown argument \"" + flag + "\" (see --help)"};
    }
    if (!s.ok()) return s.error();
  }
  const int sources = (o.creature_file.empty() ? 0 : 1) + (o.example.empty() ? 0 : 1) + (o.seed ? 1 : 0) +
                      (o.character.empty() ? 0 : 1);
  if (sources > 1) return Error{"give only one of --creature, --example, --seed, --character"};
  if (!o.replay.empty() && sources > 0) return Error{"--replay brings its own creature: drop --creature/--example/--seed/--character"};
  if (!o.replay.empty() && o.size) return Error{"--replay brings its own creature: drop --size true|FRAME_M"};
  if (frames_set && !o.headless && o.frames <= 0) return Error{"--frames: expected an integer >= 1"};
  if (o.headless) {
    o.demo = o.replay.empty();
    if (!frames_set && o.replay.empty()) o.frames = 600;
  }
  return p;
}

}  // namespace ossa
