// ossa-level — inspects and converts level files of every format load_level reads (ossa
// levels, Tiled .tmj/.tmx maps, LDtk projects; level_load.h).
//
//   ossa-level info maps/cave.tmx            JSON: format, boxes, merge figures, bounds, spawn, warnings
//   ossa-level convert world.ldtk#Level_1 levels/cave.json   writes an ossa level atomically
//
// Every failure prints one line naming the file or flag and exits with status 1.

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"

using namespace ossa;

namespace {

const char* kUsage = R"(usage: ossa-level info FILE [--pixels-per-metre P]
       ossa-level convert IN OUT.json [--pixels-per-metre P]
  FILE, IN             an ossa level (.json), a Tiled map (.tmj, .json, .tmx) or an LDtk
                       project (.ldtk; pick a level with project.ldtk#LevelName, default the first)
  --pixels-per-metre P scale of maps with neither a pixels_per_metre property nor a tile size
                       (a map property wins, then one tile = 0.5 m, then this; default 32)
info prints JSON: format, boxes, merged_from_cells (solid cells -> boxes_from_cells), bounds,
spawn, pixels_per_metre and where it came from, warnings (e.g. a spawn with no ground below).
convert writes OUT as an ossa level (temporary file, fsync, rename); OUT may not be one of the
files read (the map, its tilesets, an LDtk project's level files).
)";

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "ossa-level: %s\n", message.c_str());
  std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> positional;
  LevelLoadOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (a == "--pixels-per-metre") {
      if (i + 1 >= argc) fail("--pixels-per-metre: expected a number > 0 after it");
      const char* text = argv[++i];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(text, &end);
      if (errno || end == text || *end || !(v > 0.0) || !(v <= 1e6)) {
        fail(std::string("--pixels-per-metre: expected a number in (0, 1000000], got \"") + text + "\"");
      }
      options.pixels_per_metre = static_cast<float>(v);
    } else if (a.size() > 1 && a[0] == '-') {
      fail("unknown option " + a + " (see --help)");
    } else {
      positional.push_back(a);
    }
  }
  if (positional.empty()) fail("expected a command: info FILE or convert IN OUT.json (see --help)");
  const std::string& command = positional[0];
  if (command == "info") {
    if (positional.size() != 2) fail("info: expected one FILE");
    LevelLoadReport report;
    Result<Level> level = load_level(positional[1], options, &report);
    if (!level) fail(level.message());
    const Box b = level->bounds();
    Json out = Json::object();
    out["file"] = positional[1];
    out["format"] = level_format_name(report.format);
    out["name"] = level->name;
    out["boxes"] = level->size();
    out["merged_from_cells"] = report.solid_cells;
    out["boxes_from_cells"] = report.boxes_from_cells;
    if (report.format != LevelFormat::kOssa) {
      out["pixels_per_metre"] = shortest_decimal(report.pixels_per_metre);
      out["scale_from"] = report.scale_from;
    }
    out["bounds"] = {{"x", shortest_decimal(b.min_ws.x)}, {"y", shortest_decimal(b.min_ws.y)},
                     {"w", shortest_decimal(b.width())}, {"h", shortest_decimal(b.height())}};
    out["spawn"] = {{"x", shortest_decimal(level->spawn_ws.x)}, {"y", shortest_decimal(level->spawn_ws.y)}};
    std::vector<std::string> warnings = report.warnings;
    for (std::string& w : level_warnings(*level)) warnings.push_back(std::move(w));
    // A background image must be in the level's folder (level_load.h resolve_level_resource).
    if (level->background && !level->background->image.empty()) {
      Result<std::string> image = resolve_level_resource(positional[1], "background.image", level->background->image);
      if (!image) warnings.push_back(image.message() + " (not drawn)");
    }
    out["warnings"] = warnings;
    std::printf("%s\n", json_text(out, 2).c_str());
    return 0;
  }
  if (command == "convert") {
    if (positional.size() != 3) fail("convert: expected IN and OUT.json");
    LevelLoadReport report;
    Result<Level> level = load_level(positional[1], options, &report);
    if (!level) fail(level.message());
    // Never over one of the files just read: the map, its tilesets, an LDtk project's levels.
    if (Status st = check_output_path("convert: OUT", positional[2], report.files); !st) fail(st.message());
    Status s = save_level(positional[2], *level);
    if (!s) fail(s.message());
    std::printf("wrote %s: %d boxes (%lld solid cells merged into %lld boxes)\n", positional[2].c_str(), level->size(),
                static_cast<long long>(report.solid_cells), static_cast<long long>(report.boxes_from_cells));
    for (const std::string& w : level_warnings(*level)) std::printf("warning: %s\n", w.c_str());
    return 0;
  }
  fail("unknown command \"" + command + "\"; expected info or convert (see --help)");
}
