// Tiled XML (.tmx maps, .tsx tilesets) to the JSON document Tiled writes for the same map
// (https://doc.mapeditor.org/en/stable/reference/tmx-map-format/ and json-map-format/), so
// one importer (tiled.cpp) reads both. Only what the importer uses is converted: map and
// layer attributes (offsets, opacity, visibility, tint, parallax, image layers' images and
// repeats), properties, tilesets (their image or their tiles' images, margin, spacing,
// tileoffset) and their tiles' properties and collision objects, tile data (CSV becomes an array, base64 stays a string with its encoding and compression,
// <tile gid> children become an array, <chunk>s become "chunks"), objects and their shape.
// Errors name the file and the element path in the JSON form ("layers[2].width").

#include "ossa/level/tiled.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "ossa/io/json.h"

namespace ossa {

namespace {

constexpr int kMaxDepth = 32;

struct Converter {
  std::string file;
  std::optional<Error> error;

  void fail(const std::string& path, const std::string& what) {
    if (!error) error = Error::at(file, path, what);
  }

  // A numeric attribute copied to `out[key]` (integer when it reads as one), when present.
  void number(const pugi::xml_node& n, const std::string& path, const char* attr, Json& out, const char* key = nullptr) {
    const pugi::xml_attribute a = n.attribute(attr);
    if (!a) return;
    const char* text = a.value();
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(text, &end, 10);
    if (*text && end && *end == '\0' && errno == 0) {
      out[key ? key : attr] = i;
      return;
    }
    errno = 0;
    const double d = std::strtod(text, &end);
    if (!*text || !end || *end != '\0' || errno == ERANGE || !std::isfinite(d)) {
      fail(json_path(path, attr), std::string("expected a number, got \"") + text + "\"");
      return;
    }
    out[key ? key : attr] = d;
  }

  static void text_attr(const pugi::xml_node& n, const char* attr, Json& out) {
    if (const pugi::xml_attribute a = n.attribute(attr)) out[attr] = a.value();
  }

  void properties(const pugi::xml_node& n, const std::string& path, Json& out) {
    const pugi::xml_node props = n.child("properties");
    if (!props) return;
    Json list = Json::array();
    size_t i = 0;
    for (const pugi::xml_node& p : props.children("property")) {
      const std::string ppath = json_path(json_path(path, "properties"), i++);
      const std::string type = p.attribute("type").as_string("string");
      const std::string value = p.attribute("value") ? p.attribute("value").value() : p.text().get();
      Json v;
      if (type == "bool") {
        v = value == "true";
      } else if (type == "int" || type == "float" || type == "object") {
        char* end = nullptr;
        errno = 0;
        const double d = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(d)) {
          fail(json_path(ppath, "value"), "expected a number, got \"" + value + "\"");
          return;
        }
        v = d;
      } else {
        v = value;
      }
      list.push_back({{"name", p.attribute("name").as_string()}, {"type", type}, {"value", std::move(v)}});
    }
    out["properties"] = std::move(list);
  }

  // CSV tile data to an array of gids.
  Json csv(const char* text, const std::string& path) {
    Json out = Json::array();
    const char* p = text;
    while (*p) {
      while (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t') ++p;
      if (!*p) break;
      char* end = nullptr;
      errno = 0;
      const unsigned long long v = std::strtoull(p, &end, 10);
      if (end == p || errno == ERANGE || v > 0xFFFFFFFFull || *p == '-' || *p == '+') {
        fail(path, "expected comma-separated tile gids, got \"" + std::string(p).substr(0, 20) + "\"");
        return out;
      }
      out.push_back(static_cast<uint32_t>(v));
      p = end;
      while (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t') ++p;
      if (*p == ',') ++p;
      else if (*p) {
        fail(path, "expected a comma between tile gids, got \"" + std::string(p).substr(0, 20) + "\"");
        return out;
      }
    }
    return out;
  }

  // The tile data of a <data> or <chunk> element in `encoding`.
  Json data(const pugi::xml_node& n, const std::string& encoding, const std::string& path) {
    if (encoding == "csv") return csv(n.text().get(), path);
    if (encoding == "base64") {
      std::string s = n.text().get();
      s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }), s.end());
      return s;
    }
    if (!encoding.empty()) {
      fail(path, "expected encoding \"csv\" or \"base64\", got \"" + encoding + "\"");
      return Json::array();
    }
    // <tile gid="..."/> children: a gid is 32 bits (the tile id and the flip flags); a larger
    // number is an error, not wrapped to another tile.
    Json out = Json::array();
    size_t i = 0;
    for (const pugi::xml_node& t : n.children("tile")) {
      const char* text = t.attribute("gid").as_string("0");
      char* end = nullptr;
      errno = 0;
      const unsigned long long v = std::strtoull(text, &end, 10);
      if (end == text || *end || errno == ERANGE || v > 0xFFFFFFFFull || *text == '-' || *text == '+' || *text == ' ') {
        fail(json_path(path, i), "expected a tile gid (an integer in [0, 4294967295]), got \"" + std::string(text).substr(0, 24) + "\"");
        return out;
      }
      out.push_back(static_cast<uint32_t>(v));
      ++i;
    }
    return out;
  }

