#include "platon/script/scenario.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "lua_host.h"
#include "platon/core/data_root.h"
#include "platon/core/input.h"
#include "platon/core/live_scene.h"
#include "platon/core/run.h"
#include "platon/core/visible_text.h"
#include "platon/files/read_file.h"
#include "platon/script/script_system.h"

namespace platon::script {
namespace {

// ---- Reading a scenario file ---------------------------------------------------------------
//
// A scenario is a table literal in every example, so it is read as data first by the reader the
// manifest uses (core/lua_data.h): every value keeps the line:column it was written at, and each
// error names it. A trusted scenario may compute its values instead (a loop, a local, a call): one
// that is not a plain literal runs as Lua, and its result is read by the same checks, with the
// line of its top-level `return` as the best position there is. A repeated key or a file past the
// data reader's size limits is refused, not run: Lua would keep the last key silently, and would
// build the same oversized table.

using core::DataEntry;
using core::DataValue;

// The line of the file's last top-level `return` (a line that starts with it): the best position
// for values a scenario computed. 0 when there is none.
int returnLine(std::string_view text) {
  int line = 1, found = 0;
  for (size_t at = 0; at <= text.size(); ++line) {
    const size_t eol = std::min(text.find('\n', at), text.size());
    const std::string_view l = text.substr(at, eol - at);
    if (l.substr(0, 6) == "return" && (l.size() == 6 || !std::isalnum(static_cast<unsigned char>(l[6])))) found = line;
    at = eol + 1;
  }
  return found;
}

// Reads the Lua value at `index` into a DataValue (raw reads only: a metatable runs no code).
struct Conversion {
  DataValue out;
  std::string error;  // why it could not be read
  int line = 0;
  size_t values = 0;  // read so far: at most core::kMaxDataValues, as for a literal
};

DataValue valueOf(lua_State* L, int index, int depth, Conversion& job) {
  index = index < 0 ? lua_gettop(L) + index + 1 : index;
  if (++job.values > core::kMaxDataValues)
    throw std::runtime_error("more than " + std::to_string(core::kMaxDataValues) + " keys and values");
  DataValue d;
  d.line = job.line;
  switch (lua_type(L, index)) {
    case LUA_TNIL:
      break;
    case LUA_TBOOLEAN:
      d.kind = DataValue::Kind::Boolean, d.boolean = lua_toboolean(L, index) != 0;
      break;
    case LUA_TNUMBER:
      d.kind = DataValue::Kind::Number, d.number = lua_tonumber(L, index);
      break;
    case LUA_TSTRING: {
      size_t length = 0;
      const char* text = lua_tolstring(L, index, &length);
      d.kind = DataValue::Kind::String, d.text.assign(text, length);
      break;
    }
    case LUA_TTABLE:
      if (depth >= core::kMaxDataDepth)
        throw std::runtime_error("tables nested more than " + std::to_string(core::kMaxDataDepth) +
                                 " deep (a table that holds itself?)");
      if (!lua_checkstack(L, 4)) throw std::runtime_error("out of Lua stack");
      d.kind = DataValue::Kind::Table;
      for (lua_pushnil(L); lua_next(L, index); lua_pop(L, 1)) {
        DataValue key = valueOf(L, -2, depth + 1, job);
        DataValue value = valueOf(L, -1, depth + 1, job);
        d.entries.emplace_back(std::move(key), std::move(value));
      }
      // lua_next's order is the hash's: list items and frames are read in key order.
      std::stable_sort(d.entries.begin(), d.entries.end(), [](const auto& a, const auto& b) {
        const bool an = a.key.kind == DataValue::Kind::Number, bn = b.key.kind == DataValue::Kind::Number;
        if (an != bn) return an;
        if (an) return a.key.number < b.key.number;
        return a.key.kind == DataValue::Kind::String && b.key.kind == DataValue::Kind::String &&
               a.key.text < b.key.text;
      });
      break;
    default:
      d.kind = DataValue::Kind::Other, d.text = std::string("a ") + lua_typename(L, lua_type(L, index));
      break;
  }
  return d;
}

int convertProtected(lua_State* L) {
  auto* job = static_cast<Conversion*>(lua_touserdata(L, 1));
  try {
    job->out = valueOf(L, 2, 0, *job);
  } catch (const std::exception& e) {
    job->error = e.what();
  }
  return 0;
}

// Runs a scenario that is not a literal and reads what it returns. It runs sandboxed, like a level's
// scripts, whoever wrote it: scenarios travel with levels (the editor keeps a level's tests beside
// it, packages carry them), so running one must never run its author's code with io and os. It
// only computes a plan (loops, locals, string and math), under a frame's budget of steps.
DataValue runScenarioFile(const std::string& path, std::string_view text) {
  LuaHost host;  // the scenario's own state: it only makes the plan
  lua_State* L = host.state();
  lua::StackGuard guard(L);
  const int sandbox = host.loadFile(path, Trust::Sandboxed, std::filesystem::path(path).filename().string());
  host.beginFrame();
  if (!host.callSandboxed(sandbox, 0, 1))
    throw ScriptError(path + ": the scenario was stopped before it returned its plan (its budget of steps is spent)",
                      "");
  Conversion job;
  job.line = returnLine(text);
  lua_pushcfunction(L, convertProtected);
  lua_pushlightuserdata(L, &job);
  lua_pushvalue(L, -3);
  host.call(2, 0);
  if (!job.error.empty())
    throw ScriptError(path + (job.line ? ":" + std::to_string(job.line) : "") + ": " + job.error, "");
  return std::move(job.out);
}

DataValue readScenarioFile(const std::string& path) {
  std::string text;
  try {
    text = files::readBoundedFile(path, kMaxScenarioBytes);
  } catch (const files::FileError& e) {
    throw ScriptError(path + ": the scenario: " + e.reason(), "");
  }
  try {
    return core::readLuaData(text, path);
  } catch (const core::DataError& e) {
    if (e.kind != core::DataError::Kind::NotData) throw ScriptError(e.what(), "");
  }
  return runScenarioFile(path, text);
}

// ---- The plan: what a scenario asks for, checked whole before anything runs ----------------

struct Box {
  uint64_t frame;
  physics::MapPartId face;
  int32_t x0, y0, x1, y1;
  std::string where;  // file:line:column: expect.inside[i]
};

struct Plan {
  std::string scene;
  std::string sceneAt;  // "file:line:column" where the scene was named, for errors about its file
  uint64_t frames = 0;
  std::vector<core::Buttons> held;  // per frame, from frame 1: bit i is actions.names[i]
  core::ActionNames actions;        // the engine's, then the names the file adds (a mod's)
  std::optional<uint64_t> goalBy;
  std::optional<int> deaths;
  std::map<uint64_t, physics::MapPartId> faceAt;
  std::map<uint64_t, std::string> faceWhere;  // file:line:column: expect.face[f], for the face id check
  std::vector<Box> inside;
  std::map<uint64_t, std::string> hashAt;
  // expect.sounds: the effects each frame must play (among others it may play), and where each is named.
  std::map<uint64_t, std::vector<std::string>> soundsAt;
  std::map<uint64_t, std::vector<std::string>> soundsWhere;
  std::map<uint64_t, std::vector<uint32_t>> switchesAt;  // expect.switches: exactly these on (sorted)
  // expect.checkpoint: the last checkpoint touched, {face, x, y}; false: none yet.
  std::map<uint64_t, std::optional<std::array<int64_t, 3>>> checkpointAt;
  std::optional<core::ReplayStart> start;    // where the run starts (none: the level's start)
  std::string startWhere;                    // file:line:column: start, for the face check
  std::optional<uint64_t> sceneFilesHash;    // a replay's record of the scene's files
  std::vector<core::ReplayConsole> console;  // a replay's console lines, each run before its frame
  std::string passNote;                      // added to a passing run's summary

