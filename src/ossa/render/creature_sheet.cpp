#include "ossa/render/creature_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace ossa {

namespace {

// The font draws ASCII: German letters become their usual spellings (ä ae, ö oe, ü ue, ß ss),
// any other UTF-8 sequence one '?'.
std::string ascii(const std::string& text) {
  static const std::pair<const char*, const char*> kLetters[] = {
      {"\xc3\xa4", "ae"}, {"\xc3\xb6", "oe"}, {"\xc3\xbc", "ue"}, {"\xc3\x84", "Ae"},
      {"\xc3\x96", "Oe"}, {"\xc3\x9c", "Ue"}, {"\xc3\x9f", "ss"}};
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const auto ch = static_cast<unsigned char>(text[i]);
    if (ch >= 32 && ch < 127) {
      out += text[i++];
      continue;
    }
    bool known = false;
    for (const auto& [utf8, plain] : kLetters) {
      if (text.compare(i, 2, utf8) == 0) {
        out += plain;
        i += 2;
        known = true;
        break;
      }
    }
    if (known) continue;
    out += '?';
    // Skip the sequence's continuation bytes.
    for (++i; i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80; ++i) {
    }
  }
  return out;
}

}  // namespace

int text_width(const std::string& text, int scale) {
  std::string t = ascii(text);
  return stb_easy_font_width(t.data()) * std::max(scale, 1);
}

void draw_text(Image& image, int x, int y, const std::string& text, glm::vec3 rgb, int scale) {
  std::string t = ascii(text);
  scale = std::max(scale, 1);
  // stb_easy_font emits quads: 4 vertices of (x, y, z, colour), 16 bytes each.
  std::vector<char> buffer(t.size() * 270 + 64);
  const int quads = stb_easy_font_print(0.0f, 0.0f, t.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
  for (int q = 0; q < quads; ++q) {
    float v[4][4];
    std::memcpy(v, buffer.data() + static_cast<size_t>(q) * 64, sizeof v);
    const int x0 = x + static_cast<int>(std::lround(v[0][0] * static_cast<float>(scale)));
    const int y0 = y + static_cast<int>(std::lround(v[0][1] * static_cast<float>(scale)));
    const int x1 = x + static_cast<int>(std::lround(v[2][0] * static_cast<float>(scale)));
    const int y1 = y + static_cast<int>(std::lround(v[2][1] * static_cast<float>(scale)));
    for (int py = std::max(y0, 0); py < std::min(y1, image.height); ++py) {
      for (int px = std::max(x0, 0); px < std::min(x1, image.width); ++px) {
        uint8_t* p = image.pixel(px, py);
        p[0] = static_cast<uint8_t>(std::lround(std::clamp(rgb.r, 0.0f, 1.0f) * 255.0f));
        p[1] = static_cast<uint8_t>(std::lround(std::clamp(rgb.g, 0.0f, 1.0f) * 255.0f));
        p[2] = static_cast<uint8_t>(std::lround(std::clamp(rgb.b, 0.0f, 1.0f) * 255.0f));
        p[3] = 255;
      }
    }
  }
}

Result<Image> render_sheet(Renderer& renderer, const Atlas& atlas,
                           const std::vector<std::pair<std::string, Creature>>& creatures,
                           const SheetOptions& options) {
  const int columns = std::max(options.columns, 1);
  const int rows = std::max(1, (static_cast<int>(creatures.size()) + columns - 1) / columns);
  const int cw = options.cell_width, ch = options.cell_height + options.label_height;
  Image sheet;
  sheet.width = columns * cw;
  sheet.height = rows * ch;
  sheet.rgba.assign(static_cast<size_t>(sheet.width) * sheet.height * 4, 255);
  for (size_t i = 0; i < creatures.size(); ++i) {
    CreatureImageOptions o;
    o.width = cw;
    o.height = options.cell_height;
    o.look = options.look;
    o.ground = true;
    o.margin = 0.06f;
    o.background = options.background;
    auto image = render_creature_image(renderer, atlas, creatures[i].second, o);
    if (!image.ok()) return Error{creatures[i].first + ": " + image.message()};
    const int x0 = static_cast<int>(i % static_cast<size_t>(columns)) * cw;
    const int y0 = static_cast<int>(i / static_cast<size_t>(columns)) * ch;
    for (int y = 0; y < image->height; ++y) {
      std::memcpy(sheet.pixel(x0, y0 + y), image->pixel(0, y), static_cast<size_t>(image->width) * 4);
    }
    const std::string& label = creatures[i].first;
    draw_text(sheet, x0 + std::max(2, (cw - text_width(label, 1)) / 2), y0 + options.cell_height + 6, label,
              {0.15f, 0.15f, 0.15f}, 1);
  }
  return sheet;
}

}  // namespace ossa
