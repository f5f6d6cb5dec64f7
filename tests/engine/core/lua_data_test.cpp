// The data reader (core/lua_data.h), the one reader of scene manifests and scenarios, checked
// against LuaJIT itself: what the reader reads, Lua reads to the same value, over families of
// literals (every escape and byte, number spellings, newline kinds, long brackets, key forms, and
// some thousands of random texts, half of them broken); what it refuses names its line:column;
// a key given twice in any spelling Lua takes as equal is refused; the caps on size and depth.
#include "platon/core/lua_data.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "platon/testing/lua_reference.h"
#include "platon/testing/rng.h"

using namespace platon;
using core::DataError;
using core::DataValue;

namespace {

struct LuaState {
  std::unique_ptr<lua_State, void (*)(lua_State*)> L{luaL_newstate(), lua_close};
};

// "" when the reader and Lua read `text` alike; else what differs. `readerMayRefuse`: a refusal
// by the reader is allowed (it reads a subset of Lua), and Lua is then not asked.
std::string compare(lua_State* L, const std::string& text, bool readerMayRefuse) {
  DataValue v;
  try {
    v = core::readLuaData(text, "t.lua");
  } catch (const DataError& e) {
    return readerMayRefuse ? "" : std::string("the reader refuses it: ") + e.what();
  }
  lua_settop(L, 0);
  if (luaL_loadbuffer(L, text.data(), text.size(), "=t.lua") != 0 || lua_pcall(L, 0, 1, 0) != 0)
    return std::string("Lua refuses what the reader reads: ") + lua_tostring(L, -1);
  std::string why;
  if (!platon::testing::sameAsLua(L, 1, v, why)) return why;
  return "";
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", c);
    out += c >= 0x20 && c < 0x7f ? std::string(1, static_cast<char>(c)) : std::string(hex);
  }
  return out;
}

}  // namespace

TEST(LuaData, NumbersInEverySpellingReadAsLuaReadsThem) {
  LuaState lua;
  const std::vector<std::string> mantissas = {"0",   "1",   "08",   "123456789012345678901234567890",
                                              ".5",  "5.",  "1.25", "9007199254740993",
                                              "0.1", "000", "2.50", "17976931348623157"};
  const std::vector<std::string> exponents = {"", "e0", "e+5", "E-3", "e270", "e-300", "E+0"};
  const std::vector<std::string> hex = {"0x0",
                                        "0xff",
                                        "0XfF",
                                        "0x1p4",
                                        "0x.8",
                                        "0x1.",
                                        "0x1.8p-3",
                                        "0X1P+2",
                                        "0xep1",
                                        "0xFFFFFFFFFFFFFFFFF",
                                        "0x10",
                                        "0x7fffffff",
                                        "0x1.fffffffffffffp1023",
                                        "0xA.Bp2"};
  std::vector<std::string> numbers = hex;
  for (const auto& m : mantissas)
    for (const auto& e : exponents) numbers.push_back(m + e);
  int checked = 0;
  for (const auto& n : numbers)
    for (const char* form : {"return %s", "return -%s", "return - --[[c]] %s", "return { [%s] = 1, v = %s }"}) {
      std::string text = form;
      for (size_t at; (at = text.find("%s")) != std::string::npos;) text.replace(at, 2, n);
      const std::string diff = compare(lua.L.get(), text, false);
      EXPECT_EQ(diff, "") << text;
      ++checked;
    }
  EXPECT_GT(checked, 300);
}

