#version 330 core
// The per-bone reference path (CreatureBatch::draw_naive, benchmark only): one draw call per
// bone with its matrix in a uniform, as [T]'s RiggedShader uploaded bone matrices. Rigid:
// every vertex follows the bone of its draw.
layout(location = 0) in vec2 a_position_ms;
layout(location = 1) in vec2 a_uv;
layout(location = 4) in float a_shade;

uniform mat3 u_bone;        // palette entry of the bone being drawn
uniform mat3 u_view_proj;

out vec2 v_uv;
out float v_shade;

void main() {
  v_uv = a_uv;
  v_shade = a_shade;
  vec3 p_ws = u_bone * vec3(a_position_ms, 1.0);
  gl_Position = vec4((u_view_proj * vec3(p_ws.xy, 1.0)).xy, 0.0, 1.0);
}
