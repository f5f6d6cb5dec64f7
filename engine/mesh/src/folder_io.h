// What assimp may open while it reads a mesh: only files inside the mesh's own folder, read whole
// through the engine's file layer (platon/files: regular files only, resolved beneath the folder by
// the kernel, capped before reading) and handed to assimp from memory. assimp opens what a mesh
// names by itself (an OBJ's `mtllib`, a glTF's buffers and images); with its default file system a
// mesh could make it read any file ("../../x", an absolute path, a link) or block on a FIFO for
// ever. Writing is refused.
#pragma once
#include <assimp/IOSystem.hpp>
#include <string>
#include <vector>

namespace platon::mesh {

class FolderIO : public Assimp::IOSystem {
 public:
  // `folder`: the mesh's folder, as the path given to assimp spells it (so the names assimp joins
  // to it are recognised); `maxBytes`: the cap of each file read.
  // `maxTotal`: what all its reads together may come to (assimp may ask for one file many times: an
  // OBJ naming the same library 10,000 times, a glTF whose buffers all name one file).
  FolderIO(std::string folder, size_t maxBytes, size_t maxTotal)
      : folder_(std::move(folder)), maxBytes_(maxBytes), maxTotal_(maxTotal) {}

  bool Exists(const char* file) const override;
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override;
  void Close(Assimp::IOStream* stream) override;

  // What was refused (a name out of the folder, not a regular file, too big), "name: reason" each:
  // a mesh that names such a file is refused whole, with the first of these.
  const std::vector<std::string>& refusals() const { return refusals_; }

 private:
  // The name inside the folder, or "" with a refusal kept.
  std::string inside(const std::string& file) const;
  bool read(const std::string& file, std::string& bytes) const;

  std::string folder_;
  size_t maxBytes_, maxTotal_;
  mutable size_t read_ = 0;
  mutable std::vector<std::string> refusals_;  // Exists is const in assimp's interface
  // The file Exists read last: assimp asks Exists before Open, and a file is read once.
  mutable std::string keptName_, keptBytes_;
};

}  // namespace platon::mesh
