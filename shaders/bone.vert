#version 330 core
// BoneShader [T 4.3.1]: skeleton lines from the same palette as the skinned shader. Two
// vertices per bone, its start and end in bind-pose model space, each with its palette entry.
layout(location = 0) in vec2 a_position_ms;
layout(location = 1) in uint a_palette_index;

uniform samplerBuffer u_palette;
uniform mat3 u_view_proj;

void main() {
  int t = int(a_palette_index) * 3;
  vec2 p_ws = texelFetch(u_palette, t).xy * a_position_ms.x +
              texelFetch(u_palette, t + 1).xy * a_position_ms.y + texelFetch(u_palette, t + 2).xy;
  gl_Position = vec4((u_view_proj * vec3(p_ws, 1.0)).xy, 0.0, 1.0);
}
