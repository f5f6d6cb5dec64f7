// Mesh stages: mesh files in four formats read by the meshes system (assimp) make the same solid;
// broken meshes are refused with what is wrong; the shipped mesh levels check clean. (That the
// plugin is mapped only by a process playing a mesh level is script_tests' MeshPlugin test: this
// program links assimp itself.)
#include "platon/stage/mesh.h"

#include <algorithm>
#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "../stage/test_meshes.h"
#include "mesh_files.h"
#include "mesh_system.h"
#include "platon/core/scene.h"
#include "platon/script/scenario.h"
#include "platon/stage/level_check.h"

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
    for (const auto& face : p.faces)
      (face.size() == 3 ? triangles : rectangles) += face.size() == 3 || face.size() == 4;
    EXPECT_EQ(triangles, 2);
    EXPECT_EQ(rectangles, 3);
    stages.push_back(stage::stageFromPolyhedron(p));
  }
  for (const stage::Stage& s : stages)
    for (size_t f = 0; f < s.faceCount(); ++f)
      EXPECT_EQ(s.faces[f].corners, stages[0].faces[f].corners) << "face " << f;
  EXPECT_EQ(stages[0].faces[0].corners[1].x, 6144);  // face 0 is a long side: the longest edge is 6144
}

TEST(MeshFiles, TheFootballHasTwelvePentagonsAndTwentyHexagons) {
  const stage::Polyhedron p = stage::polyhedronFromMesh(
      read(std::string(PLATON_SOURCE_ROOT) + "/levels/soccer_ball/truncated_icosahedron.ply"), 2048);
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
  EXPECT_NE(refusal(kData + "open_box.obj").find("open mesh: the edge"), std::string::npos)
      << refusal(kData + "open_box.obj");
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
    EXPECT_TRUE(report.errors.empty()) << name << ": " << (report.errors.empty() ? "" : report.errors[0].message);
    EXPECT_EQ(stage::parseLevel(stage::writeLevel(level), path), level);
  }
}

// A mesh level whose manifest does not list "meshes" is refused, naming the fix.
TEST(MeshPlugin, AMeshLevelNeedsTheMeshesSystem) {
  const std::string dir = ::testing::TempDir() + "mesh_manifest";
  std::system(
      ("mkdir -p " + dir + " && cp " + std::string(PLATON_SOURCE_ROOT) + "/levels/prism/prism.* " + dir).c_str());
  std::ofstream(dir + "/scene.lua") << "return { stage = { level = 'prism.level' } }\n";
  core::SystemRegistry registry;
  try {
    core::loadScene(dir + "/scene.lua", registry);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& e) {
    EXPECT_EQ(
        std::string(e.what()),
        dir +
            "/prism.level:1:1: the level is drawn on a mesh: the scene's manifest must list \"meshes\" in its systems");
  }
}

std::string scratch(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "mesh_files/";
  std::filesystem::create_directories(dir);
  return dir + name;
}

stage::Stage stageOfFile(const std::string& path) {
  return stage::stageFromPolyhedron(stage::polyhedronFromMesh(read(path), 4096));
}

// The same faces, numbered alike, with the same floors (corners within `slack` units) and the
// same placement in 3D.
void expectSameStage(const stage::Stage& a, const stage::Stage& b, int slack = 0) {
  ASSERT_EQ(a.faceCount(), b.faceCount());
  for (size_t f = 0; f < a.faceCount(); ++f) {
    SCOPED_TRACE("face " + std::to_string(f));
    ASSERT_EQ(a.faces[f].corners.size(), b.faces[f].corners.size());
    for (size_t i = 0; i < a.faces[f].corners.size(); ++i) {
      EXPECT_LE(std::abs(a.faces[f].corners[i].x - b.faces[f].corners[i].x), slack);
      EXPECT_LE(std::abs(a.faces[f].corners[i].y - b.faces[f].corners[i].y), slack);
      EXPECT_EQ(a.faces[f].neighbours[i].face, b.faces[f].neighbours[i].face);
      EXPECT_EQ(a.faces[f].neighbours[i].edge, b.faces[f].neighbours[i].edge);
    }
    EXPECT_LT((a.faces[f].normal - b.faces[f].normal).norm(), 1e-6);
    EXPECT_LT((a.faces[f].xAxis - b.faces[f].xAxis).norm(), 1e-6);
  }
}

bool sameFrames(const stage::Stage& a, const stage::Stage& b) {
  if (a.faceCount() != b.faceCount()) return false;
  for (size_t f = 0; f < a.faceCount(); ++f)
    if ((a.faces[f].normal - b.faces[f].normal).norm() > 1e-6 || a.faces[f].corners != b.faces[f].corners) return false;
  return true;
}