TEST(LuaData, EveryByteAndEscapeReadsAsLuaReadsIt) {
  LuaState lua;
  std::vector<std::string> strings;
  for (int b = 0; b < 256; ++b) {
    char text[64];
    std::snprintf(text, sizeof text, "return { '\\%d', \"\\x%02x\", '\\%03d1' }", b, b, b);
    strings.emplace_back(text);
    std::snprintf(text, sizeof text, "return '\\x%02X'", b);
    strings.emplace_back(text);
    if (b != '\n' && b != '\r' && b != '\'' && b != '\\')
      strings.push_back(std::string("return 'a") + static_cast<char>(b) + "b'");  // the raw byte
  }
  for (const char* e : {"a", "b", "f", "n", "r", "t", "v", "\\", "\"", "'", "\n", "\r", "\r\n", "\n\r", "z  \n\t x"})
    strings.push_back(std::string("return 'x\\") + e + "y'");
  for (const char* u : {"0", "41", "7F", "80", "7FF", "800", "FFFF", "10000", "10FFFF", "000000000041", "D7FF", "E000"})
    strings.push_back(std::string("return '\\u{") + u + "}'");
  for (const char* nl : {"\n", "\r", "\r\n", "\n\r", "\n\n", "\r\r"})
    for (const char* level : {"", "=", "==="}) {
      const std::string open = std::string("[") + level + "[", close = std::string("]") + level + "]";
      const std::string notClose = *level ? "]]" : "]=]";  // a bracket of another level is text
      strings.push_back("return " + open + nl + "a" + nl + notClose + "b" + nl + close);
      strings.push_back(std::string("--") + open + nl + "comment " + notClose + " " + close + nl + "return " + open +
                        close);
    }
  for (const auto& text : strings) EXPECT_EQ(compare(lua.L.get(), text, false), "") << escaped(text);
}

TEST(LuaData, TablesKeysAndCommentsReadAsLuaReadsThem) {
  LuaState lua;
  const std::vector<std::string> tables = {
      "return {}",
      "return { 1, 2, 3; 4 }",
      "return { a = 1, ['b c'] = 2, [3] = 'x', [true] = false, [-0.5] = {} }",
      "return { nil, 2, nil }",
      "return { x = { y = { z = { 'deep' } } } }",
      "return {1,2,}",
      "return { [ [[long key]] ] = 1 }",
      "return { goto_ = 1, _ = 2, end_ = 3, nil_ = 4 }",
      "-- comment\nreturn --[[ inline ]] { a --[==[ x ]==] = -- line\n 1 } ; -- after",
      "return\t{\va\f=\r1\r\n}",
      "return 'single' ;",
      "\xEF\xBB\xBFreturn { bom = true }",
      "#!/usr/bin/env platon\nreturn { shebang = 1 }",
      "return { tiny = 1e-400, subnormal = 1e-310, hex = 0x1p-1074 }",
      "return { caf\xC3\xA9 = 1 }",
  };
  for (const auto& text : tables) EXPECT_EQ(compare(lua.L.get(), text, false), "") << escaped(text);
}

