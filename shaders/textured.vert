#version 330 core
// TexturedShader [T 4.3.1]: background and sprite quads, world space.
layout(location = 0) in vec2 a_position_ws;
layout(location = 1) in vec2 a_uv;

uniform mat3 u_view_proj;   // world metres -> clip

out vec2 v_uv;

void main() {
  v_uv = a_uv;
  gl_Position = vec4((u_view_proj * vec3(a_position_ws, 1.0)).xy, 0.0, 1.0);
}
