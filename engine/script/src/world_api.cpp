// platon.world: the physics world in Lua, in the world's own terms. Units: positions in whole
// units (integers), velocities in units per frame, gravity in units per frame per frame (the
// world's Q16 fixed point converted both ways, rounded to nearest), angles in degrees (binary
// angles: 2^32 per turn, rounded to nearest).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "script_context.h"

namespace platon::script {
namespace {

using lua::checkInt32;
using lua::checkNumber;
using lua::checkUint32;
using physics::EntityId;
using physics::World;

World& worldOf(lua_State* L) { return contextOf(L).scene->world(); }

using lua::pushEntity;

// What the world holds from Lua at most: C++ memory the Lua state's limit does not see.
constexpr size_t kMaxEntities = 10'000;
constexpr size_t kMaxPlatforms = 1'000;
constexpr size_t kMaxPlatformLines = 1'000;
constexpr size_t kMaxPartLines = 100'000;

physics::PlatformId checkPlatform(lua_State* L, int index) {
  const std::optional<lua::HandleBits> bits = lua::toPlatformHandle(L, index);
  if (!bits) lua::argError(L, index, "a platform handle (from createPlatform)");
  return {bits->index, bits->generation};
}

int64_t toQ16(lua_State* L, int index, const char* what) {
  const double value = checkNumber(L, index);
  if (std::fabs(value) > kMaxPerFrame) lua::argError(L, index, what);
  return std::llround(value * kQ16);
}

physics::Angle toAngle(lua_State* L, int index) {
  const double turns = checkNumber(L, index) / 360.0;
  const double fraction = turns - std::floor(turns);
  return static_cast<physics::Angle>(static_cast<uint64_t>(std::llround(fraction * 4294967296.0)) & 0xffffffffu);
}

double degrees(physics::Angle angle) { return static_cast<double>(angle) * (360.0 / 4294967296.0); }

physics::MapPartId checkPart(lua_State* L, int index) {
  const physics::MapPartId id = checkUint32(L, index);
  if (!worldOf(L).findMapPart(id))
    throw lua::ArgError("argument " + std::to_string(index) + ": no map part " + std::to_string(id));
  return id;
}

const char* kindName(physics::LineKind kind) {
  switch (kind) {
    case physics::LineKind::Solid:
      return "solid";
    case physics::LineKind::Warp:
      return "warp";
    case physics::LineKind::OneWay:
      return "oneway";
  }
  return "solid";
}

// t[key], read raw: no metamethod of a script's table runs from here.
void rawField(lua_State* L, int table, const char* key) {
  lua_pushstring(L, key);
  lua_rawget(L, table);
}

// Reads the integers of t[1..n] (a flat list x0, y0, x1, y1, ...), at most `most` of them; `what`
// names the list in errors ("createEntity: polygon", "createPlatform: argument 2").
std::vector<int32_t> intList(lua_State* L, int index, const std::string& what, size_t most) {
  if (lua_type(L, index) != LUA_TTABLE)
    throw lua::ArgError(what + ": expected a table, got " + lua::typeName(L, index));
  const size_t n = lua_objlen(L, index);
  if (n > most) throw lua::ArgError(what + ": at most " + std::to_string(most) + " numbers, got " + std::to_string(n));
  std::vector<int32_t> out;
  out.reserve(n);
  for (size_t i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, static_cast<int>(i));
    if (lua_type(L, -1) != LUA_TNUMBER || lua_tonumber(L, -1) != std::floor(lua_tonumber(L, -1)) ||
        std::fabs(lua_tonumber(L, -1)) > 1073741823.0)
      throw lua::ArgError(what + ": item " + std::to_string(i) + " is not an integer coordinate within +-(2^30 - 1)");
    out.push_back(static_cast<int32_t>(lua_tonumber(L, -1)));
    lua_pop(L, 1);
  }
  return out;
}

// An optional integer field of an option table, read raw; errors name the function and the field.
std::optional<int64_t> integerField(lua_State* L, int table, const char* function, const char* key, int64_t low,
                                    int64_t high) {
  rawField(L, table, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  const double value = lua_type(L, -1) == LUA_TNUMBER ? lua_tonumber(L, -1) : 0.5;
  if (value != std::floor(value) || value < static_cast<double>(low) || value > static_cast<double>(high))
    throw lua::ArgError(std::string(function) + ": " + key + ": expected an integer in [" + std::to_string(low) + ", " +
                        std::to_string(high) + "], got " + lua::shownValue(L, -1));
  lua_pop(L, 1);
  return static_cast<int64_t>(value);
}

// createEntity{circle = r [, sides = 16]} | {box = {halfWidth, halfHeight}} | {polygon = {x0, y0, ...}}
// Refuses a key of option table `table` that is not one of `known` (a typo would be ignored).
void onlyKnownKeys(lua_State* L, int table, const char* function, std::initializer_list<const char*> known) {
  lua_pushnil(L);
  while (lua_next(L, table)) {
    lua_pop(L, 1);  // the value; the key stays for lua_next
    bool ok = false;
    if (lua_type(L, -1) == LUA_TSTRING)
      for (const char* k : known) ok = ok || std::strcmp(lua_tostring(L, -1), k) == 0;
    if (!ok) {
      std::string list;
      for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
      const std::string key = lua::shownValue(L, -1);
      lua_pop(L, 1);
      throw lua::ArgError(std::string(function) + ": unknown field " + key + " (known: " + list + ")");
    }
  }
}

uint64_t entityKey(EntityId id) { return uint64_t{id.index} << 32 | id.generation; }

int createEntity(lua_State* L) {
  lua::checkTable(L, 1);
  onlyKnownKeys(L, 1, "createEntity", {"circle", "sides", "box", "polygon"});
  if (worldOf(L).entityCount() >= kMaxEntities)
    throw lua::ArgError("createEntity: the world holds " + std::to_string(kMaxEntities) +
                        " entities, the most scripts may make (destroy some first)");
  rawField(L, 1, "circle");
  rawField(L, 1, "box");
  rawField(L, 1, "polygon");
  std::optional<physics::Convex> shape;
  if (!lua_isnil(L, -3) + !lua_isnil(L, -2) + !lua_isnil(L, -1) > 1)
    throw lua::ArgError("createEntity: one shape: circle, box or polygon, not two");
  if (!lua_isnil(L, -3)) {
    lua_pop(L, 2);
    const auto radius = static_cast<int32_t>(*integerField(L, 1, "createEntity", "circle", 1, 1 << 28));
    const auto sides = static_cast<int>(integerField(L, 1, "createEntity", "sides", 3, 64).value_or(16));
    shape = physics::Convex::regular(sides, radius);
  } else if (!lua_isnil(L, -2)) {
    const std::vector<int32_t> half = intList(L, lua_gettop(L) - 1, "createEntity: box", 2);
    if (half.size() != 2 || half[0] <= 0 || half[1] <= 0)
      throw lua::ArgError("createEntity: box = {halfWidth, halfHeight}, both > 0");
    shape = physics::Convex::box(half[0], half[1]);
  } else if (!lua_isnil(L, -1)) {
    const std::vector<int32_t> xy =
        intList(L, lua_gettop(L), "createEntity: polygon", size_t{2} * physics::kMaxConvexVertices);
    if (xy.size() < 6 || xy.size() % 2)
      throw lua::ArgError("createEntity: polygon = {x0, y0, x1, y1, x2, y2, ...}: 3 to " +
                          std::to_string(physics::kMaxConvexVertices) + " points");
    std::vector<physics::Vec2> points;
    for (size_t i = 0; i < xy.size(); i += 2) points.push_back({xy[i], xy[i + 1]});
    shape.emplace(std::move(points));  // the Convex constructor checks convexity and order
  } else {
    throw lua::ArgError("createEntity: give a shape: {circle = r}, {box = {hw, hh}} or {polygon = {x0, y0, ...}}");
  }
  const EntityId id = worldOf(L).createEntity(*shape);
  if (const int maker = contextOf(L).host->runningSandbox(); maker != kNoSandbox)
    contextOf(L).madeBy[entityKey(id)] = maker;
  pushEntity(L, id);
  return 1;
}

// The player's entity is the game's (scripts/scene.lua names it with engine.protect): a sandbox
// may not destroy or erase it.
void checkNotProtected(lua_State* L, EntityId id, const char* function) {
  const ScriptContext& context = contextOf(L);
  if (id == context.protectedEntity && context.host->runningSandbox() != kNoSandbox)
    throw lua::ArgError(std::string(function) +
                        ": the player's entity belongs to the game (a level script or mod may not " +
                        (std::string(function) == "erase" ? "erase" : "destroy") + " it)");
}

int destroyEntity(lua_State* L) {
  const EntityId id = checkEntity(L, 1);
  checkNotProtected(L, id, "destroyEntity");
  worldOf(L).destroyEntity(id);
  contextOf(L).madeBy.erase(entityKey(id));
  return 0;
}

int valid(lua_State* L) {
  const std::optional<lua::HandleBits> bits = lua::toHandle(L, 1);
  lua_pushboolean(L, bits && worldOf(L).valid({bits->index, bits->generation}));
  return 1;
}

// Whether `p` lies on the face a part is (its warp edges closed into a loop), or beyond its edges
// by at most `slack` units; parts that are no face take any point.
bool onFace(const physics::MapPart& part, int64_t x, int64_t y, int64_t slack) {
  for (const physics::LineIndex line : part.faceLoop()) {
    const physics::Segment s = part.segments()[line];
    const physics::i128 dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const physics::i128 side = dx * (y - s.a.y) - dy * (x - s.a.x);
    if (side < 0 && side * side > physics::i128{slack} * slack * (dx * dx + dy * dy)) return false;
  }
  return true;
}

int insert(lua_State* L) {
  const EntityId e = checkEntity(L, 1);
  const physics::MapPartId part = checkPart(L, 2);
  const physics::Vec2 at{checkInt32(L, 3), checkInt32(L, 4)};
  const physics::Angle angle = lua_isnoneornil(L, 5) ? 0 : toAngle(L, 5);
  // On a stage's face the body's middle must be on the face, or over an edge by no more than the
  // body's size (as while it crosses one): farther out, it would be taken for a body gone through
  // a vertex and put back by a corner at once.
  const physics::Convex turned = worldOf(L).entity(e).shape().rotated(angle);
  int64_t cx = 0, cy = 0;
  for (const physics::Vec2 v : turned.vertices()) cx += v.x, cy += v.y;
  cx /= turned.size(), cy /= turned.size();
  int64_t reach = 0;
  for (const physics::Vec2 v : turned.vertices())
    reach = std::max<int64_t>(reach, static_cast<int64_t>(std::ceil(std::hypot(double(v.x - cx), double(v.y - cy)))));
  if (const physics::MapPart* p = worldOf(L).findMapPart(part); p && !onFace(*p, at.x + cx, at.y + cy, reach + 4))
    throw lua::ArgError("insert: (" + std::to_string(at.x) + ", " + std::to_string(at.y) + ") is not on face " +
                        std::to_string(part) +
                        " (a body's middle goes on its face, or over an edge by at most the body's size)");
  worldOf(L).insert(e, part, at, angle);
  return 0;
}

int erase(lua_State* L) {
  const EntityId id = checkEntity(L, 1);
  checkNotProtected(L, id, "erase");
  worldOf(L).erase(id, checkPart(L, 2));
  return 0;
}

int position(lua_State* L) {
  const physics::EntityView e = worldOf(L).entity(checkEntity(L, 1));
  if (!e.inserted()) throw lua::ArgError("position: the entity is in no map part (insert it first)");
  const physics::InstanceView anchor = e.instance(0);
  lua_pushnumber(L, anchor.part);
  lua_pushnumber(L, anchor.position.x);
  lua_pushnumber(L, anchor.position.y);
  return 3;
}

int angle(lua_State* L) {
  lua_pushnumber(L, degrees(worldOf(L).entity(checkEntity(L, 1)).angle()));
  return 1;
}

int velocity(lua_State* L) {
  const physics::Vec2w v = worldOf(L).entity(checkEntity(L, 1)).velocity();
  lua_pushnumber(L, static_cast<double>(v.x) / kQ16);
  lua_pushnumber(L, static_cast<double>(v.y) / kQ16);
  return 2;
}

int setVelocity(lua_State* L) {
  const EntityId e = checkEntity(L, 1);
  constexpr const char* kVelocity = "a velocity within +-2^30 units per frame";
  worldOf(L).setVelocity(e, {toQ16(L, 2, kVelocity), toQ16(L, 3, kVelocity)});
  return 0;
}

// The sub-unit motion an entity carries, in 1/131072 units (integers): for copying a body exactly.
int subunit(lua_State* L) {
  const physics::Vec2w s = worldOf(L).entity(checkEntity(L, 1)).subunit();
  lua_pushnumber(L, static_cast<double>(s.x));
  lua_pushnumber(L, static_cast<double>(s.y));
  return 2;
}

int setSubunit(lua_State* L) {
  const EntityId e = checkEntity(L, 1);
  worldOf(L).setSubunit(e, {checkInt32(L, 2, -131071, 131071), checkInt32(L, 3, -131071, 131071)});
  return 0;
}

int setAngularVelocity(lua_State* L) {
  const EntityId e = checkEntity(L, 1);
  const double perFrame = checkNumber(L, 2);
  if (std::fabs(perFrame) > 90) lua::argError(L, 2, "degrees per frame within +-90");
  worldOf(L).setAngularVelocity(e, static_cast<int32_t>(std::llround(perFrame / 360.0 * 4294967296.0)));
  return 0;
}

int setGravityEnabled(lua_State* L) {
  const EntityId e = checkEntity(L, 1);
  worldOf(L).setGravityEnabled(e, lua::checkBoolean(L, 2));
  return 0;
}

uint32_t optionalBits(lua_State* L, int table, const char* field) {
  return static_cast<uint32_t>(integerField(L, table, "setFilter", field, 0, UINT32_MAX).value_or(0));
}

// setFilter(e, {category =, solidWith =, overlapWith =, pushable =})
int setFilter(lua_State* L) {
  const EntityId e = checkEntity(L, 1);
  lua::checkTable(L, 2);
  onlyKnownKeys(L, 2, "setFilter", {"category", "solidWith", "overlapWith", "pushable"});
  physics::EntityFilter filter;
  filter.category = optionalBits(L, 2, "category");
  filter.solidWith = optionalBits(L, 2, "solidWith");
  filter.overlapWith = optionalBits(L, 2, "overlapWith");
  rawField(L, 2, "pushable");
  filter.pushable = lua_toboolean(L, -1) != 0;
  worldOf(L).setFilter(e, filter);
  return 0;
}

int contactCount(lua_State* L) {
  lua_pushnumber(L, static_cast<double>(worldOf(L).entity(checkEntity(L, 1)).contacts().size()));
  return 1;
}

// contact(e, i) -> nx, ny (unit normal, away from the line), tag, kind, part, line (1 to
// lineCount(part), as lineAt takes it; nil against a body), other entity or nil. i from 1 to
// contactCount(e): the solid contacts of the latest frame. Lua counts from 1, so every index the
// API hands out or takes does (lines, contacts, instances, faces).
int contact(lua_State* L) {
  const auto contacts = worldOf(L).entity(checkEntity(L, 1)).contacts();
  const int64_t i = lua::checkInteger(L, 2, 1, static_cast<int64_t>(contacts.size()) + 1);
  if (i > static_cast<int64_t>(contacts.size())) return 0;
  const physics::Contact& c = contacts[static_cast<size_t>(i - 1)];
  double nx = 0, ny = 0;
  lua::unitNormal(c.normal.x, c.normal.y, nx, ny);
  lua_pushnumber(L, nx);
  lua_pushnumber(L, ny);
  lua_pushnumber(L, c.line.tag);
  lua_pushstring(L, c.line.index == physics::kNoLine ? "entity" : kindName(c.line.kind));
  lua_pushnumber(L, c.part);
  if (c.line.index == physics::kNoLine)
    lua_pushnil(L);
  else
    lua_pushnumber(L, static_cast<double>(c.line.index) + 1);
  pushEntity(L, c.other);
  return 7;
}

int instanceCount(lua_State* L) {
  lua_pushnumber(L, static_cast<double>(worldOf(L).entity(checkEntity(L, 1)).instanceCount()));
  return 1;
}

// instance(e, i) -> part, x, y, angle in that part (degrees); i from 1 (the anchor).
int instance(lua_State* L) {
  const physics::EntityView e = worldOf(L).entity(checkEntity(L, 1));
  const int64_t i = lua::checkInteger(L, 2, 1, static_cast<int64_t>(e.instanceCount()) + 1);
  if (i > static_cast<int64_t>(e.instanceCount())) return 0;
  const physics::InstanceView v = e.instance(static_cast<size_t>(i - 1));
  lua_pushnumber(L, v.part);
  lua_pushnumber(L, v.position.x);
  lua_pushnumber(L, v.position.y);
  lua_pushnumber(L, degrees(v.angle));
  return 4;
}

int gravity(lua_State* L) {
  const physics::Vec2w g = worldOf(L).mapPart(checkPart(L, 1)).gravity();
  lua_pushnumber(L, static_cast<double>(g.x) / kQ16);
  lua_pushnumber(L, static_cast<double>(g.y) / kQ16);
  return 2;
}

int setGravity(lua_State* L) {
  const physics::MapPartId part = checkPart(L, 1);
  constexpr const char* kGravity = "a gravity within +-2^30 units per frame per frame";
  worldOf(L).mapPart(part).setGravity({toQ16(L, 2, kGravity), toQ16(L, 3, kGravity)});
  return 0;
}

int addLine(lua_State* L, physics::LineKind kind) {
  const physics::MapPartId part = checkPart(L, 1);
  const physics::Vec2 a{checkInt32(L, 2), checkInt32(L, 3)}, b{checkInt32(L, 4), checkInt32(L, 5)};
  const uint32_t tag = lua_isnoneornil(L, 6) ? 0 : checkUint32(L, 6);
  physics::MapPart& map = worldOf(L).mapPart(part);
  if (map.lines().size() >= kMaxPartLines)
    throw lua::ArgError("line: part " + std::to_string(part) + " holds " + std::to_string(kMaxPartLines) +
                        " lines, the most scripts may add");
  const physics::LineIndex index = kind == physics::LineKind::OneWay ? map.oneWay(a, b, tag) : map.line(a, b, tag);
  lua_pushnumber(L, index);
  return 1;
}
int line(lua_State* L) { return addLine(L, physics::LineKind::Solid); }
int oneWay(lua_State* L) { return addLine(L, physics::LineKind::OneWay); }

int lineCount(lua_State* L) {
  lua_pushnumber(L, static_cast<double>(worldOf(L).mapPart(checkPart(L, 1)).lines().size()));
  return 1;
}

// lineAt(part, i) -> x0, y0, x1, y1, tag, kind; i from 1 to lineCount(part), as Lua counts.
int lineAt(lua_State* L) {
  const physics::MapPart& map = worldOf(L).mapPart(checkPart(L, 1));
  const int64_t i = lua::checkInteger(L, 2, 1, static_cast<int64_t>(map.lines().size())) - 1;
  const physics::Segment& s = map.segments()[static_cast<size_t>(i)];
  lua_pushnumber(L, s.a.x);
  lua_pushnumber(L, s.a.y);
  lua_pushnumber(L, s.b.x);
  lua_pushnumber(L, s.b.y);
  lua_pushnumber(L, map.lines()[static_cast<size_t>(i)].tag);
  lua_pushstring(L, kindName(map.lines()[static_cast<size_t>(i)].kind));
  return 6;
}

int refreshPierce(lua_State* L) {
  worldOf(L).refreshPierce(checkUint32(L, 1));
  return 0;
}

// createPlatform(part, {x0, y0, x1, y1, ...}, tag, "solid" | "oneway") -> platform handle
int createPlatform(lua_State* L) {
  const physics::MapPartId part = checkPart(L, 1);
  ScriptContext& context = contextOf(L);
  if (context.platforms.size() >= kMaxPlatforms)
    throw lua::ArgError("createPlatform: scripts have made " + std::to_string(kMaxPlatforms) +
                        " platforms, the most they may (destroy some first)");
  const std::vector<int32_t> xy = intList(L, 2, "createPlatform: argument 2 (lines)", 4 * kMaxPlatformLines);
  if (xy.empty() || xy.size() % 4) throw lua::ArgError("createPlatform: lines as {x0, y0, x1, y1, ...}");
  const uint32_t tag = lua_isnoneornil(L, 3) ? 0 : checkUint32(L, 3);
  physics::LineKind kind = physics::LineKind::Solid;
  if (!lua_isnoneornil(L, 4)) {
    const std::string_view name = lua::checkString(L, 4);
    if (name == "oneway")
      kind = physics::LineKind::OneWay;
    else if (name != "solid")
      throw lua::ArgError("createPlatform: kind is \"solid\" or \"oneway\"");
  }
  std::vector<physics::PlatformLine> lines;
  for (size_t i = 0; i < xy.size(); i += 4) lines.push_back({{{xy[i], xy[i + 1]}, {xy[i + 2], xy[i + 3]}}, tag, kind});
  const physics::PlatformId id = worldOf(L).createPlatform(part, lines);
  context.platforms[lua::platformNumber(id.index, id.generation)] = context.host->runningSandbox();
  lua_pushnumber(L, lua::platformNumber(id.index, id.generation));
  return 1;
}

int setPlatformMotion(lua_State* L) {
  const physics::PlatformId id = checkPlatform(L, 1);
  worldOf(L).setPlatformMotion(id, {checkInt32(L, 2, -(1 << 20), 1 << 20), checkInt32(L, 3, -(1 << 20), 1 << 20)});
  return 0;
}

// setPlatformSpin(p, px, py, degreesPerFrame): turns it about (px, py) every frame.
int setPlatformSpin(lua_State* L) {
  const physics::PlatformId id = checkPlatform(L, 1);
  const physics::Vec2 pivot{checkInt32(L, 2, -physics::kCoordLimit, physics::kCoordLimit),
                            checkInt32(L, 3, -physics::kCoordLimit, physics::kCoordLimit)};
  const double perFrame = checkNumber(L, 4);
  if (std::fabs(perFrame) > 22.5) lua::argError(L, 4, "degrees per frame within +-22.5");
  worldOf(L).setPlatformSpin(id, pivot, static_cast<int32_t>(std::llround(perFrame / 360.0 * 4294967296.0)));
  return 0;
}

int platformAngle(lua_State* L) {
  lua_pushnumber(L, degrees(worldOf(L).platform(checkPlatform(L, 1)).angle));
  return 1;
}

int platformOffset(lua_State* L) {
  const physics::PlatformView p = worldOf(L).platform(checkPlatform(L, 1));
  lua_pushnumber(L, p.offset.x);
  lua_pushnumber(L, p.offset.y);
  return 2;
}

int platformPart(lua_State* L) {
  lua_pushnumber(L, worldOf(L).platform(checkPlatform(L, 1)).part);
  return 1;
}

int destroyPlatform(lua_State* L) {
  const physics::PlatformId id = checkPlatform(L, 1);
  worldOf(L).destroyPlatform(id);
  contextOf(L).platforms.erase(lua::platformNumber(id.index, id.generation));
  return 0;
}

int frame(lua_State* L) {
  lua_pushnumber(L, static_cast<double>(worldOf(L).frame()));
  return 1;
}

// Whole-world queries are charged by their real cost, after the work (chargeSteps may not return):
// a sandbox calling one in a loop spends its budget, never the frame's time.
// The hash reads every entity's state (about 16 values, 128 bytes, per entity): 8 steps each.
constexpr int64_t kHashStepsPerEntity = 8;
// The overlap check's work counts index nodes walked and pairs tested exactly: a pair's exact test
// is tens of instructions' worth, a node a few: 4 steps each on the whole.
constexpr int64_t kOverlapStepsPerWork = 4;

int stateHash(lua_State* L) {
  char text[17];
  const physics::World& world = worldOf(L);
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(world.stateHash()));
  lua_pushstring(L, text);
  chargeSteps(L, static_cast<int64_t>(world.entityCount()) * kHashStepsPerEntity + 1);
  return 1;
}

int countOverlaps(lua_State* L) {
  size_t work = 0;
  lua_pushnumber(L, static_cast<double>(worldOf(L).countOverlaps(&work)));
  chargeSteps(L, static_cast<int64_t>(work) * kOverlapStepsPerWork + 1);
  return 1;
}

// The stage's faces: partCount() and face(i) -> part id, corners {x0, y0, ...} (i from 1).
int faceCount(lua_State* L) {
  const stage::Stage* net = contextOf(L).scene->stage();
  lua_pushnumber(L, net ? static_cast<double>(net->faceCount()) : 0);
  return 1;
}

int face(lua_State* L) {
  const stage::Stage* net = contextOf(L).scene->stage();
  const int64_t count = net ? static_cast<int64_t>(net->faceCount()) : 0;
  const int64_t i = lua::checkInteger(L, 1, 1, count > 0 ? count : 1);
  if (i > count) throw lua::ArgError("face: the scene has no stage");
  const size_t f = static_cast<size_t>(i - 1);
  lua_pushnumber(L, net->part(f));
  lua_createtable(L, static_cast<int>(net->faces[f].corners.size() * 2), 0);
  int k = 1;
  for (const physics::Vec2 c : net->faces[f].corners) {
    lua_pushnumber(L, c.x);
    lua_rawseti(L, -2, k++);
    lua_pushnumber(L, c.y);
    lua_rawseti(L, -2, k++);
  }
  return 2;
}

// levelStart() -> face, x, y, degrees of the level file's start; nil without a level file.
int levelStart(lua_State* L) {
  const stage::Level* level = contextOf(L).scene->level();
  if (!level) return 0;
  lua_pushnumber(L, level->start.face);
  lua_pushnumber(L, level->start.position.x);
  lua_pushnumber(L, level->start.position.y);
  lua_pushnumber(L, static_cast<double>(level->startMillidegrees) / 1000);
  return 4;
}

constexpr luaL_Reg kWorld[] = {
    {"createEntity", lua::bound<createEntity>},
    {"levelStart", lua::bound<levelStart>},
    {"destroyEntity", lua::bound<destroyEntity>},
    {"valid", lua::bound<valid>},
    {"insert", lua::bound<insert>},
    {"erase", lua::bound<erase>},
    {"position", lua::bound<position>},
    {"angle", lua::bound<angle>},
    {"velocity", lua::bound<velocity>},
    {"setVelocity", lua::bound<setVelocity>},
    {"subunit", lua::bound<subunit>},
    {"setSubunit", lua::bound<setSubunit>},
    {"setAngularVelocity", lua::bound<setAngularVelocity>},
    {"setGravityEnabled", lua::bound<setGravityEnabled>},
    {"setFilter", lua::bound<setFilter>},
    {"contactCount", lua::bound<contactCount>},
    {"contact", lua::bound<contact>},
    {"instanceCount", lua::bound<instanceCount>},
    {"instance", lua::bound<instance>},
    {"gravity", lua::bound<gravity>},
    {"setGravity", lua::bound<setGravity>},
    {"line", lua::bound<line>},
    {"oneWay", lua::bound<oneWay>},
    {"lineCount", lua::bound<lineCount>},
    {"lineAt", lua::bound<lineAt>},
    {"refreshPierce", lua::bound<refreshPierce>},
    {"createPlatform", lua::bound<createPlatform>},
    {"setPlatformMotion", lua::bound<setPlatformMotion>},
    {"setPlatformSpin", lua::bound<setPlatformSpin>},
    {"platformAngle", lua::bound<platformAngle>},
    {"platformOffset", lua::bound<platformOffset>},
    {"platformPart", lua::bound<platformPart>},
    {"destroyPlatform", lua::bound<destroyPlatform>},
    {"frame", lua::bound<frame>},
    {"stateHash", lua::bound<stateHash>},
    {"countOverlaps", lua::bound<countOverlaps>},
    {"faceCount", lua::bound<faceCount>},
    {"face", lua::bound<face>},
    {nullptr, nullptr},
};

}  // namespace

void addApiTable(LuaHost& host, ScriptContext& context, const char* name, const luaL_Reg* functions) {
  lua_State* L = host.state();
  lua::StackGuard guard(L);
  host.pushApi();
  lua_newtable(L);
  for (; functions->name; ++functions) {
    lua_pushlightuserdata(L, &context);
    lua_pushcclosure(L, functions->func, 1);
    lua_setfield(L, -2, functions->name);
  }
  lua_setfield(L, -2, name);
}

EntityId checkEntity(lua_State* L, int index) {
  const lua::HandleBits bits = lua::checkHandle(L, index, "an entity");
  const EntityId id{bits.index, bits.generation};
  if (!worldOf(L).valid(id))
    throw lua::ArgError("argument " + std::to_string(index) + ": stale entity handle (destroyed, or never created)");
  return id;
}

void registerWorldApi(LuaHost& host, ScriptContext& context) { addApiTable(host, context, "world", kWorld); }

}  // namespace platon::script