  uint64_t lastCheck() const {
    uint64_t last = 0;
    if (!faceAt.empty()) last = std::max(last, faceAt.rbegin()->first);
    if (!hashAt.empty()) last = std::max(last, hashAt.rbegin()->first);
    if (!soundsAt.empty()) last = std::max(last, soundsAt.rbegin()->first);
    if (!switchesAt.empty()) last = std::max(last, switchesAt.rbegin()->first);
    if (!checkpointAt.empty()) last = std::max(last, checkpointAt.rbegin()->first);
    for (const Box& b : inside) last = std::max(last, b.frame);
    return last;
  }
};

constexpr double kMaxFrames = 33554432;           // 2^25, 6 days at 60 Hz, as a replay: 64 MB of input at most
constexpr double kMaxCoordinate = (1 << 30) - 1;  // positions, as the world takes them

// Checks a scenario's table against what a scenario may hold, and turns it into a plan. Every
// error is "file:line:column: where: reason", where is the value's path (expect.face[600]).
class PlanReader {
 public:
  explicit PlanReader(std::string path) : path_(std::move(path)) {}

  Plan read(const DataValue& root) {
    if (root.kind != DataValue::Kind::Table)
      fail(root, "scenario", "a scenario returns a table, got " + core::describeData(root));
    knownKeys(root, "scenario", {"scene", "frames", "start", "input", "console", "expect"});
    Plan plan;
    const DataValue* scene = field(root, "scene");
    if (!scene) fail(root, "scenario", "'scene' (the manifest's path) is missing");
    if (scene->kind != DataValue::Kind::String || scene->text.empty())
      fail(*scene, "scene", "expected the manifest's path (a string), got " + core::describeData(*scene));
    plan.scene = scene->text;
    plan.sceneAt = at(*scene, "scene");
    plan.sceneAt.resize(plan.sceneAt.size() - std::string(": scene: ").size());
    if (!plan.scene.empty() && plan.scene[0] == '/')
      fail(*scene, "scene",
           "is relative, from the scenario's folder, the current folder or the game's data folder (" + plan.scene +
               "): scenarios are shared, and an absolute path could name any file");
    if (core::hasParentStep(plan.scene))
      fail(*scene, "scene", "may not contain '..' (" + plan.scene + "): a scenario names its scene's own path");
    const DataValue* frames = field(root, "frames");
    if (!frames) fail(root, "scenario", "'frames' (how many frames to run) is missing");
    plan.frames = wholeNumber(*frames, "frames", 1, kMaxFrames);
    plan.held.assign(plan.frames + 1, 0);
    if (const DataValue* start = field(root, "start")) readStart(*start, plan);
    if (const DataValue* input = field(root, "input")) readInput(*input, plan);
    if (const DataValue* console = field(root, "console")) readConsole(*console, plan);
    if (const DataValue* expect = field(root, "expect")) readExpect(*expect, plan);
    return plan;
  }

  // "file:line:column: where: " for a value (the line alone for a computed one).
  std::string at(const DataValue& d, const std::string& where) const {
    std::string out = path_;
    if (d.line > 0) out += ":" + std::to_string(d.line);
    if (d.column > 0) out += ":" + std::to_string(d.column);
    return out + ": " + where + ": ";
  }

 private:
  [[noreturn]] void fail(const DataValue& d, const std::string& where, const std::string& reason) const {
    throw ScriptError(at(d, where) + reason, "");
  }

  static const DataValue* field(const DataValue& table, std::string_view key) {
    for (const auto& [k, v] : table.entries)
      if (k.kind == DataValue::Kind::String && k.text == key) return v.kind == DataValue::Kind::Nil ? nullptr : &v;
    return nullptr;
  }