  Json object(const pugi::xml_node& o, const std::string& path) {
    Json out = Json::object();
    for (const char* a : {"name", "type", "class"}) text_attr(o, a, out);
    for (const char* a : {"id", "x", "y", "width", "height", "rotation", "gid"}) number(o, path, a, out);
    if (o.child("point")) out["point"] = true;
    if (o.child("ellipse")) out["ellipse"] = true;
    if (o.child("polygon")) out["polygon"] = Json::array();
    if (o.child("polyline")) out["polyline"] = Json::array();
    if (o.child("text")) out["text"] = Json::object();
    properties(o, path, out);
    return out;
  }

  Json objects(const pugi::xml_node& group, const std::string& path) {
    Json list = Json::array();
    size_t i = 0;
    for (const pugi::xml_node& o : group.children("object")) list.push_back(object(o, json_path(json_path(path, "objects"), i++)));
    return list;
  }

  // An element's <image source width height> as Tiled's JSON fields image, imagewidth, imageheight.
  void image(const pugi::xml_node& n, const std::string& path, Json& out) {
    const pugi::xml_node img = n.child("image");
    if (!img) return;
    out["image"] = img.attribute("source").as_string();
    number(img, path, "width", out, "imagewidth");
    number(img, path, "height", out, "imageheight");
  }

  // A 0/1 attribute as a JSON bool, when present.
  static void flag(const pugi::xml_node& n, const char* attr, Json& out) {
    if (const pugi::xml_attribute a = n.attribute(attr)) out[attr] = a.as_int(1) != 0;
  }

  Json tileset(const pugi::xml_node& ts, const std::string& path) {
    Json out = Json::object();
    number(ts, path, "firstgid", out);
    for (const char* a : {"source", "name"}) text_attr(ts, a, out);
    for (const char* a : {"tilewidth", "tileheight", "tilecount", "columns", "margin", "spacing"}) number(ts, path, a, out);
    text_attr(ts, "tilerendersize", out);
    properties(ts, path, out);
    image(ts, path, out);
    if (const pugi::xml_node o = ts.child("tileoffset")) {
      Json offset = Json::object();
      for (const char* a : {"x", "y"}) number(o, json_path(path, "tileoffset"), a, offset);
      out["tileoffset"] = std::move(offset);
    }
    Json tiles = Json::array();
    size_t i = 0;
    for (const pugi::xml_node& t : ts.children("tile")) {
      const std::string tpath = json_path(json_path(path, "tiles"), i++);
      Json tile = Json::object();
      number(t, tpath, "id", tile);
      for (const char* a : {"type", "class"}) text_attr(t, a, tile);
      properties(t, tpath, tile);
      image(t, tpath, tile);
      if (const pugi::xml_node og = t.child("objectgroup")) {
        tile["objectgroup"] = {{"type", "objectgroup"}, {"objects", objects(og, json_path(tpath, "objectgroup"))}};
      }
      tiles.push_back(std::move(tile));
    }
    if (!tiles.empty()) out["tiles"] = std::move(tiles);
    return out;
  }

