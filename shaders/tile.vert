#version 330 core
// Tile program (level_view.h): a level's tile and image layers and an ossa level's box look,
// world space, shifted by the layer's parallax.
layout(location = 0) in vec2 a_position_ws;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_colour;   // multiplies the texel (a tile's own alpha)

uniform mat3 u_view_proj;   // world metres -> clip
uniform vec2 u_shift_ws;    // the layer's parallax shift, metres

out vec2 v_uv;
out vec4 v_colour;

void main() {
  v_uv = a_uv;
  v_colour = a_colour;
  gl_Position = vec4((u_view_proj * vec3(a_position_ws + u_shift_ws, 1.0)).xy, 0.0, 1.0);
}
