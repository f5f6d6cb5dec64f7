#include "render_system.h"

#include <SDL2/SDL_image.h>
#include <algorithm>
#include <cstdio>
#include <epoxy/gl.h>
#include <stdexcept>

#include "batch.h"
#include "hud_layout.h"
#include "stage_renderer.h"
#include "text.h"
#include "window.h"

namespace platon::render {
namespace {

using core::Color;
using core::Point2;

constexpr Color kBackground{20, 17, 36, 255};  // dusk: a deep indigo behind the solid

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    for (size_t tab; (tab = line.find('\t')) != std::string::npos;) line.replace(tab, 1, "    ");
    out.push_back(std::move(line));
    start = end + 1;
  }
  return out;
}

// The draw list's shapes not drawn in 3D: text on faces, flat over the picture at the height its
// face's distance gives it (hidden while a menu covers the world), and the screen's own shapes,
// from points to pixels.
void drawFlatShapes(const core::View& view, const core::DrawList& draw, StageRenderer& stage, Batch& batch, Text& text,
                    float dpi) {
  const auto points = draw.points();
  for (const core::DrawShape& s : draw.shapes()) {
    if (!s.place.screen) {
      Point2 at;
      float pixels = 0;  // the text's height on the screen, as far away as its face is
      // Text on a face is drawn flat over the picture: hidden while a menu covers the world.
      if (s.kind == core::ShapeKind::Text && view.centreText.empty() &&
          stage.project(s.place.face, s.at, s.size, at, pixels))
        text.draw(std::string(draw.text(s)), at, std::max(6.0f, pixels), s.color);
      continue;
    }
    auto at = [&](Point2 p) { return Point2{p.x * dpi, p.y * dpi}; };
    switch (s.kind) {
      case core::ShapeKind::Circle:
        batch.circle(at(s.at), s.size * dpi, s.color);
        break;
      case core::ShapeKind::Line:
        for (uint32_t i = 1; i < s.count; ++i)
          batch.line(at(points[s.first + i - 1]), at(points[s.first + i]), std::max(1.0f, s.size * dpi), s.color);
        break;
      case core::ShapeKind::Polygon: {
        std::vector<Point2> p;
        for (uint32_t i = 0; i < s.count; ++i) p.push_back(at(points[s.first + i]));
        batch.polygon(p, s.color);
        break;
      }
      case core::ShapeKind::Text:
        text.draw(std::string(draw.text(s)), at(s.at), std::max(6.0f, s.size * dpi), s.color);
        break;
      case core::ShapeKind::Wall:  // on faces only (the world's platforms)
        break;
    }
  }
}

// The laid-out text: the centre block on its dark band (its first line a title), the heads-up
// lines and the frame rate each on a dark box.
void drawScreenText(const ScreenLayout& layout, Batch& batch, Text& text, float width, float height, float dpi) {
  if (!layout.centre.empty()) {
    const TextBox& band = layout.centreBand;
    batch.rectangle({band.x, band.y}, {band.width, band.height}, {0, 0, 0, 170});
    batch.flush(width, height);
    for (size_t i = 0; i < layout.centre.size(); ++i)
      text.draw(layout.centre[i].text, {layout.centre[i].x, layout.centre[i].y}, layout.centre[i].size,
                i == 0 ? Color{255, 220, 120, 255} : Color{235, 235, 240, 255});
    text.flush(width, height);
  }
  for (const TextBox& line : layout.hud) {
    batch.rectangle({line.x - 4 * dpi, line.y - 2 * dpi}, {line.width, line.height}, {0, 0, 0, 150});
    text.draw(line.text, {line.x, line.y}, line.size, {240, 240, 240, 255});
  }
  if (layout.fps.width > 0) {
    batch.rectangle({layout.fps.x - 4 * dpi, layout.fps.y - 2 * dpi}, {layout.fps.width, layout.fps.height},
                    {0, 0, 0, 150});
    text.draw(layout.fps.text, {layout.fps.x, layout.fps.y}, layout.fps.size, {180, 240, 180, 255});
  }
  batch.flush(width, height);
  text.flush(width, height);
}

// The error overlay's lines: its heading, then the error's lines with those wider than `available`
// cut, each rest indented on a line of its own.
std::vector<std::string> errorOverlayLines(const std::string& error, Text& text, float size, float available) {
  std::vector<std::string> lines{"Script error: the game goes on with the last good version"};
  for (std::string line : splitLines(error)) {
    while (line.size() > 1 && text.width(line, size) > available) {
      size_t cut = line.size() * 9 / 10;
      while (cut > 1 && text.width(line.substr(0, cut), size) > available) cut = cut * 9 / 10;
      if (cut <= 4) break;  // no wider than the indent (a tiny window): cutting would grow the line forever
      lines.push_back(line.substr(0, cut));
      line = "    " + line.substr(cut);
    }
    lines.push_back(line);
  }
  return lines;
}

