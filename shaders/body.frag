#version 330 core
// The coat of a body (src/ossa/body/coat.h, whose coat_pattern() is this on the CPU — keep
// the two in step): countershaded colour from the vertices, and a pattern from seeded noise in
// pattern cells, so it moves with the skin: integer hash (lowbias32), value noise with a
// smoothstep fade, Worley F1/F2 with one jittered point per cell.
in vec2 v_coat;
in vec4 v_colour;
in vec4 v_pattern;
flat in uint v_kind;
uniform float u_alpha;   // 1 for the body look; the x-ray look draws bodies translucent
out vec4 o_colour;

uint coat_hash(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}
uint cell_hash(ivec2 c) { return coat_hash(uint(c.x) * 0x9e3779b1u ^ coat_hash(uint(c.y) + 0x85ebca6bu)); }
float unit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

float value_noise(vec2 p) {
  vec2 f = floor(p);
  ivec2 i = ivec2(f);
  vec2 t = p - f;
  vec2 u = t * t * (3.0 - 2.0 * t);
  float a = unit(cell_hash(i)), b = unit(cell_hash(i + ivec2(1, 0)));
  float c = unit(cell_hash(i + ivec2(0, 1))), d = unit(cell_hash(i + ivec2(1, 1)));
  return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}

// Worley: x = F1, y = F2, z = the nearest cell's hash (as a float of its bits)
vec3 worley(vec2 p, out uint cell) {
  vec2 f = floor(p);
  ivec2 i = ivec2(f);
  float f1 = 8.0, f2 = 8.0;
  cell = 0u;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      uint h = cell_hash(i + ivec2(dx, dy));
      vec2 q = f + vec2(float(dx), float(dy)) + 0.1 + 0.8 * vec2(unit(h), unit(coat_hash(h)));
      float d = length(p - q);
      if (d < f1) { f2 = f1; f1 = d; cell = h; } else if (d < f2) { f2 = d; }
    }
  }
  return vec3(f1, f2, 0.0);
}

float pattern(uint kind, vec2 p, float aa) {
  uint cell;
  if (kind == 1u) {  // stripes
    float x = p.x + 0.2 * p.y + 0.9 * (value_noise(0.5 * p) - 0.5);
    float d = abs(x - floor(x) - 0.5);
    float w = 0.16 + 0.1 * value_noise(p + vec2(17.0, 5.0));
    return smoothstep(0.5 - w - aa, 0.5 - w + aa, d);
  } else if (kind == 2u) {  // spots
    vec3 w = worley(p, cell);
    float r = 0.16 + 0.14 * unit(coat_hash(cell + 1u));
    return 1.0 - smoothstep(r - aa, r + aa, w.x);
  } else if (kind == 3u) {  // rosettes
    vec3 w = worley(p, cell);
    float r_in = 0.17 + 0.06 * unit(coat_hash(cell + 2u)), r_out = r_in + 0.13;
    float ring = smoothstep(r_in - aa, r_in + aa, w.x) * (1.0 - smoothstep(r_out - aa, r_out + aa, w.x));
    return ring * smoothstep(0.3, 0.4, value_noise(3.3 * p));
  } else if (kind == 4u) {  // dapples
    float n = 0.6 * value_noise(p) + 0.4 * value_noise(2.3 * p + vec2(3.1, 7.7));
    return 0.85 * smoothstep(0.52 - aa, 0.6 + aa, n);
  } else if (kind == 5u) {  // patches
    vec3 w = worley(p, cell);
    return smoothstep(0.07 - aa, 0.07 + aa, w.y - w.x);
  }
  return 0.0;
}

void main() {
  vec3 rgb = v_colour.rgb;
  if (v_kind != 0u && v_pattern.a > 0.0) {
    float aa = max(0.75 * length(fwidth(v_coat)), 0.01);
    rgb = mix(rgb, v_pattern.rgb, pattern(v_kind, v_coat, aa) * v_pattern.a);
  }
  float alpha = v_colour.a * u_alpha;
  if (alpha < 0.004) discard;
  o_colour = vec4(rgb, alpha);
}