  void knownKeys(const DataValue& table, const std::string& where, std::initializer_list<const char*> known) const {
    std::string list;
    for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
    for (const auto& [key, value] : table.entries) {
      bool ok = false;
      for (const char* k : known) ok = ok || (key.kind == DataValue::Kind::String && key.text == k);
      if (ok) continue;
      const std::string name =
          key.kind == DataValue::Kind::String ? core::dataKeyText(key) : "[" + core::dataKeyText(key) + "]";
      fail(key.line ? key : value, where, "unknown key " + name + " (known: " + list + ")");
    }
  }

  int64_t integer(const DataValue& d, const std::string& where, double low, double high) const {
    char range[96];
    std::snprintf(range, sizeof range, "%.0f..%.0f", low, high);
    if (d.kind != DataValue::Kind::Number || !std::isfinite(d.number) || d.number != std::floor(d.number))
      fail(d, where, "expected a whole number in " + std::string(range) + ", got " + core::describeData(d));
    if (d.number < low || d.number > high) fail(d, where, core::describeData(d) + " is outside " + range);
    return static_cast<int64_t>(d.number);
  }
  uint64_t wholeNumber(const DataValue& d, const std::string& where, double low, double high) const {
    return static_cast<uint64_t>(integer(d, where, low, high));
  }
  // A box corner: a position on a face.
  int32_t coordinate(const DataValue& d, const std::string& where) const {
    return static_cast<int32_t>(integer(d, where, -kMaxCoordinate, kMaxCoordinate));
  }
  // A list: keys 1, 2, ... n with no holes, each of `itemKind` (a table unless said).
  std::vector<const DataValue*> list(const DataValue& d, const std::string& where, const char* ofWhat,
                                     DataValue::Kind itemKind = DataValue::Kind::Table) const {
    if (d.kind != DataValue::Kind::Table)
      fail(d, where, std::string("expected a list of ") + ofWhat + ", got " + core::describeData(d));
    std::vector<const DataValue*> items;
    for (const auto& [key, value] : d.entries) {
      const std::string item = where + "[" + core::dataKeyText(key) + "]";
      if (key.kind != DataValue::Kind::Number || key.number != static_cast<double>(items.size() + 1))
        fail(key.line ? key : value, item,
             std::string("not item ") + std::to_string(items.size() + 1) + " of a list (" + where + " is a list of " +
                 ofWhat + ", items 1, 2, 3... with no holes)");
      if (value.kind != itemKind)
        fail(value, item, std::string("expected ") + ofWhat + ", got " + core::describeData(value));
      items.push_back(&value);
    }
    return items;
  }
  // start = { face = F, x = X, y = Y }: the run starts there (a play-test from the editor's cursor).
  void readStart(const DataValue& d, Plan& plan) const {
    if (d.kind != DataValue::Kind::Table)
      fail(d, "start", "expected { face = F, x = X, y = Y }, got " + core::describeData(d));
    knownKeys(d, "start", {"face", "x", "y"});
    core::ReplayStart start;
    for (const char* key : {"face", "x", "y"}) {
      const DataValue* v = field(d, key);
      if (!v) fail(d, "start", std::string("'") + key + "' is missing (start = { face = F, x = X, y = Y })");
      const std::string where = std::string("start.") + key;
      if (std::string_view(key) == "face")
        start.face = static_cast<int>(wholeNumber(*v, where, 0, 1e6));
      else
        (std::string_view(key) == "x" ? start.x : start.y) = static_cast<int32_t>(
            integer(*v, where, -double(core::kMaxStartCoordinate), double(core::kMaxStartCoordinate)));
    }
    plan.start = start;
    plan.startWhere = at(d, "start");
  }
  uint64_t frameKey(const DataValue& key, const DataValue& value, const std::string& where, const Plan& plan) const {
    return wholeNumber(key.line ? key : value, where + " (a frame)", 1, static_cast<double>(plan.frames));
  }

  // The bit of the action `d` names: the engine's, or another name, which the scene must have.
  int action(const DataValue& d, const std::string& where, Plan& plan) const {
    const std::string place = at(d, where);  // "file:line:column: where: "
    const std::optional<int> b = d.kind == DataValue::Kind::String
                                     ? plan.actions.bitOf(d.text, place.substr(0, place.size() - 2))
                                     : std::nullopt;
    if (!b)
      fail(d, where,
           "unknown action " + (d.kind == DataValue::Kind::String ? core::dataKeyText(d) : core::describeData(d)) +
               " (" + core::actionList(core::engineActions()) + ", or one a mod adds)");
    return *b;
  }

  void readInput(const DataValue& input, Plan& plan) const {
    const std::vector<const DataValue*> items =
        list(input, "input", "{ hold = \"button\", from =, to = } or { press = \"button\", at =, frames = }");
    for (size_t i = 0; i < items.size(); ++i) {
      const DataValue& item = *items[i];
      const std::string where = "input[" + std::to_string(i + 1) + "]";
      const DataValue* hold = field(item, "hold");
      const DataValue* press = field(item, "press");
      if (hold && press) fail(*press, where, "give hold or press, not both");
      const auto last = static_cast<double>(plan.frames);
      uint64_t from = 0, to = 0;
      int b = 0;
      if (hold) {
        knownKeys(item, where, {"hold", "from", "to"});
        b = action(*hold, where + ".hold", plan);
        from = wholeNumber(required(item, "from", where), where + ".from", 1, last);
        to = wholeNumber(required(item, "to", where), where + ".to", 1, last);
        if (to < from)
          fail(required(item, "to", where), where + ".to",
               "frame " + std::to_string(to) + " is before from = " + std::to_string(from));
      } else if (press) {
        knownKeys(item, where, {"press", "at", "frames"});
        b = action(*press, where + ".press", plan);
        from = wholeNumber(required(item, "at", where), where + ".at", 1, last);
        const DataValue* count = field(item, "frames");
        to = from + (count ? wholeNumber(*count, where + ".frames", 1, last) : 1) - 1;
        if (to > plan.frames)
          fail(*count, where + ".frames",
               "the press runs to frame " + std::to_string(to) + ", past the scenario's " +
                   std::to_string(plan.frames) + " frames");
      } else {
        fail(item, where, "give hold = \"button\" (from, to) or press = \"button\" (at, frames)");
      }
      for (uint64_t f = from; f <= to; ++f) plan.held[f] |= static_cast<core::Buttons>(1u << b);
    }
  }

