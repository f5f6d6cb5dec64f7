#version 330 core
// A text quad in pixels from the top left, with its texture coordinates.
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
uniform vec2 screenSize;
out vec2 textureUv;
void main() {
  gl_Position = vec4(position.x / screenSize.x * 2.0 - 1.0, 1.0 - position.y / screenSize.y * 2.0, 0.0, 1.0);
  textureUv = uv;
}
