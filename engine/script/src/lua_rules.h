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
// A trusted script's Lua error inside a callback throws ScriptError; the world finishes the frame
// and rethrows it. A sandboxed script's is kept for the frame's report, and the default applies.
//
// Two ways to make the call, the same arguments either way. Classic: every argument pushed through
// the C API (eight pushes for contact()). FFI (trusted states with the ffi library): the contact's
// numbers are written into a plain C struct and a small Lua function per callback, compiled by the
// JIT, reads them and calls the script's function, so C++ makes one argument-less call.
// bench/script/script_callbacks measures both.
#pragma once
#include <array>
#include <memory>
#include <string>

#include "lua_host.h"
#include "platon/physics/rules.h"

namespace platon::script {

class LuaRules final : public physics::Rules {
 public:
  // Classic: arguments pushed. Ffi: trampolines, for trusted scripts only. A sandboxed script's
  // functions run with the JIT off: a trace calling one is aborted and the trampoline blacklisted,
  // leaving its FFI reads to the interpreter (320 ns a call), and calling them through
  // lua::callThrough to keep the trace measured 46 ns against the classic path's 44.
  enum class Call { Classic, Ffi };
  // Reads the callbacks of the table at `index`. `sandbox`: the sandbox whose script it is (its
  // callbacks run under the frame's budget, and answer with the defaults when it is spent or the
  // sandbox is disabled), or kNoSandbox for trusted rules.
  LuaRules(LuaHost& host, int index, Call how = Call::Classic, int sandbox = kNoSandbox);

  bool pierce(physics::EntityId entity, const physics::LineRef& line) override;
  void beginContact(const physics::Contact& c) override { event(kBegin, c); }
  void overContact(const physics::Contact& c) override { event(kOver, c); }
  void endContact(const physics::Contact& c) override { event(kEnd, c); }
  void contact(const physics::Contact& c, physics::ContactResponse& response) override;
  void touchContact(const physics::Contact& c) override { event(kTouch, c); }
  void crushed(const physics::Contact& c) override { event(kCrushed, c); }

 private:
  enum Callback { kPierce, kBegin, kOver, kEnd, kContact, kTouch, kCrushed, kCount };
  std::string places_[kCount];  // "file:line: " where each callback is written, or empty
  void event(Callback which, const physics::Contact& c);
  // Classic: pushes entity, tag, kind, part, line (5 values). FFI: writes them into the slot, pushes
  // nothing. Returns the number of values pushed.
  inline int pushLine(physics::EntityId entity, const physics::LineRef& line);
  inline int pushOther(physics::EntityId other);
  inline int pushNormal(const physics::Vec2w& normal);
  // Runs push (which returns how many values it pushed); if it throws (a handle out of the range
  // Lua numbers hold), the stack goes back to `top` first, so no slot leaks.
  template <class Push>
  int pushArguments(int top, Push&& push) {
    try {
      return push();
    } catch (...) {
      lua_settop(host_.state(), top);
      throw;
    }
  }
  void makeTrampolines(int index);
  // Calls the pushed callback with its n arguments; false: it was skipped (the defaults apply).
  // A sandboxed script's error is kept for the frame's report (LuaHost::keepError) and its
  // callback answers with the default: nothing of a level's rules can fail the engine's own calls
  // into the world (a spawn's insert, say).
  bool invoke(int n, int results) {
    if (sandbox_ == kNoSandbox) [[likely]] {
      host_.call(n, results);
      return true;
    }
    return invokeSandboxed(n, results);
  }
  bool invokeSandboxed(int n, int results);
  // A bad answer: thrown for trusted rules, kept (named after the script) for sandboxed ones.
  void fail(const std::string& message);
  bool skipped() const { return sandbox_ != kNoSandbox && host_.disabled(sandbox_); }

  // What the FFI trampolines read (doubles only: the same numbers the classic path pushes, but the
  // normal as the world gives it; -1 for "no line" and "no other entity", which they turn into nil).
  struct Slot {
    double entity, tag, kind, part, line, nx, ny, other;
    double answer;  // contact()'s, written back: 0 nil, 1 false, 2 true, 3 returned (a table or a mistake)
  };

  LuaHost& host_;
  std::array<lua::Ref, kCount> callbacks_;  // the script's functions, or their FFI trampolines
  std::array<lua::Ref, 4> kindNames_;       // solid, warp, oneway, entity: interned once
  std::unique_ptr<Slot> slot_;              // set for Call::Ffi; Lua holds its address
  int sandbox_ = kNoSandbox;
};

}  // namespace platon::script