TEST(LuaData, WhatIsNotDataIsRefusedAtItsPlace) {
  struct Case {
    std::string text, error;
    DataError::Kind kind = DataError::Kind::NotData;
  };
  const Case cases[] = {
      {"", "t.lua:1:1: a data file is 'return { ... }'"},
      {"return", "t.lua:1:7: unexpected end of file (a value is missing)"},
      {"return {\n  a = os.time(),\n}", "t.lua:2:7: 'os': a data file holds only strings"},
      {"return { a = 1 + 2 }", "t.lua:1:16: expected ',' or '}'"},
      {"return 1 .. 2", "t.lua:1:10: unexpected text after the value"},
      {"return { end = 1 }", "t.lua:1:10: 'end' is a Lua keyword, not a name: write [\"end\"] ="},
      {"return { [nil] = 1 }", "t.lua:1:11: a table key cannot be nil"},
      {"return { [{}] = 1 }", "t.lua:1:11: a table key in data is a string, a number or a boolean"},
      {"return { a = 1", "t.lua:1:8: unfinished table (no '}' for this '{')"},
      {"return 'abc\ndef'", "t.lua:1:8: unfinished string"},
      {"return 'a\\qb'", "t.lua:1:10: escape: unknown escape '\\q'"},
      {"return '\\256'", "t.lua:1:9: escape: \\ddd is past 255"},
      {"return '\\x4g'", "t.lua:1:9: escape: \\x takes two hex digits"},
      {"return '\\u{110000}'", "t.lua:1:9: escape: \\u{...} is past 10FFFF"},
      {"return '\\u{D800}'", "t.lua:1:9: escape: \\u{...} is a UTF-16 surrogate"},
      {"return [==[ open", "t.lua:1:8: unfinished long string (no ]==])"},
      {"--[[ open\nreturn 1", "t.lua:1:3: unfinished long comment (no ]])"},
      {"return 0x10LL", "t.lua:1:8: '0x10LL' is a 64-bit integer (a cdata), not a number"},
      {"return 3i", "t.lua:1:8: '3i' is a complex number (a cdata), not a number"},
      {"return 1e999", "t.lua:1:8: '1e999' is too large for a number"},
      {"return 1..2", "t.lua:1:8: '1..2' is not a number"},
      {"return 0x", "t.lua:1:8: '0x' is not a number"},
      {"return -'a'", "t.lua:1:9: '-' in data is the sign of a number"},
      {"\n\n  return { a = 1, b = 2, a = 3 }", "t.lua:3:26: the key 'a' is given twice in one table",
       DataError::Kind::RepeatedKey},
  };
  for (const Case& c : cases) {
    try {
      (void)core::readLuaData(c.text, "t.lua");
      ADD_FAILURE() << "read: " << escaped(c.text);
    } catch (const DataError& e) {
      EXPECT_EQ(std::string(e.what()).substr(0, c.error.size()), c.error) << escaped(c.text);
      EXPECT_EQ(e.kind, c.kind) << escaped(c.text);
    }
  }
}

// Lua keeps the last of two equal keys silently; the reader refuses every spelling of one.
TEST(LuaData, AKeyGivenTwiceInAnySpellingIsRefused) {
  for (const char* body : {"a = 1, a = 2", "a = 1, ['a'] = 2", "[\"a\"] = 1, [ [[a]] ] = 2", "'x', [1] = 'y'",
                           "[1] = 'y', 'x'", "[1] = 1, [1.0] = 2", "[0] = 1, [-0] = 2", "[0x10] = 1, [16] = 2",
                           "[true] = 1, [true] = 2", "[1e2] = 1, [100] = 2", "['\\65'] = 1, A = 2"}) {
    const std::string text = std::string("return { ") + body + " }";
    try {
      (void)core::readLuaData(text, "t.lua");
      ADD_FAILURE() << "read: " << text;
    } catch (const DataError& e) {
      EXPECT_EQ(e.kind, DataError::Kind::RepeatedKey) << text << ": " << e.what();
    }
  }
}

TEST(LuaData, SizeAndDepthAreCapped) {
  auto kindOf = [](const std::string& text) {
    try {
      (void)core::readLuaData(text, "t.lua");
    } catch (const DataError& e) {
      return static_cast<int>(e.kind);
    }
    return -1;
  };
  auto nested = [](int n) {
    return "return " + std::string(static_cast<size_t>(n), '{') + std::string(static_cast<size_t>(n), '}');
  };
  EXPECT_EQ(kindOf(nested(core::kMaxDataDepth)), -1);
  EXPECT_EQ(kindOf(nested(core::kMaxDataDepth + 1)), static_cast<int>(DataError::Kind::TooLarge));
  std::string many = "return {";
  for (size_t i = 0; i < core::kMaxDataValues; ++i) many += "1,";
  EXPECT_EQ(kindOf(many + "}"), static_cast<int>(DataError::Kind::TooLarge));  // the table is one value too
  std::string keyed = "return {";
  for (size_t i = 0; i < core::kMaxDataValues / 2; ++i) keyed += "a" + std::to_string(i) + "=1,";
  EXPECT_EQ(kindOf(keyed + "}"), static_cast<int>(DataError::Kind::TooLarge));  // keys count as values
}