testfiles::Node turn(double radians, const Eigen::Vector3d& axis, bool asMatrix = false) {
  testfiles::Node n;
  n.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(radians, axis));
  n.asMatrix = asMatrix;
  return n;
}

testfiles::Node scaled(const Eigen::Vector3d& s, bool asMatrix = false) {
  testfiles::Node n;
  n.scale = s;
  n.asMatrix = asMatrix;
  return n;
}

// A glTF mesh under nodes that tilt it by a hundredth of a radian or less, scale it by 1% or less,
// nest, shift and mirror it: the same stage as the same mesh with the transforms written into its
// points (and not the stage of the untransformed mesh). assimp's own pre-transform step skipped
// any node within 1% of identity.
TEST(MeshFiles, NodeTransformsApplyHoweverSmall) {
  const stage::MeshData box = testmesh::box({1, 0.7, 0.45});
  const stage::Stage plain = stageOfFile((testfiles::writeObj(box, scratch("plain.obj")), scratch("plain.obj")));
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  std::vector<std::vector<testfiles::Node>> chains;
  for (const bool matrix : {false, true}) {
    for (const double a : {0.001, 0.01, -0.01, 0.02})
      for (const auto& axis : {x, y, z}) chains.push_back({turn(a, axis, matrix)});
    for (const Eigen::Vector3d& s :
         {Eigen::Vector3d(0.99, 1, 1), Eigen::Vector3d(1, 1.006, 1), Eigen::Vector3d(1, 1, 0.992),
          Eigen::Vector3d(1.01, 0.995, 1.003), Eigen::Vector3d(-1, 1, 1)})
      chains.push_back({scaled(s, matrix)});
    testfiles::Node shift = turn(0.005, y, matrix);
    shift.translation = {0.3, -0.2, 5};
    chains.push_back({turn(0.01, x, matrix), scaled({1.008, 1, 1}, !matrix), shift});
  }
  for (size_t i = 0; i < chains.size(); ++i) {
    SCOPED_TRACE("chain " + std::to_string(i));
    testfiles::writeGltf(box, chains[i], scratch("node.gltf"));
    testfiles::writeObj(testfiles::baked(box, chains[i]), scratch("baked.obj"));
    const stage::Stage fromNodes = stageOfFile(scratch("node.gltf"));
    expectSameStage(fromNodes, stageOfFile(scratch("baked.obj")), 1);
    const bool mirrorOnly = chains[i].size() == 1 && chains[i][0].scale.x() < 0;  // the box is symmetric
    if (!mirrorOnly) {
      EXPECT_FALSE(sameFrames(fromNodes, plain)) << "the transform was dropped";
    }
  }
}

// A box of any size from a millionth of a unit to a million units (points shared, or repeated per
// triangle as STL files do) makes the same stage: points are welded relative to the mesh's size.
TEST(MeshFiles, TinyAndHugeMeshesMakeTheSameStage) {
  for (const Eigen::Vector3d& half : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 0.7, 0.45)})
    for (int e = -6; e <= 6; ++e) {
      const stage::MeshData box = testmesh::box(half);
      testfiles::writeObj(box, scratch("unit.obj"));
      const stage::Stage unit = stageOfFile(scratch("unit.obj"));
      SCOPED_TRACE("scale 1e" + std::to_string(e) + ", depth " + std::to_string(half.z()));
      stage::MeshData m = box, loose;
      for (auto& p : m.positions) p *= std::pow(10.0, e);
      for (const auto& t : m.triangles) {
        const int base = int(loose.positions.size());
        for (const int v : t) loose.positions.push_back(m.positions[size_t(v)]);
        loose.triangles.push_back({base, base + 1, base + 2});
      }
      testfiles::writeObj(m, scratch("scaled.obj"));
      testfiles::writeObj(loose, scratch("loose.obj"));
      expectSameStage(stageOfFile(scratch("scaled.obj")), unit);
      expectSameStage(stageOfFile(scratch("loose.obj")), unit);
      std::ofstream quads(scratch("quads.obj"));  // the box's faces as quads, for assimp to split
      for (size_t v = 0; v < 8; ++v)
        quads << "v " << m.positions[v].x() << " " << m.positions[v].y() << " " << m.positions[v].z() << "\n";
      for (size_t t = 0; t < 12; t += 2)
        quads << "f " << m.triangles[t][0] + 1 << " " << m.triangles[t][1] + 1 << " " << m.triangles[t][2] + 1 << " "
              << m.triangles[t + 1][2] + 1 << "\n";
      quads.close();
      expectSameStage(stageOfFile(scratch("quads.obj")), unit);
    }
}

