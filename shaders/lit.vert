#version 330 core
// The stage and what stands on it, in 3D: positions in stage space (centred, scaled to the
// solid's radius), one normal and colour per vertex. Lit here, per vertex: faces and walls are
// flat (one normal per triangle) and the balls are fine enough, so per-pixel lighting would cost a
// software rasterizer much more for the same picture.
//
// A light from over the viewer's shoulder plus a term for facing the eye, so the face in front
// reads brightest and the faces turning away darken with their angle. A colour whose alpha is
// exactly 254/255 glows (drawn unlit: the goal, hazards).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(location = 3) in vec2 tile;  // a face's place in tiles (lit.frag)
uniform mat4 viewProjection;
uniform vec3 lightDirection;  // toward the light, unit length
uniform vec3 eye;
out vec4 litColor;
out vec2 tileCoord;
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  tileCoord = tile;
  if (abs(color.a - 254.0 / 255.0) < 0.001) {
    litColor = vec4(color.rgb, 1.0);
    return;
  }
  vec3 n = normalize(normal);
  float diffuse = max(dot(n, lightDirection), 0.0);
  vec3 toEye = normalize(eye - position);
  float facing = max(dot(n, toEye), 0.0);
  vec3 halfway = normalize(lightDirection + toEye);
  float shine = pow(max(dot(n, halfway), 0.0), 32.0) * 0.25;
  litColor = vec4(color.rgb * (0.30 + 0.40 * diffuse + 0.35 * facing) + vec3(shine), color.a);
}