// The error overlay: over everything, at the bottom, long lines cut to fit, as many as fit in
// six tenths of the window.
void drawErrorOverlay(const std::string& error, Batch& batch, Text& text, float width, float height, float dpi) {
  const float pad = 8 * dpi;
  const float size = 15 * dpi, step = size * 1.35f, available = width - 4 * pad;
  const std::vector<std::string> lines = errorOverlayLines(error, text, size, available);
  const size_t shown = std::min(lines.size(), static_cast<size_t>((height * 0.6f) / step));
  const float boxHeight = static_cast<float>(shown) * step + 2 * pad;
  batch.rectangle({pad, height - boxHeight - pad}, {width - 2 * pad, boxHeight}, {120, 20, 24, 225});
  batch.flush(width, height);
  for (size_t i = 0; i < shown; ++i)
    text.draw(lines[i], {2 * pad, height - boxHeight + static_cast<float>(i) * step}, size,
              i == 0 ? Color{255, 210, 120, 255} : Color{255, 255, 255, 255});
  text.flush(width, height);
}

}  // namespace

struct RenderSystem::Gl {
  Gl(int width, int height) : window("Platon", width, height) {}
  Window window;  // first: the context outlives the objects below
  StageRenderer stage;
  Batch batch;
  Text text;
};

RenderSystem::RenderSystem() = default;
RenderSystem::~RenderSystem() = default;

RenderSystem::Gl& RenderSystem::gl() {
  if (!gl_) gl_ = std::make_shared<Gl>(firstWidth_, firstHeight_);
  return *gl_;
}

void RenderSystem::carryOver(core::Scene&, core::System& previous) {
  // The same name in the same registry: the same plugin's class. Shared, not moved: a system after
  // this one may still refuse the reload, and the old version then goes on with the window.
  auto& old = static_cast<RenderSystem&>(previous);
  if (old.gl_) gl_ = old.gl_;
}

core::WindowInput RenderSystem::pollEvents() { return gl().window.pollEvents(); }

std::vector<std::string> RenderSystem::setBindings(const core::KeyBindings& bindings) {
  return gl().window.setBindings(bindings);  // opens the window: SDL names keys only once it is up
}

void RenderSystem::setFullscreen(bool on) { gl().window.setFullscreen(on); }

void RenderSystem::setVsync(bool on) { gl().window.setVsync(on); }

void RenderSystem::setMultisamples(int samples) { gl().window.setMultisamples(samples); }

void RenderSystem::resize(int width, int height) {
  if (!gl_) {  // not open yet: open at that size (an offscreen surface cannot grow later)
    firstWidth_ = width, firstHeight_ = height;
    return;
  }
  gl_->window.resize(width, height);
}

void RenderSystem::present(const core::View& view, const core::DrawList& draw) {
  const uint64_t now = SDL_GetPerformanceCounter();
  if (lastPresent_ != 0) {
    const double seconds = static_cast<double>(now - lastPresent_) / static_cast<double>(SDL_GetPerformanceFrequency());
    frameSeconds_ = frameSeconds_ == 0 ? seconds : frameSeconds_ + 0.05 * (seconds - frameSeconds_);
  }
  lastPresent_ = now;
  paint(view, draw);
  gl().window.swap();
  lastView_ = view;
  lastDraw_ = draw;
}

std::vector<uint8_t> RenderSystem::capture(int& width, int& height) {
  if (!lastView_) throw std::runtime_error("nothing was shown yet");
  paint(*lastView_, lastDraw_);  // again into the back buffer, which a swap leaves undefined
  return gl().window.readPixels(width, height);
}

void RenderSystem::saveScreenshot(const std::string& path) {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels = capture(width, height);
  SDL_Surface* surface =
      SDL_CreateRGBSurfaceWithFormatFrom(pixels.data(), width, height, 32, width * 4, SDL_PIXELFORMAT_ABGR8888);
  if (!surface) throw std::runtime_error(path + ": " + SDL_GetError());
  const int status = IMG_SavePNG(surface, path.c_str());
  SDL_FreeSurface(surface);
  if (status != 0) throw std::runtime_error(path + ": cannot write the PNG: " + IMG_GetError());
}

void RenderSystem::paint(const core::View& view, const core::DrawList& draw) {
  Gl& g = gl();
  g.window.setTitle(view.title.empty() ? "Platon" : "Platon: " + view.title);
  const float width = static_cast<float>(g.window.pixelWidth()), height = static_cast<float>(g.window.pixelHeight());
  const float dpi = g.window.pixelsPerPoint();
  g.window.beginFrame();
  glViewport(0, 0, g.window.pixelWidth(), g.window.pixelHeight());
  glClearColor(kBackground.r / 255.0f, kBackground.g / 255.0f, kBackground.b / 255.0f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  // The stage in 3D, what the scripts drew on its faces, then their text and screen shapes flat.
  g.stage.draw(view, draw, g.window.pixelWidth(), g.window.pixelHeight());
  drawFlatShapes(view, draw, g.stage, g.batch, g.text, dpi);
  g.batch.flush(width, height);
  g.text.flush(width, height);

  // Titles and menus in the middle on a dark band, the heads-up lines top left, the frame rate top
  // right: laid out together (hud_layout.h) so that none overlaps another at any window size.
  char fps[48] = "";
  if (view.showFps && frameSeconds_ > 0)
    std::snprintf(fps, sizeof fps, "%.0f fps  %.2f ms", 1 / frameSeconds_, frameSeconds_ * 1000);
  const ScreenLayout layout = layOut(width, height, dpi, view.hud, view.centreText, fps,
                                     [&](const std::string& text, float size) { return g.text.width(text, size); });
  drawScreenText(layout, g.batch, g.text, width, height, dpi);
  if (!view.error.empty()) drawErrorOverlay(view.error, g.batch, g.text, width, height, dpi);
  g.window.endFrame();
}

}  // namespace platon::render
