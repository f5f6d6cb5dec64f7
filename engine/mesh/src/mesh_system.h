// The meshes system: a mesh reader for the scene's stage (core::MeshSource) and nothing per frame.
#pragma once
#include "platon/core/mesh_source.h"
#include "platon/core/system.h"

namespace platon::mesh {

class MeshSystem final : public core::System, public core::MeshSource {
 public:
  core::MeshSource* meshSource() override { return this; }
  core::MeshFile loadMesh(const std::string& path) override;
};

}  // namespace platon::mesh
