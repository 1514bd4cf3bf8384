#include "ossa/level/level_io.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "ossa/io/file.h"
#include "ossa/io/json.h"

namespace ossa {

double shortest_decimal(float f) {
  if (!std::isfinite(f)) return static_cast<double>(f);
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), f);
  if (ec != std::errc()) return static_cast<double>(f);
  double d = 0.0;
  const auto [p, ec2] = std::from_chars(buf, end, d);
  if (ec2 != std::errc() || static_cast<float>(d) != f) return static_cast<double>(f);
  return d;
}

namespace {

// A size field: finite, > 0, <= kMaxLevelCoordinate. Returns 0 after an error.
double read_size(JsonReader& r, const Json& parent, const std::string& path, const char* key) {
  const double v = r.number(parent, path, key);
  if (r.failed()) return 0.0;
  if (v <= 0.0) {
    r.fail(json_path(path, key), "expected a number > 0, got " + describe_json(parent.at(key)));
    return 0.0;
  }
  // (A little slack: a box from -1000 to 1000 may be written as 2000.0001 when that is the
  // shortest width that rounds back to its far edge; the far edge is checked below.)
  if (v > 2.0 * kMaxLevelCoordinate * (1.0 + 1e-6)) {
    r.fail(json_path(path, key), "expected a number <= " + std::to_string(static_cast<int>(2.0 * kMaxLevelCoordinate)) +
                                     ", got " + describe_json(parent.at(key)));
    return 0.0;
  }
  return v;
}

std::optional<Background> read_background(JsonReader& r, const Json& doc) {
  if (!r.has(doc, "background")) return std::nullopt;
  const Json* bg = r.object(doc, "", "background");
  if (!bg) return std::nullopt;
  Background b;
  b.image = r.string_or(*bg, "background", "image", "");
  b.parallax = static_cast<float>(r.number_or(*bg, "background", "parallax", 0.5, 0.0, 1.0));
  if (r.has(*bg, "colour")) {
    const Json* c = r.array(*bg, "background", "colour");
    if (c && c->size() != 3) {
      r.fail("background.colour", "expected an array of 3 numbers (r, g, b), got " +
                                      std::to_string(c->size()) + " elements");
    } else if (c) {
      for (size_t i = 0; i < 3; ++i) {
        b.colour[static_cast<int>(i)] =
            static_cast<float>(r.as_number((*c)[i], json_path("background.colour", i), 0.0, 1.0));
      }
    }
  }
  return b;
}

std::optional<LevelLook> read_look(JsonReader& r, const Json& doc) {
  if (!r.has(doc, "look")) return std::nullopt;
  const Json* o = r.object(doc, "", "look");
  if (!o) return std::nullopt;
  LevelLook look;
  look.tileset = r.string(*o, "look", "tileset");
  if (!r.failed() && look.tileset.empty()) r.fail("look.tileset", "expected an image file name, got an empty string");
  look.tile_px = static_cast<int>(r.integer_or(*o, "look", "tile_px", 32, 1, 4096));
  look.tile_m = static_cast<float>(r.number_or(*o, "look", "tile_m", 0.5, 0.01, 100.0));
  look.top = static_cast<int>(r.integer_or(*o, "look", "top", 0, 0, 1 << 20));
  look.fill = static_cast<int>(r.integer_or(*o, "look", "fill", 0, 0, 1 << 20));
  look.top_left = static_cast<int>(r.integer_or(*o, "look", "top_left", -1, -1, 1 << 20));
  look.top_right = static_cast<int>(r.integer_or(*o, "look", "top_right", -1, -1, 1 << 20));
  look.left = static_cast<int>(r.integer_or(*o, "look", "left", -1, -1, 1 << 20));
  look.right = static_cast<int>(r.integer_or(*o, "look", "right", -1, -1, 1 << 20));
  return look;
}

}  // namespace