  Json layers(const pugi::xml_node& parent, const std::string& parent_path, int depth) {
    Json list = Json::array();
    if (depth > kMaxDepth) {
      fail(parent_path, "group layers nested more than " + std::to_string(kMaxDepth) + " deep");
      return list;
    }
    size_t i = 0;
    for (const pugi::xml_node& n : parent.children()) {
      const std::string name = n.name();
      if (name != "layer" && name != "objectgroup" && name != "imagelayer" && name != "group") continue;
      const std::string path = json_path(json_path(parent_path, "layers"), i++);
      Json layer = Json::object();
      layer["type"] = name == "layer" ? "tilelayer" : name;
      for (const char* a : {"name", "class"}) text_attr(n, a, layer);
      for (const char* a : {"id", "width", "height", "offsetx", "offsety", "parallaxx", "parallaxy", "opacity"}) number(n, path, a, layer);
      text_attr(n, "tintcolor", layer);
      flag(n, "visible", layer);
      properties(n, path, layer);
      if (name == "layer") {
        const pugi::xml_node d = n.child("data");
        if (!d) {
          fail(path, "a <layer> without <data>");
        } else {
          const std::string encoding = d.attribute("encoding").as_string();
          const std::string compression = d.attribute("compression").as_string();
          if (!encoding.empty() && encoding != "csv") layer["encoding"] = encoding;
          if (!compression.empty()) layer["compression"] = compression;
          if (d.child("chunk")) {
            Json chunks = Json::array();
            size_t k = 0;
            for (const pugi::xml_node& c : d.children("chunk")) {
              const std::string cpath = json_path(json_path(path, "chunks"), k++);
              Json chunk = Json::object();
              for (const char* a : {"x", "y", "width", "height"}) number(c, cpath, a, chunk);
              chunk["data"] = data(c, encoding, json_path(cpath, "data"));
              chunks.push_back(std::move(chunk));
            }
            layer["chunks"] = std::move(chunks);
          } else {
            layer["data"] = data(d, encoding, json_path(path, "data"));
          }
        }
      } else if (name == "objectgroup") {
        layer["objects"] = objects(n, path);
      } else if (name == "imagelayer") {
        image(n, path, layer);
        flag(n, "repeatx", layer);
        flag(n, "repeaty", layer);
      } else {
        layer["layers"] = layers(n, path, depth + 1);
      }
      list.push_back(std::move(layer));
    }
    return list;
  }
};

Result<pugi::xml_document*> parse_xml(pugi::xml_document& doc, std::string_view text, std::string_view file) {
  if (auto enc = non_utf8_encoding(text)) {
    return Error::at(file, "", "is " + *enc + " text; Tiled files must be UTF-8 (save it as UTF-8)");
  }
  // Names and properties become JSON strings, which must be UTF-8 (and XML declares it here).
  if (const size_t bad = first_invalid_utf8(text); bad != std::string_view::npos) {
    const size_t line = 1 + static_cast<size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n'));
    return Error::at(file, "", "not valid UTF-8 at byte " + std::to_string(bad) + " (line " + std::to_string(line) +
                                   "); save the map as UTF-8");
  }
  const pugi::xml_parse_result pr = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!pr) {
    return Error::at(file, "", std::string("not valid XML at byte ") + std::to_string(pr.offset) + ": " + pr.description());
  }
  return &doc;
}

}  // namespace

Result<Json> tmx_to_json(std::string_view text, std::string_view file) {
  pugi::xml_document doc;
  if (auto p = parse_xml(doc, text, file); !p) return p.error();
  const pugi::xml_node map = doc.child("map");
  if (!map) {
    const char* root = doc.first_child() ? doc.first_child().name() : "";
    return Error::at(file, "", std::string("expected a Tiled map (root element <map>), got <") + root + ">");
  }
  Converter c{std::string(file), std::nullopt};
  Json out = Json::object();
  out["type"] = "map";
  for (const char* a : {"orientation", "backgroundcolor", "version", "tiledversion"}) Converter::text_attr(map, a, out);
  for (const char* a : {"width", "height", "tilewidth", "tileheight", "parallaxoriginx", "parallaxoriginy"}) c.number(map, "", a, out);
  out["infinite"] = map.attribute("infinite").as_int(0) != 0;
  c.properties(map, "", out);
  Json tilesets = Json::array();
  size_t i = 0;
  for (const pugi::xml_node& ts : map.children("tileset")) tilesets.push_back(c.tileset(ts, json_path("tilesets", i++)));
  out["tilesets"] = std::move(tilesets);
  out["layers"] = c.layers(map, "", 0);
  if (c.error) return *c.error;
  return out;
}

Result<Json> tsx_to_json(std::string_view text, std::string_view file) {
  pugi::xml_document doc;
  if (auto p = parse_xml(doc, text, file); !p) return p.error();
  const pugi::xml_node ts = doc.child("tileset");
  if (!ts) {
    const char* root = doc.first_child() ? doc.first_child().name() : "";
    return Error::at(file, "", std::string("expected a Tiled tileset (root element <tileset>), got <") + root + ">");
  }
  Converter c{std::string(file), std::nullopt};
  Json out = c.tileset(ts, "");
  if (c.error) return *c.error;
  return out;
}

}  // namespace ossa