  // Lines typed in the console, each run before its frame (a replay's, in a kept play-test):
  // console = { { at = F, code = "..." }, ... }, frames that do not decrease.
  void readConsole(const DataValue& console, Plan& plan) const {
    const std::vector<const DataValue*> items = list(console, "console", "{ at = frame, code = \"Lua\" }");
    uint64_t last = 1;
    for (size_t i = 0; i < items.size(); ++i) {
      const DataValue& item = *items[i];
      const std::string where = "console[" + std::to_string(i + 1) + "]";
      knownKeys(item, where, {"at", "code"});
      const DataValue& atFrame = required(item, "at", where);
      const uint64_t frame = wholeNumber(atFrame, where + ".at", 1, static_cast<double>(plan.frames));
      if (frame < last)
        fail(atFrame, where + ".at",
             "frame " + std::to_string(frame) + " is before the line above's, " + std::to_string(last) +
                 " (lines run in the order typed)");
      const DataValue& code = required(item, "code", where);
      if (code.kind != DataValue::Kind::String)
        fail(code, where + ".code", "expected the line of Lua (a string), got " + core::describeData(code));
      plan.console.push_back({frame, code.text});
      last = frame;
    }
  }

  const DataValue& required(const DataValue& table, const char* key, const std::string& where) const {
    const DataValue* v = field(table, key);
    if (!v) fail(table, where, std::string("'") + key + "' is missing");
    return *v;
  }

  void readExpect(const DataValue& expect, Plan& plan) const {
    if (expect.kind != DataValue::Kind::Table)
      fail(expect, "expect", "expected a table of checks, got " + core::describeData(expect));
    knownKeys(expect, "expect", {"goal_by", "deaths", "face", "inside", "hash", "sounds", "switches", "checkpoint"});
    const auto last = static_cast<double>(plan.frames);
    if (const DataValue* goal = field(expect, "goal_by")) plan.goalBy = wholeNumber(*goal, "expect.goal_by", 1, last);
    if (const DataValue* deaths = field(expect, "deaths"))
      plan.deaths = static_cast<int>(wholeNumber(*deaths, "expect.deaths", 0, 2147483647.0));
    if (const DataValue* face = field(expect, "face")) readExpectedFaces(*face, plan);
    if (const DataValue* hash = field(expect, "hash")) readExpectedHashes(*hash, plan);
    if (const DataValue* sounds = field(expect, "sounds")) readExpectedSounds(*sounds, plan);
    if (const DataValue* switches = field(expect, "switches")) readExpectedSwitches(*switches, plan);
    if (const DataValue* checkpoint = field(expect, "checkpoint")) readExpectedCheckpoints(*checkpoint, plan);
    if (const DataValue* inside = field(expect, "inside")) {
      const std::vector<const DataValue*> items =
          list(*inside, "expect.inside", "{ frame =, face =, box = { x0, y0, x1, y1 } }");
      for (size_t i = 0; i < items.size(); ++i)
        plan.inside.push_back(insideBox(*items[i], "expect.inside[" + std::to_string(i + 1) + "]", last));
    }
  }

  // expect.face = { [frame] = face, ... }: the face the player is on at those frames.
  void readExpectedFaces(const DataValue& face, Plan& plan) const {
    if (face.kind != DataValue::Kind::Table)
      fail(face, "expect.face", "expected { [frame] = face, ... }, got " + core::describeData(face));
    for (const auto& [key, value] : face.entries) {
      const std::string where = "expect.face[" + core::dataKeyText(key) + "]";
      const uint64_t f = frameKey(key, value, where, plan);
      plan.faceAt[f] = static_cast<physics::MapPartId>(wholeNumber(value, where, 0, 4095));
      plan.faceWhere[f] = at(value, where);
    }
  }

  // expect.hash = { [frame] = "16 hex digits", ... }: the world's state hash at those frames.
  void readExpectedHashes(const DataValue& hash, Plan& plan) const {
    if (hash.kind != DataValue::Kind::Table)
      fail(hash, "expect.hash", "expected { [frame] = \"16 hex digits\", ... }, got " + core::describeData(hash));
    for (const auto& [key, value] : hash.entries) {
      const std::string where = "expect.hash[" + core::dataKeyText(key) + "]";
      const uint64_t f = frameKey(key, value, where, plan);
      if (value.kind != DataValue::Kind::String || value.text.size() != 16 ||
          value.text.find_first_not_of("0123456789abcdef") != std::string::npos)
        fail(value, where,
             "frame " + std::to_string(f) + ": state hash " + core::describeData(value) +
                 " is not 16 lower-case hex digits");
      plan.hashAt[f] = value.text;
    }
  }

