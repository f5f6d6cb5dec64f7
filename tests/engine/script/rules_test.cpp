// LuaRules calls a rules script two ways (arguments pushed, or an FFI slot read by JIT-compiled
// trampolines): the script must not be able to tell them apart. Random contacts of every shape
// (entity or line, world bound, other entity or none, any normal) through every callback.
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "lua_host.h"
#include "lua_rules.h"
#include "platon/testing/rng.h"

namespace platon::script {
namespace {

// Records every callback's name and arguments, as text with every digit of every number.
constexpr const char* kRecorder = R"lua(
local log, n = {}, 0
local function record(name, ...)
  local parts = { name }
  for i = 1, select("#", ...) do
    local v = select(i, ...)
    parts[#parts + 1] = type(v) == "number" and string.format("%.17g", v) or tostring(v)
  end
  n = n + 1
  log[n] = table.concat(parts, " ")
end
local rules = {}
for _, name in ipairs { "pierce", "beginContact", "overContact", "endContact", "contact", "touchContact", "crushed" } do
  rules[name] = function(...) record(name, ...) end
end
return rules, function() local text = table.concat(log, "\n") log, n = {}, 0 return text end
)lua";

struct Recorded {
  LuaHost host;
  std::unique_ptr<LuaRules> rules;
  lua::Ref take;
  explicit Recorded(LuaRules::Call how) {
    host.loadString(kRecorder, "=recorder", Trust::Trusted);
    host.call(0, 2);
    take = lua::Ref(host.state(), -1);
    rules = std::make_unique<LuaRules>(host, -2, how);
    lua_pop(host.state(), 2);
  }
  std::string log() {
    take.push();
    host.call(0, 1);
    std::string text = lua_tostring(host.state(), -1);
    lua_pop(host.state(), 1);
    return text;
  }
};

physics::Contact randomContact(testing::Rng& rng) {
  physics::Contact c{};
  c.entity = {static_cast<uint32_t>(rng.next() % (1u << 24)), static_cast<uint32_t>(rng.next() % (1u << 29))};
  c.line.part = static_cast<uint32_t>(rng.next() % 64);
  c.line.tag = static_cast<uint32_t>(rng.next());
  c.line.kind = static_cast<physics::LineKind>(rng.between(0, 2));
  switch (rng.between(0, 3)) {
    case 0:
      c.line.index = physics::kNoLine;
      break;
    case 1:
      c.line.index = physics::kWorldBoundLine;
      break;
    default:
      c.line.index = static_cast<uint32_t>(rng.next() % 100000);
  }
  c.part = c.line.part;
  if (rng.between(0, 1))
    c.other = {static_cast<uint32_t>(rng.next() % (1u << 24)), static_cast<uint32_t>(rng.next() % 1000)};
  const int64_t range = int64_t{1} << rng.between(0, 46);
  switch (rng.between(0, 4)) {
    case 0:
      c.normal = {0, 0};
      break;
    case 1:
      c.normal = {0, range};
      break;
    case 2:
      c.normal = {-range, 0};
      break;
    default:
      c.normal = {static_cast<int64_t>(rng.next() % static_cast<uint64_t>(2 * range + 1)) - range,
                  static_cast<int64_t>(rng.next() % static_cast<uint64_t>(2 * range + 1)) - range};
  }
  return c;
}

TEST(Rules, ClassicAndFfiCallsGiveTheSameArguments) {
  Recorded classic(LuaRules::Call::Classic), ffi(LuaRules::Call::Ffi);
  testing::Rng rng{2026};
  int entityContacts = 0, noOther = 0;
  for (int i = 0; i < 20000; ++i) {  // enough for the trampolines to be compiled and run compiled
    const physics::Contact c = randomContact(rng);
    entityContacts += c.line.index == physics::kNoLine;
    noOther += !c.other.isSet();
    physics::ContactResponse a, b;
    for (Recorded* r : {&classic, &ffi}) {
      r->rules->pierce(c.entity, c.line);
      r->rules->beginContact(c);
      r->rules->overContact(c);
      r->rules->contact(c, r == &classic ? a : b);
      r->rules->endContact(c);
      r->rules->touchContact(c);
      r->rules->crushed(c);
    }
    ASSERT_EQ(classic.log(), ffi.log()) << "contact " << i;
  }
  EXPECT_GT(entityContacts, 1000);
  EXPECT_GT(noOther, 1000);
}

const char* kFailing =
    "return { contact = function(entity, tag)\n"
    "  if tag == 7 then error('tag seven') end\n"
    "end }\n";

// Each test: one host, a rules script loaded into it, called the way the parameter says.
class RulesBothWays : public ::testing::TestWithParam<LuaRules::Call> {
 protected:
  LuaRules load(const char* code, const std::string& chunkName, Trust trust) {
    const int sandbox = host.loadString(code, chunkName, trust);
    host.beginFrame();
    if (trust == Trust::Sandboxed)
      host.callSandboxed(sandbox, 0, 1);
    else
      host.call(0, 1);
    LuaRules rules(host, -1, GetParam(), sandbox);
    lua_pop(host.state(), 1);
    return rules;
  }
  LuaHost host;
};

TEST_P(RulesBothWays, AnErrorInACallbackCarriesFileLineAndTraceback) {
  LuaRules rules = load(kFailing, "@levels/demo/rules.lua", Trust::Trusted);
  physics::Contact c{};
  c.entity = {1, 0};
  physics::ContactResponse response;
  for (int i = 0; i < 1000; ++i) rules.contact(c, response);  // compiled by now
  c.line.tag = 7;
  try {
    rules.contact(c, response);
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "levels/demo/rules.lua:2: tag seven");
    EXPECT_NE(e.traceback().find("levels/demo/rules.lua:2"), std::string::npos) << e.traceback();
  }
  EXPECT_EQ(lua_gettop(host.state()), 1);  // the traceback handler only
}

// What contact() returns is checked, and the error names where the callback is written (it named
// no line before: "rules: contact() returned a string").
TEST_P(RulesBothWays, AWrongResponseNamesTheCallbacksFileAndLine) {
  LuaRules rules = load(
      "local rules = {}\n"
      "function rules.contact(e, tag)\n"
      "  if tag == 1 then return 'slide' end\n"
      "  return { restitution = 2 }\n"
      "end\n"
      "return rules\n",
      "@levels/demo/rules.lua", Trust::Trusted);
  physics::Contact c{};
  c.entity = {1, 0};
  physics::ContactResponse response;
  for (const auto& [tag, message] :
       {std::pair{1u,
                  "levels/demo/rules.lua:2: rules: contact() returned a string; return nothing, "
                  "false, or {slide =, keepVelocity =, restitution =}"},
        std::pair{0u, "levels/demo/rules.lua:2: rules: contact() returned restitution outside [0, 1]"}}) {
    c.line.tag = tag;
    try {
      rules.contact(c, response);
      ADD_FAILURE() << "no error for tag " << tag;
    } catch (const ScriptError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}

// A sandboxed script's response table is read raw: its metamethods never run outside a sandboxed
// call, where no time budget would stop them.
TEST_P(RulesBothWays, AResponseTableIsReadRaw) {
  LuaRules rules = load(
      "local loop = setmetatable({ slide = false }, { __index = function() while true do end end })\n"
      "return { contact = function() return loop end }\n",
      "@mod.lua", Trust::Sandboxed);
  physics::Contact c{};
  c.entity = {1, 0};
  physics::ContactResponse response;
  rules.contact(c, response);
  EXPECT_FALSE(response.slide);
  EXPECT_TRUE(response.removeNormalVelocity);
  EXPECT_EQ(response.restitution, physics::Fraction::zero());
}

TEST_P(RulesBothWays, CallbacksLeaveTheStackAsTheyFoundIt) {
  LuaRules rules = load(
      "local r = 0\n"
      "return { pierce = function() return true end,\n"
      "  beginContact = function() end,\n"
      "  contact = function(e, tag)\n"
      "    r = r + 1\n"
      "    if r % 3 == 0 then return nil elseif r % 3 == 1 then return false end\n"
      "    return { slide = true, keepVelocity = false, restitution = 0.5 }\n"
      "  end }\n",
      "=rules", Trust::Trusted);
  lua_State* L = host.state();
  const int top = lua_gettop(L);
  physics::Contact c{};
  c.entity = {1, 0};
  physics::ContactResponse response;
  for (int i = 0; i < 100000; ++i) {
    rules.contact(c, response);
    rules.beginContact(c);
    EXPECT_TRUE(rules.pierce(c.entity, c.line));
    ASSERT_EQ(lua_gettop(L), top) << "after " << i + 1 << " calls";
  }
}

INSTANTIATE_TEST_SUITE_P(, RulesBothWays, ::testing::Values(LuaRules::Call::Classic, LuaRules::Call::Ffi),
                         [](const auto& p) { return p.param == LuaRules::Call::Ffi ? "Ffi" : "Classic"; });

}  // namespace
}  // namespace platon::script
