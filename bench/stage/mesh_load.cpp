// Mesh stages of many triangles: geodesic spheres of 1,280 to 81,920 triangles, from mesh data
// to a stage (polyhedronFromMesh + stageFromPolyhedron), and from a binary STL file through the
// meshes system's reader (assimp) to a stage, as a level loads it. Goal: the 20,480-triangle
// sphere in well under a second (it took 2.4 s when every point was tested against every plane).
// Exits 1 when the goal is missed.
//
// Usage: mesh_load [--runs=N]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "mesh_system.h"
#include "platon/core/scene.h"
#include "platon/stage/mesh.h"
#include "platon/stage/stage.h"
#include "spread.h"
#include "test_meshes.h"

using namespace platon;

namespace {

double millisecondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void writeBinaryStl(const stage::MeshData& m, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  const char header[80] = "platon mesh_load";
  out.write(header, 80);
  const auto count = static_cast<uint32_t>(m.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : m.triangles) {
    float record[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) record[3 + 3 * k + c] = static_cast<float>(m.positions[size_t(t[size_t(k)])][c]);
    out.write(reinterpret_cast<const char*>(record), sizeof record);
    out.write("\0\0", 2);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--runs=", 7) == 0) runs = std::atoi(argv[i] + 7);
  mesh::MeshSystem reader;
  bool met = true;
  std::printf("geodesic spheres to stages, %d runs, median (min-max) ms:\n", runs);
  std::printf("  %9s  %22s  %22s\n", "triangles", "mesh data -> stage", "binary STL -> stage");
  for (int levels = 3; levels <= 6; ++levels) {
    const stage::MeshData m = testmesh::icosphere(levels);
    const std::string path = "/tmp/platon_mesh_load_" + std::to_string(getpid()) + ".stl";
    writeBinaryStl(m, path);
    std::vector<double> data, file;
    for (int r = 0; r < runs; ++r) {
      data.push_back(millisecondsOf([&] { (void)stage::stageFromPolyhedron(stage::polyhedronFromMesh(m, 1 << 20)); }));
      file.push_back(millisecondsOf([&] {
        (void)stage::stageFromPolyhedron(stage::polyhedronFromMesh(core::meshDataOf(reader.loadMesh(path)), 1 << 20));
      }));
    }
    std::remove(path.c_str());
    const bench::Spread d = bench::Spread::of(data), f = bench::Spread::of(file);
    std::printf("  %9zu  %22s  %22s\n", m.triangles.size(), d.show("%.1f").c_str(), f.show("%.1f").c_str());
    if (m.triangles.size() == 20480) met = f.high < 1000;
  }
  std::printf("goal: the 20,480-triangle sphere from its file in under 1 s: %s\n", met ? "met in every run" : "MISSED");
  return met ? 0 : 1;
}