  // expect.sounds = { [frame] = "name" or { "name", ... }, ... }: effects that play at those frames.
  void readExpectedSounds(const DataValue& sounds, Plan& plan) const {
    if (sounds.kind != DataValue::Kind::Table)
      fail(sounds, "expect.sounds",
           "expected { [frame] = \"name\" or { \"name\", ... }, ... }, got " + core::describeData(sounds));
    for (const auto& [key, value] : sounds.entries) {
      const std::string where = "expect.sounds[" + core::dataKeyText(key) + "]";
      const uint64_t f = frameKey(key, value, where, plan);
      std::vector<const DataValue*> names;
      if (value.kind == DataValue::Kind::String)
        names.push_back(&value);
      else
        names = list(value, where, "sounds' names", DataValue::Kind::String);
      for (size_t i = 0; i < names.size(); ++i) {
        const std::string named =
            value.kind == DataValue::Kind::String ? where : where + "[" + std::to_string(i + 1) + "]";
        plan.soundsAt[f].push_back(names[i]->text);
        plan.soundsWhere[f].push_back(at(*names[i], named));
      }
    }
  }

  // expect.switches = { [frame] = { id, ... }, ... }: the switches on at those frames, each once.
  void readExpectedSwitches(const DataValue& switches, Plan& plan) const {
    if (switches.kind != DataValue::Kind::Table)
      fail(switches, "expect.switches", "expected { [frame] = { id, ... }, ... }, got " + core::describeData(switches));
    for (const auto& [key, value] : switches.entries) {
      const std::string where = "expect.switches[" + core::dataKeyText(key) + "]";
      const uint64_t f = frameKey(key, value, where, plan);
      std::vector<uint32_t>& on = plan.switchesAt[f];
      const std::vector<const DataValue*> ids = list(value, where, "switch ids", DataValue::Kind::Number);
      for (size_t i = 0; i < ids.size(); ++i)
        on.push_back(static_cast<uint32_t>(wholeNumber(*ids[i], where + "[" + std::to_string(i + 1) + "]", 1, 999)));
      std::sort(on.begin(), on.end());
      if (std::adjacent_find(on.begin(), on.end()) != on.end()) fail(value, where, "a switch id given twice");
    }
  }

  // expect.checkpoint = { [frame] = { face, x, y } or false, ... }: the checkpoint at those frames.
  void readExpectedCheckpoints(const DataValue& checkpoint, Plan& plan) const {
    if (checkpoint.kind != DataValue::Kind::Table)
      fail(checkpoint, "expect.checkpoint",
           "expected { [frame] = { face, x, y } or false, ... }, got " + core::describeData(checkpoint));
    for (const auto& [key, value] : checkpoint.entries) {
      const std::string where = "expect.checkpoint[" + core::dataKeyText(key) + "]";
      const uint64_t f = frameKey(key, value, where, plan);
      if (value.kind == DataValue::Kind::Boolean && !value.boolean) {
        plan.checkpointAt[f] = std::nullopt;
        continue;
      }
      const std::vector<const DataValue*> v =
          list(value, where, "face, x, y (or false: none)", DataValue::Kind::Number);
      if (v.size() != 3)
        fail(value, where, "expected { face, x, y } (or false: none), got " + std::to_string(v.size()) + " values");
      plan.checkpointAt[f] =
          std::array<int64_t, 3>{static_cast<int64_t>(wholeNumber(*v[0], where + "[1]", 0, 4095)),
                                 static_cast<int64_t>(wholeNumber(*v[1], where + "[2]", -1073741823.0, 1073741823.0)),
                                 static_cast<int64_t>(wholeNumber(*v[2], where + "[3]", -1073741823.0, 1073741823.0))};
    }
  }

  // One of expect.inside: { frame =, face =, box = { x0, y0, x1, y1 } }, the player inside the box
  // (corners lower left, upper right) on that face at that frame. `last`: the scenario's last frame.
  Box insideBox(const DataValue& item, const std::string& where, double last) const {
    knownKeys(item, where, {"frame", "face", "box"});
    Box b{};
    b.frame = wholeNumber(required(item, "frame", where), where + ".frame", 1, last);
    b.face = static_cast<physics::MapPartId>(wholeNumber(required(item, "face", where), where + ".face", 0, 4095));
    b.where = at(*field(item, "face"), where + ".face");
    const DataValue& box = required(item, "box", where);
    const std::vector<DataEntry>& corners = box.entries;
    bool isList = box.kind == DataValue::Kind::Table && corners.size() == 4;
    for (size_t k = 0; isList && k < 4; ++k)
      isList = corners[k].key.kind == DataValue::Kind::Number && corners[k].key.number == static_cast<double>(k + 1);
    if (!isList) fail(box, where + ".box", "expected { x0, y0, x1, y1 }, got " + core::describeData(box));
    int32_t* out[] = {&b.x0, &b.y0, &b.x1, &b.y1};
    for (size_t k = 0; k < 4; ++k)
      *out[k] = coordinate(corners[k].value, where + ".box[" + std::to_string(k + 1) + "]");
    if (b.x1 < b.x0 || b.y1 < b.y0)
      fail(box, where + ".box", "an inverted box: x0 <= x1 and y0 <= y1 (corners lower left, upper right)");
    return b;
  }

