#version 330 core
in vec2 v_uv;
in vec4 v_colour;
uniform sampler2D u_texture;
uniform vec4 u_tint;        // the layer's tint, its opacity in alpha
out vec4 o_colour;

void main() {
  o_colour = texture(u_texture, v_uv) * v_colour * u_tint;
}
