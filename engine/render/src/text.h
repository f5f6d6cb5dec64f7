// Text drawn with SDL_ttf (DejaVu Sans from fonts-dejavu-core): each distinct string, size and
// colour is rendered once to a texture and kept while it is drawn; textures not drawn in the last 60
// flushes (a frame flushes up to three times: scene, heads-up lines, error overlay) are dropped.
#pragma once
#include <SDL2/SDL_ttf.h>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "gl_program.h"
#include "platon/core/draw_list.h"

namespace platon::render {

class Text {
 public:
  // Throws when the font cannot be opened (the message names the file and the package).
  Text();
  ~Text();
  Text(const Text&) = delete;
  Text& operator=(const Text&) = delete;

  // Queues `text` with its top left at `at`, `height` pixels tall. Returns its width in pixels.
  float draw(const std::string& text, core::Point2 at, float height, core::Color color);
  // Width in pixels `text` would take.
  float width(const std::string& text, float height);
  // Draws what was queued onto a screen of that many pixels, then forgets it.
  void flush(float screenWidth, float screenHeight);

 private:
  struct Texture {
    GLuint id = 0;
    int width = 0, height = 0;
    uint64_t lastFrame = 0;
  };
  struct Quad {
    GLuint texture;
    float x, y, w, h;
  };
  using Key = std::tuple<std::string, int, uint32_t>;
  TTF_Font* font(int pixels);
  const Texture* texture(const std::string& text, int pixels, core::Color color);

  std::string fontFile_;
  std::map<int, TTF_Font*> fonts_;
  std::map<Key, Texture> textures_;
  std::vector<Quad> queued_;
  uint64_t frame_ = 0;
  GlProgram program_;
  GLint screenSize_ = -1;
  GLuint vao_ = 0, vbo_ = 0;
};

}  // namespace platon::render