// A file too big for a stage is refused before assimp reads it: by its size, or by the triangle
// count in a binary STL's header. (Sparse files: nothing is written but the header.)
TEST(MeshFiles, FilesOverTheCapsAreRefusedBeforeReading) {
  const std::string big = scratch("big.obj");
  std::ofstream(big) << "v 0 0 0\n";
  std::filesystem::resize_file(big, (size_t{65} << 20) + 5);
  EXPECT_EQ(refusal(big), big + ": 65 MB, more than the 64 MB such a file may have");
  const std::string stl = scratch("many.stl");
  {
    std::ofstream out(stl, std::ios::binary);
    const char header[80] = "binary";
    out.write(header, 80);
    const uint32_t count = 200000;
    out.write(reinterpret_cast<const char*>(&count), 4);
  }
  std::filesystem::resize_file(stl, 84 + 50 * size_t{200000});
  EXPECT_EQ(refusal(stl), stl + ": the file has 200000 triangles; a stage takes at most 100000");
}

// A glTF node turning a box by any multiple of 90 degrees about the axes (assimp hands the
// rotation over as a float matrix: about 1e-7 of noise) makes the stage of the OBJ with the turn
// written exactly into its points: the same faces, numbers and floors.
TEST(MeshFiles, QuarterTurnNodesMakeTheBakedStage) {
  for (const Eigen::Vector3d& half :
       {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 0.7, 0.45), Eigen::Vector3d(0.5, 1, 0.25)})
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c) {
          SCOPED_TRACE("turns " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c));
          const stage::MeshData box = testmesh::box(half);
          testfiles::Node node;
          node.rotation = Eigen::AngleAxisd(c * M_PI / 2, Eigen::Vector3d::UnitZ()) *
                          Eigen::AngleAxisd(b * M_PI / 2, Eigen::Vector3d::UnitY()) *
                          Eigen::AngleAxisd(a * M_PI / 2, Eigen::Vector3d::UnitX());
          stage::MeshData exact = box;
          const Eigen::Matrix3d turn = node.rotation.toRotationMatrix().array().round().matrix();
          for (auto& p : exact.positions) p = turn * p;
          testfiles::writeGltf(box, {node}, scratch("turned.gltf"));
          testfiles::writeObj(exact, scratch("turned.obj"));
          expectSameStage(stageOfFile(scratch("turned.gltf")), stageOfFile(scratch("turned.obj")));
        }
}