Result<Level> level_from_json(const Json& doc, std::string_view file) {
  JsonReader r{std::string(file)};
  if (!r.expect_object(doc, "")) return r.error();
  if (!r.has(doc, "format") && r.has(doc, "orientation")) {
    r.fail("format", "missing; this looks like a Tiled map: import it with import_tiled");
    return r.error();
  }
  const std::string format = r.string(doc, "", "format");
  if (r.failed()) return r.error();
  if (format != kLevelFormat) {
    r.fail("format", std::string("expected \"") + kLevelFormat + "\", got " + describe_json(doc.at("format")));
    return r.error();
  }
  r.integer(doc, "", "version", kLevelVersion, kLevelVersion);
  if (r.failed()) return r.error();

  Level level;
  level.name = r.string_or(doc, "", "name", "");
  if (const Json* spawn = r.object(doc, "", "spawn")) {
    level.spawn_ws.x = r.number_f(*spawn, "spawn", "x", -kMaxLevelCoordinate, kMaxLevelCoordinate);
    level.spawn_ws.y = r.number_f(*spawn, "spawn", "y", -kMaxLevelCoordinate, kMaxLevelCoordinate);
  }
  level.background = read_background(r, doc);
  level.look = read_look(r, doc);
  if (r.has(doc, "kill_height")) {
    level.kill_height_ws = r.number_f(doc, "", "kill_height", -kMaxLevelCoordinate, kMaxLevelCoordinate);
  }
  if (r.failed()) return r.error();

  const Json* colliders = r.array(doc, "", "colliders");
  if (!colliders) return r.error();
  if (colliders->size() > static_cast<size_t>(kMaxLevelColliders)) {
    r.fail("colliders", "expected at most " + std::to_string(kMaxLevelColliders) + " boxes, got " +
                            std::to_string(colliders->size()));
    return r.error();
  }
  std::vector<Box> boxes;
  boxes.reserve(colliders->size());
  for (size_t i = 0; i < colliders->size(); ++i) {
    const Json& c = (*colliders)[i];
    const std::string path = json_path("colliders", i);
    if (!r.expect_object(c, path)) return r.error();
    const double x = r.number(c, path, "x", -kMaxLevelCoordinate, kMaxLevelCoordinate);
    const double y = r.number(c, path, "y", -kMaxLevelCoordinate, kMaxLevelCoordinate);
    const double w = read_size(r, c, path, "w");
    const double h = read_size(r, c, path, "h");
    if (r.failed()) return r.error();
    // The far corner is x + w rounded once to a float, so saved files read back exactly; the
    // bound applies to that float, the edge the level holds (a writer's x + w may lie a
    // rounding step past 1000 m and still be the edge at 1000 m).
    const Box box{{static_cast<float>(x), static_cast<float>(y)},
                  {static_cast<float>(x + w), static_cast<float>(y + h)}};
    for (const auto& [key, far] : {std::pair{"w", box.max_ws.x}, std::pair{"h", box.max_ws.y}}) {
      if (far > static_cast<float>(kMaxLevelCoordinate)) {
        r.fail(json_path(path, key), "puts the box's far edge at " + std::to_string(far) + ", expected at most " +
                                         std::to_string(static_cast<int>(kMaxLevelCoordinate)) +
                                         " m from the origin (beyond it a float cannot keep 0.1 mm)");
        return r.error();
      }
    }
    if (!(box.min_ws.x < box.max_ws.x)) {
      r.fail(json_path(path, "w"), "too small to be represented at x = " + std::to_string(x));
      return r.error();
    }
    if (!(box.min_ws.y < box.max_ws.y)) {
      r.fail(json_path(path, "h"), "too small to be represented at y = " + std::to_string(y));
      return r.error();
    }
    boxes.push_back(box);
  }
  level.set_colliders(std::move(boxes));
  if (Status s = check_level(level, file); !s) return s.error();
  return level;
}

Status check_level(const Level& level, std::string_view file) {
  const float limit = static_cast<float>(kMaxLevelCoordinate);
  const auto outside = [&](float v) { return !(std::fabs(v) <= limit); };
  char text[256];
  if (outside(level.spawn_ws.x) || outside(level.spawn_ws.y)) {
    std::snprintf(text, sizeof text, "(%g, %g) lies more than %g m from the origin", double(level.spawn_ws.x),
                  double(level.spawn_ws.y), kMaxLevelCoordinate);
    return Error::at(file, "spawn", text);
  }
  if (level.kill_height_ws) {
    const float kill = *level.kill_height_ws;
    if (outside(kill)) {
      std::snprintf(text, sizeof text, "expected a number in [-%g, %g], got %g", kMaxLevelCoordinate, kMaxLevelCoordinate, double(kill));
      return Error::at(file, "kill_height", text);
    }
    // A creature starts at the spawn: below the kill height it would start again every tick.
    if (!(kill < level.spawn_ws.y)) {
      std::snprintf(text, sizeof text,
                    "expected below the spawn (y %g), got %g: a creature would start below the kill height and "
                    "start again every tick",
                    double(level.spawn_ws.y), double(kill));
      return Error::at(file, "kill_height", text);
    }
  }
  if (const std::optional<Box> b = level.empty() ? std::nullopt : std::optional<Box>(level.bounds())) {
    if (outside(b->min_ws.x) || outside(b->min_ws.y) || outside(b->max_ws.x) || outside(b->max_ws.y)) {
      for (int i = 0; i < level.size(); ++i) {
        const Box& c = level.box(i);
        if (outside(c.min_ws.x) || outside(c.min_ws.y) || outside(c.max_ws.x) || outside(c.max_ws.y)) {
          std::snprintf(text, sizeof text, "the box [%g, %g] x [%g, %g] reaches more than %g m from the origin",
                        double(c.min_ws.x), double(c.max_ws.x), double(c.min_ws.y), double(c.max_ws.y), kMaxLevelCoordinate);
          return Error::at(file, json_path("colliders", static_cast<size_t>(i)), text);
        }
      }
    }
  }
  if (level.size() > kMaxLevelColliders) {
    return Error::at(file, "colliders", "expected at most " + std::to_string(kMaxLevelColliders) + " boxes, got " +
                                            std::to_string(level.size()));
  }
  return {};
}

