#include "platon/core/manifest.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits.h>
#include <sstream>
#include <stdexcept>
#include <stdlib.h>

#include "platon/files/read_file.h"

namespace platon::core {

const DataTable* DataValue::table() const {
  const auto* t = std::get_if<std::shared_ptr<DataTable>>(&value);
  return t ? t->get() : nullptr;
}
const std::string* DataValue::string() const { return std::get_if<std::string>(&value); }
const double* DataValue::number() const { return std::get_if<double>(&value); }
const bool* DataValue::boolean() const { return std::get_if<bool>(&value); }
const DataValue* DataValue::field(std::string_view key) const {
  if (const DataTable* t = table())
    for (const auto& [k, v] : *t)
      if (k == key) return &v;
  return nullptr;
}

namespace {

// A recursive-descent reader of the literal subset of Lua.
class DataReader {
 public:
  DataReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  DataValue file() {
    skipSpace();
    expectWord("return");
    DataValue v = value(0);
    skipSpace();
    if (pos_ < text_.size()) fail("unexpected text after the table");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw std::runtime_error(file_ + ":" + std::to_string(line_) + ":" + std::to_string(column_) + ": " + reason);
  }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void advance() {
    if (text_[pos_] == '\n')
      ++line_, column_ = 1;
    else
      ++column_;
    ++pos_;
  }
  void skipSpace() {
    for (;;) {
      while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(peek()))) advance();
      if (text_.substr(pos_, 2) == "--") {
        advance(), advance();
        if (longBracketLevel() >= 0) {
          (void)longBracket("comment");
        } else {
          while (pos_ < text_.size() && peek() != '\n') advance();
        }
        continue;
      }
      return;
    }
  }
  // At a Lua long bracket, [[ or [=[ or [==[ ...: its level (the number of '='), else -1.
  int longBracketLevel() const {
    if (peek() != '[') return -1;
    size_t i = pos_ + 1;
    while (i < text_.size() && text_[i] == '=') ++i;
    return i < text_.size() && text_[i] == '[' ? static_cast<int>(i - pos_ - 1) : -1;
  }
  // A long-bracket string or comment's text, from its opening to the matching ]=*] (a newline
  // right after the opening is dropped, as Lua does).
  std::string longBracket(const char* what) {
    const int level = longBracketLevel();
    const std::string close = "]" + std::string(static_cast<size_t>(level), '=') + "]";
    const int openLine = line_, openColumn = column_;
    for (int i = 0; i < level + 2; ++i) advance();
    if (peek() == '\r') advance();
    if (peek() == '\n') advance();
    const size_t end = text_.find(close, pos_);
    if (end == std::string_view::npos) {
      line_ = openLine, column_ = openColumn;
      fail(std::string("unfinished long ") + what + " (no " + close + ")");
    }
    std::string out(text_.substr(pos_, end - pos_));
    while (pos_ < end + close.size()) advance();
    return out;
  }

  std::string_view word() {
    size_t end = pos_;
    while (end < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) ++end;
    return text_.substr(pos_, end - pos_);
  }
  void expectWord(std::string_view w) {
    if (word() != w) fail("expected '" + std::string(w) + "'");
    for (size_t i = 0; i < w.size(); ++i) advance();
  }

  DataValue value(int depth) {
    if (depth > 32) fail("tables nested more than 32 deep");
    skipSpace();
    DataValue v;
    v.line = line_, v.column = column_;
    const char c = peek();
    if (c == '{') {
      v.value = table(depth);
    } else if (c == '"' || c == '\'') {
      v.value = quoted();
    } else if (longBracketLevel() >= 0) {
      v.value = longBracket("string");
    } else if (c == '-' || c == '.' || std::isdigit(static_cast<unsigned char>(c))) {
      v.value = number();
    } else {
      const std::string_view w = word();
      if (w == "true" || w == "false") {
        v.value = w == "true";
        expectWord(w);
      } else if (w == "nil") {
        expectWord(w);
      } else if (w.empty()) {
        fail(pos_ < text_.size() ? std::string("unexpected '") + c + "'" : "unexpected end of file");
      } else {
        fail("'" + std::string(w) + "': a manifest holds only strings, numbers, booleans and tables");
      }
    }
    return v;
  }