// A level's mesh must be a regular file inside the level's folder once symbolic links are
// followed: a link to a file elsewhere, to /dev/zero or to /etc/passwd is refused, naming where it
// leads; links and subfolders that stay inside are fine.
TEST(MeshFiles, TheMeshMustStayInTheLevelsFolder) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(::testing::TempDir()) / "mesh_folder";
  fs::remove_all(root);
  fs::create_directories(root / "level" / "meshes");
  testfiles::writeObj(testmesh::box({1, 0.7, 0.45}), (root / "outside.obj").string());
  testfiles::writeObj(testmesh::box({1, 0.7, 0.45}), (root / "level" / "meshes" / "box.obj").string());
  fs::create_symlink(root / "outside.obj", root / "level" / "out.obj");
  fs::create_symlink("/dev/zero", root / "level" / "zero.obj");
  fs::create_symlink("/etc/passwd", root / "level" / "passwd.obj");
  fs::create_symlink("meshes/box.obj", root / "level" / "inside.obj");
  fs::create_symlink(root / "level" / "meshes", root / "level" / "linked");
  const std::string file = (root / "level" / "l.level").string(), folder = (root / "level").string() + "/";
  auto load = [&](const std::string& mesh) -> std::string {
    std::string text = "MESH " + mesh + "\n0 1000 1000\n0 2000 2000\n4096\n";
    for (int f = 0; f < 6; ++f) text += "%\n";
    mesh::MeshSystem reader;
    try {
      (void)core::meshStageOf(stage::parseLevel(text, file), reader);
    } catch (const stage::StageError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_EQ(load("meshes/box.obj"), "(accepted)");
  EXPECT_EQ(load("inside.obj"), "(accepted)");
  EXPECT_EQ(load("linked/box.obj"), "(accepted)");
  EXPECT_EQ(load("out.obj"), file + ":1:6: " + folder + "out.obj: the mesh file leads out of the level's folder (to " +
                                 (root / "outside.obj").string() + "): it must be a file in that folder");
  EXPECT_EQ(
      load("zero.obj"),
      file + ":1:6: " + folder +
          "zero.obj: the mesh file leads out of the level's folder (to /dev/zero): it must be a file in that folder");
  EXPECT_EQ(load("passwd.obj"), file + ":1:6: " + folder +
                                    "passwd.obj: the mesh file leads out of the level's folder (to /etc/passwd): it "
                                    "must be a file in that folder");
  EXPECT_EQ(load("meshes"),
            file + ":1:6: " + folder + "meshes: the mesh file (" + folder + "meshes): not a regular file (a folder)");
  EXPECT_EQ(load("nowhere.obj"), file + ":1:6: " + folder + "nowhere.obj: cannot find the mesh file");
  fs::create_symlink("/dev/zero", root / "level" / "meshes" / "zero.obj");  // a link in a subfolder
  EXPECT_NE(load("meshes/zero.obj").find("leads out of the level's folder (to /dev/zero)"), std::string::npos);
  // The MESH line where it is: after comments and blank lines, indented, the name's own column.
  for (const std::string before : {"# a level\n# on a box\n", "\n\n   ", "# one\n\n  # two\n\t"}) {
    std::string text = before + "MESH   nowhere.obj\n0 1000 1000\n0 2000 2000\n4096\n";
    for (int f = 0; f < 6; ++f) text += "%\n";
    const stage::Level level = stage::parseLevel(text, file);
    const int line = 1 + static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    const size_t lastLine = before.find_last_of('\n');
    const int column = static_cast<int>(before.size() - (lastLine == std::string::npos ? 0 : lastLine + 1)) + 8;
    mesh::MeshSystem reader;
    try {
      (void)core::meshStageOf(level, reader);
      ADD_FAILURE() << "a missing mesh was accepted";
    } catch (const stage::StageError& e) {
      EXPECT_EQ(std::string(e.what()), file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                                           folder + "nowhere.obj: cannot find the mesh file")
          << before;
    }
  }
}

}  // namespace

namespace {

namespace fs = std::filesystem;

// A folder of meshes naming other files, with things to name inside it and outside it.
struct Referencing {
  fs::path root = fs::path(::testing::TempDir()) / ("mesh_references_" + std::to_string(getpid()));
  fs::path level = root / "level";
  Referencing() {
    fs::remove_all(root);
    fs::create_directories(level / "dir.mtl");
    std::ofstream(root / "outside.mtl") << "newmtl m\nKd 1 0 0\n";
    std::ofstream(level / "good.mtl") << "newmtl m\nKd 0 1 0\n";
    fs::create_symlink(root / "outside.mtl", level / "link_out.mtl");
    fs::create_symlink("/dev/zero", level / "zero.mtl");
    mkfifo((level / "fifo.mtl").c_str(), 0644);
    mkfifo((root / "fifo_out.mtl").c_str(), 0644);
    mkfifo((level / "fifo.bin").c_str(), 0644);
  }
  ~Referencing() { fs::remove_all(root); }
  // The load's refusal ("(accepted)" when it loads); a load that blocks fails the test instead of
  // hanging it: after 30 s every FIFO is opened for writing and closed, which ends the read.
  std::string load(const std::string& file) const {
    auto loading = std::async(std::launch::async, [file] { return refusal(file); });
    if (loading.wait_for(std::chrono::seconds(30)) == std::future_status::timeout) {
      for (const fs::path& fifo : {level / "fifo.mtl", root / "fifo_out.mtl", level / "fifo.bin"}) {
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
      }
      ADD_FAILURE() << file << ": the load blocked for 30 s";
    }
    return loading.get();
  }
};

}  // namespace

