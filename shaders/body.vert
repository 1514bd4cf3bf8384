#version 330 core
// Bodies (issue 30, DESIGN.md §9): the same batched GPU skinning as the bone sprites
// (skinned.vert) — one palette of 2x3 matrices in a texture buffer, three RG32F texels each,
// every creature's vertices in one buffer with their palette base — for the body mesh built
// on the CPU (src/ossa/body/body_mesh.h). A vertex carries its coat: colour (countershaded),
// the pattern's colour and strength, the pattern kind and its coordinates in pattern cells.
layout(location = 0) in vec2 a_position_ms;   // bind (= rest) pose, creature model space, metres
layout(location = 1) in vec2 a_coat;          // pattern cells (rest pose), moves with the skin
layout(location = 2) in uvec4 a_bones;        // palette entries within the creature
layout(location = 3) in vec4 a_weights;       // sum to 1
layout(location = 4) in vec4 a_colour;        // sRGB + alpha
layout(location = 5) in vec4 a_pattern;       // sRGB of the pattern + its strength
layout(location = 6) in uint a_kind;          // CoatPattern
layout(location = 7) in uint a_palette_base;  // first palette entry of this creature
layout(location = 8) in uint a_floor_base;    // its floor: kBodyFloorEntries entries
layout(location = 9) in float a_overhang;     // metres past a top's ends it still holds
layout(location = 10) in uint a_foot;         // a leg's vertex: its foot (< 8), else 255

uniform samplerBuffer u_palette;
uniform mat3 u_view_proj;                     // world metres -> clip

out vec2 v_coat;
out vec4 v_colour;
out vec4 v_pattern;
flat out uint v_kind;

vec2 skin(uint bone, vec2 p) {
  int t = int(a_palette_base + bone) * 3;
  vec2 x_axis = texelFetch(u_palette, t).xy;
  vec2 y_axis = texelFetch(u_palette, t + 1).xy;
  vec2 origin = texelFetch(u_palette, t + 2).xy;
  return x_axis * p.x + y_axis * p.y + origin;
}

// The floor (src/ossa/body/body_floor.h, floor_point): box tops under the creature, two per
// palette entry (x from, x to, top; then the next), unused ones with x from > x to; flesh
// below a top over which it lies, or within a_overhang of its ends, is lifted onto it. A
// leg's flesh is held up past a top's ends only by the top its own foot stands on (four
// entries after the segments, two feet each), and only within a_overhang below it.
vec2 rest_on_floor(vec2 p) {
  bool leg = a_foot < 8u;
  float past = leg ? 0.0 : a_overhang;
  for (int k = 0; k < 4; ++k) {
    int t = int(a_floor_base) * 3 + k * 3;
    vec2 a = texelFetch(u_palette, t).xy;
    vec2 b = texelFetch(u_palette, t + 1).xy;
    vec2 c = texelFetch(u_palette, t + 2).xy;
    if (a.x > a.y) break;  // segments are filled in order
    if (p.x >= a.x - past && p.x <= a.y + past && p.y < b.x) p.y = b.x;
    if (b.y > c.x) break;
    if (p.x >= b.y - past && p.x <= c.x + past && p.y < c.y) p.y = c.y;
  }
  if (leg) {
    int t = (int(a_floor_base) + 4 + int(a_foot / 2u)) * 3;
    vec2 a = texelFetch(u_palette, t).xy;
    vec2 b = texelFetch(u_palette, t + 1).xy;
    vec2 c = texelFetch(u_palette, t + 2).xy;
    vec3 s = (a_foot % 2u) == 0u ? vec3(a, b.x) : vec3(b.y, c);
    if (s.x <= s.y && p.x >= s.x - a_overhang && p.x <= s.y + a_overhang && p.y < s.z && p.y > s.z - a_overhang) p.y = s.z;
  }
  return p;
}

void main() {
  vec2 p_ws = a_weights.x * skin(a_bones.x, a_position_ms);
  if (a_weights.y > 0.0) p_ws += a_weights.y * skin(a_bones.y, a_position_ms);
  if (a_weights.z > 0.0) p_ws += a_weights.z * skin(a_bones.z, a_position_ms);
  if (a_weights.w > 0.0) p_ws += a_weights.w * skin(a_bones.w, a_position_ms);
  p_ws = rest_on_floor(p_ws);
  v_coat = a_coat;
  v_colour = a_colour;
  v_pattern = a_pattern;
  v_kind = a_kind;
  gl_Position = vec4((u_view_proj * vec3(p_ws, 1.0)).xy, 0.0, 1.0);
}
