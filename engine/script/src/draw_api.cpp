// platon.draw: what scripts ask the renderer to draw this frame. Without a renderer every call
// checks its arguments and records nothing. Places: a face id (shapes in that face's units) or
// "screen" (pixels from the top left). Colours: 0xRRGGBB, with an optional alpha 0..255.
#include <cmath>
#include <vector>

#include "script_context.h"

namespace platon::script {
namespace {

// Arguments are checked whether or not a renderer records the shape, so that a script's mistake
// shows headless (in a scenario) as it would in the window.
core::Place checkPlace(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TSTRING) {
    if (lua::checkString(L, index) == "screen") return core::Place::onScreen();
  } else if (lua_type(L, index) == LUA_TNUMBER) {
    const double v = lua_tonumber(L, index);
    if (v >= 0 && v <= 4294967295.0 && v == static_cast<double>(static_cast<uint32_t>(v)) &&
        contextOf(L).scene->world().findMapPart(static_cast<uint32_t>(v)))
      return core::Place::onFace(static_cast<uint32_t>(v));
  }
  lua::argError(L, index, "a face id of this stage or \"screen\"");
}

core::Color checkColor(lua_State* L, int index) {
  const auto rgb = static_cast<uint32_t>(lua::checkInteger(L, index, 0, 0xffffff));
  const auto alpha = lua_isnoneornil(L, index + 1) ? 255 : lua::checkInteger(L, index + 1, 0, 255);
  return {static_cast<uint8_t>(rgb >> 16), static_cast<uint8_t>(rgb >> 8), static_cast<uint8_t>(rgb),
          static_cast<uint8_t>(alpha)};
}

// Coordinates: finite, and within what a float holds well (2^30, the world's range).
float checkFloat(lua_State* L, int index) {
  const double v = lua::checkNumber(L, index);
  if (!(std::fabs(v) <= 1073741824.0)) lua::argError(L, index, "a number within +-2^30");
  return static_cast<float>(v);
}

// A radius, width or text height: more than 0.
float checkSize(lua_State* L, int index) {
  const double v = lua::checkNumber(L, index);
  if (!(v > 0 && v <= 1073741824.0)) lua::argError(L, index, "a size above 0 (and at most 2^30)");
  return static_cast<float>(v);
}

// A shape the frame's list had no room for (DrawList's limits): the first of a frame is an error
// at the script's line, the rest are dropped quietly.
void dropped(lua_State* L) {
  ScriptContext& context = contextOf(L);
  if (context.drawOverflowReported) return;
  context.drawOverflowReported = true;
  throw lua::ArgError("draw: this frame's picture is full (at most " + std::to_string(core::DrawList::kMaxShapes) +
                      " shapes, " + std::to_string(core::DrawList::kMaxPoints) + " points and " +
                      std::to_string(core::DrawList::kMaxTextBytes / 1024) + " KB of text); the rest of it is dropped");
}

// circle(place, x, y, radius, colour [, alpha])
int circle(lua_State* L) {
  const core::Place place = checkPlace(L, 1);
  const core::Point2 centre{checkFloat(L, 2), checkFloat(L, 3)};
  const float radius = checkSize(L, 4);
  const core::Color colour = checkColor(L, 5);
  core::DrawList* out = contextOf(L).draw;
  if (out && !out->circle(place, centre, radius, colour)) dropped(L);
  return 0;
}

// line(place, x0, y0, x1, y1, width, colour [, alpha])
int drawLine(lua_State* L) {
  const core::Place place = checkPlace(L, 1);
  const core::Point2 a{checkFloat(L, 2), checkFloat(L, 3)}, b{checkFloat(L, 4), checkFloat(L, 5)};
  const float width = checkSize(L, 6);
  const core::Color colour = checkColor(L, 7);
  core::DrawList* out = contextOf(L).draw;
  if (out && !out->line(place, a, b, width, colour)) dropped(L);
  return 0;
}

// polygon(place, {x0, y0, x1, y1, ...}, colour [, alpha]): convex, counter-clockwise
int polygon(lua_State* L) {
  const core::Place place = checkPlace(L, 1);
  lua::checkTable(L, 2);
  const size_t n = lua_objlen(L, 2);
  if (n < 6 || n % 2 || n > 512) throw lua::ArgError("polygon: argument 2: 3 to 256 points as {x0, y0, x1, y1, ...}");
  std::vector<core::Point2> points;
  for (size_t i = 1; i <= n; i += 2) {
    lua_rawgeti(L, 2, static_cast<int>(i));
    lua_rawgeti(L, 2, static_cast<int>(i + 1));
    const double x = lua_tonumber(L, -2), y = lua_tonumber(L, -1);
    if (lua_type(L, -2) != LUA_TNUMBER || lua_type(L, -1) != LUA_TNUMBER || !(std::fabs(x) <= 1073741824.0) ||
        !(std::fabs(y) <= 1073741824.0))
      throw lua::ArgError("polygon: argument 2: point " + std::to_string(i / 2 + 1) +
                          " is not two numbers within +-2^30");
    points.push_back({static_cast<float>(x), static_cast<float>(y)});
    lua_pop(L, 2);
  }
  // Convex and counter-clockwise: every turn to the left (or straight).
  for (size_t i = 0; i < points.size(); ++i) {
    const core::Point2 a = points[i], b = points[(i + 1) % points.size()], c = points[(i + 2) % points.size()];
    const double turn = (double(b.x) - a.x) * (double(c.y) - b.y) - (double(b.y) - a.y) * (double(c.x) - b.x);
    if (turn < 0)
      throw lua::ArgError(
          "polygon: argument 2: the points must go counter-clockwise round a convex shape (it turns right at point " +
          std::to_string((i + 1) % points.size() + 1) + ")");
  }
  const core::Color colour = checkColor(L, 3);
  core::DrawList* out = contextOf(L).draw;
  if (out && !out->polygon(place, points, colour)) dropped(L);
  return 0;
}

// text(place, x, y, text, height, colour [, alpha])
int text(lua_State* L) {
  const core::Place place = checkPlace(L, 1);
  const core::Point2 at{checkFloat(L, 2), checkFloat(L, 3)};
  const std::string_view s = lua::checkString(L, 4);
  if (s.size() > 4096) throw lua::ArgError("text: at most 4096 bytes");
  const float height = checkSize(L, 5);
  const core::Color colour = checkColor(L, 6);
  core::DrawList* out = contextOf(L).draw;
  if (out && !out->text(place, at, s, height, colour)) dropped(L);
  return 0;
}

// look(entity, colour [, form [, squash]]): how the engine draws the entity from now on. Form
// "shape" (its polygon, the default), "ball" (once, as a ball) or "none" (the script draws it);
// squash (0.25..4, 1 by default) is a ball's height over its width, its volume kept. Set headless
// too: the look is the scene's, not the frame's, and never the simulation's.
int look(lua_State* L) {
  const physics::EntityId id = checkEntity(L, 1);
  const auto rgb = static_cast<uint32_t>(lua::checkInteger(L, 2, 0, 0xffffff));
  core::Look style;
  style.color = {static_cast<uint8_t>(rgb >> 16), static_cast<uint8_t>(rgb >> 8), static_cast<uint8_t>(rgb), 255};
  if (!lua_isnoneornil(L, 3)) {
    const std::string_view form = lua::checkString(L, 3);
    if (form == "ball")
      style.form = core::Look::Form::Ball;
    else if (form == "none")
      style.form = core::Look::Form::None;
    else if (form != "shape")
      lua::argError(L, 3, "\"shape\", \"ball\" or \"none\"");
  }
  if (!lua_isnoneornil(L, 4)) {
    const double squash = lua::checkNumber(L, 4);
    if (!(squash >= 0.25 && squash <= 4)) lua::argError(L, 4, "a squash 0.25..4");
    style.squash = static_cast<float>(squash);
  }
  contextOf(L).scene->looks().set(id, style);
  return 0;
}

int enabled(lua_State* L) {
  lua_pushboolean(L, contextOf(L).draw != nullptr);
  return 1;
}

constexpr luaL_Reg kDraw[] = {
    {"circle", lua::bound<circle>},
    {"line", lua::bound<drawLine>},
    {"polygon", lua::bound<polygon>},
    {"text", lua::bound<text>},
    {"enabled", lua::bound<enabled>},
    {"look", lua::bound<look>},
    {nullptr, nullptr},
};

}  // namespace

void registerDrawApi(LuaHost& host, ScriptContext& context) { addApiTable(host, context, "draw", kDraw); }

}  // namespace platon::script
