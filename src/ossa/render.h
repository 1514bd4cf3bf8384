#pragma once
// ossa's drawing side in one include: src/ossa/platform (SDL2 window, input, images) and
// src/ossa/render (the OpenGL 3.3 renderer through libepoxy, CreatureBatch's GPU skinning,
// rigged meshes through Assimp, capture). Link ossa::render (find_package(ossa COMPONENTS
// render)); it brings ossa::draw and ossa::core, whose headers are <ossa/draw.h> and
// <ossa/ossa.h>.

#include "ossa/draw.h"
#include "ossa/ossa.h"

// platform: SDL2 window, mouse/keyboard and gamepad input, images
#include "ossa/platform/image.h"
#include "ossa/platform/input.h"
#include "ossa/platform/window.h"

// render: renderer, shaders, textures, CreatureBatch, rigged meshes, capture
#include "ossa/render/background.h"
#include "ossa/render/box_look.h"
#include "ossa/render/capture.h"
#include "ossa/render/character_mesh.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/creature_image.h"
#include "ossa/render/creature_sheet.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/gltf_export.h"
#include "ossa/render/level_view.h"
#include "ossa/render/render_target.h"
#include "ossa/render/renderer.h"
#include "ossa/render/rigged_batch.h"
#include "ossa/render/rigged_mesh.h"
#include "ossa/render/shader.h"
#include "ossa/render/texture.h"
#include "ossa/render/tile_atlas.h"
#include "ossa/render/vertex_array.h"