  std::shared_ptr<DataTable> table(int depth) {
    auto t = std::make_shared<DataTable>();
    advance();  // {
    int nextIndex = 1;
    for (;;) {
      skipSpace();
      if (pos_ >= text_.size()) fail("unexpected end of file (a '}' is missing)");
      if (peek() == '}') {
        advance();
        return t;
      }
      std::string key;
      const std::string_view w = word();
      const int keyLine = line_, keyColumn = column_;
      size_t save = pos_;
      int saveLine = line_, saveColumn = column_;
      bool keyed = false;
      if (!w.empty() && !std::isdigit(static_cast<unsigned char>(w[0])) && w != "true" && w != "false" && w != "nil") {
        for (size_t i = 0; i < w.size(); ++i) advance();
        skipSpace();
        if (peek() == '=') {
          advance();
          key = std::string(w);
          keyed = true;
        } else {
          pos_ = save, line_ = saveLine, column_ = saveColumn;
        }
      } else if (peek() == '[') {
        advance();
        skipSpace();
        if (peek() != '"' && peek() != '\'') fail("a [key] must be a string");
        key = quoted();
        skipSpace();
        if (peek() != ']') fail("expected ']'");
        advance();
        skipSpace();
        if (peek() != '=') fail("expected '='");
        advance();
        keyed = true;
      }
      if (!keyed) key = std::to_string(nextIndex++);
      for (const auto& entry : *t)
        if (entry.first == key) {
          line_ = keyLine, column_ = keyColumn;
          fail("'" + key + "' is given twice");
        }
      t->emplace_back(std::move(key), value(depth + 1));
      skipSpace();
      if (peek() == ',' || peek() == ';') {
        advance();
      } else if (pos_ >= text_.size()) {
        fail("unexpected end of file (a '}' is missing)");
      } else if (peek() != '}') {
        fail("expected ',' or '}'");
      }
    }
  }

  std::string quoted() {
    const char quote = peek();
    advance();
    std::string out;
    for (;;) {
      if (pos_ >= text_.size() || peek() == '\n') fail("unfinished string");
      char c = peek();
      advance();
      if (c == quote) return out;
      if (c == '\\') {
        if (pos_ >= text_.size()) fail("unfinished string");
        const char e = peek();
        advance();
        switch (e) {
          case 'n':
            c = '\n';
            break;
          case 't':
            c = '\t';
            break;
          case '\\':
          case '"':
          case '\'':
            c = e;
            break;
          default:
            fail(std::string("unknown escape '\\") + e + "'");
        }
      }
      out += c;
    }
  }

  double number() {
    size_t end = pos_;
    while (end < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '.' ||
                                  text_[end] == '-' || text_[end] == '+'))
      ++end;
    const std::string token(text_.substr(pos_, end - pos_));
    char* stop = nullptr;
    const double v = std::strtod(token.c_str(), &stop);
    if (token.empty() || *stop != '\0' || !std::isfinite(v)) fail("'" + token + "' is not a number");
    while (pos_ < end) advance();
    return v;
  }

  std::string_view text_;
  const std::string& file_;
  size_t pos_ = 0;
  int line_ = 1, column_ = 1;
};

std::string placeText(const std::string& file, const DataValue& v) {
  return file + ":" + std::to_string(v.line) + ":" + std::to_string(v.column);
}

[[noreturn]] void fieldError(const std::string& file, const DataValue& v, const std::string& reason) {
  throw std::runtime_error(file + ":" + std::to_string(v.line) + ":" + std::to_string(v.column) + ": " + reason);
}

std::string stringField(const std::string& file, const DataValue& table, const char* key, std::string fallback) {
  const DataValue* v = table.field(key);
  if (!v) return fallback;
  if (!v->string()) fieldError(file, *v, std::string("'") + key + "' must be a string");
  return *v->string();
}

std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", v);
  return text;
}

double numberField(const std::string& file, const DataValue& table, const char* key, double fallback, double low,
                   double high) {
  const DataValue* v = table.field(key);
  if (!v) return fallback;
  if (!v->number()) fieldError(file, *v, std::string("'") + key + "' must be a number");
  if (*v->number() < low || *v->number() > high)
    fieldError(file, *v,
               std::string("'") + key + "' must be within [" + shown(low) + ", " + shown(high) + "], not " +
                   shown(*v->number()));
  return *v->number();
}

// A whole number within [low, high] (an edge, a seed, a limit: 4096.7 is a mistake, not 4096).
double wholeField(const std::string& file, const DataValue& table, const char* key, double fallback, double low,
                  double high) {
  const double v = numberField(file, table, key, fallback, low, high);
  if (v != std::floor(v))
    fieldError(file, *table.field(key), std::string("'") + key + "' must be a whole number, not " + shown(v));
  return v;
}

