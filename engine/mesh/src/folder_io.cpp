#include "folder_io.h"

#include <assimp/MemoryIOWrapper.h>
#include <cerrno>
#include <cstring>

#include "platon/files/read_file.h"

namespace platon::mesh {
namespace {

// A file's bytes, owned by the stream assimp reads them from (a base before MemoryIOStream, so
// they are there when it is made).
struct Owned {
  std::string bytes;
};
class BytesStream : private Owned, public Assimp::MemoryIOStream {
 public:
  explicit BytesStream(std::string contents)
      : Owned{std::move(contents)},
        MemoryIOStream(reinterpret_cast<const uint8_t*>(Owned::bytes.data()), Owned::bytes.size()) {}
};

}  // namespace

std::string FolderIO::inside(const std::string& file) const {
  // assimp joins the mesh's folder to what a file names, and tries other joins of its own when that
  // is not found ("<folder>//<folder>/x", "<folder>//x"): the folder is taken off for as long as the
  // name starts with it, and what is left is a name inside the folder, an absolute one included (it
  // is looked for there, never outside: "/etc/x" is the folder's etc/x).
  std::string name = file;
  while (name.rfind(folder_ + "/", 0) == 0) name.erase(0, folder_.size() + 1);
  name.erase(0, name.find_first_not_of('/'));
  if (name.empty()) refusals_.push_back(file + ": names no file");
  return name;
}

bool FolderIO::read(const std::string& file, std::string& bytes) const {
  // Once anything is refused, the mesh is refused whole: nothing more is read for it (assimp may
  // go on asking, thousands of times).
  if (!refusals_.empty()) return false;
  if (read_ >= maxTotal_) {
    refusals_.push_back(file + ": the mesh and the files it names come to more than " +
                        std::to_string(maxTotal_ >> 20) + " MB read");
    return false;
  }
  const std::string name = inside(file);
  if (name.empty()) return false;
  try {
    bytes = files::readFileInside(folder_, name, maxBytes_);
    read_ += bytes.size();
    if (read_ > maxTotal_) {
      refusals_.push_back(file + ": the mesh and the files it names come to more than " +
                          std::to_string(maxTotal_ >> 20) + " MB read");
      bytes.clear();
      return false;
    }
    return true;
  } catch (const files::FileError& e) {
    // A file that is simply not there is assimp's to report (or to do without: a missing material
    // library is only a warning); anything else is a refusal.
    if (e.reason().find(std::strerror(ENOENT)) == std::string::npos) refusals_.push_back(e.what());
    return false;
  }
}

bool FolderIO::Exists(const char* file) const {
  if (!file || !read(file, keptBytes_)) return false;
  keptName_ = file;
  return true;
}

Assimp::IOStream* FolderIO::Open(const char* file, const char* mode) {
  if (!file || !mode || std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;
  std::string bytes;
  if (keptName_ == file) {
    bytes.swap(keptBytes_);
    keptName_.clear();
  } else if (!read(file, bytes)) {
    return nullptr;
  }
  return new BytesStream(std::move(bytes));
}

void FolderIO::Close(Assimp::IOStream* stream) { delete stream; }

}  // namespace platon::mesh
