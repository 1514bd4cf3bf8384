#version 330 core
in vec4 v_colour;
uniform vec4 u_colour;      // tint, (1,1,1,1) for the vertex colours as they are
out vec4 o_colour;

void main() {
  o_colour = v_colour * u_colour;
}
