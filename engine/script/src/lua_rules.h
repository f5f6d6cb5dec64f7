// physics::Rules answered by a Lua table. The table may define any of pierce, beginContact,
// overContact, endContact, contact, touchContact and crushed; the others keep the C++ defaults
// and cost nothing (no Lua call is made for them).
//
// Arguments, all plain values so no table is built per call:
//   pierce(entity, tag, kind, part, line)                     -> true to pass through
//   beginContact / overContact / endContact / touchContact / crushed
//         (entity, tag, kind, part, line, other)
//   contact(entity, tag, kind, part, line, nx, ny, other)     -> nothing: slide (the default);
//         false: stop for the rest of the frame; or a table {slide =, keepVelocity =,
//         restitution = 0..1}
// kind is "solid", "warp", "oneway" or "entity"; line is the line's index in its part (nil for an
// entity); nx, ny the unit normal from the line towards the entity; other the other entity or nil.
// A Lua error inside a callback throws ScriptError; the world finishes the frame and rethrows it.
#pragma once
#include <array>

#include "lua_host.h"
#include "platon/physics/rules.h"

namespace platon::script {

class LuaRules final : public physics::Rules {
 public:
  // Reads the callbacks of the table at `index`.
  LuaRules(LuaHost& host, int index);

  bool pierce(physics::EntityId entity, const physics::LineRef& line) override;
  void beginContact(const physics::Contact& c) override { event(kBegin, c); }
  void overContact(const physics::Contact& c) override { event(kOver, c); }
  void endContact(const physics::Contact& c) override { event(kEnd, c); }
  void contact(const physics::Contact& c, physics::ContactResponse& response) override;
  void touchContact(const physics::Contact& c) override { event(kTouch, c); }
  void crushed(const physics::Contact& c) override { event(kCrushed, c); }

 private:
  enum Callback { kPierce, kBegin, kOver, kEnd, kContact, kTouch, kCrushed, kCount };
  void event(Callback which, const physics::Contact& c);
  int pushLine(physics::EntityId entity, const physics::LineRef& line);

  LuaHost& host_;
  std::array<lua::Ref, kCount> callbacks_;
  std::array<lua::Ref, 4> kindNames_;  // solid, warp, oneway, entity: interned once
};

}  // namespace platon::script
