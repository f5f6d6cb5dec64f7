// package.lua: the manifest's text and its reader (the data reader, core/lua_data.h: a literal,
// never run).
#include <algorithm>
#include <cmath>

#include "package_paths.h"
#include "platon/core/lua_data.h"
#include "platon/package/package.h"

namespace platon::package {
namespace {

[[noreturn]] void fail(const std::string& file, const core::DataValue& at, const std::string& why) {
  throw PackageError(file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + why);
}

const core::DataValue& required(const std::string& file, const core::DataValue& table, const char* key,
                                core::DataValue::Kind kind) {
  const core::DataValue* v = table.field(key);
  if (!v) fail(file, table, std::string("'") + key + "' is missing");
  if (v->kind != kind)
    fail(file, *v,
         std::string(key) + ": expected a " +
             (kind == core::DataValue::Kind::Number   ? "number"
              : kind == core::DataValue::Kind::String ? "string"
                                                      : "table") +
             ", got " + core::describeData(*v));
  return *v;
}

bool hex64(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return std::isdigit(static_cast<unsigned char>(c)) || (c >= 'a' && c <= 'f');
         });
}

}  // namespace

std::string manifestText(const PackageManifest& m) {
  std::string out = "-- A Platon level package's manifest (docs/packages.md), written by `platon pack`.\nreturn {\n";
  out += "  format = " + std::to_string(m.format) + ",\n  name = " + core::luaQuoted(m.name) +
         ",\n  folder = " + core::luaQuoted(m.folder) + ",\n  hash = " + core::luaQuoted(m.hash) + ",\n  files = {\n";
  for (const PackageFile& f : m.files)
    out += "    { path = " + core::luaQuoted(f.path) + ", bytes = " + std::to_string(f.bytes) +
           ", sha256 = " + core::luaQuoted(f.sha256) + " },\n";
  return out + "  },\n}\n";
}

PackageManifest parseManifest(const std::string& text, const std::string& file) {
  core::DataValue root;
  try {
    root = core::readLuaData(text, file);
  } catch (const core::DataError& e) {
    throw PackageError(e.what());
  }
  if (!root.isTable()) fail(file, root, "a manifest returns a table");
  PackageManifest m;
  const core::DataValue& format = required(file, root, "format", core::DataValue::Kind::Number);
  if (format.number != 1) fail(file, format, "format " + core::describeData(format) + ": this Platon reads format 1");
  m.name = required(file, root, "name", core::DataValue::Kind::String).text;
  const core::DataValue& folder = required(file, root, "folder", core::DataValue::Kind::String);
  if (!plainName(folder.text))
    fail(file, folder, "folder: not a plain folder name (letters, digits, '.', '-' and '_')");
  m.folder = folder.text;
  const core::DataValue& hash = required(file, root, "hash", core::DataValue::Kind::String);
  if (!hex64(hash.text)) fail(file, hash, "hash: expected 64 lower-case hex digits");
  m.hash = hash.text;
  const core::DataValue& files = required(file, root, "files", core::DataValue::Kind::Table);
  if (files.entries.size() > kMaxFiles) fail(file, files, "files: more than " + std::to_string(kMaxFiles));
  for (const core::DataEntry& e : files.entries) {
    if (!e.value.isTable()) fail(file, e.value, "files: expected { path =, bytes =, sha256 = }");
    PackageFile f;
    const core::DataValue& path = required(file, e.value, "path", core::DataValue::Kind::String);
    if (const std::string why = pathProblem(path.text); !why.empty())
      fail(file, path, "path " + core::luaQuoted(path.text) + ": " + why);
    f.path = path.text;
    const core::DataValue& bytes = required(file, e.value, "bytes", core::DataValue::Kind::Number);
    if (!(bytes.number >= 0 && bytes.number <= static_cast<double>(kMaxFileBytes)) ||
        bytes.number != std::floor(bytes.number))
      fail(file, bytes, "bytes: expected a whole number of bytes, at most " + std::to_string(kMaxFileBytes));
    f.bytes = static_cast<uint64_t>(bytes.number);
    const core::DataValue& sha = required(file, e.value, "sha256", core::DataValue::Kind::String);
    if (!hex64(sha.text)) fail(file, sha, "sha256: expected 64 lower-case hex digits");
    f.sha256 = sha.text;
    if (!m.files.empty() && !(m.files.back().path < f.path)) fail(file, path, "files: not in order, or given twice");
    m.files.push_back(std::move(f));
  }
  if (manifestHash(m.files) != m.hash)
    fail(file, hash, "hash: not the hash of the files listed (the manifest was changed)");
  return m;
}

}  // namespace platon::package

namespace platon::package {

std::string pathProblem(const std::string& path) {
  if (path.empty()) return "empty";
  if (path.size() > 200) return "longer than 200 bytes";
  size_t parts = 0, start = 0;
  while (start <= path.size()) {
    const size_t end = std::min(path.find('/', start), path.size());
    const std::string part = path.substr(start, end - start);
    if (part.empty()) return "an empty part (a leading, trailing or doubled '/')";
    if (part[0] == '.') return "a part starting with '.' ('" + part.substr(0, 40) + "')";
    for (const char c : part)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
        return "a character other than letters, digits, '.', '-' and '_'";
    if (++parts > 8) return "more than 8 folders deep";
    start = end + 1;
  }
  return "";
}

}  // namespace platon::package
