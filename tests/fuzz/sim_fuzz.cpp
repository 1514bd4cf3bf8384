// Fuzzes ossa-sim's inputs: the --script parser, an ossa level, and a few ticks of the
// script on that level with the horse (issue 17). Nothing may assert, hang or produce NaN;
// a refused script names "--script".
//
// Input: the first line is the script; the rest, when present, is a level file (ossa JSON).
// A level that does not load is replaced by a flat floor, so the script still runs. Each
// segment runs for at most 0.25 s (at most 8 segments), so one input stays fast.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>

#include "ossa/body/body_mesh.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/data_dir.h"
#include "ossa/level/level_io.h"

namespace {

std::shared_ptr<const ossa::Creature> horse() {
  static const std::shared_ptr<const ossa::Creature> creature = [] {
    auto generator = ossa::Generator::load(ossa::data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
    if (!generator.ok()) {
      std::fprintf(stderr, "fuzz_sim: %s\n", generator.message().c_str());
      std::abort();
    }
    auto built = ossa::build_creature(*generator->example("horse"));
    return std::make_shared<const ossa::Creature>(std::move(*built));
  }();
  return creature;
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_sim: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ossa;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const size_t newline = text.find('\n');
  const std::string_view script_text = text.substr(0, newline);
  const std::string_view level_text = newline == std::string_view::npos ? std::string_view() : text.substr(newline + 1);

  Result<std::vector<ScriptSegment>> script = parse_script(script_text);
  if (!script.ok()) {
    if (script.message().rfind("--script", 0) != 0) fail("a script error that does not name --script");
    return 0;
  }
  if (script->size() > 8) script->resize(8);
  for (ScriptSegment& s : *script) s.seconds = std::min(s.seconds, 0.25f);

  Level level(std::vector<Box>{Box::from_corner(-20.0f, -1.0f, 60.0f, 1.0f)});
  if (!level_text.empty()) {
    Result<Level> parsed = parse_level(level_text, "fuzz.level.json");
    if (parsed.ok()) {
      level = std::move(*parsed);
    } else if (parsed.message().rfind("fuzz.level.json", 0) != 0) {
      fail("a level error that does not name the file");
    }
  }

  Player player(horse(), SplinePrototypes::defaults());
  player.animator().reset(level.spawn_ws + glm::vec2(0.0f, 1.0f), level);
  const SimResult result = run_script(player, level, *script, 120);
  if (result.probe.nan_count > 0) fail("non-finite pose");
  if (!std::isfinite(result.x_reached)) fail("non-finite x");
  return 0;
}
