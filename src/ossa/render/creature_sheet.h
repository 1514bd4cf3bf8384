#pragma once
// Contact sheets: many creatures in a grid, each drawn by render_creature_image (the game's
// renderer, offscreen) in its rest pose on a ground strip, with its name written below it
// (stb_easy_font's built-in font, ASCII: other characters print as '?'). ossa-gen --sheet
// F.png writes one; --sheet F.svg is the vector version (gen/export_svg.h, body/body_svg.h).

#include <string>
#include <utility>
#include <vector>

#include "ossa/gen/creature.h"
#include "ossa/io/result.h"
#include "ossa/platform/image.h"
#include "ossa/render/creature_image.h"

namespace ossa {

struct SheetOptions {
  int columns = 8;             // >= 1
  int cell_width = 256;        // pixels
  int cell_height = 190;       // pixels, the picture above the label
  int label_height = 22;       // pixels
  CreatureLook look = CreatureLook::kBody;
  glm::vec4 background{0.62f, 0.75f, 0.87f, 1.0f};
};

// The sheet of `creatures` (label, creature), row by row. Needs a current GL context.
Result<Image> render_sheet(Renderer& renderer, const Atlas& atlas,
                           const std::vector<std::pair<std::string, Creature>>& creatures,
                           const SheetOptions& options = {});

// Writes `text` into `image` at pixel (x, y) (top-left), `scale` pixels per font unit, opaque
// `rgb` (stb_easy_font's font; characters outside ASCII 32–126 print as '?').
void draw_text(Image& image, int x, int y, const std::string& text, glm::vec3 rgb, int scale = 1);
// The width in pixels of `text` at `scale`.
int text_width(const std::string& text, int scale = 1);

}  // namespace ossa
