// platon.draw: what scripts ask the renderer to draw this frame. Without a renderer every call
// returns at once and records nothing. Places: a face id (shapes in that face's units) or
// "screen" (pixels from the top left). Colours: 0xRRGGBB, with an optional alpha 0..255.
#include <vector>

#include "script_context.h"

namespace platon::script {
namespace {

core::Place checkPlace(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TSTRING && lua::checkString(L, index) == "screen") return core::Place::onScreen();
  return core::Place::onFace(lua::checkUint32(L, index));
}

core::Color checkColor(lua_State* L, int index) {
  const auto rgb = static_cast<uint32_t>(lua::checkInteger(L, index, 0, 0xffffff));
  const auto alpha = lua_isnoneornil(L, index + 1) ? 255 : lua::checkInteger(L, index + 1, 0, 255);
  return {static_cast<uint8_t>(rgb >> 16), static_cast<uint8_t>(rgb >> 8), static_cast<uint8_t>(rgb),
          static_cast<uint8_t>(alpha)};
}

float checkFloat(lua_State* L, int index) { return static_cast<float>(lua::checkNumber(L, index)); }

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
  core::DrawList* out = contextOf(L).draw;
  if (!out) return 0;
  if (!out->circle(checkPlace(L, 1), {checkFloat(L, 2), checkFloat(L, 3)}, checkFloat(L, 4), checkColor(L, 5))) dropped(L);
  return 0;
}

// line(place, x0, y0, x1, y1, width, colour [, alpha])
int line(lua_State* L) {
  core::DrawList* out = contextOf(L).draw;
  if (!out) return 0;
  if (!out->line(checkPlace(L, 1), {checkFloat(L, 2), checkFloat(L, 3)}, {checkFloat(L, 4), checkFloat(L, 5)},
                 checkFloat(L, 6), checkColor(L, 7)))
    dropped(L);
  return 0;
}

// polygon(place, {x0, y0, x1, y1, ...}, colour [, alpha]): convex, counter-clockwise
int polygon(lua_State* L) {
  core::DrawList* out = contextOf(L).draw;
  if (!out) return 0;
  const core::Place place = checkPlace(L, 1);
  lua::checkTable(L, 2);
  const size_t n = lua_objlen(L, 2);
  if (n < 6 || n % 2 || n > 512) throw lua::ArgError("polygon: 3 to 256 points as {x0, y0, x1, y1, ...}");
  std::vector<core::Point2> points;
  for (size_t i = 1; i <= n; i += 2) {
    lua_rawgeti(L, 2, static_cast<int>(i));
    lua_rawgeti(L, 2, static_cast<int>(i + 1));
    points.push_back({checkFloat(L, -2), checkFloat(L, -1)});
    lua_pop(L, 2);
  }
  if (!out->polygon(place, points, checkColor(L, 3))) dropped(L);
  return 0;
}

// text(place, x, y, text, height, colour [, alpha])
int text(lua_State* L) {
  core::DrawList* out = contextOf(L).draw;
  if (!out) return 0;
  const std::string_view s = lua::checkString(L, 4);
  if (s.size() > 4096) throw lua::ArgError("text: at most 4096 bytes");
  if (!out->text(checkPlace(L, 1), {checkFloat(L, 2), checkFloat(L, 3)}, s, checkFloat(L, 5), checkColor(L, 6))) dropped(L);
  return 0;
}

int enabled(lua_State* L) {
  lua_pushboolean(L, contextOf(L).draw != nullptr);
  return 1;
}

constexpr luaL_Reg kDraw[] = {
    {"circle", lua::bound<circle>}, {"line", lua::bound<line>}, {"polygon", lua::bound<polygon>},
    {"text", lua::bound<text>},     {"enabled", lua::bound<enabled>}, {nullptr, nullptr},
};

}  // namespace

void registerDrawApi(LuaHost& host, ScriptContext& context) { addApiTable(host, context, "draw", kDraw); }

}  // namespace platon::script