void checkKeys(const std::string& file, const DataValue& table, std::initializer_list<const char*> known) {
  for (const auto& [key, v] : *table.table()) {
    bool ok = false;
    for (const char* k : known) ok = ok || key == k;
    if (!ok) {
      std::string list;
      for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
      fieldError(file, v, "unknown field '" + key + "' (known: " + list + ")");
    }
  }
}

std::string realPath(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) ? std::string(resolved) : std::string();
}

// A level's own file: `p` (no "..", not absolute: checked by the caller) inside the manifest's
// folder, with every link resolved, and refused when a link leads out of the folder. A file that
// does not exist (yet) is the folder's real path joined with p: loading it says it is missing.
std::string insideFolder(const std::string& manifest, const std::string& folder, const DataValue& where,
                         const std::string& p) {
  const std::string realFolder = realPath(folder);
  if (realFolder.empty()) fieldError(manifest, where, "'" + folder + "': the scene's folder cannot be resolved");
  std::string file = realPath(folder + "/" + p);
  if (file.empty()) return realFolder + "/" + p;
  if (file.rfind(realFolder + "/", 0) != 0)
    fieldError(manifest, where, "'" + p + "' leads to " + file + ", outside the scene's folder (a link?)");
  return file;
}

}  // namespace

DataValue parseDataFile(std::string_view text, const std::string& fileName) {
  return DataReader(text, fileName).file();
}

bool SceneManifest::needs(std::string_view system) const {
  for (const auto& s : systems)
    if (s == system) return true;
  return false;
}

