#version 330 core
// The stage and what stands on it, in 3D: positions in stage space (centred, scaled to the
// solid's radius), one normal and colour per vertex.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
uniform mat4 viewProjection;
out vec3 worldNormal;
out vec4 vertexColor;
out vec3 worldPosition;
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  worldNormal = normal;
  worldPosition = position;
  vertexColor = color;
}
