// Lua 5.1 patterns with a step budget (lua_pattern.h). Written from the reference manual's rules:
//
//   a single character class:  x (itself), . (any), %a %c %d %g %l %p %s %u %w %x %z (and their
//     upper-case complements), %<non-alphanumeric> (that character), [set] and [^set] (characters,
//     ranges a-z and %classes; a ']' first in the set is itself);
//   a pattern item: a class, optionally followed by * (longest run), + (one or more, longest),
//     - (shortest run) or ? (optional); %1..%9 (the text a capture matched); %bxy (a balanced run
//     from x to y); %f[set] (a frontier: the previous character is not in the set, this one is);
//   a pattern: items in a row; ^ at the start anchors it, $ at the end anchors the end;
//   captures: (...) the text, () a position.
//
// The matcher backtracks like the reference implementation, so results are LuaJIT's (a test checks
// that over many thousands of random patterns), but every unit of work is counted and a call that
// needs more than kPatternStepBudget steps is refused.
#include "lua_pattern.h"

#include <array>
#include <cstddef>
#include <cstring>

#include "lua_host.h"

namespace platon::script {
namespace {

constexpr int kMaxCaptures = 32;            // as LuaJIT: "too many captures"
constexpr int kMaxDepth = 200;              // nested backtracking points: "pattern too complex"
constexpr ptrdiff_t kOpen = -1;             // a capture still open
constexpr ptrdiff_t kPosition = -2;         // a () capture: a position, not text
constexpr int kSetCacheBits = 5;            // a call keeps up to 32 compiled [sets] (Matcher::setAt)
constexpr char kSpecials[] = "^$*+?.([%-";  // a find() pattern without any of these is plain text

// Raised by the matcher (which holds nothing that needs freeing) and turned into a Lua error by
// the function Lua called, once no C++ handler is active.
struct Refusal {
  const char* message;  // nullptr: the step budget is spent
};

inline unsigned char uc(char c) { return static_cast<unsigned char>(c); }

// The C locale's classes, by value, so no locale can change a match.
bool isLower(int c) { return c >= 'a' && c <= 'z'; }
bool isUpper(int c) { return c >= 'A' && c <= 'Z'; }
bool isAlpha(int c) { return isLower(c) || isUpper(c); }
bool isDigit(int c) { return c >= '0' && c <= '9'; }
bool isAlnum(int c) { return isAlpha(c) || isDigit(c); }
bool isSpace(int c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
bool isControl(int c) { return c < 32 || c == 127; }
bool isGraph(int c) { return c > 32 && c < 127; }
bool isPunct(int c) { return isGraph(c) && !isAlnum(c); }
bool isHex(int c) { return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// c against the class letter after a '%'.
bool classMatches(int c, int letter) {
  bool yes;
  switch (letter | 0x20) {  // a letter's lower case (no other character maps onto a class letter)
    case 'a':
      yes = isAlpha(c);
      break;
    case 'c':
      yes = isControl(c);
      break;
    case 'd':
      yes = isDigit(c);
      break;
    case 'g':
      yes = isGraph(c);
      break;
    case 'l':
      yes = isLower(c);
      break;
    case 'p':
      yes = isPunct(c);
      break;
    case 's':
      yes = isSpace(c);
      break;
    case 'u':
      yes = isUpper(c);
      break;
    case 'w':
      yes = isAlnum(c);
      break;
    case 'x':
      yes = isHex(c);
      break;
    case 'z':
      yes = c == 0;
      break;
    default:
      return letter == c;  // %x for any other x: that character
  }
  return isUpper(letter) ? !yes : yes;
}

// The characters a single class or a [set] admits: 256 bits, so testing a character costs one
// lookup however long the set is (a set is compiled once per call, see Matcher::setAt).
class CharSet {
 public:
  bool has(int c) const { return (bits_[c >> 6] >> (c & 63)) & 1; }
  void add(int c) { bits_[c >> 6] |= uint64_t{1} << (c & 63); }
  void add(const CharSet& other) {
    for (int i = 0; i < 4; ++i) bits_[i] |= other.bits_[i];
  }
  // lo..hi inclusive, a word at a time (a set of many wide ranges stays linear in its length).
  void addRange(int lo, int hi) {
    for (int word = lo >> 6; lo <= hi && word < 4; ++word) {
      const int first = lo & 63, last = hi >> 6 == word ? hi & 63 : 63;
      const uint64_t upToLast = last == 63 ? ~uint64_t{0} : (uint64_t{1} << (last + 1)) - 1;
      bits_[word] |= upToLast & ~((uint64_t{1} << first) - 1);
      lo = (word + 1) << 6;
    }
  }
  void invert() {
    for (uint64_t& word : bits_) word = ~word;
  }

 private:
  uint64_t bits_[4] = {};
};

// What "%x" admits inside a set, for every byte x: the class's characters, or x itself.
const CharSet& classSet(int letter) {
  static const auto sets = [] {
    std::array<CharSet, 256> all;
    for (int x = 0; x < 256; ++x)
      for (int c = 0; c < 256; ++c)
        if (classMatches(c, x)) all[x].add(c);
    return all;
  }();
  return sets[letter];
}

// The set [first ... last] (first at '[', last at its ']'), read as LuaJIT's matchbracketclass
// reads it: '^' first negates, "%x" is a class or x, "a-z" a range unless the '-' is last, any
// other byte is itself.
CharSet compileSet(const char* first, const char* last) {
  CharSet set;
  const char* p = first + 1;
  const bool negated = *p == '^';
  if (negated) ++p;
  for (; p < last; ++p) {
    if (*p == '%' && p + 1 < last) {
      ++p;
      set.add(classSet(uc(*p)));
    } else if (p[1] == '-' && p + 2 < last) {
      set.addRange(uc(p[0]), uc(p[2]));
      p += 2;
    } else {
      set.add(uc(*p));
    }
  }
  if (negated) set.invert();
  return set;
}

struct Capture {
  const char* start;
  ptrdiff_t length;  // or kOpen, kPosition
};

// The steps one call takes (the per-call bound counts them all) and how many of them were charged to
// the frame's budget already (before each callback: an error there unwinds past the call's end).
struct StepCount {
  uint64_t total = 0;
  uint64_t charged = 0;
  void chargeSoFar(lua_State* L) {
    const uint64_t due = total - charged;
    charged = total;
    chargeSteps(L, static_cast<int64_t>(due));
  }
};

class Matcher {
 public:
  // The pattern ends at its first "\0" (as in LuaJIT); the byte at patternEnd is always readable
  // ("\0": an embedded one, or the terminator every Lua string has).
  // Its steps are added to `steps`, which the caller charges to the frame's budget.
  Matcher(const char* subject, size_t subjectLength, const char* pattern, size_t patternLength, StepCount& steps)
      : steps_(steps),
        subject_(subject),
        subjectEnd_(subject + subjectLength),
        pattern_(pattern),
        patternEnd_(pattern + strnlen(pattern, patternLength)) {}

  const char* patternEnd() const { return patternEnd_; }
  int captures() const { return level_; }
  const Capture& capture(int i) const { return capture_[i]; }

  void step(uint64_t n = 1) {
    steps_.total += n;
    if (steps_.total > kPatternStepBudget) throw Refusal{nullptr};
  }
  StepCount& steps() { return steps_; }

  // Where a match of `p` starting at `s` ends, or nullptr. Captures are reset.
  const char* matchAt(const char* s, const char* p) {
    level_ = 0;
    depth_ = 0;
    step();
    return match(s, p);
  }

 private:
  struct Depth {
    int& depth;
    explicit Depth(int& d) : depth(d) {
      if (++depth > kMaxDepth) throw Refusal{"pattern too complex"};
    }
    ~Depth() { --depth; }
  };

  // A [set] of the pattern, compiled: where it ends and what it admits.
  struct CompiledSet {
    const char* start = nullptr;  // its '[' (nullptr: an empty slot)
    const char* end = nullptr;    // past its ']'
    CharSet chars;
  };

  bool single(int c, const char* p) {
    switch (*p) {
      case '.':
        return true;
      case '%':
        return classMatches(c, uc(p[1]));
      case '[':
        return setAt(p).chars.has(c);
      default:
        return uc(*p) == c;
    }
  }

  // Past the class that starts at p.
  const char* classEnd(const char* p) {
    if (*p == '[') return setAt(p).end;
    const char c = *p++;
    if (c == '%') {
      if (p >= patternEnd_) throw Refusal{"malformed pattern (ends with '%')"};
      return p + 1;
    }
    return p;
  }

  // Past the ']' of the set whose '[' is at p.
  const char* setEnd(const char* p) const {
    ++p;
    if (p < patternEnd_ && *p == '^') ++p;
    do {  // the set's first character is itself, even a ']'
      if (p >= patternEnd_) throw Refusal{"malformed pattern (missing ']')"};
      if (*p++ == '%' && p < patternEnd_) ++p;
    } while (p >= patternEnd_ || *p != ']');
    return p + 1;
  }

  // The set whose '[' is at p, compiled on first use in this call and kept in a small cache keyed
  // by its place in the pattern. A set is read every time a character is tried against it, so a
  // set of a megabyte read for each character of the subject would be hours of work in C, where
  // no hook stops it; compiled, each test is one lookup, and each compilation is charged a step
  // per byte of the set (a pattern with more sets than the cache holds pays for each rereading).
  const CompiledSet& setAt(const char* p) {
    const auto offset = static_cast<uint64_t>(p - pattern_);
    CompiledSet& slot = sets_[(offset * 0x9E3779B97F4A7C15u) >> (64 - kSetCacheBits)];
    if (slot.start == p) return slot;
    const char* end = setEnd(p);
    step(static_cast<uint64_t>(end - p));
    slot.start = p;
    slot.end = end;
    slot.chars = compileSet(p, end - 1);
    return slot;
  }

  const char* match(const char* s, const char* p) {
    Depth guard(depth_);
    for (;;) {
      if (p >= patternEnd_) return s;
      switch (*p) {
        case '(':
          if (p + 1 < patternEnd_ && p[1] == ')') return openCapture(s, p + 2, kPosition);
          return openCapture(s, p + 1, kOpen);
        case ')':
          return closeCapture(s, p + 1);
        case '$':
          if (p + 1 == patternEnd_) return s == subjectEnd_ ? s : nullptr;
          break;
        case '%':
          if (special(s, p)) {
            if (!s) return nullptr;
            continue;
          }
          break;
        default:
          break;
      }
      const char* ep = classEnd(p);
      step();
      const bool here = s < subjectEnd_ && single(uc(*s), p);
      const char next = ep < patternEnd_ ? *ep : '\0';
      switch (next) {
        case '?':
          if (here) {
            if (const char* r = match(s + 1, ep + 1)) return r;
          }
          p = ep + 1;
          continue;
        case '*':
          return longest(s, p, ep);
        case '+':
          return here ? longest(s + 1, p, ep) : nullptr;
        case '-':
          return shortest(s, p, ep);
        default:
          if (!here) return nullptr;
          ++s;
          p = ep;
          continue;
      }
    }
  }

  // A '%b', '%f' or back-reference item at p: true with s past what it matched (null if it failed)
  // and p past the item; false when p holds none of them (a class such as %d: a single character).
  bool special(const char*& s, const char*& p) {
    if (p + 1 >= patternEnd_) return false;
    if (p[1] == 'b') {
      s = balanced(s, p + 2);
      p += 4;
      return true;
    }
    if (p[1] == 'f') {
      s = frontier(s, p);
      return true;
    }
    if (!isDigit(uc(p[1]))) return false;
    s = backReference(s, uc(p[1]));
    p += 2;
    return true;
  }

  // '%f[set]' at p: s if the character before s is outside the set and the one at s inside it
  // (the subject's ends count as '\0'), else null; p moves past the set.
  const char* frontier(const char* s, const char*& p) {
    const char* set = p + 2;
    if (set >= patternEnd_ || *set != '[') throw Refusal{"missing '[' after '%f' in pattern"};
    const CompiledSet& compiled = setAt(set);
    const int before = s == subject_ ? 0 : uc(s[-1]);
    const int here = s < subjectEnd_ ? uc(*s) : 0;
    step();
    p = compiled.end;
    return compiled.chars.has(before) || !compiled.chars.has(here) ? nullptr : s;
  }

  // The longest run of the class at p, then shorter ones until the rest matches.
  const char* longest(const char* s, const char* p, const char* ep) {
    ptrdiff_t n = 0;
    while (s + n < subjectEnd_ && single(uc(s[n]), p)) {
      step();
      ++n;
    }
    for (; n >= 0; --n) {
      step();
      if (const char* r = match(s + n, ep + 1)) return r;
    }
    return nullptr;
  }

  // The shortest run of the class at p after which the rest matches.
  const char* shortest(const char* s, const char* p, const char* ep) {
    for (;;) {
      step();
      if (const char* r = match(s, ep + 1)) return r;
      if (s < subjectEnd_ && single(uc(*s), p))
        ++s;
      else
        return nullptr;
    }
  }

  const char* openCapture(const char* s, const char* p, ptrdiff_t what) {
    if (level_ >= kMaxCaptures) throw Refusal{"too many captures"};
    capture_[level_] = {s, what};
    ++level_;
    const char* r = match(s, p);
    if (!r) --level_;
    return r;
  }

  const char* closeCapture(const char* s, const char* p) {
    int open = level_ - 1;
    while (open >= 0 && capture_[open].length != kOpen) --open;
    if (open < 0) throw Refusal{"invalid pattern capture"};
    capture_[open].length = s - capture_[open].start;
    const char* r = match(s, p);
    if (!r) capture_[open].length = kOpen;
    return r;
  }

  // %bxy at s: x, then text until the y that balances it.
  const char* balanced(const char* s, const char* xy) {
    if (xy + 1 >= patternEnd_) throw Refusal{"unbalanced pattern"};
    step();
    if (s >= subjectEnd_ || *s != xy[0]) return nullptr;
    int depth = 1;
    while (++s < subjectEnd_) {
      step();
      if (*s == xy[1]) {
        if (--depth == 0) return s + 1;
      } else if (*s == xy[0]) {
        ++depth;
      }
    }
    return nullptr;
  }

  // %1..%9 at s: the same text as that capture.
  const char* backReference(const char* s, int digit) {
    const int i = digit - '1';
    if (i < 0 || i >= level_ || capture_[i].length == kOpen) throw Refusal{"invalid capture index"};
    const ptrdiff_t n = capture_[i].length;
    if (n == kPosition) return nullptr;  // a position is no text: it never matches
    step(static_cast<uint64_t>(n) + 1);
    if (subjectEnd_ - s >= n && std::memcmp(capture_[i].start, s, static_cast<size_t>(n)) == 0) return s + n;
    return nullptr;
  }

  StepCount& steps_;
  const char* subject_;
  const char* subjectEnd_;
  const char* pattern_;
  const char* patternEnd_;
  int level_ = 0;
  int depth_ = 0;
  Capture capture_[kMaxCaptures];
  std::array<CompiledSet, size_t{1} << kSetCacheBits> sets_{};
};

// Capture i of a match from s to e (the whole match when the pattern has no captures and i is 0).
void pushCapture(lua_State* L, const Matcher& m, int i, const char* subject, const char* s, const char* e) {
  if (i >= m.captures()) {
    if (i != 0) throw Refusal{"invalid capture index"};
    lua_pushlstring(L, s, static_cast<size_t>(e - s));
    return;
  }
  const Capture& c = m.capture(i);
  if (c.length == kOpen) throw Refusal{"unfinished capture"};
  if (c.length == kPosition) {
    lua_pushinteger(L, static_cast<lua_Integer>(c.start - subject + 1));
  } else {
    lua_pushlstring(L, c.start, static_cast<size_t>(c.length));
  }
}

// Every capture (or the whole match when there are none and s is given); returns how many.
int pushCaptures(lua_State* L, const Matcher& m, const char* subject, const char* s, const char* e) {
  const int n = m.captures() == 0 && s ? 1 : m.captures();
  luaL_checkstack(L, n, "too many captures");
  for (int i = 0; i < n; ++i) pushCapture(L, m, i, subject, s, e);
  return n;
}

// An optional integer argument as LuaJIT reads it: a number (or a numeric string) truncated to
// 32 bits, where anything out of range reads as INT32_MIN.
int64_t optInt32(lua_State* L, int index, int64_t fallback) {
  if (lua_isnoneornil(L, index)) return fallback;
  const double d = luaL_checknumber(L, index);
  if (!(d > -2147483649.0 && d < 2147483648.0)) return INT32_MIN;
  return static_cast<int32_t>(d);
}

// The start position of find and match: init counts from 1, negative from the end, clamped.
size_t startOf(lua_State* L, int index, size_t length) {
  int64_t start = optInt32(L, index, 1);
  if (start < 0)
    start += static_cast<int64_t>(length);
  else
    start -= 1;
  if (start < 0) start = 0;
  return static_cast<size_t>(start) > length ? length : static_cast<size_t>(start);
}

// Runs f(steps) (which returns the number of results) and raises its refusal as a Lua error at the
// caller's line once the handler is left. The steps its matchers took are charged to the frame's
// budget (which may stop the sandbox here: a C comparator or callback that matches again and again
// runs no instruction a hook could count).
template <class F>
int refusing(lua_State* L, F&& f) {
  const char* message = "";
  bool costly = false;
  StepCount steps;
  int results = 0;
  try {
    results = f(steps);
  } catch (const Refusal& r) {
    if (r.message)
      message = r.message;
    else
      costly = true;
  }
  steps.chargeSoFar(L);
  if (!message[0] && !costly) return results;
  if (costly) return luaL_error(L, "pattern too costly (more than %d steps)", static_cast<int>(kPatternStepBudget));
  return luaL_error(L, "%s", message);
}

bool hasSpecials(const char* p, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (p[i] != '\0' && std::strchr(kSpecials, p[i])) return true;
  return false;
}

int findOrMatch(lua_State* L, bool find) {
  size_t length = 0, patternLength = 0;
  const char* s = luaL_checklstring(L, 1, &length);
  const char* p = luaL_checklstring(L, 2, &patternLength);
  const size_t start = startOf(L, 3, length);
  return refusing(L, [&](StepCount& steps) {
    Matcher m(s, length, p, patternLength, steps);
    if (find && (lua_toboolean(L, 4) || !hasSpecials(p, patternLength))) {
      // Plain text: a linear search (two-way), charged by the bytes it passes.
      m.step((length - start + patternLength) / 16 + 1);
      const void* hit = patternLength == 0 ? s + start : memmem(s + start, length - start, p, patternLength);
      if (!hit) {
        lua_pushnil(L);
        return 1;
      }
      const auto at = static_cast<lua_Integer>(static_cast<const char*>(hit) - s);
      lua_pushinteger(L, at + 1);
      lua_pushinteger(L, at + static_cast<lua_Integer>(patternLength));
      return 2;
    }
    const bool anchored = *p == '^';
    if (anchored) ++p;
    const char* end = s + length;
    for (const char* at = s + start;; ++at) {
      if (const char* e = m.matchAt(at, p)) {
        if (!find) return pushCaptures(L, m, s, at, e);
        lua_pushinteger(L, static_cast<lua_Integer>(at - s + 1));
        lua_pushinteger(L, static_cast<lua_Integer>(e - s));
        return pushCaptures(L, m, s, nullptr, nullptr) + 2;
      }
      if (anchored || at >= end) break;
    }
    lua_pushnil(L);
    return 1;
  });
}

// The iterator gmatch returns: upvalues subject, pattern, next start (a number).
int gmatchNext(lua_State* L) {
  size_t length = 0, patternLength = 0;
  const char* s = lua_tolstring(L, lua_upvalueindex(1), &length);
  const char* p = lua_tolstring(L, lua_upvalueindex(2), &patternLength);
  const auto start = static_cast<size_t>(lua_tointeger(L, lua_upvalueindex(3)));
  return refusing(L, [&](StepCount& steps) {
    Matcher m(s, length, p, patternLength, steps);
    for (const char* at = s + (start > length ? length + 1 : start); at <= s + length; ++at) {
      if (const char* e = m.matchAt(at, p)) {
        const size_t next = static_cast<size_t>(e - s) + (e == at ? 1 : 0);  // an empty match moves on by one
        lua_pushinteger(L, static_cast<lua_Integer>(next));
        lua_replace(L, lua_upvalueindex(3));
        return pushCaptures(L, m, s, at, e);
      }
    }
    lua_pushinteger(L, static_cast<lua_Integer>(length + 1));
    lua_replace(L, lua_upvalueindex(3));
    return 0;
  });
}

// Appends the replacement for the match s..e to b: the string with %0-%9 (and %% or %x for x),
// the table's value for the first capture, or the function's result for all of them; nil or false
// keep the match as it was.
void addReplacement(lua_State* L, luaL_Buffer& b, Matcher& m, const char* subject, const char* s, const char* e) {
  const int kind = lua_type(L, 3);
  if (kind == LUA_TSTRING || kind == LUA_TNUMBER) {
    size_t n = 0;
    const char* r = lua_tolstring(L, 3, &n);
    m.step(n + 1);
    for (size_t i = 0; i < n; ++i) {
      if (r[i] != '%') {
        luaL_addchar(&b, r[i]);
        continue;
      }
      ++i;  // r[n] is the string's terminating "\0": a '%' at the end adds it, as LuaJIT does
      const int c = uc(r[i]);
      if (!isDigit(c)) {
        luaL_addchar(&b, r[i]);
      } else if (c == '0') {
        luaL_addlstring(&b, s, static_cast<size_t>(e - s));
        m.step(static_cast<uint64_t>(e - s));
      } else {
        pushCapture(L, m, c - '1', subject, s, e);
        size_t added = 0;
        lua_tolstring(L, -1, &added);
        m.step(added);
        luaL_addvalue(&b);
      }
    }
    return;
  }
  m.steps().chargeSoFar(L);  // the callback (or an __index) may raise: its error leaves this call here
  {
    const CallbackDepth nested(L);
    if (kind == LUA_TTABLE) {
      pushCapture(L, m, 0, subject, s, e);
      lua_gettable(L, 3);
    } else {
      lua_pushvalue(L, 3);
      const int n = pushCaptures(L, m, subject, s, e);
      lua_call(L, n, 1);
    }
  }
  if (!lua_toboolean(L, -1)) {
    lua_pop(L, 1);
    lua_pushlstring(L, s, static_cast<size_t>(e - s));
  } else if (!lua_isstring(L, -1)) {
    const char* type = luaL_typename(L, -1);
    lua_pop(L, 1);
    lua_pushfstring(L, "invalid replacement value (a %s)", type);
    lua_error(L);
  }
  size_t added = 0;
  lua_tolstring(L, -1, &added);
  m.step(added);
  luaL_addvalue(&b);
}

}  // namespace

int patternFind(lua_State* L) { return findOrMatch(L, true); }
int patternMatch(lua_State* L) { return findOrMatch(L, false); }

int patternGmatch(lua_State* L) {
  luaL_checkstring(L, 1);
  luaL_checkstring(L, 2);
  lua_settop(L, 2);
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, gmatchNext, 3);
  return 1;
}

int patternGsub(lua_State* L) {
  size_t length = 0, patternLength = 0;
  const char* s = luaL_checklstring(L, 1, &length);
  const char* p = luaL_checklstring(L, 2, &patternLength);
  const int kind = lua_type(L, 3);
  luaL_argcheck(L, kind == LUA_TNUMBER || kind == LUA_TSTRING || kind == LUA_TFUNCTION || kind == LUA_TTABLE, 3,
                "string/function/table expected");
  const int64_t most = optInt32(L, 4, static_cast<int64_t>(length) + 1);
  lua_settop(L, 3);
  luaL_Buffer b;
  luaL_buffinit(L, &b);
  return refusing(L, [&](StepCount& steps) {
    Matcher m(s, length, p, patternLength, steps);
    const bool anchored = *p == '^';
    if (anchored) ++p;
    const char* end = s + length;
    const char* at = s;
    int64_t n = 0;
    while (n < most) {
      const char* e = m.matchAt(at, p);
      if (e) {
        ++n;
        addReplacement(L, b, m, s, at, e);
      }
      if (e && e > at) {
        at = e;
      } else if (at < end) {
        luaL_addchar(&b, *at++);
      } else {
        break;
      }
      if (anchored) break;
    }
    m.step(static_cast<uint64_t>(end - at) / 16);
    luaL_addlstring(&b, at, static_cast<size_t>(end - at));
    luaL_pushresult(&b);
    lua_pushinteger(L, static_cast<lua_Integer>(n));
    return 2;
  });
}

void setPatternFunctions(lua_State* L, int index) {
  if (index < 0 && index > LUA_REGISTRYINDEX) index = lua_gettop(L) + 1 + index;
  const luaL_Reg functions[] = {
      {"find", patternFind}, {"match", patternMatch}, {"gmatch", patternGmatch}, {"gsub", patternGsub}};
  for (const luaL_Reg& f : functions) {
    lua_pushcfunction(L, f.func);
    lua_setfield(L, index, f.name);
  }
}

}  // namespace platon::script
