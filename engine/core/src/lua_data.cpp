#include "platon/core/lua_data.h"

#include <cmath>
#include <cstdio>
#include <locale.h>
#include <stdlib.h>
#include <unordered_set>

#include "platon/core/visible_text.h"

namespace platon::core {

const DataValue* DataValue::field(std::string_view name) const {
  if (kind != Kind::Table) return nullptr;
  for (const DataEntry& e : entries)
    if (e.key.kind == Kind::String && e.key.text == name) return e.value.kind == Kind::Nil ? nullptr : &e.value;
  return nullptr;
}

std::string luaQuoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      (out += '\\') += c;
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\%03u", byte);  // Lua's decimal escape
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string describeData(const DataValue& d) {
  char number[64];
  switch (d.kind) {
    case DataValue::Kind::Nil:
      return "nil";
    case DataValue::Kind::Boolean:
      return d.boolean ? "true" : "false";
    case DataValue::Kind::Number:
      if (std::isnan(d.number)) return "nan";
      std::snprintf(number, sizeof number, "%.17g", d.number);
      return number;
    case DataValue::Kind::String:
      return "'" + visibleText(d.text.substr(0, 40)) + (d.text.size() > 40 ? "...'" : "'") + " (a string)";
    case DataValue::Kind::Table:
      return "a table";
    case DataValue::Kind::Other:
      return d.text;
  }
  return "?";
}

std::string dataKeyText(const DataValue& key) {
  if (key.kind == DataValue::Kind::String)
    return "'" + visibleText(key.text.substr(0, 60)) + (key.text.size() > 60 ? "...'" : "'");
  return describeData(key);
}

DataError::DataError(const std::string& file, int atLine, int atColumn, const std::string& reason, Kind why)
    : std::runtime_error(file + ":" + std::to_string(atLine) + ":" + std::to_string(atColumn) + ": " + reason),
      line(atLine),
      column(atColumn),
      kind(why) {}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isHex(char c) { return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
int hexValue(char c) { return isDigit(c) ? c - '0' : (c | 0x20) - 'a' + 10; }
// Lua's identifier characters (LuaJIT counts every byte from 0x80 as one).
bool isNameChar(char c) {
  return isDigit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;
}
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\n' || c == '\r'; }

bool isKeyword(std::string_view w) {
  static constexpr std::string_view kKeywords[] = {
      "and", "break", "do",  "else", "elseif", "end",    "false",  "for",  "function", "goto",  "if",
      "in",  "local", "nil", "not",  "or",     "repeat", "return", "then", "true",     "until", "while"};
  for (std::string_view k : kKeywords)
    if (k == w) return true;
  return false;
}

// UTF-8 of a code point up to 0x10FFFF, as Lua's \u{...} writes it.
void appendUtf8(std::string& out, uint32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// A recursive-descent reader of the literal subset of Lua, following LuaJIT's lexer (lj_lex.c):
// the same newlines (\n, \r, \r\n and \n\r are one), escapes, long brackets and number tokens.
class Reader {
 public:
  Reader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  DataValue file() {
    // As LuaJIT's lexer (lj_lex_setup): a UTF-8 byte order mark, then a first line starting with
    // '#' (a #! line), are skipped.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    if (peek() == '#')
      while (!atEnd() && !atNewline()) advance();
    skipSpace();
    if (name() != "return") fail("a data file is 'return { ... }'");
    skip(6);
    DataValue v = value(0);
    skipSpace();
    if (peek() == ';') advance(), skipSpace();
    if (pos_ < text_.size()) fail("unexpected text after the value (an operator? a data file holds no expressions)");
    return v;
  }

 private:
  [[noreturn]] void failAt(int line, int column, const std::string& reason,
                           DataError::Kind kind = DataError::Kind::NotData) const {
    throw DataError(file_, line, column, reason, kind);
  }
  [[noreturn]] void fail(const std::string& reason) const { failAt(line_, column_, reason); }

  char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  bool atEnd() const { return pos_ >= text_.size(); }
  bool atNewline() const { return peek() == '\n' || peek() == '\r'; }
  // One character; a newline pair counts as one, as Lua counts lines.
  void advance() {
    if (atNewline()) {
      const char first = text_[pos_++];
      if (atNewline() && peek() != first) ++pos_;
      ++line_, column_ = 1;
      return;
    }
    ++pos_, ++column_;
  }
  void skip(size_t n) {
    for (size_t i = 0; i < n && !atEnd(); ++i) advance();
  }
  void skipSpace() {
    for (;;) {
      while (!atEnd() && isSpace(peek())) advance();
      if (peek() == '-' && peek(1) == '-') {
        skip(2);
        if (longBracketLevel() >= 0)
          (void)longBracket("comment");
        else
          while (!atEnd() && !atNewline()) advance();
        continue;
      }
      return;
    }
  }
  // The identifier at the current place (empty when there is none).
  std::string_view name() const {
    if (isDigit(peek())) return {};
    size_t end = pos_;
    while (end < text_.size() && isNameChar(text_[end])) ++end;
    return text_.substr(pos_, end - pos_);
  }

  // At a long bracket [[ or [=[ or [==[ ...: its level (the number of '='), else -1.
  int longBracketLevel() const {
    if (peek() != '[') return -1;
    size_t i = 1;
    while (peek(i) == '=') ++i;
    return peek(i) == '[' ? static_cast<int>(i - 1) : -1;
  }
  // A long string or comment from its opening to the matching ]=*]. A newline right after the
  // opening is dropped, and every newline inside reads as "\n", as Lua does.
  std::string longBracket(const char* what) {
    const auto level = static_cast<size_t>(longBracketLevel());
    const int openLine = line_, openColumn = column_;
    skip(level + 2);
    if (atNewline()) advance();
    std::string out;
    for (;;) {
      if (atEnd())
        failAt(openLine, openColumn,
               std::string("unfinished long ") + what + " (no ]" + std::string(level, '=') + "])");
      if (peek() == ']') {
        size_t equals = 0;
        while (equals < level && peek(1 + equals) == '=') ++equals;
        if (equals == level && peek(1 + level) == ']') {
          skip(level + 2);
          return out;
        }
      }
      if (atNewline()) {
        out += '\n';
        advance();
      } else {
        out += peek();
        advance();
      }
    }
  }

  void count() {
    if (++values_ > kMaxDataValues)
      failAt(line_, column_, "more than " + std::to_string(kMaxDataValues) + " keys and values in one file",
             DataError::Kind::TooLarge);
  }

  DataValue value(int depth) {
    skipSpace();
    DataValue v;
    v.line = line_, v.column = column_;
    count();
    const char c = peek();
    if (c == '{') {
      if (depth >= kMaxDataDepth)
        failAt(line_, column_, "tables nested more than " + std::to_string(kMaxDataDepth) + " deep",
               DataError::Kind::TooLarge);
      v.kind = DataValue::Kind::Table;
      table(v, depth + 1);
    } else if (c == '"' || c == '\'') {
      v.kind = DataValue::Kind::String;
      v.text = quoted();
    } else if (longBracketLevel() >= 0) {
      v.kind = DataValue::Kind::String;
      v.text = longBracket("string");
    } else if (c == '-' && peek(1) != '-') {
      advance();
      skipSpace();
      if (!isDigit(peek()) && !(peek() == '.' && isDigit(peek(1))))
        fail("'-' in data is the sign of a number (an expression is not data)");
      v.kind = DataValue::Kind::Number;
      v.number = -number();
    } else if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
      v.kind = DataValue::Kind::Number;
      v.number = number();
    } else {
      const std::string_view w = name();
      if (w == "true" || w == "false") {
        v.kind = DataValue::Kind::Boolean;
        v.boolean = w == "true";
        skip(w.size());
      } else if (w == "nil") {
        skip(3);
      } else if (w.empty()) {
        fail(atEnd() ? "unexpected end of file (a value is missing)"
                     : "unexpected '" + visibleText(std::string(1, c)) + "' (a value is missing)");
      } else {
        fail("'" + visibleText(std::string(w.substr(0, 40))) +
             "': a data file holds only strings, numbers, booleans, nil and tables (no names, calls or expressions)");
      }
    }
    return v;
  }

  // The key of a [key] = field.
  DataValue bracketKey(int depth) {
    advance();  // [
    DataValue key = value(depth);
    if (key.kind == DataValue::Kind::Nil) failAt(key.line, key.column, "a table key cannot be nil");
    if (key.kind == DataValue::Kind::Table)
      failAt(key.line, key.column, "a table key in data is a string, a number or a boolean");
    skipSpace();
    if (peek() != ']') fail("expected ']' after the key");
    advance();
    skipSpace();
    if (peek() != '=') fail("expected '=' after [key]");
    advance();
    return key;
  }

  // A key as one string, equal for keys Lua takes as equal (0 and -0, 1 and 1.0).
  static std::string identity(const DataValue& key) {
    if (key.kind == DataValue::Kind::String) return "s" + key.text;
    if (key.kind == DataValue::Kind::Boolean) return key.boolean ? "T" : "F";
    char text[40];
    std::snprintf(text, sizeof text, "n%.17g", key.number == 0 ? 0.0 : key.number);
    return text;
  }

  void table(DataValue& t, int depth) {
    const int openLine = line_, openColumn = column_;
    advance();  // {
    double nextIndex = 1;
    std::unordered_set<std::string> seen;
    for (;;) {
      skipSpace();
      if (atEnd()) failAt(openLine, openColumn, "unfinished table (no '}' for this '{')");
      if (peek() == '}') return advance();
      DataValue key;
      key.line = line_, key.column = column_;
      const std::string_view w = name();
      bool keyed = false;
      if (!w.empty()) {
        // name = value: look past the name for a single '='.
        const size_t save = pos_;
        const int saveLine = line_, saveColumn = column_;
        skip(w.size());
        skipSpace();
        if (peek() == '=' && peek(1) != '=') {
          if (isKeyword(w))
            failAt(key.line, key.column,
                   "'" + std::string(w) + "' is a Lua keyword, not a name: write [\"" + std::string(w) +
                       "\"] =");  // a keyword: short
          advance();
          count();
          key.kind = DataValue::Kind::String;
          key.text = std::string(w);
          keyed = true;
        } else {
          pos_ = save, line_ = saveLine, column_ = saveColumn;
        }
      } else if (peek() == '[' && longBracketLevel() < 0) {
        key = bracketKey(depth);
        keyed = true;
      }
      if (!keyed) {
        count();  // a list item's key is a value read too
        key.kind = DataValue::Kind::Number;
        key.number = nextIndex++;
      }
      if (!seen.insert(identity(key)).second)
        failAt(key.line, key.column, "the key " + dataKeyText(key) + " is given twice in one table",
               DataError::Kind::RepeatedKey);
      DataValue v = value(depth);
      t.entries.emplace_back(std::move(key), std::move(v));
      skipSpace();
      if (peek() == ',' || peek() == ';')
        advance();
      else if (atEnd())
        failAt(openLine, openColumn, "unfinished table (no '}' for this '{')");
      else if (peek() != '}')
        fail("expected ',' or '}' (a data file holds no expressions)");
    }
  }

  std::string quoted() {
    const char quote = peek();
    const int openLine = line_, openColumn = column_;
    advance();
    std::string out;
    for (;;) {
      if (atEnd() || atNewline()) failAt(openLine, openColumn, "unfinished string");
      const char c = peek();
      if (c == quote) {
        advance();
        return out;
      }
      if (c != '\\') {
        out += c;
        advance();
        continue;
      }
      escape(out);
    }
  }

  // One escape after a '\\' (the reader is at the backslash): appended to `out`, as Lua reads it.
  void escape(std::string& out) {
    const int escapeLine = line_, escapeColumn = column_;
    advance();
    const char e = peek();
    auto bad = [&](const std::string& why) { failAt(escapeLine, escapeColumn, "escape: " + why); };
    switch (e) {
      // clang-format off
      case 'a': out += '\a'; advance(); break;
      case 'b': out += '\b'; advance(); break;
      case 'f': out += '\f'; advance(); break;
      case 'n': out += '\n'; advance(); break;
      case 'r': out += '\r'; advance(); break;
      case 't': out += '\t'; advance(); break;
      case 'v': out += '\v'; advance(); break;
      case '\\': case '"': case '\'': out += e; advance(); break;
      // clang-format on
      case '\n':
      case '\r':
        out += '\n';
        advance();
        break;
      case 'x':
        advance();
        if (!isHex(peek()) || !isHex(peek(1))) bad("\\x takes two hex digits");
        out += static_cast<char>(hexValue(peek()) * 16 + hexValue(peek(1)));
        skip(2);
        break;
      case 'z':
        advance();
        while (!atEnd() && isSpace(peek())) advance();
        break;
      case 'u':
        appendUtf8(out, unicodeEscape(bad));
        break;
      default: {
        if (!isDigit(e))
          bad(atEnd() ? "unfinished string" : "unknown escape '\\" + visibleText(std::string(1, e)) + "'");
        int byte = 0;
        for (int k = 0; k < 3 && isDigit(peek()); ++k) byte = byte * 10 + (peek() - '0'), advance();
        if (byte > 255) bad("\\ddd is past 255");
        out += static_cast<char>(byte);
      }
    }
  }

  // \u{XXX} (the reader is at the 'u'): the code point, which must be one UTF-8 can hold.
  template <class Bad>
  uint32_t unicodeEscape(const Bad& bad) {
    advance();
    if (peek() != '{' || !isHex(peek(1))) bad("\\u takes {hex digits}");
    advance();
    uint32_t code = 0;
    while (isHex(peek())) {
      code = code * 16 + static_cast<uint32_t>(hexValue(peek()));
      if (code > 0x10FFFF) bad("\\u{...} is past 10FFFF");
      advance();
    }
    if (peek() != '}') bad("\\u{...} has no '}'");
    if (code >= 0xD800 && code <= 0xDFFF) bad("\\u{...} is a UTF-16 surrogate");
    advance();
    return code;
  }

  // The end of the number token at pos_: name characters, '.', and a sign after the exponent's letter.
  size_t numberEnd(char exponent) const {
    size_t end = pos_;
    while (end < text_.size()) {
      const char c = text_[end];
      if (isNameChar(c) || c == '.' || ((c == '-' || c == '+') && end > pos_ && (text_[end - 1] | 0x20) == exponent))
        ++end;
      else
        break;
    }
    return end;
  }

  // Whether the token starts as a number: digits with one optional '.', at least one digit, then an
  // optional exponent with digits. `end` is where that number ends (the token's size if it is all).
  static bool numberPrefix(std::string_view token, bool hex, size_t& end) {
    const char exponent = hex ? 'p' : 'e';
    size_t i = hex ? 2 : 0, digits = 0;
    bool dot = false;
    for (; i < token.size(); ++i) {
      if (token[i] == '.' && !dot)
        dot = true;
      else if (hex ? isHex(token[i]) : isDigit(token[i]))
        ++digits;
      else
        break;
    }
    end = i;
    if (digits == 0) return false;
    if (i < token.size() && (token[i] | 0x20) == exponent) {
      ++i;
      if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
      const size_t first = i;
      while (i < token.size() && isDigit(token[i])) ++i;
      end = i;
      if (i == first) return false;
    }
    return true;
  }

  // A number token as LuaJIT's lexer cuts it, then read exactly: decimal or hex, with an optional
  // fraction and exponent.
  double number() {
    const bool hex = peek() == '0' && (peek(1) | 0x20) == 'x';
    const std::string_view token = text_.substr(pos_, numberEnd(hex ? 'p' : 'e') - pos_);
    size_t end = 0;
    const bool ok = numberPrefix(token, hex, end);
    if (!ok || end != token.size()) {
      const std::string shown = visibleText(std::string(token.substr(0, 40)));
      if (ok && (token.back() | 0x20) == 'l') fail("'" + shown + "' is a 64-bit integer (a cdata), not a number");
      if (ok && (token.back() | 0x20) == 'i') fail("'" + shown + "' is a complex number (a cdata), not a number");
      fail("'" + shown + "' is not a number");
    }
    // strtod in the C locale reads what LuaJIT reads, correctly rounded, underflow (1e-400: 0,
    // 1e-310: a subnormal) included; std::from_chars calls underflow an error.
    static const locale_t cLocale = newlocale(LC_ALL_MASK, "C", nullptr);
    const std::string text(token);
    char* stop = nullptr;
    const double v = strtod_l(text.c_str(), &stop, cLocale);
    if (stop != text.c_str() + text.size() || !std::isfinite(v))
      fail("'" + visibleText(text.substr(0, 40)) + "' is too large for a number");
    skip(token.size());
    return v;
  }

  std::string_view text_;
  const std::string& file_;
  size_t pos_ = 0;
  int line_ = 1, column_ = 1;
  size_t values_ = 0;
};

}  // namespace

DataValue readLuaData(std::string_view text, const std::string& fileName) { return Reader(text, fileName).file(); }

}  // namespace platon::core
