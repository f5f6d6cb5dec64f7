#version 330 core
// Text rendered by SDL_ttf: colour and coverage come from the texture (premultiplied on upload).
in vec2 textureUv;
uniform sampler2D glyphs;
out vec4 fragColor;
void main() { fragColor = texture(glyphs, textureUv); }
