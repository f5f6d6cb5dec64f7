#include "render_system.h"

#include <SDL2/SDL_image.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>

#include "batch.h"
#include "text.h"
#include "window.h"

namespace platon::render {
namespace {

using core::Color;
using core::Point2;

constexpr Color kBackground{22, 24, 30, 255};
constexpr Color kFace{50, 56, 70, 255};
constexpr Color kWarp{80, 150, 170, 255};
constexpr Color kOneWay{180, 120, 230, 255};
constexpr float kLineUnits = 20;  // map lines' width, in face units

// The game's tags (scripts/rules/game.lua): 0 solid, 1 hazard, 2 goal, 3 checkpoint, 1000 + n
// door, 2000 + n switch.
Color lineColor(const core::ViewLine& line) {
  if (line.kind == 1) return kWarp;
  if (line.kind == 2) return kOneWay;
  if (line.tag == 1) return {235, 70, 60, 255};
  if (line.tag == 2) return {90, 225, 110, 255};
  if (line.tag == 3) return {90, 160, 245, 255};
  if (line.tag >= 1000 && line.tag < 2000) return {245, 160, 60, 255};
  if (line.tag >= 2000 && line.tag < 3000) return {250, 225, 70, 255};
  return {225, 225, 230, 255};
}

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

// Face coordinates (y up) to pixels (y down), the face fitted into the window with a margin.
struct FaceToScreen {
  float minX = 0, maxY = 0, scale = 1, left = 0, top = 0;
  FaceToScreen(const core::View& view, float width, float height, float margin) {
    float minx = 1e30f, miny = 1e30f, maxx = -1e30f, maxy = -1e30f;
    auto grow = [&](Point2 p) {
      minx = std::min(minx, p.x), miny = std::min(miny, p.y), maxx = std::max(maxx, p.x), maxy = std::max(maxy, p.y);
    };
    for (Point2 p : view.border) grow(p);
    if (view.border.empty())
      for (const core::ViewLine& l : view.lines) grow(l.a), grow(l.b);
    if (minx > maxx) minx = miny = 0, maxx = maxy = 1;
    const float w = std::max(maxx - minx, 1.0f), h = std::max(maxy - miny, 1.0f);
    scale = std::max(std::min((width - 2 * margin) / w, (height - 2 * margin) / h), 1e-6f);
    minX = minx, maxY = maxy;
    left = (width - w * scale) / 2, top = (height - h * scale) / 2;
  }
  Point2 operator()(Point2 p) const { return {left + (p.x - minX) * scale, top + (maxY - p.y) * scale}; }
};

}  // namespace

struct RenderSystem::Gl {
  Window window{"Platon", 1280, 720};  // first: the context outlives the objects below
  Batch batch;
  Text text;
};

RenderSystem::RenderSystem() = default;
RenderSystem::~RenderSystem() = default;

RenderSystem::Gl& RenderSystem::gl() {
  if (!gl_) gl_ = std::make_shared<Gl>();
  return *gl_;
}

void RenderSystem::carryOver(core::Scene&, core::System& previous) {
  // The same name in the same registry: the same plugin's class. Shared, not moved: a system after
  // this one may still refuse the reload, and the old version then goes on with the window.
  auto& old = static_cast<RenderSystem&>(previous);
  if (old.gl_) gl_ = old.gl_;
}

bool RenderSystem::pollEvents(uint8_t& held) { return gl().window.pollEvents(held); }

void RenderSystem::present(const core::View& view, const core::DrawList& draw) {
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
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormatFrom(pixels.data(), width, height, 32, width * 4, SDL_PIXELFORMAT_ABGR8888);
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
  glViewport(0, 0, g.window.pixelWidth(), g.window.pixelHeight());
  glClearColor(kBackground.r / 255.0f, kBackground.g / 255.0f, kBackground.b / 255.0f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  // The face, its lines, and what the scripts drew on it.
  const FaceToScreen toScreen(view, width, height, 40 * dpi);
  std::vector<Point2> border;
  for (Point2 p : view.border) border.push_back(toScreen(p));
  g.batch.polygon(border, kFace);
  for (const core::ViewLine& l : view.lines)
    g.batch.line(toScreen(l.a), toScreen(l.b), l.kind == 1 ? 2 * dpi : std::max(2 * dpi, kLineUnits * toScreen.scale), lineColor(l));
  const auto points = draw.points();
  for (const core::DrawShape& s : draw.shapes()) {
    if (!s.place.screen && s.place.face != view.face) continue;  // other faces: with the 3D view
    auto at = [&](Point2 p) { return s.place.screen ? Point2{p.x * dpi, p.y * dpi} : toScreen(p); };
    const float scale = s.place.screen ? dpi : toScreen.scale;
    switch (s.kind) {
      case core::ShapeKind::Circle: g.batch.circle(at(s.at), s.size * scale, s.color); break;
      case core::ShapeKind::Line:
        for (uint32_t i = 1; i < s.count; ++i)
          g.batch.line(at(points[s.first + i - 1]), at(points[s.first + i]), std::max(1.0f, s.size * scale), s.color);
        break;
      case core::ShapeKind::Polygon: {
        std::vector<Point2> p;
        for (uint32_t i = 0; i < s.count; ++i) p.push_back(at(points[s.first + i]));
        g.batch.polygon(p, s.color);
        break;
      }
      case core::ShapeKind::Text:
        g.text.draw(std::string(draw.text(s)), at(s.at), std::max(6.0f, s.size * scale), s.color);
        break;
    }
  }
  g.batch.flush(width, height);
  g.text.flush(width, height);

  // The heads-up lines, top left.
  const float hudHeight = 18 * dpi, pad = 8 * dpi;
  for (size_t i = 0; i < view.hud.size(); ++i) {
    const Point2 at{pad, pad + static_cast<float>(i) * (hudHeight + 4 * dpi)};
    const float w = g.text.width(view.hud[i], hudHeight);
    g.batch.rectangle({at.x - 4 * dpi, at.y - 2 * dpi}, {w + 8 * dpi, hudHeight + 8 * dpi}, {0, 0, 0, 150});
    g.text.draw(view.hud[i], at, hudHeight, {240, 240, 240, 255});
  }
  g.batch.flush(width, height);
  g.text.flush(width, height);

  // The error overlay: over everything, at the bottom, long lines cut to fit.
  if (!view.error.empty()) {
    const float size = 15 * dpi, step = size * 1.35f, available = width - 4 * pad;
    std::vector<std::string> lines{"Script error: the game goes on with the last good version"};
    for (std::string line : splitLines(view.error)) {
      while (line.size() > 1 && g.text.width(line, size) > available) {
        size_t cut = line.size() * 9 / 10;
        while (cut > 1 && g.text.width(line.substr(0, cut), size) > available) cut = cut * 9 / 10;
        if (cut <= 4) break;  // no wider than the indent (a tiny window): cutting would grow the line forever
        lines.push_back(line.substr(0, cut));
        line = "    " + line.substr(cut);
      }
      lines.push_back(line);
    }
    const size_t shown = std::min(lines.size(), static_cast<size_t>((height * 0.6f) / step));
    const float boxHeight = static_cast<float>(shown) * step + 2 * pad;
    g.batch.rectangle({pad, height - boxHeight - pad}, {width - 2 * pad, boxHeight}, {120, 20, 24, 225});
    g.batch.flush(width, height);
    for (size_t i = 0; i < shown; ++i)
      g.text.draw(lines[i], {2 * pad, height - boxHeight + static_cast<float>(i) * step}, size,
                  i == 0 ? Color{255, 210, 120, 255} : Color{255, 255, 255, 255});
    g.text.flush(width, height);
  }
}

}  // namespace platon::render
