#version 330 core
in vec2 v_uv;
uniform sampler2D u_texture;
uniform vec4 u_tint;        // multiplies the texel
out vec4 o_colour;

void main() {
  o_colour = texture(u_texture, v_uv) * u_tint;
}