SceneManifest loadManifest(const std::string& path) {
  std::string text;
  try {
    text = files::readBoundedFile(path, kMaxManifestBytes);
  } catch (const files::FileError& e) {
    throw std::runtime_error(path + ": the manifest: " + e.reason());
  }
  const DataValue root = parseDataFile(text, path);
  if (!root.table()) fieldError(path, root, "a manifest is a table: return { ... }");
  checkKeys(path, root, {"name", "systems", "stage", "gravity", "scripts", "limits", "seed"});

  SceneManifest m;
  m.path = path;
  const size_t slash = path.find_last_of('/');
  m.directory = slash == std::string::npos ? "." : path.substr(0, slash);
  m.name = stringField(path, root, "name", path);
  if (const DataValue* systems = root.field("systems")) {
    if (!systems->table()) fieldError(path, *systems, "'systems' must be a list of names");
    for (const auto& [key, v] : *systems->table()) {
      if (!v.string()) fieldError(path, v, "'systems' must be a list of names");
      const std::string& s = *v.string();
      if (s != "scripting" && s != "rendering" && s != "meshes" && s != "audio")
        fieldError(path, v, "unknown system '" + s + "' (known: scripting, rendering, meshes, audio)");
      m.systems.push_back(s);
    }
  }
  if (const DataValue* stage = root.field("stage")) {
    if (!stage->table()) fieldError(path, *stage, "'stage' must be a table {solid =, edge =} or {level =}");
    checkKeys(path, *stage, {"solid", "edge", "level"});
    if (const DataValue* level = stage->field("level")) {
      if (stage->field("solid") || stage->field("edge"))
        fieldError(path, *level, "a level file gives the solid and its size: no 'solid' or 'edge' beside 'level'");
      const std::string p = stringField(path, *stage, "level", "");
      if (p.empty() || p.find("..") != std::string::npos || p[0] == '/')
        fieldError(path, *level,
                   "'" + p + "': a level file is a path inside the scene's folder (no '..', not absolute)");
      m.levelFile = insideFolder(path, m.directory, *level, p);
      m.placeOf[m.levelFile] = placeText(path, *level);
    }
    m.solid = stringField(path, *stage, "solid", m.solid);
    if (!solidOfManifest(m.solid))
      fieldError(path, *stage->field("solid"),
                 "unknown solid '" + m.solid + "' (known: tetrahedron, cube, octahedron, dodecahedron, icosahedron)");
    m.edge = static_cast<int32_t>(wholeField(path, *stage, "edge", m.edge, 64, 1 << 24));
  }
  m.gravity = numberField(path, root, "gravity", m.gravity, 0, 1000);
  m.seed = static_cast<uint32_t>(wholeField(path, root, "seed", m.seed, 0, 4294967295.0));
  if (const DataValue* scripts = root.field("scripts")) {
    if (!scripts->table()) fieldError(path, *scripts, "'scripts' must be a table");
    checkKeys(path, *scripts, {"preset", "rules", "player", "progression", "level", "mods"});
    // Trust is decided here, once, from what the manifest wrote: "scripts/..." names an engine
    // script (trusted; the script system finds it under the engine's root), anything else is the
    // level's own (sandboxed), resolved inside the manifest's folder.
    auto script = [&](const char* key, bool& trusted) {
      std::string p = stringField(path, *scripts, key, "");
      trusted = false;
      if (p.empty()) return p;
      const bool engine = p.rfind("scripts/", 0) == 0;
      if (p.find("..") != std::string::npos || p[0] == '/' || p.size() < 5 || p.substr(p.size() - 4) != ".lua")
        fieldError(
            path, *scripts->field(key),
            "'" + p + "': a script is a .lua path inside the level's folder or under scripts/ (no '..', not absolute)");
      trusted = engine;
      std::string kept = engine ? p : insideFolder(path, m.directory, *scripts->field(key), p);
      m.placeOf[kept] = placeText(path, *scripts->field(key));
      return kept;
    };
    m.rules = script("rules", m.rulesTrusted);
    m.player = script("player", m.playerTrusted);
    m.progression = script("progression", m.progressionTrusted);
    // preset = "game": the game's own rules, player and progression, for any of the three the
    // manifest does not name itself (every campaign level uses them).
    if (const DataValue* preset = scripts->field("preset")) {
      if (!preset->string() || *preset->string() != "game")
        fieldError(path, *preset, "unknown script preset (known: \"game\")");
      if (m.rules.empty()) m.rules = "scripts/rules/game.lua", m.rulesTrusted = true;
      if (m.player.empty()) m.player = "scripts/player.lua", m.playerTrusted = true;
      if (m.progression.empty()) m.progression = "scripts/progression.lua", m.progressionTrusted = true;
    }
    m.level = script("level", m.levelTrusted);
    if (const DataValue* mods = scripts->field("mods")) {
      if (!mods->table()) fieldError(path, *mods, "'mods' must be a list of paths");
      int index = 0;
      for (const auto& [key, v] : *mods->table()) {
        if (key != std::to_string(++index))
          fieldError(path, v, "'mods' must be a list of paths ({ \"a.lua\", \"b.lua\" }), not keyed");
        const std::string* p = v.string();
        if (!p || p->size() < 5 || p->substr(p->size() - 4) != ".lua" || p->find("..") != std::string::npos ||
            p->rfind("scripts/", 0) == 0 || (*p)[0] == '/')
          fieldError(path, v,
                     "a mod is a .lua path inside the level's folder (no '..', not absolute, not under scripts/)");
        m.mods.push_back(insideFolder(path, m.directory, v, *p));
        m.placeOf[m.mods.back()] = placeText(path, v);
      }
    }
    if (!m.rules.empty() || !m.player.empty() || !m.progression.empty() || !m.level.empty() || !m.mods.empty())
      if (!m.needs("scripting"))
        fieldError(path, *scripts, "the scene has scripts but does not list \"scripting\" in its systems");
  }
  if (const DataValue* limits = root.field("limits")) {
    if (!limits->table()) fieldError(path, *limits, "'limits' must be a table {memory_mb =, steps =, deadline_ms =}");
    checkKeys(path, *limits, {"memory_mb", "steps", "deadline_ms"});
    m.memoryMegabytes = static_cast<size_t>(wholeField(path, *limits, "memory_mb", 128, 4, 4096));
    m.frameSteps = static_cast<int64_t>(wholeField(path, *limits, "steps", 10'000'000, 1000, 1'000'000'000));
    m.deadlineMilliseconds = numberField(path, *limits, "deadline_ms", 2000, 1, 60000);
  }
  return m;
}

std::optional<stage::Solid> solidOfManifest(const std::string& name) {
  using stage::Solid;
  if (name == "tetrahedron") return Solid::Tetrahedron;
  if (name == "cube" || name == "hexahedron") return Solid::Hexahedron;
  if (name == "octahedron") return Solid::Octahedron;
  if (name == "dodecahedron") return Solid::Dodecahedron;
  if (name == "icosahedron") return Solid::Icosahedron;
  return std::nullopt;
}

}  // namespace platon::core
