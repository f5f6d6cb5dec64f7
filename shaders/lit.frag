#version 330 core
// Lit per vertex (lit.vert).
in vec4 litColor;
out vec4 fragColor;
void main() { fragColor = litColor; }
