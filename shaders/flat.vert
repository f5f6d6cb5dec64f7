#version 330 core
// Shapes in pixels from the top left; colours per vertex.
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
uniform vec2 screenSize;
out vec4 vertexColor;
void main() {
  gl_Position = vec4(position.x / screenSize.x * 2.0 - 1.0, 1.0 - position.y / screenSize.y * 2.0, 0.0, 1.0);
  vertexColor = color;
}
