// libFuzzer target: the mesh-to-stage builder, fed mesh data directly (no assimp). Half the inputs
// are raw points and triangles; the other half a Platonic solid's triangles, nudged, shuffled,
// flipped or cut, which reach the merging and convexity code. Any mesh is either refused with a
// StageError, or becomes a stage that builds into a world and carries a body across its faces.
#include <cstdio>
#include <cstdlib>
#include <fuzzer/FuzzedDataProvider.h>
#include <string>

#include "platon/stage/mesh.h"
#include "platon/stage/stage.h"
#include "platon/stage/stage_error.h"

using namespace platon;

namespace {

[[noreturn]] void bug(const std::string& what) {
  std::fprintf(stderr, "BUG: %s\n", what.c_str());
  std::abort();
}

stage::MeshData rawMesh(FuzzedDataProvider& in) {
  stage::MeshData m;
  const int points = in.ConsumeIntegralInRange(0, 40);
  for (int i = 0; i < points; ++i) {
    const double x = in.ConsumeIntegralInRange(-8, 8), y = in.ConsumeIntegralInRange(-8, 8),
                 z = in.ConsumeIntegralInRange(-8, 8);
    m.positions.emplace_back(x, y, z);
  }
  const int triangles = in.ConsumeIntegralInRange(0, 80);
  for (int t = 0; t < triangles; ++t)
    m.triangles.push_back({in.ConsumeIntegralInRange(-1, points), in.ConsumeIntegralInRange(-1, points),
                           in.ConsumeIntegralInRange(-1, points)});
  return m;
}

stage::MeshData solidMesh(FuzzedDataProvider& in) {
  const stage::Polyhedron p = stage::platonicSolid(stage::kSolids[in.ConsumeIntegralInRange(0, 4)], 100);
  stage::MeshData m;
  for (const auto& v : p.vertices) m.positions.push_back(v);
  for (const auto& f : p.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k) m.triangles.push_back({f[0], f[k], f[k + 1]});
  while (in.remaining_bytes() > 0) {
    switch (in.ConsumeIntegralInRange(0, 5)) {
      case 0: {  // nudge a point
        auto& v = m.positions[in.ConsumeIntegralInRange<size_t>(0, m.positions.size() - 1)];
        v[in.ConsumeIntegralInRange(0, 2)] += in.ConsumeFloatingPointInRange(-5.0, 5.0);
        break;
      }
      case 1: {  // flip a triangle
        auto& t = m.triangles[in.ConsumeIntegralInRange<size_t>(0, m.triangles.size() - 1)];
        std::swap(t[1], t[2]);
        break;
      }
      case 2:  // drop a triangle
        if (m.triangles.size() > 1)
          m.triangles.erase(m.triangles.begin() + in.ConsumeIntegralInRange<long>(0, long(m.triangles.size()) - 1));
        break;
      case 3: {  // split a triangle at its centre
        const auto t = m.triangles[in.ConsumeIntegralInRange<size_t>(0, m.triangles.size() - 1)];
        const int c = static_cast<int>(m.positions.size());
        m.positions.push_back((m.positions[size_t(t[0])] + m.positions[size_t(t[1])] + m.positions[size_t(t[2])]) / 3);
        m.triangles.push_back({t[0], t[1], c});
        m.triangles.push_back({t[1], t[2], c});
        m.triangles.push_back({t[2], t[0], c});
        break;
      }
      case 4:  // repeat a point (as STL does) for one corner
        m.positions.push_back(m.positions[size_t(m.triangles[0][0])]);
        m.triangles[0][0] = static_cast<int>(m.positions.size()) - 1;
        break;
      default:  // scale everything
        for (auto& v : m.positions) v *= in.ConsumeFloatingPointInRange(1e-3, 1e3);
        break;
    }
  }
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const bool raw = in.ConsumeBool();
  const double longest = in.ConsumeIntegralInRange(1, 1 << 20);
  const stage::MeshData mesh = raw ? rawMesh(in) : solidMesh(in);
  stage::Stage stage;
  try {
    stage = stage::stageFromPolyhedron(stage::polyhedronFromMesh(mesh, longest));
  } catch (const stage::StageError&) {
    return 0;  // refused: fine
  }
  try {
    physics::World world;
    stage::addStageToWorld(stage, world, 0);
    for (size_t f = 0; f < stage.faceCount(); ++f) {
      world.mapPart(stage.part(f)).setGravity({0, -20000});
      world.mapPart(stage.part(f)).initialize();
      if (world.mapPart(stage.part(f)).faceLoop().empty()) bug("a stage face is not a closed convex warp loop");
    }
    const auto& c = stage.faces[0].corners;
    physics::Vec2w centre{0, 0};
    for (const auto p : c) centre = centre + physics::Vec2w{p.x, p.y};
    const physics::Vec2 at{static_cast<int32_t>(centre.x / int64_t(c.size())),
                           static_cast<int32_t>(centre.y / int64_t(c.size()))};
    const physics::EntityId body = world.createEntity(physics::Convex::regular(8, 1));
    world.insert(body, stage.part(0), at, 0);
    world.setVelocity(body, {65536 * 7, 65536 * 3});
    for (int frame = 0; frame < 50; ++frame) world.solve();
    if (!world.entity(body).inserted()) bug("the body left the stage");
  } catch (const physics::Error& e) {
    bug(std::string("the physics refused a built stage: ") + e.what());
  }
  return 0;
}
