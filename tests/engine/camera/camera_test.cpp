// The camera over every edge of every stage: a ball crosses each edge of each face of the five
// Platonic solids and the two mesh stages, straight and at an angle, under each face's own down
// (the faces' -y as in most levels, or a random down per face, as a level's `gravity` option
// gives), and the camera is checked frame by frame: it never turns faster than its top speed (no
// jump, and so no flip), keeps the ball on the screen, and once the ball stops it settles on the
// seed's line (centre -> player, the floor level) within half a degree (no roll left over).
#include "platon/camera/camera.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "mesh_system.h"
#include "platon/core/display.h"
#include "platon/core/mesh_source.h"
#include "platon/core/scene.h"
#include "platon/stage/mesh.h"
#include "platon/stage/stage.h"

using namespace platon;
using physics::Vec2;

namespace {

constexpr double kStep = 1.0 / 60.0;

struct Built {
  physics::World world;
  stage::Stage stage;
  std::shared_ptr<const core::StageView> view;
};

std::unique_ptr<Built> build(stage::Stage s) {
  auto b = std::make_unique<Built>();
  b->stage = std::move(s);
  stage::addStageToWorld(b->stage, b->world, 0);
  for (size_t f = 0; f < b->stage.faceCount(); ++f)
    b->world.mapPart(b->stage.part(f)).initialize();  // no gravity: straight lines
  b->view = core::stageView(b->stage, b->world);
  return b;
}

struct Stats {
  int crossings = 0;
  double fastest = 0;  // radians per frame
  int frames = 0;
};

// Whether the point shows on a 16:9 screen from this pose.
bool onScreen(const camera::Camera& cam, const Eigen::Vector3d& p) {
  const camera::CameraPose& pose = cam.pose();
  const Eigen::Vector3d v = pose.orientation.conjugate() * (p - pose.eye());
  if (v.z() >= 0) return false;  // behind the eye
  const double t = std::tan(cam.settings().verticalFov / 2);
  return std::fabs(v.y() / -v.z()) < t && std::fabs(v.x() / -v.z()) < t * cam.aspect();
}

// `turned`: each face's down a random direction in its plane instead of its -y.
void walkEveryEdge(const std::string& name, stage::Stage s, Stats& stats, bool turned) {
  auto b = build(std::move(s));
  std::vector<physics::Vec2w> downs(b->stage.faceCount(), physics::Vec2w{0, -1});
  uint64_t seed = 0x9e3779b97f4a7c15ull;
  for (auto& d : downs) {
    if (!turned) break;
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    const double a = static_cast<double>(seed >> 11) / 9007199254740992.0 * 2 * M_PI;
    d = {static_cast<int64_t>(std::cos(a) * 65536), static_cast<int64_t>(std::sin(a) * 65536)};
  }
  const double edgeLength = b->view->edge;
  const int32_t radius = static_cast<int32_t>(edgeLength * 0.03);
  const double maxTurn = camera::CameraSettings{}.topSpeed * kStep * (1 + 1e-9) + 1e-12;
  for (size_t f = 0; f < b->stage.faceCount(); ++f) {
    const stage::StageFace& face = b->stage.faces[f];
    const size_t n = face.corners.size();
    double cx = 0, cy = 0;
    for (const Vec2 c : face.corners) cx += c.x / double(n), cy += c.y / double(n);
    for (size_t k = 0; k < n; ++k)
      for (const double slant : {0.0, 0.6, -0.6}) {
        SCOPED_TRACE(name + " face " + std::to_string(f) + " edge " + std::to_string(k) + " slant " +
                     std::to_string(slant));
        const Vec2 a = face.corners[k], c = face.corners[(k + 1) % n];
        const double mx = (a.x + c.x) / 2.0, my = (a.y + c.y) / 2.0;
        // Start halfway between the face's centre and the edge's middle, heading for the edge.
        const double sx = (cx + mx) / 2, sy = (cy + my) / 2;
        double dx = mx - sx, dy = my - sy;
        const double len = std::hypot(dx, dy);
        dx /= len, dy /= len;
        const double rx = dx * std::cos(slant) - dy * std::sin(slant), ry = dx * std::sin(slant) + dy * std::cos(slant);
        const physics::EntityId ball = b->world.createEntity(physics::Convex::regular(16, radius));
        b->world.insert(ball, b->stage.part(f), {static_cast<int32_t>(sx), static_cast<int32_t>(sy)}, 0);
        const double speed = edgeLength / 90;  // units a frame: an edge in a second and a half
        b->world.setVelocity(ball,
                             {static_cast<int64_t>(rx * speed * 65536), static_cast<int64_t>(ry * speed * 65536)});

        camera::Camera cam;
        auto target = [&] {
          const physics::EntityView e = b->world.entity(ball);
          const physics::InstanceView i = e.instance(0);
          return core::cameraTarget(*b->view, i.part, static_cast<float>(i.position.x),
                                    static_cast<float>(i.position.y), downs[i.part]);
        };
        cam.set(target(), 1280, 720);
        const physics::MapPartId startPart = b->stage.part(f);
        int afterCrossing = -1;
        for (int frame = 0; frame < 2000; ++frame) {
          const camera::CameraPose before = cam.pose();
          if (afterCrossing == 30) b->world.setVelocity(ball, {});  // stop on the new face
          b->world.solve();
          const camera::CameraTarget t = target();
          cam.lerp(t, kStep);
          const double turn = before.orientation.angularDistance(cam.pose().orientation);
          stats.fastest = std::max(stats.fastest, turn);
          ++stats.frames;
          ASSERT_LE(turn, maxTurn) << "frame " << frame << ": the view jumped";
          ASSERT_TRUE(onScreen(cam, t.player)) << "frame " << frame << ": the ball left the screen";
          if (afterCrossing < 0 && b->world.entity(ball).instance(0).part != startPart &&
              b->world.entity(ball).instanceCount() == 1)
            afterCrossing = 0;
          if (afterCrossing >= 0) ++afterCrossing;
          if (afterCrossing > 30 + 150) {
            // Standing still for 2.5 s: on the seed's pose.
            const double gap = cam.pose().orientation.angularDistance(camera::Camera::wanted(t).orientation);
            EXPECT_LT(gap, 0.5 * M_PI / 180) << "not settled 2.5 s after stopping";
            break;
          }
        }
        ASSERT_GE(afterCrossing, 0) << "the ball never crossed";
        ++stats.crossings;
        b->world.destroyEntity(ball);
      }
  }
}

stage::Stage meshStage(const std::string& file, int32_t size) {
  mesh::MeshSystem reader;
  return stage::stageFromPolyhedron(stage::polyhedronFromMesh(core::meshDataOf(reader.loadMesh(file)), size));
}

TEST(Camera, EveryEdgeOfEveryStageTurnsTheViewSmoothly) {
  Stats stats;
  const std::pair<const char*, stage::Solid> solids[] = {{"tetrahedron", stage::Solid::Tetrahedron},
                                                         {"cube", stage::Solid::Hexahedron},
                                                         {"octahedron", stage::Solid::Octahedron},
                                                         {"dodecahedron", stage::Solid::Dodecahedron},
                                                         {"icosahedron", stage::Solid::Icosahedron}};
  const std::string root = PLATON_SOURCE_ROOT;
  for (const bool turned : {false, true}) {
    for (const auto& [name, solid] : solids) walkEveryEdge(name, stage::platonicStage(solid, 4096), stats, turned);
    walkEveryEdge("prism", meshStage(root + "/levels/prism/prism.ply", 6144), stats, turned);
    walkEveryEdge("football", meshStage(root + "/levels/soccer_ball/truncated_icosahedron.ply", 2048), stats, turned);
  }
  // 2 downs x 3 angles x (4 x 3 + 6 x 4 + 8 x 3 + 12 x 5 + 20 x 3 + the prism's 18 + 12 x 5 + 20 x 6)
  EXPECT_EQ(stats.crossings, 2 * 3 * (12 + 24 + 24 + 60 + 60 + 18 + 60 + 120));
  std::printf("%d crossings, %d frames, fastest turn %.2f degrees a frame\n", stats.crossings, stats.frames,
              stats.fastest * 180 / M_PI);
}

// The seed's line: the eye on the ray from the centre through the player, looking at the centre,
// the way the player walks (normal x down) pointing right on the screen, and so its up (against
// its down) upward; over random targets, faces seen from straight above or at a slant.
TEST(Camera, TheWantedPoseIsOnTheLineFromTheCentreThroughThePlayer) {
  std::srand(7);
  auto random = [] { return Eigen::Vector3d::Random(); };
  for (int i = 0; i < 1000; ++i) {
    camera::CameraTarget t;
    t.centre = random() * 100;
    t.player = t.centre + random().normalized() * (1 + std::rand() % 50);
    Eigen::Vector3d out = (t.player - t.centre).normalized();
    t.normal = (out + 0.7 * random()).normalized();  // the face, leaning up to ~50 degrees off the view line
    if (t.normal.dot(out) < 0.3) t.normal = out;
    t.down = random().cross(t.normal);  // along the face, whatever its length
    t.viewHeight = 3;
    const camera::CameraPose p = camera::Camera::wanted(t);
    const Eigen::Vector3d toEye = (p.eye() - t.centre).normalized();
    EXPECT_GT(toEye.dot(out), 1 - 1e-9);
    EXPECT_NEAR((p.eye() - t.player).norm(), 3, 1e-6);
    EXPECT_GT(p.forward().dot(-out), 1 - 1e-9);
    const Eigen::Vector3d walk = t.normal.cross(t.down).normalized();
    const Eigen::Vector3d right = p.orientation * Eigen::Vector3d::UnitX();
    EXPECT_NEAR(right.dot(p.forward()), 0, 1e-9);
    EXPECT_NEAR(right.dot((walk - walk.dot(p.forward()) * p.forward()).normalized()), 1,
                1e-9);                               // the floor reads level
    EXPECT_GT(p.up().dot(-t.down.normalized()), 0);  // and up is against the gravity
  }
}

TEST(Camera, TheSameTimeInAnySplitGivesTheSamePose) {
  // 60 steps of 1/60 s or 240 of 1/240 s: the same pose within a hair (the exponential approach
  // composes; the speed cap is per second).
  camera::CameraTarget from, to;
  from.player = {0, 0, 1}, from.down = {0, -1, 0};
  to.player = {1, 0, 0}, to.down = {0, 0, -1};
  camera::Camera a, b;
  a.set(from, 1280, 720), b.set(from, 1280, 720);
  for (int i = 0; i < 12; ++i) a.lerp(to, 1.0 / 60);
  for (int i = 0; i < 48; ++i) b.lerp(to, 1.0 / 240);
  EXPECT_LT(a.pose().orientation.angularDistance(b.pose().orientation), 0.02);
}

}  // namespace
