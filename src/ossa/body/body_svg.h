#pragma once
// SVG side views with bodies: a creature (or a contact sheet) as `look` shows it — its body,
// its body translucent over its bones (x-ray), or its bones (gen/export_svg.h). The body is
// drawn as its mesh's triangles in draw order (strokes before fills), each filled with the
// mean of its vertices' coat colours and the pattern at its centre (coat.h): the pattern at
// the mesh's resolution, where the game and ossa-render evaluate it per pixel.

#include <string>
#include <utility>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/export_svg.h"

namespace ossa {

// The SVG groups of a body (export_svg.h's SvgBody), in model coordinates.
SvgBody body_svg_layers(const BodyMesh& mesh, float opacity = 1.0f);

// creature_svg / sheet_svg with a look (body: no bones; xray: bones, then the body at
// kXrayBodyAlpha; bones: as before).
std::string look_svg(const Creature& creature, CreatureLook look, const SvgOptions& options = {});
std::string look_sheet_svg(const std::vector<std::pair<std::string, Creature>>& creatures, int columns,
                           const std::vector<int>& skull_variants, CreatureLook look,
                           const SvgOptions& options = {});

}  // namespace ossa
