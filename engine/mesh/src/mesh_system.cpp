#include "mesh_system.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <stdexcept>

namespace platon::mesh {

core::MeshFile MeshSystem::loadMesh(const std::string& path) {
  Assimp::Importer importer;
  // Node transforms baked in (one mesh in the level's space), polygons split into triangles, and
  // points that files repeat per triangle (STL) joined; the stage builder welds what is left.
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                aiProcess_SortByPType | aiProcess_FindDegenerates);
  if (!scene) throw std::runtime_error(path + ": " + importer.GetErrorString());
  core::MeshFile out;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const auto base = static_cast<int32_t>(out.positions.size() / 3);
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      for (const float c : {mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z}) out.positions.push_back(c);
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines: not part of a surface
      for (unsigned k = 0; k < 3; ++k) out.triangles.push_back(base + static_cast<int32_t>(face.mIndices[k]));
    }
  }
  if (out.triangles.empty()) throw std::runtime_error(path + ": the file holds no triangles");
  return out;
}

}  // namespace platon::mesh
