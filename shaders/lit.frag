#version 330 core
// Lit per vertex (lit.vert). A face's surface (alpha 253) is drawn in tiles: a darker line where
// its coordinates in tiles cross a whole number. Per pixel, because long thin triangles for the
// lines cost a software rasterizer far more than a few instructions a pixel.
in vec4 litColor;
in vec2 tileCoord;
out vec4 fragColor;
void main() {
  if (abs(litColor.a - 253.0 / 255.0) < 0.001) {
    vec2 d = abs(fract(tileCoord) - 0.5);  // 0.5 on a line between tiles
    fragColor = vec4(litColor.rgb * (max(d.x, d.y) > 0.485 ? 0.84 : 1.0), 1.0);
  } else {
    fragColor = litColor;
  }
}
