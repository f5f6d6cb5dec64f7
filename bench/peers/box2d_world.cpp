// Box2D 2.4.1 behind PeerWorld (see peer.h for the configuration).
#include <box2d/box2d.h>
#include <cmath>
#include <stdexcept>

#include "peer.h"

namespace platon::bench {
namespace {

b2Vec2 vec(double x, double y) { return {static_cast<float>(x), static_cast<float>(y)}; }

// Counts sensor begin events; Box2D reports them through the world's contact listener.
class SensorCounter : public b2ContactListener {
 public:
  void BeginContact(b2Contact* contact) override {
    begins += contact->GetFixtureA()->IsSensor() || contact->GetFixtureB()->IsSensor();
  }
  int begins = 0;
};

class Box2DWorld final : public PeerWorld {
 public:
  Box2DWorld(int velocityIterations, int positionIterations)
      : velocityIterations_(velocityIterations), positionIterations_(positionIterations) {
    world_.SetContactListener(&sensors_);
    const b2BodyDef groundDef;
    ground_ = world_.CreateBody(&groundDef);
  }

  std::string name() const override {
    std::string n = "Box2D 2.4.1 v" + std::to_string(velocityIterations_) + "p" + std::to_string(positionIterations_);
    if (lastDt_ > 0) n += " " + std::to_string(std::lround(1 / lastDt_)) + "Hz";
    return n;
  }

  void setGravity(double gx, double gy) override { world_.SetGravity(vec(gx, gy)); }

  void addSegment(double x0, double y0, double x1, double y1, bool sensor) override {
    b2EdgeShape edge;
    edge.SetTwoSided(vec(x0, y0), vec(x1, y1));
    b2FixtureDef def;
    def.shape = &edge;
    def.friction = 0;
    def.restitution = static_cast<float>(restitution_);
    def.isSensor = sensor;
    ground_->CreateFixture(&def);
  }

  int addBody(const Polygon& convexCCW, double x, double y, bool fixedRotation) override {
    if (convexCCW.size() > b2_maxPolygonVertices) throw std::invalid_argument("Box2D: too many vertices");
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.fixedRotation = fixedRotation;
    def.position = vec(x, y);
    b2Body* body = world_.CreateBody(&def);
    std::vector<b2Vec2> points;
    for (const auto& [vx, vy] : convexCCW) points.push_back(vec(vx, vy));
    b2PolygonShape shape;
    shape.Set(points.data(), static_cast<int32>(points.size()));
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = 1;
    fixture.friction = 0;
    fixture.restitution = static_cast<float>(restitution_);
    body->CreateFixture(&fixture);
    bodies_.push_back(body);
    return static_cast<int>(bodies_.size()) - 1;
  }

  void setVelocity(int body, double vx, double vy) override { bodies_.at(body)->SetLinearVelocity(vec(vx, vy)); }
  void setAngularVelocity(int body, double w) override { bodies_.at(body)->SetAngularVelocity(static_cast<float>(w)); }

  // Box2D mixes two fixtures' restitutions by their maximum; both are set alike.
  void setRestitution(double restitution) override {
    restitution_ = restitution;
    for (b2Body* b = world_.GetBodyList(); b; b = b->GetNext())
      for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext()) f->SetRestitution(static_cast<float>(restitution));
  }

  void step(double dt) override {
    lastDt_ = dt;
    world_.Step(static_cast<float>(dt), velocityIterations_, positionIterations_);
  }

  Pose pose(int body) const override {
    const b2Body* b = bodies_.at(body);
    return {b->GetPosition().x, b->GetPosition().y, b->GetAngle()};
  }

  int sensorBeginEvents() const override { return sensors_.begins; }

 private:
  b2World world_{b2Vec2(0, 0)};
  SensorCounter sensors_;
  b2Body* ground_ = nullptr;
  std::vector<b2Body*> bodies_;
  int velocityIterations_, positionIterations_;
  double lastDt_ = 0;
  double restitution_ = 0;
};

}  // namespace

std::unique_ptr<PeerWorld> makeBox2D(int velocityIterations, int positionIterations) {
  return std::make_unique<Box2DWorld>(velocityIterations, positionIterations);
}

}  // namespace platon::bench
