// Lua table literals read as data, in C++, without a Lua state: the one reader of the scene
// manifest and of scenarios. A data file is `return <value>` where a value is a string (quoted,
// with Lua's escapes, or long-bracketed), a number (decimal or hex, with an optional unary minus),
// true, false, nil, or a table of `name = value`, `[key] = value` and positional fields, with Lua's
// comments anywhere. Every value keeps the line:column it was written at.
//
// What it reads, Lua reads to the same value (tests/fuzz/reader_fuzz.cpp checks this against
// LuaJIT itself); what Lua would read differently or silently is refused: a key given twice (Lua
// keeps the last), an expression, a number Lua would make a cdata (1LL) or an infinity (1e999).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace platon::core {

struct DataEntry;

struct DataValue {
  enum class Kind : uint8_t { Nil, Boolean, Number, String, Table, Other };
  Kind kind = Kind::Nil;
  bool boolean = false;
  double number = 0;
  std::string text;                // a string's bytes; for Other, what it is ("a function")
  std::vector<DataEntry> entries;  // a table's keys and values, in the order written
  int line = 0, column = 0;        // where it was written (0: computed by Lua, not written)

  bool isTable() const { return kind == Kind::Table; }
  bool isString() const { return kind == Kind::String; }
  bool isNumber() const { return kind == Kind::Number; }
  // The value of the string key `name` in a table; nullptr when absent, nil, or not a table.
  const DataValue* field(std::string_view name) const;
};

// A key and its value.
struct DataEntry {
  DataValue key, value;
  DataEntry(DataValue k, DataValue v) : key(std::move(k)), value(std::move(v)) {}
};

// A value as an error message shows it: nil, true, 12.5, 'text' (a string), a table, a function.
std::string describeData(const DataValue& value);
// A key as a path shows it: 'name' for a string, the number for a number.
std::string dataKeyText(const DataValue& key);

// Why a text is not data, at the line:column where reading stopped.
class DataError : public std::runtime_error {
 public:
  enum class Kind : uint8_t {
    NotData,      // not a literal (an expression, a call, a syntax error): Lua may still read it
    RepeatedKey,  // a key given twice in one table: Lua would keep the last one silently
    TooLarge,     // more values or deeper tables than a data file may hold
  };
  DataError(const std::string& file, int atLine, int atColumn, const std::string& reason, Kind why);
  int line, column;
  Kind kind;
};

inline constexpr int kMaxDataDepth = 32;          // tables nested in tables
inline constexpr size_t kMaxDataValues = 250000;  // keys and values in one file (each costs 100-400 bytes read)

// Reads `text` (the file's contents); throws DataError "file:line:column: reason".
DataValue readLuaData(std::string_view text, const std::string& fileName);

// `text` as a Lua string literal, "..." with the quote, the backslash and control bytes escaped,
// that readLuaData (and Lua) read back as `text` byte for byte: for the data files the engine
// writes (scenarios made from replays, package manifests).
std::string luaQuoted(std::string_view text);

}  // namespace platon::core
