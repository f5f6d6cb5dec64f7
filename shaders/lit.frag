#version 330 core
// A light from over the viewer's shoulder plus a sky term, so the face in front reads brightest
// and the faces turning away darken with their angle. Alpha above 0.99 is lit; a colour whose
// alpha is exactly 254/255 glows (drawn unlit: the goal, hazards).
in vec3 worldNormal;
in vec4 vertexColor;
in vec3 worldPosition;
uniform vec3 lightDirection;  // toward the light, unit length
uniform vec3 eye;
out vec4 fragColor;
void main() {
  vec3 n = normalize(worldNormal);
  if (abs(vertexColor.a - 254.0 / 255.0) < 0.001) {
    fragColor = vec4(vertexColor.rgb, 1.0);
    return;
  }
  float diffuse = max(dot(n, lightDirection), 0.0);
  vec3 toEye = normalize(eye - worldPosition);
  float facing = max(dot(n, toEye), 0.0);
  vec3 halfway = normalize(lightDirection + toEye);
  float shine = pow(max(dot(n, halfway), 0.0), 32.0) * 0.25;
  vec3 lit = vertexColor.rgb * (0.30 + 0.40 * diffuse + 0.35 * facing) + vec3(shine);
  fragColor = vec4(lit, vertexColor.a);
}
