#include <algorithm>
#include <cmath>

#include "platon/core/display.h"
#include "platon/core/scene.h"

namespace platon::core {
namespace {

Point3 point3(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}
Eigen::Vector3d vector3(const Point3& p) { return {p.x, p.y, p.z}; }

std::vector<ViewLine> linesOf(const physics::MapPart& part, const stage::TagTable& tags) {
  const auto segments = part.segments();
  const auto lines = part.lines();
  std::vector<ViewLine> out;
  out.reserve(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    const physics::Segment& s = segments[i];
    out.push_back({{static_cast<float>(s.a.x), static_cast<float>(s.a.y)},
                   {static_cast<float>(s.b.x), static_cast<float>(s.b.y)},
                   lines[i].tag,
                   static_cast<uint8_t>(lines[i].kind),
                   tags.style(lines[i].tag),
                   tags.passage(lines[i].tag) == stage::Passage::Door});
  }
  return out;
}

// A scene built in Lua has map parts but no solid: the player's part is a flat face in the z = 0
// plane, outlined by its lines' bounding box.
std::shared_ptr<StageView> flatStage(const Scene& scene, physics::MapPartId part) {
  auto view = std::make_shared<StageView>();
  view->flat = true;
  float extent = 1;
  if (const physics::MapPart* found = scene.world().findMapPart(part)) {
    const physics::MapPartId id = part;
    ViewFace face;
    face.part = id;
    face.lines = linesOf(*found, *scene.tags());
    float x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    bool first = true;
    for (const ViewLine& l : face.lines)
      for (const Point2 p : {l.a, l.b}) {
        if (first) x0 = x1 = p.x, y0 = y1 = p.y, first = false;
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      }
    face.corners = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    face.xAxis = {1, 0, 0}, face.yAxis = {0, 1, 0}, face.normal = {0, 0, 1};
    extent = std::max({extent, x1 - x0, y1 - y0});
    view->faces.push_back(std::move(face));
  }
  view->edge = view->faceSize = view->radius = extent;
  return view;
}

}  // namespace

std::shared_ptr<const StageView> stageView(const Scene& scene, physics::MapPartId playerPart) {
  if (!scene.stage()) return flatStage(scene, playerPart);
  return stageView(*scene.stage(), scene.world(), *scene.tags());
}

std::shared_ptr<StageView> stageView(const stage::Stage& net, const physics::World& world,
                                     const stage::TagTable& tags) {
  const stage::Stage* stage = &net;
  auto view = std::make_shared<StageView>();
  view->centre = point3(stage->centre);
  double radius = 0, edge = 0, size = 0;
  for (size_t i = 0; i < stage->faceCount(); ++i) {
    const stage::StageFace& f = stage->faces[i];
    ViewFace face;
    face.part = stage->part(i);
    for (size_t k = 0; k < f.corners.size(); ++k) {
      const physics::Vec2 c = f.corners[k], d = f.corners[(k + 1) % f.corners.size()];
      face.corners.push_back({static_cast<float>(c.x), static_cast<float>(c.y)});
      radius = std::max(radius, (f.toWorld(c.x, c.y) - stage->centre).norm());
      edge = std::max(edge, std::hypot(static_cast<double>(d.x) - c.x, static_cast<double>(d.y) - c.y));
      for (const physics::Vec2 e : f.corners)
        size = std::max(size, std::hypot(static_cast<double>(e.x) - c.x, static_cast<double>(e.y) - c.y));
    }
    face.origin = point3(f.origin), face.xAxis = point3(f.xAxis), face.yAxis = point3(f.yAxis);
    face.normal = point3(f.normal);
    face.lines = linesOf(world.mapPart(face.part), tags);
    view->faces.push_back(std::move(face));
  }
  view->radius = static_cast<float>(radius);
  view->edge = static_cast<float>(edge);
  view->faceSize = static_cast<float>(size);
  return view;
}

camera::CameraTarget cameraTarget(const StageView& stage, const Scene& scene, physics::MapPartId part, float x,
                                  float y) {
  const physics::MapPart* found = scene.world().findMapPart(part);
  return cameraTarget(stage, part, x, y, found ? found->gravity() : physics::Vec2w{});
}

camera::CameraTarget cameraTarget(const StageView& stage, physics::MapPartId part, float x, float y, physics::Vec2w g) {
  camera::CameraTarget target;
  const ViewFace* face = nullptr;
  for (const ViewFace& f : stage.faces)
    if (f.part == part) face = &f;
  const double gx = static_cast<double>(g.x), gy = g == physics::Vec2w{} ? -1.0 : static_cast<double>(g.y);
  if (!face) return target;
  const Eigen::Vector3d origin = vector3(face->origin), xAxis = vector3(face->xAxis), yAxis = vector3(face->yAxis);
  target.player = origin + double{x} * xAxis + double{y} * yAxis;
  target.down = gx * xAxis + gy * yAxis;
  target.normal = vector3(face->normal);
  // The eye sits a little less than the widest face's diameter above the player: the face fills
  // most of the screen and its neighbours show round it.
  target.viewHeight = 0.8 * stage.faceSize;
  target.centre = stage.flat ? target.player - vector3(face->normal) * stage.edge : vector3(stage.centre);
  return target;
}

}  // namespace platon::core