Result<Level> parse_level(std::string_view text, std::string_view file) {
  Result<Json> doc = parse_json(text, file);
  if (!doc) return doc.error();
  return level_from_json(*doc, file);
}

Result<Level> load_level(const std::string& path) { return load_level(path, LevelLoadOptions{}); }

namespace {

// The width (or height) to write for [lo, hi] so that the loader's float(x + w), with x the
// written corner, gives back exactly `hi`: the shortest decimal that does so (0.6 rather than
// 0.6000004 for the step from 10.6 to 11.2), else the exact difference.
double extent_for(float lo, float hi) {
  const double x = shortest_decimal(lo);
  const double exact = shortest_decimal(hi) - x;
  for (int digits = 1; digits <= 9; ++digits) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.*g", digits, exact);
    double w = 0.0;
    const auto [p, ec] = std::from_chars(buf, buf + std::strlen(buf), w);
    if (ec == std::errc() && w > 0.0 && static_cast<float>(x + w) == hi) return w;
  }
  return static_cast<double>(hi) - x;
}

}  // namespace

Json level_to_json(const Level& level) {
  Json doc = Json::object();
  doc["format"] = kLevelFormat;
  doc["version"] = kLevelVersion;
  doc["name"] = level.name;
  doc["spawn"] = {{"x", shortest_decimal(level.spawn_ws.x)}, {"y", shortest_decimal(level.spawn_ws.y)}};
  if (level.background) {
    const Background& b = *level.background;
    doc["background"] = {{"image", b.image},
                         {"parallax", shortest_decimal(b.parallax)},
                         {"colour", {shortest_decimal(b.colour.r), shortest_decimal(b.colour.g),
                                     shortest_decimal(b.colour.b)}}};
  }
  if (level.look) {
    const LevelLook& l = *level.look;
    Json look = {{"tileset", l.tileset}, {"tile_px", l.tile_px}, {"tile_m", shortest_decimal(l.tile_m)},
                 {"top", l.top}, {"fill", l.fill}};
    for (const auto& [key, value] : {std::pair{"top_left", l.top_left}, std::pair{"top_right", l.top_right},
                                     std::pair{"left", l.left}, std::pair{"right", l.right}}) {
      if (value >= 0) look[key] = value;
    }
    doc["look"] = std::move(look);
  }
  if (level.kill_height_ws) doc["kill_height"] = shortest_decimal(*level.kill_height_ws);
  Json colliders = Json::array();
  for (const Box& box : level.colliders()) {
    colliders.push_back({{"x", shortest_decimal(box.min_ws.x)},
                         {"y", shortest_decimal(box.min_ws.y)},
                         {"w", extent_for(box.min_ws.x, box.max_ws.x)},
                         {"h", extent_for(box.min_ws.y, box.max_ws.y)}});
  }
  doc["colliders"] = std::move(colliders);
  return doc;
}

std::string level_to_text(const Level& level) {
  // Same content as level_to_json, but in the documented key order and one collider per
  // line, so shipped levels read well and diff line by line.
  const Json doc = level_to_json(level);
  std::string out = "{\n";
  for (const char* key : {"format", "version", "name", "spawn", "background", "look", "kill_height"}) {
    if (!doc.contains(key)) continue;
    out += "  \"" + std::string(key) + "\": ";
    if (doc[key].is_object()) {
      // Keep the documented field order inside spawn and background too.
      nlohmann::ordered_json o;
      for (const char* k : {"x", "y", "image", "parallax", "colour", "tileset", "tile_px", "tile_m", "top", "top_left",
                            "top_right", "left", "right", "fill"}) {
        if (doc[key].contains(k)) o[k] = doc[key][k];
      }
      out += o.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    } else {
      out += json_text(doc[key]);
    }
    out += ",\n";
  }
  out += "  \"colliders\": [";
  const Json& colliders = doc["colliders"];
  for (size_t i = 0; i < colliders.size(); ++i) {
    nlohmann::ordered_json c;
    for (const char* k : {"x", "y", "w", "h"}) c[k] = colliders[i][k];
    out += (i == 0 ? "\n    " : ",\n    ") + c.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  }
  out += colliders.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

Status save_level(const std::string& path, const Level& level) {
  // Whatever is saved loads back: a level the loader would refuse is not written.
  if (Status s = check_level(level, path); !s) return Error{s.message() + " (not saved)"};
  return write_file_atomic(path, level_to_text(level));
}

}  // namespace ossa