// assimp opens what a mesh names by itself (an OBJ's material library): only a regular file inside
// the mesh's folder may be read. Every other name is refused, the whole mesh with it, naming it:
// "..", a link out, /dev/zero, a FIFO inside or out (which blocked assimp for ever), a folder. An
// absolute name is looked for inside the folder. A library inside loads; a missing one is assimp's
// warning, not a refusal.
TEST(MeshFiles, AnObjReadsOnlyMaterialLibrariesInsideItsFolder) {
  const Referencing r;
  const std::string prism = [] {
    std::ifstream in(kData + "prism.obj");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  const std::pair<std::string, std::string> cases[] = {
      {"good.mtl", "(accepted)"},
      {"missing.mtl", "(accepted)"},
      {"../outside.mtl", "leads out of its folder"},
      // an absolute name is looked for inside the folder, so a FIFO outside is never opened (it
      // would be refused as a FIFO), and the library is missing
      {(r.root / "fifo_out.mtl").string(), "(accepted)"},
      {"link_out.mtl", "leads out of its folder"},
      {"zero.mtl", "leads out of its folder"},
      {"fifo.mtl", "not a regular file (a FIFO)"},
      {"../fifo_out.mtl", "leads out of its folder"},
      {"dir.mtl", "not a regular file (a folder)"},
  };
  for (const auto& [library, expected] : cases) {
    SCOPED_TRACE(library);
    const std::string file = (r.level / "prism.obj").string();
    std::ofstream(file) << "mtllib " << library << "\nusemtl m\n" << prism;
    const std::string why = r.load(file);
    EXPECT_NE(why.find(expected), std::string::npos) << why;
    if (expected != "(accepted)") {
      EXPECT_NE(why.find("it names a file it may not read"), std::string::npos) << why;
    }
  }
}

// The same for a glTF's buffer: the bytes of its points come only from inside its folder.
TEST(MeshFiles, AGltfReadsOnlyBuffersInsideItsFolder) {
  const Referencing r;
  const std::pair<std::string, std::string> cases[] = {
      {"good.bin", "(accepted)"},
      {"../outside.bin", "leads out of its folder"},
      {(r.root / "outside.bin").string(), "could not open referenced file"},
      {"fifo.bin", "not a regular file (a FIFO)"},
  };
  for (const auto& [uri, expected] : cases) {
    SCOPED_TRACE(uri);
    const std::string file = (r.level / "box.gltf").string();
    std::string buffer;
    testfiles::writeGltf(testmesh::box({1, 0.7, 0.45}), {}, file, uri, &buffer);
    std::ofstream(r.level / "good.bin", std::ios::binary) << buffer;
    std::ofstream(r.root / "outside.bin", std::ios::binary) << buffer;
    const std::string why = r.load(file);
    EXPECT_NE(why.find(expected), std::string::npos) << why;
  }
}

// A polygon is split into triangles by assimp in time that grows as its corners squared or worse:
// one of 90,000 corners (under the cap of triangles) is refused before it is split, at once.
TEST(MeshFiles, APolygonWithTooManyCornersIsRefusedBeforeItIsSplit) {
  for (const int corners : {1025, 90000}) {
    SCOPED_TRACE(corners);
    std::string text;
    for (int i = 0; i < corners; ++i) {
      const double a = 2 * M_PI * i / corners;
      text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    text += "v 0 0 1\nf";
    for (int i = corners; i >= 1; --i) text += " " + std::to_string(i);
    text += "\n";
    const std::string file = scratch("many_corners.obj");
    std::ofstream(file) << text;
    EXPECT_EQ(refusal(file), file + ": a polygon of " + std::to_string(corners) +
                                 " corners; a stage's mesh takes polygons of at most 1024");
  }
}

// A mesh is one of the four formats a stage takes (assimp reads dozens, some of them archives it
// unpacks itself), and what assimp reads for it in all is bounded: an OBJ naming one 20 MB material
// library 10,000 times is refused once the reads pass the bound (it read 200 GB before).
TEST(MeshFiles, OnlyTheStagesFormatsAndABoundedReadInAll) {
  const Referencing r;
  const std::string prism = [] {
    std::ifstream in(kData + "prism.obj");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  for (const char* name : {"prism.dae", "prism.3mf", "prism.pk3", "prism", "prism.OBJ.zip"}) {
    SCOPED_TRACE(name);
    std::ofstream(r.level / name) << prism;
    EXPECT_NE(refusal((r.level / name).string()).find("a stage's mesh is an OBJ, glTF, PLY or STL file"),
              std::string::npos);
  }
  std::ofstream(r.level / "PRISM.OBJ") << prism;  // the ending in capitals is the same kind
  EXPECT_EQ(refusal((r.level / "PRISM.OBJ").string()), "(accepted)");
  {
    std::ofstream big(r.level / "big.mtl");
    big << "newmtl m\nKd 1 0 0\n";
    for (int i = 0; i < 20 << 16; ++i) big << "# padding\n";  // about 20 MB
  }
  std::string text;
  for (int i = 0; i < 10000; ++i) text += "mtllib big.mtl\n";
  std::ofstream(r.level / "many.obj") << text << prism;
  const std::string why = r.load((r.level / "many.obj").string());
  EXPECT_NE(why.find("come to more than 192 MB read"), std::string::npos) << why;
}
