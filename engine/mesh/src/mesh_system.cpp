#include "mesh_system.h"

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "folder_io.h"
#include "platon/files/read_file.h"

namespace platon::mesh {
namespace {

using Transform = std::array<std::array<double, 4>, 4>;  // row-major, acting on column vectors

// The most corners one polygon of a mesh file may have. A face of a stage is one polygon of the
// solid, and a solid's face with more corners than this is no level anyone draws; the cap is what
// keeps assimp's split of a polygon into triangles (quadratic or worse in its corners) short.
constexpr unsigned kMaxPolygonCorners = 1024;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw std::runtime_error(path + ": " + reason);
}

Transform identity() {
  Transform t{};
  for (int i = 0; i < 4; ++i) t[size_t(i)][size_t(i)] = 1;
  return t;
}

// parent * node's own matrix, in double (assimp keeps node matrices as floats).
Transform compose(const Transform& parent, const aiMatrix4x4& m) {
  const float own[4][4] = {
      {m.a1, m.a2, m.a3, m.a4}, {m.b1, m.b2, m.b3, m.b4}, {m.c1, m.c2, m.c3, m.c4}, {m.d1, m.d2, m.d3, m.d4}};
  Transform out{};
  for (size_t i = 0; i < 4; ++i)
    for (size_t j = 0; j < 4; ++j)
      for (size_t k = 0; k < 4; ++k) out[i][j] += parent[i][k] * double(own[k][j]);
  return out;
}

double determinant3(const Transform& t) {
  return t[0][0] * (t[1][1] * t[2][2] - t[1][2] * t[2][1]) - t[0][1] * (t[1][0] * t[2][2] - t[1][2] * t[2][0]) +
         t[0][2] * (t[1][0] * t[2][1] - t[1][1] * t[2][0]);
}

// Refuses a file too big to be a stage before assimp reads it: over the size cap, or a binary STL
// whose header counts more triangles than a stage takes. The file is read through the file layer
// (a regular file, capped) as assimp will read it.
void checkBeforeReading(const std::string& folder, const std::string& name, const std::string& path) {
  std::string bytes;
  try {
    bytes = files::readFileInside(folder, name, core::kMaxMeshFileBytes);
  } catch (const files::FileError& e) {
    fail(path, e.reason());
  }
  if (bytes.size() < 84) return;
  uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  const bool binaryStl = bytes.size() == 84 + 50 * uint64_t{count};
  if (binaryStl && count > core::kMaxMeshFileTriangles)
    fail(path, "the file has " + std::to_string(count) + " triangles; a stage takes at most " +
                   std::to_string(core::kMaxMeshFileTriangles));
}

// The formats a stage's mesh may be (and a package carries): assimp reads dozens more, some of
// them archives it unpacks itself (3MF, Quake's .pk3), which no level needs.
void checkKind(const std::string& name, const std::string& path) {
  std::string ending = name.substr(std::min(name.size(), name.find_last_of('.')));
  std::transform(ending.begin(), ending.end(), ending.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* kind : {".obj", ".gltf", ".glb", ".ply", ".stl"})
    if (ending == kind) return;
  fail(path, "a stage's mesh is an OBJ, glTF, PLY or STL file (.obj, .gltf, .glb, .ply, .stl)");
}

// Refuses polygons a stage cannot take before assimp splits them into triangles (its split of an
// n-cornered polygon takes time that grows as n squared or worse): every polygon of at most
// kMaxPolygonCorners, and no more triangles in all than a stage takes.
void checkPolygons(const aiScene& scene, const std::string& path) {
  uint64_t triangles = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const unsigned corners = mesh.mFaces[f].mNumIndices;
      if (corners > kMaxPolygonCorners)
        fail(path, "a polygon of " + std::to_string(corners) + " corners; a stage's mesh takes polygons of at most " +
                       std::to_string(kMaxPolygonCorners));
      if (corners >= 3) triangles += corners - 2;
    }
  }
  if (triangles > core::kMaxMeshFileTriangles)
    fail(path, "the file makes " + std::to_string(triangles) + " triangles; a stage takes at most " +
                   std::to_string(core::kMaxMeshFileTriangles));
}

// Each mesh the node tree places, with the node's accumulated transform applied in double
// precision (assimp's aiProcess_PreTransformVertices skips transforms within 1% of identity).
class Flattener {
 public:
  explicit Flattener(const aiScene& scene) : scene_(scene) {}

  void add(const aiNode& node, const Transform& parent) {
    const Transform t = compose(parent, node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) place(*scene_.mMeshes[node.mMeshes[i]], t);
    for (unsigned c = 0; c < node.mNumChildren; ++c) add(*node.mChildren[c], t);
  }
  core::MeshFile take() { return std::move(out_); }
  size_t triangles() const { return out_.triangles.size() / 3; }

 private:
  void place(const aiMesh& mesh, const Transform& t) {
    const auto base = static_cast<int32_t>(out_.positions.size() / 3);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const double p[3] = {mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z};
      for (size_t r = 0; r < 3; ++r)
        out_.positions.push_back(t[r][0] * p[0] + t[r][1] * p[1] + t[r][2] * p[2] + t[r][3]);
    }
    const bool mirrored = determinant3(t) < 0;  // a mirroring node turns the winding over: turn it back
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines: not part of a surface
      const unsigned order[3] = {0, mirrored ? 2u : 1u, mirrored ? 1u : 2u};
      for (const unsigned k : order) out_.triangles.push_back(base + static_cast<int32_t>(face.mIndices[k]));
    }
  }

  const aiScene& scene_;
  core::MeshFile out_;
};

}  // namespace

core::MeshFile MeshSystem::loadMesh(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  checkKind(name, path);
  checkBeforeReading(folder, name, path);
  Assimp::Importer importer;
  auto* io = new FolderIO(folder, core::kMaxMeshFileBytes, 3 * core::kMaxMeshFileBytes);
  importer.SetIOHandler(io);  // the importer owns it
  // Read as the file has it, checked, then polygons split into triangles, nothing else: no joining
  // of points (assimp's is within an absolute 1e-5, which collapses small models;
  // polyhedronFromMesh welds relative to the size), no dropping of degenerate triangles (the stage
  // builder says what it does with them).
  const aiScene* scene = importer.ReadFile(slash == std::string::npos ? folder + "/" + name : path, 0);
  if (!io->refusals().empty()) fail(path, "it names a file it may not read: " + io->refusals().front());
  if (!scene) fail(path, importer.GetErrorString());
  checkPolygons(*scene, path);
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene) fail(path, importer.GetErrorString());
  if (!scene->mRootNode) fail(path, "the file places no mesh (it has no nodes)");
  Flattener flat(*scene);
  flat.add(*scene->mRootNode, identity());
  if (flat.triangles() == 0) fail(path, "the file holds no triangles");
  if (flat.triangles() > core::kMaxMeshFileTriangles)
    fail(path, "the file has " + std::to_string(flat.triangles()) + " triangles; a stage takes at most " +
                   std::to_string(core::kMaxMeshFileTriangles));
  return flat.take();
}

}  // namespace platon::mesh
