// Chipmunk 7.0.3 behind PeerWorld (see peer.h for the configuration).
#include <chipmunk/chipmunk.h>
#include <cmath>

#include "peer.h"

namespace platon::bench {
namespace {

class ChipmunkWorld final : public PeerWorld {
 public:
  ChipmunkWorld(int iterations, double collisionSlop) : space_(cpSpaceNew()), iterations_(iterations) {
    cpSpaceSetIterations(space_, iterations);
    cpSpaceSetCollisionSlop(space_, collisionSlop);
    // Sensor begin events come through the default handler; a pair with no sensor still collides.
    cpCollisionHandler* handler = cpSpaceAddDefaultCollisionHandler(space_);
    handler->userData = &sensorBegins_;
    handler->beginFunc = [](cpArbiter* arb, cpSpace*, cpDataPointer data) -> cpBool {
      CP_ARBITER_GET_SHAPES(arb, a, b);
      if (cpShapeGetSensor(a) || cpShapeGetSensor(b)) ++*static_cast<int*>(data);
      return cpTrue;
    };
  }
  ~ChipmunkWorld() override {
    // cpSpaceFree does not free what was added to the space.
    for (cpShape* s : shapes_) {
      cpSpaceRemoveShape(space_, s);
      cpShapeFree(s);
    }
    for (cpBody* b : bodies_) {
      cpSpaceRemoveBody(space_, b);
      cpBodyFree(b);
    }
    cpSpaceFree(space_);
  }
  ChipmunkWorld(const ChipmunkWorld&) = delete;
  ChipmunkWorld& operator=(const ChipmunkWorld&) = delete;

  std::string name() const override {
    std::string n = "Chipmunk 7.0.3 it" + std::to_string(iterations_);
    if (lastDt_ > 0) n += " " + std::to_string(std::lround(1 / lastDt_)) + "Hz";
    return n;
  }

  void setGravity(double gx, double gy) override { cpSpaceSetGravity(space_, cpv(gx, gy)); }

  void addSegment(double x0, double y0, double x1, double y1, bool sensor) override {
    cpShape* s = cpSegmentShapeNew(cpSpaceGetStaticBody(space_), cpv(x0, y0), cpv(x1, y1), 0);
    cpShapeSetSensor(s, sensor);
    addShape(s);
  }

  int addBody(const Polygon& convexCCW, double x, double y, bool fixedRotation) override {
    std::vector<cpVect> verts;
    for (const auto& [vx, vy] : convexCCW) verts.push_back(cpv(vx, vy));
    const int n = static_cast<int>(verts.size());
    const cpFloat mass = cpAreaForPoly(n, verts.data(), 0);  // density 1
    const cpFloat moment = fixedRotation ? INFINITY : cpMomentForPoly(mass, n, verts.data(), cpvzero, 0);
    cpBody* body = cpSpaceAddBody(space_, cpBodyNew(mass, moment));
    cpBodySetPosition(body, cpv(x, y));
    bodies_.push_back(body);
    addShape(cpPolyShapeNew(body, n, verts.data(), cpTransformIdentity, 0));
    return static_cast<int>(bodies_.size()) - 1;
  }

  void setVelocity(int body, double vx, double vy) override { cpBodySetVelocity(bodies_.at(body), cpv(vx, vy)); }
  void setAngularVelocity(int body, double w) override { cpBodySetAngularVelocity(bodies_.at(body), w); }

  // Chipmunk multiplies two shapes' elasticities: both are set alike.
  void setRestitution(double restitution) override {
    restitution_ = restitution;
    for (cpShape* s : shapes_) cpShapeSetElasticity(s, restitution);
  }

  void step(double dt) override {
    lastDt_ = dt;
    cpSpaceStep(space_, dt);
  }

  Pose pose(int body) const override {
    const cpBody* b = bodies_.at(body);
    const cpVect p = cpBodyGetPosition(b);
    return {p.x, p.y, cpBodyGetAngle(b)};
  }

  int sensorBeginEvents() const override { return sensorBegins_; }

 private:
  void addShape(cpShape* s) {
    cpShapeSetElasticity(s, restitution_);
    cpShapeSetFriction(s, 0);
    shapes_.push_back(cpSpaceAddShape(space_, s));
  }

  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  int iterations_;
  int sensorBegins_ = 0;
  double lastDt_ = 0;
  double restitution_ = 0;
};

}  // namespace

std::unique_ptr<PeerWorld> makeChipmunk(int iterations, double collisionSlop) {
  return std::make_unique<ChipmunkWorld>(iterations, collisionSlop);
}

}  // namespace platon::bench
