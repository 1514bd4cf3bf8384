// load_level(path, options): format dispatch for every level file ossa reads (level_load.h).

#include "ossa/level/level_load.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/ldtk.h"
#include "ossa/level/level_io.h"
#include "ossa/level/tiled.h"

namespace ossa {

namespace {

std::string extension(std::string_view path) {
  std::string ext = std::filesystem::path(std::string(path)).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The first character that is not white space or a UTF-8 byte order mark.
char first_char(std::string_view text) {
  size_t i = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return i < text.size() ? text[i] : '\0';
}

std::optional<LevelFormat> format_of_json(const Json& doc) {
  if (!doc.is_object()) return std::nullopt;
  if (doc.contains("format")) return LevelFormat::kOssa;
  if ((doc.contains("__header__") || doc.contains("jsonVersion")) && doc.contains("levels")) return LevelFormat::kLdtk;
  if (doc.contains("orientation") || doc.contains("tilewidth") || doc.contains("tileheight") ||
      (doc.contains("type") && doc["type"] == "map")) {
    return LevelFormat::kTiledJson;
  }
  return std::nullopt;
}

std::optional<LevelFormat> format_of_extension(std::string_view path) {
  const std::string ext = extension(path);
  if (ext == ".tmx") return LevelFormat::kTiledXml;
  if (ext == ".tmj") return LevelFormat::kTiledJson;
  if (ext == ".ldtk") return LevelFormat::kLdtk;
  return std::nullopt;
}

}  // namespace

const char* level_format_name(LevelFormat format) {
  switch (format) {
    case LevelFormat::kOssa: return "ossa";
    case LevelFormat::kTiledJson: return "tiled-json";
    case LevelFormat::kTiledXml: return "tiled-xml";
    case LevelFormat::kLdtk: return "ldtk";
  }
  return "ossa";
}

std::vector<std::string> level_warnings(const Level& level) {
  std::vector<std::string> out;
  if (level.empty()) {
    out.push_back("the level has no colliders: nothing to stand on");
    return out;
  }
  const glm::vec2 s = level.spawn_ws;
  char at[96];
  std::snprintf(at, sizeof(at), "(%.3g, %.3g)", double(s.x), double(s.y));
  if (level.point_inside(s + glm::vec2(0.0f, 0.01f))) {
    out.push_back(std::string("the spawn ") + at + " is inside a box");
  }
  const float kill = level.kill_y();
  const auto g = s.y > kill ? level.ground_height_below(s.x - 0.05f, s.x + 0.05f, s.y + 0.01f, s.y + 0.01f - kill) : std::nullopt;
  if (!g) {
    char text[256];
    std::snprintf(text, sizeof(text),
                  "the spawn %s has no ground below it: creatures fall to the kill height (y %.3g) and start again there",
                  at, double(kill));
    out.push_back(text);
  } else if (s.y - g->height_ws > 0.05f) {
    char gap[256];
    std::snprintf(gap, sizeof(gap), "the spawn %s is %.3g m above the ground below it; the creature drops", at,
                  double(s.y - g->height_ws));
    out.push_back(gap);
  }
  return out;
}

LevelFormat detect_level_format(std::string_view text, std::string_view path) {
  const char c = first_char(text);
  if (c == '<') return LevelFormat::kTiledXml;
  if (c == '{') {
    Result<Json> doc = parse_json(text, path);
    if (doc) {
      if (auto f = format_of_json(*doc)) return *f;
    }
  }
  return format_of_extension(path).value_or(LevelFormat::kOssa);
}

Result<Level> parse_level_any(std::string_view text, const std::string& file, const LevelLoadOptions& options,
                              LevelLoadReport* report, const FileLoader& loader, const std::string& level_name) {
  OSSA_ASSERT(options.pixels_per_metre > 0.0f && std::isfinite(options.pixels_per_metre),
              "LevelLoadOptions::pixels_per_metre must be > 0");
  LevelLoadReport local;
  LevelLoadReport& rep = report ? *report : local;
  std::vector<std::string> files = std::move(rep.files);  // load_level's, kept
  rep = LevelLoadReport{};
  rep.files = std::move(files);
  if (auto enc = non_utf8_encoding(text)) {
    return Error::at(file, "", "is " + *enc + " text; level files must be UTF-8 (save it as UTF-8)");
  }
  // Parse JSON once: the content decides, the extension only when the content says nothing.
  std::optional<Result<Json>> doc;
  LevelFormat format;
  if (first_char(text) == '<') {
    format = LevelFormat::kTiledXml;
  } else {
    doc.emplace(parse_json(text, file));
    std::optional<LevelFormat> f = *doc ? format_of_json(**doc) : std::nullopt;
    format = f ? *f : format_of_extension(file).value_or(LevelFormat::kOssa);
    if (format == LevelFormat::kTiledXml) format = LevelFormat::kTiledJson;  // JSON text named .tmx
    if (!*doc) return doc->error();
  }
  rep.format = format;
  if (!level_name.empty() && format != LevelFormat::kLdtk) {
    return Error::at(file, "", "\"#" + level_name + "\" picks a level of an LDtk project, but this is a " +
                                   level_format_name(format) + " file");
  }
  switch (format) {
    case LevelFormat::kOssa:
      return level_from_json(**doc, file);
    case LevelFormat::kTiledJson:
    case LevelFormat::kTiledXml: {
      TiledOptions o;
      o.pixels_per_metre = options.pixels_per_metre;
      o.tile_is_half_metre = true;
      o.read_file = loader;
      return format == LevelFormat::kTiledXml ? import_tmx(text, file, o, &rep)
                                              : import_tiled_json(**doc, file, o, &rep);
    }
    case LevelFormat::kLdtk: {
      LdtkOptions o;
      o.pixels_per_metre = options.pixels_per_metre;
      o.passable = options.ldtk_passable;
      o.read_file = loader;
      return import_ldtk_json(**doc, file, level_name, o, &rep);
    }
  }
  return Error::at(file, "", "unknown level format");
}

Result<Level> load_level(const std::string& path, const LevelLoadOptions& options, LevelLoadReport* report) {
  // "project.ldtk#Level" picks a level, unless a file of that very name exists.
  std::string file = path, level_name;
  const size_t hash = path.rfind('#');
  std::error_code ec;
  if (hash != std::string::npos && !std::filesystem::exists(path, ec)) {
    file = path.substr(0, hash);
    level_name = path.substr(hash + 1);
    if (level_name.empty()) return Error::at(path, "", "expected a level name after '#'");
  }
  Result<std::string> text = read_file(file);
  if (!text) return text.error();
  LevelLoadReport local;
  LevelLoadReport& rep = report ? *report : local;
  rep.files = {file};
  const FileLoader loader = [&rep](const std::string& p) {
    rep.files.push_back(p);
    return read_file(p);
  };
  return parse_level_any(*text, file, options, &rep, loader, level_name);
}

Result<std::string> resolve_level_resource(const std::string& level_file, std::string_view field,
                                           const std::string& resource, const std::string& fallback_folder) {
  namespace fs = std::filesystem;
  std::string file = level_file;
  std::error_code ec;
  if (const size_t hash = file.rfind('#'); hash != std::string::npos && !fs::exists(file, ec)) file.resize(hash);
  const fs::path rel(resource);
  if (resource.empty()) return Error::at(file, field, "expected a file name, got an empty string");
  const fs::path norm = rel.lexically_normal();
  if (rel.is_absolute() || rel.has_root_name() || (!norm.empty() && *norm.begin() == "..")) {
    return Error::at(file, field, "\"" + resource + "\" leaves the level's folder; name a file in it or below it");
  }
  const fs::path folder = fs::path(file).parent_path();
  const fs::path in_level = folder / norm;
  if (fs::exists(in_level, ec) || fallback_folder.empty()) return in_level.string();
  const fs::path in_fallback = fs::path(fallback_folder) / norm;
  if (fs::exists(in_fallback, ec)) return in_fallback.string();
  return in_level.string();  // missing: the reader names it
}

}  // namespace ossa
