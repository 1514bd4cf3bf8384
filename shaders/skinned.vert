#version 330 core
// RiggedShader [T 4.3.1], batched: every creature's sprite mesh shares one vertex buffer and
// one palette of bone matrices in a texture buffer (CreatureBatch). A palette entry is a 2x3
// affine matrix stored as three RG32F texels: x axis, y axis, translation (Mat2x3 order).
// Each vertex carries its creature's palette base, baked in when the batch is uploaded, so
// one draw call per layer skins all creatures.
layout(location = 0) in vec2 a_position_ms;   // bind pose, creature model space, metres
layout(location = 1) in vec2 a_uv;            // atlas
layout(location = 2) in uvec4 a_bones;        // bone indices within the creature
layout(location = 3) in vec4 a_weights;       // sum to 1
layout(location = 4) in float a_shade;        // 1 near/body, < 1 far side
layout(location = 5) in uint a_palette_base;  // first palette entry of this creature

uniform samplerBuffer u_palette;
uniform mat3 u_view_proj;                     // world metres -> clip

out vec2 v_uv;
out float v_shade;

vec2 skin(uint bone, vec2 p) {
  int t = int(a_palette_base + bone) * 3;
  vec2 x_axis = texelFetch(u_palette, t).xy;
  vec2 y_axis = texelFetch(u_palette, t + 1).xy;
  vec2 origin = texelFetch(u_palette, t + 2).xy;
  return x_axis * p.x + y_axis * p.y + origin;
}

void main() {
  vec2 p_ws = a_weights.x * skin(a_bones.x, a_position_ms);
  if (a_weights.y > 0.0) p_ws += a_weights.y * skin(a_bones.y, a_position_ms);
  if (a_weights.z > 0.0) p_ws += a_weights.z * skin(a_bones.z, a_position_ms);
  if (a_weights.w > 0.0) p_ws += a_weights.w * skin(a_bones.w, a_position_ms);
  v_uv = a_uv;
  v_shade = a_shade;
  gl_Position = vec4((u_view_proj * vec3(p_ws, 1.0)).xy, 0.0, 1.0);
}
