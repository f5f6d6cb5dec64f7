// Mesh stages: mesh files in four formats read by the meshes system (assimp) make the same solid;
// broken meshes are refused with what is wrong; the shipped mesh levels check clean. (That the
// plugin is mapped only by a process playing a mesh level is script_tests' MeshPlugin test: this
// program links assimp itself.)
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "mesh_system.h"
#include "platon/core/scene.h"
#include "platon/script/scenario.h"
#include "platon/stage/level_check.h"
#include "platon/stage/mesh.h"

using namespace platon;

namespace {

const std::string kData = std::string(PLATON_SOURCE_ROOT) + "/tests/data/meshes/";

stage::MeshData read(const std::string& path) {
  mesh::MeshSystem reader;
  return core::meshDataOf(reader.loadMesh(path));
}

std::string refusal(const std::string& path) {
  try {
    stage::polyhedronFromMesh(read(path), 4096);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(MeshFiles, FourFormatsMakeTheSamePrism) {  // and the shipped level's PLY is that prism too
  const std::string files[] = {kData + "prism.obj", kData + "prism.stl", kData + "prism.ply", kData + "prism.gltf",
                               std::string(PLATON_SOURCE_ROOT) + "/levels/prism/prism.ply"};
  std::vector<stage::Stage> stages;
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    const stage::Polyhedron p = stage::polyhedronFromMesh(read(f), 6144);
    ASSERT_EQ(p.faces.size(), 5u);
    int triangles = 0, rectangles = 0;
    for (const auto& face : p.faces) (face.size() == 3 ? triangles : rectangles) += face.size() == 3 || face.size() == 4;
    EXPECT_EQ(triangles, 2);
    EXPECT_EQ(rectangles, 3);
    stages.push_back(stage::stageFromPolyhedron(p));
  }
  for (const stage::Stage& s : stages)
    for (size_t f = 0; f < s.faceCount(); ++f) EXPECT_EQ(s.faces[f].corners, stages[0].faces[f].corners) << "face " << f;
  EXPECT_EQ(stages[0].faces[0].corners[1].x, 6144);  // face 0 is a long side: the longest edge is 6144
}

TEST(MeshFiles, TheFootballHasTwelvePentagonsAndTwentyHexagons) {
  const stage::Polyhedron p =
      stage::polyhedronFromMesh(read(std::string(PLATON_SOURCE_ROOT) + "/levels/soccer_ball/truncated_icosahedron.ply"), 2048);
  int pentagons = 0, hexagons = 0;
  for (const auto& face : p.faces) pentagons += face.size() == 5, hexagons += face.size() == 6;
  EXPECT_EQ(pentagons, 12);
  EXPECT_EQ(hexagons, 20);
  physics::World world;
  stage::Stage s = stage::stageFromPolyhedron(p);
  stage::addStageToWorld(s, world, 0);
  for (size_t f = 0; f < s.faceCount(); ++f) world.mapPart(s.part(f)).initialize();
  EXPECT_EQ(world.mapPart(0).faceLoop().size(), s.faces[0].corners.size());
}

TEST(MeshFiles, BrokenMeshesAreRefusedWithWhatIsWrong) {
  EXPECT_NE(refusal(kData + "open_box.obj").find("open mesh: the edge"), std::string::npos) << refusal(kData + "open_box.obj");
  EXPECT_NE(refusal(kData + "l_prism.obj").find("not convex"), std::string::npos) << refusal(kData + "l_prism.obj");
  const std::string junk = refusal(kData + "not_a_mesh.obj");
  EXPECT_EQ(junk.rfind(kData + "not_a_mesh.obj: ", 0), 0u) << junk;
  const std::string missing = refusal(kData + "nowhere.obj");
  EXPECT_EQ(missing.rfind(kData + "nowhere.obj: ", 0), 0u) << missing;
}

TEST(MeshFiles, TheShippedMeshLevelsCheckClean) {
  mesh::MeshSystem reader;
  for (const char* name : {"prism/prism.level", "soccer_ball/soccer_ball.level"}) {
    const std::string path = std::string(PLATON_SOURCE_ROOT) + "/levels/" + name;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const stage::Level level = stage::parseLevel(text.str(), path);
    const stage::Stage s = core::meshStageOf(level, reader);
    const stage::CheckReport report = stage::checkLevel(level, s);
    EXPECT_TRUE(report.errors.empty()) << name;
    EXPECT_EQ(stage::parseLevel(stage::writeLevel(level), path), level);
  }
}

// A mesh level whose manifest does not list "meshes" is refused, naming the fix.
TEST(MeshPlugin, AMeshLevelNeedsTheMeshesSystem) {
  const std::string dir = ::testing::TempDir() + "mesh_manifest";
  std::system(("mkdir -p " + dir + " && cp " + std::string(PLATON_SOURCE_ROOT) + "/levels/prism/prism.* " + dir).c_str());
  std::ofstream(dir + "/scene.lua") << "return { stage = { level = 'prism.level' } }\n";
  core::SystemRegistry registry;
  try {
    core::loadScene(dir + "/scene.lua", registry);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/prism.level:1:1: the level is drawn on a mesh: the scene's manifest must list \"meshes\" in its systems");
  }
}

}  // namespace