  std::string path_;
};

Plan readPlan(const std::string& path) { return PlanReader(path).read(readScenarioFile(path)); }

// The face ids the plan checks, against the stage the scene loaded: a face that does not exist
// can never match.
void checkFaces(const Plan& plan, const core::Scene& scene) {
  const size_t faces = scene.stage() ? scene.stage()->faceCount() : 0;
  auto check = [&](physics::MapPartId face, const std::string& where) {
    if (face >= faces)
      throw ScriptError(where + "face " + std::to_string(face) + " does not exist (the stage's faces are 0.." +
                            std::to_string(faces == 0 ? 0 : faces - 1) + ")",
                        "");
  };
  if (plan.start) check(static_cast<physics::MapPartId>(plan.start->face), plan.startWhere);
  for (const auto& [frame, face] : plan.faceAt) check(face, plan.faceWhere.at(frame));
  for (const Box& b : plan.inside) check(b.face, b.where);
  // Likewise a sound the scene's bank does not have.
  for (const auto& [frame, names] : plan.soundsAt)
    for (size_t i = 0; i < names.size(); ++i)
      if (!scene.sounds().bank().hasEffect(names[i]))
        throw ScriptError(plan.soundsWhere.at(frame)[i] + "the scene's sound bank has no effect '" + names[i] + "'",
                          "");
}

// The effects the frame played, "jump, land", or "nothing".
std::string heardText(const core::Scene& scene) {
  std::string text;
  for (const core::SoundEvent& e : scene.sounds().thisFrame()) text += (text.empty() ? "" : ", ") + e.name;
  return text.empty() ? "nothing" : text;
}

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// One line of --trace: where the player is and how it moves, and what the level holds.
std::string traceText(const GameStatus& s) {
  char line[256];
  std::snprintf(line, sizeof line, "face %u at (%d, %d), velocity (%.2f, %.2f), %s, deaths %d", s.face, s.x, s.y, s.vx,
                s.vy, s.grounded ? "grounded" : "in the air", s.deaths);
  std::string out = line;
  out += ", switches on:";
  bool any = false;
  for (const uint32_t tag : s.openTags)
    if (tag > 1000 && tag < 2000) out += " " + std::to_string(tag - 1000), any = true;
  if (!any) out += " none";
  if (s.hasCheckpoint)
    out += ", checkpoint face " + std::to_string(s.checkpointFace) + " (" + std::to_string(s.checkpointX) + ", " +
           std::to_string(s.checkpointY) + ")";
  else
    out += ", no checkpoint";
  if (s.won) out += ", won";
  return out;
}

// --trace's lines for frame f: the game's state every `traceEvery` frames, and the sounds on the
// frame they play, whatever the trace's period (a scenario expects them there).
void traceFrame(uint64_t f, const core::Scene& scene, ScriptSystem* scripts, uint64_t traceEvery,
                const std::string& path) {
  if (traceEvery == 0) return;
  if (scripts && f % traceEvery == 0)
    std::fprintf(stderr, "%s: frame %llu: %s\n", path.c_str(), static_cast<unsigned long long>(f),
                 traceText(scripts->status()).c_str());
  if (!scene.sounds().thisFrame().empty())
    std::fprintf(stderr, "%s: frame %llu: sounds %s\n", path.c_str(), static_cast<unsigned long long>(f),
                 heardText(scene).c_str());
}

std::string checkSwitches(const std::vector<uint32_t>& expected, const GameStatus& s) {
  std::vector<uint32_t> on;
  for (const uint32_t tag : s.openTags)
    if (tag > 1000 && tag < 2000) on.push_back(tag - 1000);
  std::sort(on.begin(), on.end());
  auto text = [](const std::vector<uint32_t>& ids) {
    std::string out = "{";
    for (size_t i = 0; i < ids.size(); ++i) out += (i ? ", " : " ") + std::to_string(ids[i]);
    return out + (ids.empty() ? "}" : " }");
  };
  return on == expected ? "" : "switches on " + text(on) + ", expected " + text(expected);
}

template <class Want>
std::string checkCheckpoint(const Want& want, const GameStatus& s) {
  auto text = [](bool has, int64_t face, int64_t x, int64_t y) {
    return has ? "face " + std::to_string(face) + " (" + std::to_string(x) + ", " + std::to_string(y) + ")"
               : std::string("none");
  };
  const bool same = want ? s.hasCheckpoint && s.checkpointFace == (*want)[0] && s.checkpointX == (*want)[1] &&
                               s.checkpointY == (*want)[2]
                         : !s.hasCheckpoint;
  if (same) return "";
  return "checkpoint " + text(s.hasCheckpoint, s.checkpointFace, s.checkpointX, s.checkpointY) + ", expected " +
         (want ? text(true, (*want)[0], (*want)[1], (*want)[2]) : "none");
}

std::string checkSounds(const std::vector<std::string>& expected, const core::Scene& scene) {
  const auto& heard = scene.sounds().thisFrame();
  for (const std::string& name : expected)
    if (std::none_of(heard.begin(), heard.end(), [&](const core::SoundEvent& e) { return e.name == name; }))
      return "expected the sound '" + name + "', heard " + heardText(scene);
  return "";
}

// Where the player must be at frame f: on a face, inside a box.
// The game's status is read only on a frame that checks it.
std::string checkPlace(const Plan& plan, uint64_t f, ScriptSystem& scripts) {
  if (auto face = plan.faceAt.find(f); face != plan.faceAt.end()) {
    const GameStatus s = scripts.status();
    if (s.face != face->second)
      return "player on face " + std::to_string(s.face) + ", expected face " + std::to_string(face->second);
  }
  for (const Box& b : plan.inside) {
    if (b.frame != f) continue;
    const GameStatus s = scripts.status();
    if (s.face != b.face || s.x < b.x0 || s.x > b.x1 || s.y < b.y0 || s.y > b.y1)
      return "player at face " + std::to_string(s.face) + " (" + std::to_string(s.x) + ", " + std::to_string(s.y) +
             "), expected inside face " + std::to_string(b.face) + " [" + std::to_string(b.x0) + ", " +
             std::to_string(b.y0) + "]-[" + std::to_string(b.x1) + ", " + std::to_string(b.y1) + "]";
  }
  return "";
}

// The checks of frame f; "" when they pass.
// `filesNote`: said before a hash mismatch ("" or why the recorded hashes may no longer hold).
std::string checkFrame(const Plan& plan, uint64_t f, core::Scene& scene, ScriptSystem* scripts, uint64_t traceEvery,
                       const std::string& path, const std::string& filesNote) {
  const std::string at = "frame " + std::to_string(f) + ": ";
  traceFrame(f, scene, scripts, traceEvery, path);
  std::string failed;
  if (auto expected = plan.switchesAt.find(f); expected != plan.switchesAt.end() && scripts)
    failed = checkSwitches(expected->second, scripts->status());
  if (auto expected = plan.checkpointAt.find(f); failed.empty() && expected != plan.checkpointAt.end() && scripts)
    failed = checkCheckpoint(expected->second, scripts->status());
  if (auto expected = plan.soundsAt.find(f); failed.empty() && expected != plan.soundsAt.end())
    failed = checkSounds(expected->second, scene);
  if (!failed.empty()) return at + failed;
  if (const size_t overlaps = scene.world().countOverlaps(); overlaps != 0)
    return at + std::to_string(overlaps) + " instance(s) overlap a solid line";
  if (auto h = plan.hashAt.find(f); h != plan.hashAt.end() && hex(scene.world().stateHash()) != h->second)
    return filesNote + at + "state hash " + hex(scene.world().stateHash()) + ", expected " + h->second;
  if (!scripts) return "";
  failed = checkPlace(plan, f, *scripts);
  return failed.empty() ? "" : at + failed;
}
}  // namespace

namespace {

// The scene's script system (the last one, were there several); none when it has no scripts.
ScriptSystem* scriptSystemOf(core::Scene& scene) {
  ScriptSystem* scripts = nullptr;
  for (size_t i = 0; i < scene.systemCount(); ++i)
    if (auto* s = dynamic_cast<ScriptSystem*>(&scene.system(i))) scripts = s;
  return scripts;
}

// Said before a hash mismatch when the scene's files are not the ones a replay was recorded with
// (its hashes may no longer hold); "" when they are, or nothing was recorded.
std::string filesChangedNote(const Plan& plan, uint64_t filesHash) {
  return plan.sceneFilesHash && *plan.sceneFilesHash != filesHash
             ? "the scene's files changed since the recording (files " + hex(filesHash) + ", recorded with " +
                   hex(*plan.sceneFilesHash) + "): "
             : "";
}

struct PlanVerdict {
  bool passed;
  std::string message;
};

// The verdict on a run whose every frame passed its checks: the goal by its frame and the deaths
// (for a scene with scripts: `status` is the game's at the end, else null), and what was shown.
PlanVerdict planVerdict(const Plan& plan, const GameStatus* status) {
  if (!status) return {true, plan.hashAt.empty() ? "ok" : std::to_string(plan.hashAt.size()) + " hashes matched"};
  const GameStatus& s = *status;
  if (plan.goalBy && (!s.won || s.wonFrame > *plan.goalBy))
    return {false, "goal not reached by frame " + std::to_string(*plan.goalBy) + " (player on face " +
                       std::to_string(s.face) + " at " + std::to_string(s.x) + ", " + std::to_string(s.y) + ")"};
  if (plan.deaths && s.deaths != *plan.deaths)
    return {false, std::to_string(s.deaths) + " deaths, expected " + std::to_string(*plan.deaths)};
  if (!plan.hashAt.empty() && !plan.goalBy)
    return {true, std::to_string(plan.hashAt.size()) + " hashes matched" +
                      (s.won ? ", goal at frame " + std::to_string(s.wonFrame) : "")};
  return {true, s.won ? "goal at frame " + std::to_string(s.wonFrame) : "ok"};
}

// Plays the plan's frames on `run`, each frame's checks after it: the first failure, "" when none.
// `frames`: the frames played, kept up to date as they go (a run that throws says how far it got).
std::string playPlanFrames(const Plan& plan, core::Run& run, core::Scene& scene, ScriptSystem* scripts,
                           const core::ActionMap& actions, const RunOptions& options, const std::string& path,
                           const std::string& filesNote, uint64_t& frames) {
  std::string failure;
  size_t nextLine = 0;
  for (uint64_t f = 1; f <= plan.frames && failure.empty(); ++f) {
    // The console's lines where the run typed them (their answers were the player's to read).
    for (; nextLine < plan.console.size() && plan.console[nextLine].frame == f; ++nextLine)
      (void)run.console(plan.console[nextLine].code);
    run.step(actions(plan.held[f]));
    frames = f;
    failure = checkFrame(plan, f, scene, scripts, options.traceEvery, path, filesNote);
    // With the goal reached there is nothing left to see, unless a check waits for a later frame.
    if (failure.empty() && plan.goalBy && f >= plan.lastCheck() && scripts && scripts->status().won) break;
  }
  return failure;
}

// Runs a plan: the scene, its input, every check on every frame.
ScenarioResult runPlan(const std::string& path, const std::function<Plan()>& makePlan, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ScenarioResult result;
  std::string passNote;
  auto finish = [&](bool passed, std::string message) {
    if (passed) message += passNote;
    result.passed = passed;
    result.message = std::move(message);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  };
  std::optional<core::Run> run;  // the run every way of playing drives (core/run.h)
  auto keepRecording = [&] {
    if (run) result.recorded = run->recorded();
  };
  try {
    const Plan plan = makePlan();
    passNote = plan.passNote;
    core::SystemRegistry registry;
    registry.add("scripting", makeScriptSystem);
    registry.addPlugin("meshes", "platon_meshes", options.pluginFolders);
    const std::string scenePath = core::resolveNamedPath(plan.scene, path);
    try {  // a scene path that names no readable manifest is the naming line's error
      files::checkBoundedFile(scenePath, core::kMaxManifestBytes);
    } catch (const files::FileError& e) {
      return finish(false, plan.sceneAt + ": scene \"" + plan.scene + "\": " + e.reason());
    }
    core::LevelOverride override;
    if (plan.start) override.start = stage::LevelPoint{plan.start->face, {plan.start->x, plan.start->y}};
    std::unique_ptr<core::Scene> scene;
    try {
      scene = core::loadScene(scenePath, registry, nullptr, &override);
    } catch (const stage::StageError& e) {  // the start put off its face or into a wall: the start's own error
      if (!plan.start) throw;
      return finish(false, plan.startWhere + "the level does not start there: " + e.what());
    }
    checkFaces(plan, *scene);
    const uint64_t filesHash = core::sceneFilesHash(core::sceneSourceFiles(*scene));
    const std::string filesNote = filesChangedNote(plan, filesHash);
    ScriptSystem* const scripts = scriptSystemOf(*scene);
    if ((plan.goalBy || plan.deaths || !plan.faceAt.empty() || !plan.inside.empty()) && !scripts)
      return finish(false, "the scene has no scripts, so no player to check");
    const core::ActionMap actions(plan.actions, scene->actions());  // a name the scene lacks: at its place
    run.emplace(*scene);
    if (options.record) run->record({plan.scene, options.hashEvery, filesHash, plan.start, 100});
    const std::string failure =
        playPlanFrames(plan, *run, *scene, scripts, actions, options, path, filesNote, result.frames);
    // The last frame played is traced too (the goal's, a failure's), whatever the period.
    if (options.traceEvery > 0 && scripts && result.frames % options.traceEvery != 0)
      std::fprintf(stderr, "%s: frame %llu: %s\n", path.c_str(), static_cast<unsigned long long>(result.frames),
                   traceText(scripts->status()).c_str());
    keepRecording();
    result.hash = hex(scene->world().stateHash());
    if (scripts) result.status = scripts->status();
    if (!failure.empty()) return finish(false, failure);
    // An error the last frame's checks met (status() keeps its errors for the next frame).
    if (scripts)
      if (std::optional<std::string> error = scripts->takeError()) return finish(false, *error);
    PlanVerdict verdict = planVerdict(plan, scripts ? &*result.status : nullptr);
    return finish(verdict.passed, std::move(verdict.message));
  } catch (const ScriptError& e) {
    keepRecording();
    return finish(false, e.report());
  } catch (const std::exception& e) {
    keepRecording();
    return finish(false, e.what());
  }
}

}  // namespace

ScenarioResult runScenario(const std::string& path, const RunOptions& options) {
  return runPlan(
      path, [&] { return readPlan(path); }, options);
}

ScenarioResult runReplay(const std::string& path, const RunOptions& options) {
  return runPlan(
      path,
      [&] {
        const core::Replay replay = core::readReplay(path);
        Plan plan;
        plan.scene = replay.scene;
        plan.sceneAt = replay.sceneAt;
        plan.frames = replay.frames();
        plan.held.assign(1, 0);
        plan.held.insert(plan.held.end(), replay.held.begin(), replay.held.end());
        plan.actions = replay.actions;
        for (const core::ReplayHash& h : replay.hashes) plan.hashAt[h.frame] = hex(h.hash);
        plan.sceneFilesHash = replay.sceneFiles;
        plan.start = replay.start;
        plan.startWhere = replay.sceneAt + ": start: ";
        plan.console = replay.console;
        if (replay.hashes.empty()) plan.passNote = " (the replay has no hashes: its input ran, nothing was compared)";
        return plan;
      },
      options);
}

namespace {

// A name for the leading comment: one line.
std::string oneLine(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

}  // namespace

std::string scenarioFromReplay(const core::Replay& replay, const ScenarioResult& outcome, const std::string& name) {
  // Every line within the project's lint (120 characters): the name is cut if need be.
  std::string from = oneLine(name);
  if (from.size() > 100) from = from.substr(0, 97) + "...";
  std::string out =
      "-- Made by `platon scenario`: the recorded input, and what that run reached.\n-- From " + from + ".\n";
  out += "return {\n  scene = " + core::luaQuoted(replay.scene) + ",\n  frames = " + std::to_string(replay.frames()) +
         ",\n";
  if (replay.start)
    out += "  start = { face = " + std::to_string(replay.start->face) + ", x = " + std::to_string(replay.start->x) +
           ", y = " + std::to_string(replay.start->y) + " },\n";
  out += "  input = {\n";
  for (size_t b = 0; b < replay.actions.names.size(); ++b) {
    const std::string& button = replay.actions.names[b];
    for (size_t i = 0; i < replay.held.size();) {
      if (!(replay.held[i] >> b & 1)) {
        ++i;
        continue;
      }
      size_t j = i;
      while (j < replay.held.size() && (replay.held[j] >> b & 1)) ++j;
      out +=
          "    { hold = \"" + button + "\", from = " + std::to_string(i + 1) + ", to = " + std::to_string(j) + " },\n";
      i = j;
    }
  }
  out += "  },\n";
  if (!replay.console.empty()) {  // what was typed, where it ran: part of the input
    out += "  console = {\n";
    for (const core::ReplayConsole& line : replay.console)
      out += "    { at = " + std::to_string(line.frame) + ", code = " + core::luaQuoted(line.code) + " },\n";
    out += "  },\n";
  }
  out += "  expect = {\n";
  if (outcome.status) {
    const GameStatus& s = *outcome.status;
    if (s.won) out += "    goal_by = " + std::to_string(s.wonFrame) + ",\n";
    out += "    deaths = " + std::to_string(s.deaths) + ",\n";
    out += "    face = { [" + std::to_string(outcome.frames) + "] = " + std::to_string(s.face) + " },\n";
  }
  // Three hashes a line: the lines stay within the project's lint (120 characters).
  out += "    hash = {\n";
  int onLine = 0;
  for (const core::ReplayHash& h : replay.hashes) {
    if (h.frame > outcome.frames) break;
    out += std::string(onLine == 0 ? "     " : "") + " [" + std::to_string(h.frame) + "] = \"" + hex(h.hash) + "\",";
    if (++onLine == 3) out += "\n", onLine = 0;
  }
  if (onLine) out += "\n";
  out += "    },\n  },\n}\n";
  return out;
}

}  // namespace platon::script