// Random texts from a literal grammar, half of them with a byte changed, inserted or cut: each is
// read alike by the reader and Lua, or refused by the reader with its place.
TEST(LuaData, RandomTextsAreReadAsLuaReadsThemOrRefusedAtTheirPlace) {
  LuaState lua;
  platon::testing::Rng rng{2026};
  const char* atoms[] = {"1",    "-2.5",  "0x1F", ".5e3",   "'s'",     "\"q\\n\"",   "[[l]]", "[=[\n]]]=]",
                         "true", "false", "nil",  "'\\65'", "'\\x41'", "'\\z \n x'", "1e308", "0x1p-1022"};
  const char* names[] = {"a", "b", "_x", "and_", "k9"};
  const char* noise[] = {" ", "\n", "\r\n", "--c\n", "--[[c]]", "\t"};
  std::function<std::string(int)> value = [&](int depth) -> std::string {
    if (depth > 3 || rng.between(0, 2) > 0) return atoms[rng.between(0, 15)];
    std::string t = "{";
    const int n = rng.between(0, 4);
    for (int i = 0; i < n; ++i) {
      t += noise[rng.between(0, 5)];
      switch (rng.between(0, 2)) {
        case 0:
          t += std::string(names[rng.between(0, 4)]) + std::to_string(i) + " = ";
          break;
        case 1:
          t += "[" + std::string(i % 2 ? "'k" + std::to_string(i) + "'" : std::to_string(i + 10)) + "] = ";
          break;
        default:
          break;
      }
      t += value(depth + 1);
      t += rng.between(0, 1) ? "," : ";";
    }
    return t + noise[rng.between(0, 5)] + "}";
  };
  const char bytes[] = "{}[]=,;'\"\\-.0xe+\n\r ab[=";
  int read = 0, refused = 0;
  for (int i = 0; i < 4000; ++i) {
    std::string text = "return " + value(0);
    if (i % 2) {
      const size_t at = static_cast<size_t>(rng.between(0, static_cast<int>(text.size()) - 1));
      const char b = bytes[rng.between(0, static_cast<int>(sizeof bytes) - 2)];
      switch (rng.between(0, 2)) {
        case 0:
          text[at] = b;
          break;
        case 1:
          text.insert(at, 1, b);
          break;
        default:
          text.erase(at, 1);
      }
    }
    try {
      (void)core::readLuaData(text, "t.lua");
      ++read;
      EXPECT_EQ(compare(lua.L.get(), text, false), "") << escaped(text);
    } catch (const DataError& e) {
      ++refused;
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("t.lua:" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": ", 0), 0u)
          << message;
      EXPECT_GE(e.line, 1) << message;
      EXPECT_GE(e.column, 1) << message;
    }
  }
  EXPECT_GT(read, 2000);  // every unbroken text, and some broken ones that are still data
  EXPECT_GT(refused, 500);
}

// What the engine writes as a Lua string (luaQuoted) reads back as itself, for every byte and for
// random strings of them: scenarios and package manifests name any path the same way.
TEST(LuaData, AQuotedStringReadsBackAsItself) {
  std::string every;
  for (int b = 0; b < 256; ++b) every += static_cast<char>(b);
  std::vector<std::string> texts = {"", every, "\"", "\\", "a\\\"b", "\n\r\t", "\0012", "]]", "--"};
  uint64_t state = 7;
  for (int i = 0; i < 500; ++i) {
    std::string t;
    const int n = static_cast<int>((state = state * 6364136223846793005ULL + 1) >> 58);
    for (int k = 0; k < n; ++k) t += static_cast<char>((state = state * 6364136223846793005ULL + 1) >> 56);
    texts.push_back(t);
  }
  for (const std::string& t : texts) {
    const DataValue v = core::readLuaData("return " + core::luaQuoted(t), "q.lua");
    ASSERT_TRUE(v.isString());
    EXPECT_EQ(v.text, t);
  }
}
