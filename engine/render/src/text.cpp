#include "text.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <unistd.h>
#include <vector>

#include "shaders.h"

namespace platon::render {
namespace {

// The size a text is rendered at: whole pixels up to 25, above that a ladder of steps 4 % apart,
// and the quad scaled to the size asked for. A label on a face follows the camera's distance, and
// rendered at its exact size it made a texture (and opened the font at a new size) nearly every
// frame while the view moved.
int rung(float height) {
  const float h = std::clamp(height, 6.0f, 256.0f);
  if (h <= 25) return static_cast<int>(std::lround(h));
  return std::min(256,
                  static_cast<int>(std::lround(25 * std::pow(1.04f, std::round(std::log(h / 25) / std::log(1.04f))))));
}

}  // namespace

namespace {

constexpr const char* kFontFiles[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                      "/usr/share/fonts/TTF/DejaVuSans.ttf"};
constexpr uint64_t kKeepFrames = 60;

}  // namespace

Text::Text() : program_(shaders::text_vert, shaders::text_frag, "text") {
  if (!TTF_WasInit() && TTF_Init() != 0) throw std::runtime_error(std::string("SDL_ttf: ") + TTF_GetError());
  for (const char* file : kFontFiles)
    if (access(file, R_OK) == 0) fontFile_ = file;
  if (fontFile_.empty())
    throw std::runtime_error(std::string("no font: ") + kFontFiles[0] +
                             " is missing (Debian package fonts-dejavu-core)");
  screenSize_ = program_.uniform("screenSize");
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), reinterpret_cast<void*>(2 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
}

Text::~Text() {
  for (auto& [key, t] : textures_) glDeleteTextures(1, &t.id);
  for (auto& [size, f] : fonts_) TTF_CloseFont(f);
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

TTF_Font* Text::font(int pixels) {
  pixels = std::clamp(pixels, 6, 256);
  auto it = fonts_.find(pixels);
  if (it != fonts_.end()) return it->second;
  TTF_Font* f = TTF_OpenFont(fontFile_.c_str(), pixels);
  if (!f) throw std::runtime_error(fontFile_ + ": " + TTF_GetError());
  fonts_[pixels] = f;
  return f;
}

const Text::Texture* Text::texture(const std::string& text, int pixels, core::Color color) {
  const uint32_t rgba = uint32_t{color.r} << 24 | uint32_t{color.g} << 16 | uint32_t{color.b} << 8 | color.a;
  Key key{text, pixels, rgba};
  auto it = textures_.find(key);
  if (it != textures_.end()) {
    it->second.lastFrame = frame_;
    return &it->second;
  }
  SDL_Surface* rendered =
      TTF_RenderUTF8_Blended(font(pixels), text.c_str(), SDL_Color{color.r, color.g, color.b, color.a});
  if (!rendered) return nullptr;  // an empty string, say
  SDL_Surface* rgbaSurface = SDL_ConvertSurfaceFormat(rendered, SDL_PIXELFORMAT_ABGR8888, 0);
  SDL_FreeSurface(rendered);
  if (!rgbaSurface) return nullptr;
  // Premultiplied alpha, so that the blend (ONE, ONE_MINUS_SRC_ALPHA) gives clean edges.
  std::vector<uint8_t> pixelsOut(static_cast<size_t>(rgbaSurface->w) * rgbaSurface->h * 4);
  for (int y = 0; y < rgbaSurface->h; ++y) {
    const auto* row = static_cast<const uint8_t*>(rgbaSurface->pixels) + static_cast<ptrdiff_t>(y) * rgbaSurface->pitch;
    uint8_t* out = pixelsOut.data() + static_cast<size_t>(y) * rgbaSurface->w * 4;
    for (int x = 0; x < rgbaSurface->w; ++x) {
      const uint8_t a = row[4 * x + 3];
      for (int c = 0; c < 3; ++c) out[4 * x + c] = static_cast<uint8_t>(row[4 * x + c] * a / 255);
      out[4 * x + 3] = a;
    }
  }
  Texture t;
  t.width = rgbaSurface->w, t.height = rgbaSurface->h, t.lastFrame = frame_;
  SDL_FreeSurface(rgbaSurface);
  glGenTextures(1, &t.id);
  glBindTexture(GL_TEXTURE_2D, t.id);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t.width, t.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixelsOut.data());
  return &textures_.emplace(std::move(key), t).first->second;
}

float Text::width(const std::string& text, float height) {
  int w = 0, h = 0;
  const int pixels = rung(height);
  if (text.empty() || TTF_SizeUTF8(font(pixels), text.c_str(), &w, &h) != 0) return 0;
  return static_cast<float>(w) * std::clamp(height, 6.0f, 256.0f) / static_cast<float>(pixels);
}

float Text::draw(const std::string& text, core::Point2 at, float height, core::Color color) {
  if (text.empty()) return 0;
  const int pixels = rung(height);
  const Texture* t = texture(text, pixels, color);
  if (!t) return 0;
  const float scale = std::clamp(height, 6.0f, 256.0f) / static_cast<float>(pixels);
  queued_.push_back({t->id, at.x, at.y, static_cast<float>(t->width) * scale, static_cast<float>(t->height) * scale});
  return static_cast<float>(t->width) * scale;
}

void Text::flush(float screenWidth, float screenHeight) {
  if (!queued_.empty()) {
    glUseProgram(program_.id());
    glUniform2f(screenSize_, screenWidth, screenHeight);
    glUniform1i(program_.uniform("glyphs"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    for (const Quad& q : queued_) {
      const float v[] = {q.x, q.y, 0, 0, q.x + q.w, q.y,       1, 0, q.x + q.w, q.y + q.h, 1, 1,
                         q.x, q.y, 0, 0, q.x + q.w, q.y + q.h, 1, 1, q.x,       q.y + q.h, 0, 1};
      glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
      glBindTexture(GL_TEXTURE_2D, q.texture);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(0);
    queued_.clear();
  }
  ++frame_;
  for (auto it = textures_.begin(); it != textures_.end();) {
    if (frame_ - it->second.lastFrame > kKeepFrames) {
      glDeleteTextures(1, &it->second.id);
      it = textures_.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace platon::render
