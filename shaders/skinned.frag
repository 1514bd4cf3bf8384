#version 330 core
in vec2 v_uv;
in float v_shade;
uniform sampler2D u_atlas;
out vec4 o_colour;

void main() {
  vec4 texel = texture(u_atlas, v_uv);
  if (texel.a < 0.02) discard;
  o_colour = vec4(texel.rgb * v_shade, texel.a);
}
