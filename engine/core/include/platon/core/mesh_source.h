// Mesh files as the meshes plugin (engine/mesh, libplaton_meshes.so) reads them: points and
// triangles, plain data, so that the engine needs no mesh library and the plugin no engine code.
// stage::polyhedronFromMesh turns them into a solid.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace platon::core {

// What a mesh file may hold: the meshes plugin refuses a bigger file before reading it whole (the
// stage builder's own cap, stage::kMaxMeshTriangles, is the same number).
inline constexpr size_t kMaxMeshFileBytes = size_t{64} << 20;
inline constexpr size_t kMaxMeshFileTriangles = 100000;

struct MeshFile {
  std::vector<double> positions;   // x, y, z of each point
  std::vector<int32_t> triangles;  // three point indices each, counter-clockwise seen from outside
};

class MeshSource {
 public:
  virtual ~MeshSource() = default;
  // Reads every mesh the file's node tree places, with each node's accumulated transform applied
  // (in double precision), points as the file has them (not joined). Throws std::runtime_error
  // "path: reason" for a file that cannot be read, holds no triangles or is over the caps above.
  virtual MeshFile loadMesh(const std::string& path) = 0;
};

}  // namespace platon::core
