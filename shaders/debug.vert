#version 330 core
// DebugShader [T 4.3.1]: flat-coloured lines and triangles in world space (colliders,
// splines, targets). The per-vertex colour is multiplied by u_colour.
layout(location = 0) in vec2 a_position_ws;
layout(location = 1) in vec4 a_colour;

uniform mat3 u_view_proj;   // world metres -> clip

out vec4 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = vec4((u_view_proj * vec3(a_position_ws, 1.0)).xy, 0.0, 1.0);
}
