#pragma once
// ossa's draw data in one include: src/ossa/draw — a creature and its pose as triangles any
// renderer can draw (creature_draw.h), bone-sprite meshes (sprite_mesh.h), the sprite atlas
// image (sprite_atlas.h) and image decoding (image.h). No SDL, no OpenGL: link ossa::draw
// (find_package(ossa)); it brings ossa::core, whose headers are <ossa/ossa.h>. ossa::render
// (<ossa/render.h>) draws the same meshes with OpenGL.

#include "ossa/ossa.h"

#include "ossa/draw/creature_draw.h"
#include "ossa/draw/image.h"
#include "ossa/draw/sprite_atlas.h"
#include "ossa/draw/sprite_mesh.h"
