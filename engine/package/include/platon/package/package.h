// Level packages: a level that travels (docs/packages.md). A package is one file, NAME.platon, a
// gzipped tar holding FOLDER/ (the level's folder: its scene.lua and every file beside it, with
// FOLDER/finish.replay, a run that reaches its goal) and package.lua, its manifest: every file's
// size and SHA-256 and one hash over them all. writePackage makes one from files already checked;
// readPackage unpacks one into a fresh folder and refuses, before writing a byte outside it,
// anything but regular files and folders under FOLDER/ named plainly, and any file whose size or
// hash is not the manifest's.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace platon::package {

struct PackageFile {
  std::string path;  // inside FOLDER/, with '/' between folders
  uint64_t bytes = 0;
  std::string sha256;  // 64 lower-case hex digits
};

struct PackageManifest {
  int format = 1;
  std::string name;                // the level's name, from its scene.lua
  std::string folder;              // where it installs: a plain name (letters, digits, - and _)
  std::vector<PackageFile> files;  // sorted by path; finish.replay among them
  std::string hash;                // SHA-256 over every file's path, size and hash, in order
};

// What a package may hold: a file at most kMaxFileBytes, at most kMaxFiles files and kMaxTotalBytes
// in all (a package that unpacks to more is refused as it unpacks, not after).
inline constexpr uint64_t kMaxFileBytes = uint64_t{64} << 20;
inline constexpr uint64_t kMaxTotalBytes = uint64_t{256} << 20;
inline constexpr size_t kMaxFiles = 1000;

class PackageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether `name` is a folder name a package may install to.
bool plainName(const std::string& name);
// The manifest's hash of its files (PackageManifest::hash).
std::string manifestHash(const std::vector<PackageFile>& files);
std::string sha256Hex(const std::string& bytes);

// Writes `out` (a .platon file) from `root`/`folder`/: every regular file under it (a link or any
// other kind of file is an error), with the manifest. Throws PackageError.
PackageManifest writePackage(const std::string& root, const std::string& folder, const std::string& name,
                             const std::string& out);

// Unpacks `archive` into `into` (a folder that must not exist yet; made here): FOLDER/ and its
// files. Throws PackageError naming the archive and what is wrong; nothing is left in `into` then.
PackageManifest readPackage(const std::string& archive, const std::string& into);

// Removes from a level's folder (staged to be packed, or unpacked to be installed) every file a
// package does not carry: what is neither data a level is made of (.level, .replay, the mesh
// formats and the files they name, .txt, .md) nor Lua its scene.lua loads (its scripts, mods and
// sound bank; scene.lua itself). Returns each one's path inside the folder and why, sorted. Throws
// (std::runtime_error, file:line:column) if scene.lua cannot be read.
std::vector<std::string> removeUncarriedFiles(const std::string& levelFolder);

// The manifest's text (package.lua, a Lua table literal) and its reader.
std::string manifestText(const PackageManifest& manifest);
PackageManifest parseManifest(const std::string& text, const std::string& file);

}  // namespace platon::package
